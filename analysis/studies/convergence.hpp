// Convergence study: every method over a geometric dt sweep, errors against the exact solution
// (or, on a scene without one, against a reference solution), and the fitted order per method
// (analysis/fits/order_fit.hpp).
//
// The reference: the adaptive Dormand-Prince 5(4) (core/dopri5.hpp) at rtol = atol = 1e-13, its
// steps as fine as the contacts need, computed once per study. Its own error is estimated from a
// second resolution, rtol = atol = 1e-12: |u(1e-12) - u(1e-13)| bounds the error of the finer one
// (about 10x above it, the error following the tolerance). A run's error counts only where it is
// 100x above that estimate: points below it are left out of the fit like those at the round-off
// floor, so the reference's error never shapes a fitted order.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string_view>
#include <vector>

#include "analysis/kernel/parallel.hpp"
#include "analysis/fits/order_fit.hpp"
#include "core/simulate.hpp"

namespace steplab {

enum class ErrorKind { Final, Max, Rms };
std::string_view to_string(ErrorKind k);

struct ConvergenceConfig {
  std::size_t scene = 1;
  std::vector<double> params;         // the scene's parameter values, table order
  std::vector<std::size_t> methods;   // indices into the method table
  MethodSettings settings{};          // those of the methods that take them (sweeps, CG: core/method.hpp)
  double t_end = 10;
  double dt_max = 0.1, dt_min = 1e-4;
  int points = 16;
  ErrorKind fit_error = ErrorKind::Final;  // which error the order is fitted to
  Workers workers;  // threads (0: all cores), progress, shard log
  int pack_width = 0;  // a method's runs stepped together in SIMD lanes (run_all, analysis/kernel/kernel.hpp): 0 the CPU's best, 2, 4, 8, or 1 (one at a time); the same numbers
  // Work-precision: time every run again, one at a time, repeated until kTimingSeconds of
  // runs and at least 3 repetitions; the median is kept. Wall-clock times differ from run to
  // run: the only part of the output that is not reproducible, so it is off by default.
  bool timing = false;
  // Converge against the reference solution even where the scene has an exact one (a scene
  // without one always does). Only the final error: the reference is known at t_end alone.
  bool reference = false;
};

struct ReferenceSolution {
  double rtol = 1e-13, check_rtol = 1e-12;  // the reference's tolerance, and the second resolution's
  long long steps = 0, check_steps = 0;     // accepted steps of each
  double estimated_error = 0;               // |u(check) - u(reference)| at t_end
  double floor = 0;                         // 100 x estimated_error: errors below are not fitted
  std::vector<double> x, v;                 // the reference state at t_end
  // Asked for frames: the positions at t_k = k t_end / frames, k = 0 .. frames (dopri5's dense
  // output), and |x(check) - x(reference)| there, the largest over the coordinates and frames.
  std::vector<Eigen::VectorXd> frames;
  double frames_error = 0;
};

struct SceneKernel;  // analysis/kernel/kernel.hpp

// The reference solution at t_end of a scene with those parameters (and at `frames` evenly spaced
// times, if any): dopri5 at rtol = atol = 1e-13, its error estimated against a run at 1e-12.
ReferenceSolution reference_solution(const SceneKernel& s, const std::vector<double>& params, double t_end, int frames = 0);

inline constexpr double kTimingSeconds = 0.02;

struct ConvergenceRecord {
  std::size_t method;
  double dt;
  long long steps;          // steps planned (t_end / dt)
  RunStatus status;
  long long failed_step;    // -1 unless diverged
  double error_final, error_v_final, error_max, error_rms;
  double floor;             // round-off floor of this run's position error
  double seconds = -1;      // median wall-clock time of the run (timing only), else -1
};

struct ConvergenceFit {
  std::size_t method;
  OrderFit fit;
};

struct ConvergenceResult {
  ConvergenceConfig config;
  std::vector<double> dts;
  std::vector<ConvergenceRecord> records;  // method-major: records[m * dts.size() + i]
  std::vector<ConvergenceFit> fits;
  bool uses_reference = false;  // errors against `reference`, not the exact solution
  ReferenceSolution reference;
};

// The record's error of that kind (the one the order is fitted to).
double error_of(const ConvergenceRecord& r, ErrorKind k);

// Geometric sweep from dt_max down to dt_min; each dt adjusted so that t_end is a whole number
// of steps (dt = t_end / n); duplicates (same n) dropped.
std::vector<double> sweep_steps(double t_end, double dt_max, double dt_min, int points);

// Round-off floor of a position error after n steps on a state of size `scale`: each step adds
// about an ulp of the state, and on the cannon ball (large, smooth velocity) those add up
// linearly: eps scale n. Measured there: the exact methods' errors stay 5-7x below it.
double roundoff_floor(double scale, long long steps);

// A run that stays finite but whose error outgrows the solution (of size `scale`) a million times
// over has blown up as surely as one that overflows (RK4 on the stiff chain at dt 0.5: 3e143 after
// 20 steps): the studies count it as diverged rather than fit it.
inline constexpr double kBlownUp = 1e6;
inline bool blown_up(double error, double scale) { return !(error <= kBlownUp * std::max(scale, 1.0)); }

// Throws std::invalid_argument if the errors asked for need the exact solution the scene lacks
// (max or rms error against a reference).
ConvergenceResult convergence_study(const ConvergenceConfig& config);

// Order against a parameter (`study convergence --sweep NAME=LIST`): the study again at each value
// of one of the scene's parameters, everything else the same (the same dt sweep), so that each
// method's fitted order can be read against, say, the stiffness.
struct ConvergenceSweep {
  std::size_t param = 0;         // the parameter swept (its index in the scene's table)
  std::vector<double> values;    // increasing
  std::vector<ConvergenceResult> studies;  // one per value, in that order
};
ConvergenceSweep convergence_sweep(const ConvergenceConfig& config, std::size_t param, const std::vector<double>& values);

}  // namespace steplab
