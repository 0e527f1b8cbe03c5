// How the choice of integrator changes as the system grows: a scene of run-time size that
// declares its modes (core/scene.hpp: size_param, modes(); the rope of N masses, the soft body of
// n x n masses: N = n^2) refined over `sizes`, every method and the peers at each size.
//
// For each solver and size:
//   the largest stable step dt*, predicted from the scene's modes (analysis/mode_stability.hpp;
//     measured against runs there);
//   the step (dopri5 and the peers: the tolerance rtol = atol) at which the run reaches the
//     target position error, the largest over the coordinates at t_end against the exact solution
//     (the rope) or the reference solution (the soft body: dopri5 at rtol 1e-13), so that the same
//     error per mass is asked at every N: a secant search in log-log on
//     error ~ C dt^p (p the method's order; for a tolerance p = 1), the largest step tried whose
//     error is at or below the target, from at most kSearchRuns runs;
//     A fixed-step method's search is capped at 0.95 dt*: it is told where its steps stop being
//     stable, from the exact modes, which no adaptive solver is told (ScalingRow::capped marks
//     the rows that stopped there).
//   that run's cost: its wall-clock time (the minimum of repeated runs, at least one and kSeconds
//     in all, one at a time after the searches; for every solver alike the scene is made outside
//     the timed region, the solver's set-up, run and clean-up inside), its counts (analysis/
//     counts.hpp: steps, rejected steps, force and Jacobian evaluations, factorisations, linear
//     solves, Newton iterations); the cost of one step is their ratio.
// Then per solver the exponents p of cost ~ N^p, N the number of masses, for one step and for the
// whole run, and q of dt* ~ N^q (Exponent below), and the size from which an implicit method's
// whole run is cheaper than every explicit one's.
#pragma once

#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/parallel.hpp"
#include "analysis/counts.hpp"
#include "analysis/defaults.hpp"
#include "core/simulate.hpp"

namespace steplab {

inline constexpr int kSearchRuns = 10;

struct ScalingConfig {
  std::string scene{kDefaultSizedScene};  // a scene that scales(): of run-time size, with modes
  std::vector<double> params;  // the scene's parameters, table order (its size parameter replaced by each size)
  std::vector<int> sizes{16, 64, 256, 1024};
  std::vector<std::size_t> methods;  // numerical methods of the table
  // steplab's dopri5 and the peers (analysis/peers.hpp) that run on the scene: by default all
  // that are built (scaling_config)
  std::vector<std::string> adaptive;
  double target_error = 1e-4;
  double t_end = 2;
  long long max_steps = 2'000'000;   // a search does not try steps that need more
  bool timing = true;
  Workers workers;  // threads (0: all cores), progress, shard log
};

struct ScalingRow {
  std::string solver;    // a method's name, dopri5 or a peer's (analysis/peers.hpp)
  bool implicit = false;
  bool adaptive = false; // dt below is then the tolerance
  int n = 0;             // the size: the value of the scene's size parameter
  int masses = 0;        // N
  double dt_stable = 0;  // predicted dt* (inf: none; NaN for the adaptive solvers)
  double dt = 0;         // the step (tolerance) that reaches the target; NaN if none did
  bool capped = false;   // a fixed step at the search's cap, 0.95 dt* (told by the modes)
  double error = 0;      // its error (largest over the coordinates at t_end)
  long long steps = 0, forces = 0, jacobians = 0;
  long long rejected = 0, factorisations = 0, solves = 0, newton = 0;  // analysis/counts.hpp
  double seconds = 0;    // the whole run (0 without timing)
  int runs = 0;          // runs the search took
  Counts counts() const { return {steps, rejected, forces, jacobians, factorisations, solves, newton}; }
  bool reached() const { return dt == dt; }
};

// An exponent p of y ~ N^p: least squares in log-log over the sizes where y is finite and > 0,
// with its 95 % interval (Student's t, n - 2 degrees of freedom: analysis/fit.hpp), fitted only
// over at least kFitSizes sizes spanning at least kFitDecades decades of N (two sizes fit any
// exponent exactly; a narrow span measures the overheads' mix, not a power): else NaN, with the
// sizes and span it had. `early`: the sizes begin below the asymptotic regime, where a step's cost
// grows by less than N^kAsymptoticSlope from the smallest size to the next (a step touches every
// mass, so its work grows at least as N; flatter, fixed overheads still dominate).
inline constexpr int kFitSizes = 3;
inline constexpr double kFitDecades = 1.5;
inline constexpr double kAsymptoticSlope = 0.5;
struct Exponent {
  double value = std::numeric_limits<double>::quiet_NaN(), lo = value, hi = value;
  int sizes = 0;       // sizes with a value
  double decades = 0;  // log10(N_max / N_min) over them
  bool early = false;
  bool fitted() const { return !std::isnan(value); }
};
Exponent fit_exponent(std::span<const double> masses, std::span<const double> y);
// Whether a step's cost (NaN or <= 0 where unknown) grows by less than N^kAsymptoticSlope from
// the smallest size with one to the next.
bool begins_early(std::span<const double> masses, std::span<const double> step_cost);

struct ScalingFit {
  std::string solver;
  Exponent step, run;  // cost of one step, of the whole run at the target error
  Exponent stable;     // dt* ~ N^q, where dt* is finite and > 0
};

struct ScalingResult {
  ScalingConfig config;
  std::vector<ScalingRow> rows;  // solver-major, sizes in order
  std::vector<ScalingFit> fits;
  // The smallest size at which some implicit method's whole run is cheaper than every explicit
  // method's (time, or force + Jacobian evaluations without timing), and which; 0 if none.
  int crossover = 0;
  std::string crossover_method;

  std::size_t solvers() const { return config.sizes.empty() ? 0 : rows.size() / config.sizes.size(); }
  // Solver s's rows, one per size in order.
  std::span<const ScalingRow> rows_of(std::size_t s) const {
    return {rows.data() + s * config.sizes.size(), config.sizes.size()};
  }
};

// Whether the study runs on a scene: of run-time size (a size parameter) with modes.
struct SceneKernel;
bool scales(const SceneKernel& scene);
// The study's defaults on a scene: its default parameters; the sizes and step cap of
// analysis/defaults.hpp (the rope at 16, 64, 256, 1024 masses with searches of up to 2 000 000
// steps, the soft body at n = 4, 8, 16 with up to 200 000); dopri5 and every peer built that runs
// on the scene.
ScalingConfig scaling_config(std::string_view scene);

ScalingResult scaling_study(const ScalingConfig& c);

// What a row's run cost: its seconds, or without timing its force and Jacobian evaluations times
// N (each touches every mass; the linear solves not counted).
double scaling_cost(const ScalingConfig& c, const ScalingRow& r);
// The number of masses at size n (the scene's: n on the rope, n^2 on the soft body).
int scaling_masses(const ScalingConfig& c, int n);
// The adaptive solvers that run on the scene: dopri5 and the peers built for it.
std::vector<std::string> scaling_adaptive_solvers(std::string_view scene);

}  // namespace steplab
