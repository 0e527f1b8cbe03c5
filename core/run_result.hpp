// What a run is asked (RunSpec) and what it gives back (RunResult, its samples), the sample plan
// and the step count for a span: the run loop's interface (core/simulate.hpp), kept apart so that
// a reader of the loop sees the loop.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "core/method.hpp"
#include "core/state.hpp"

namespace steplab {

enum class RunStatus { Ok, Diverged, NoConvergence };

inline const char* to_string(RunStatus s) {
  switch (s) {
    case RunStatus::Ok: return "ok";
    case RunStatus::Diverged: return "diverged";
    case RunStatus::NoConvergence: return "no_convergence";
  }
  return "?";
}

struct RunSpec {
  double dt = 0.01;
  long long steps = 1000;
  long long max_samples = 0;   // 0: no samples; otherwise at most this many (>= 2)
  // Output between steps (core/dense_output.hpp): if > 0, the samples are instead this many
  // states at the times t_k = k T / (outputs - 1), T = steps dt, each interpolated in its step
  // (cubic or quintic Hermite by the method's order; the quintic's force evaluations counted).
  // Only where an output falls does a step keep its start (and, at run-time size, allocate).
  long long outputs = 0;
  bool energy_rate = false;    // fit the growth rate of ln E
  bool errors = true;          // compare with the exact solution where there is one
  // On a scene whose exact positions cost a transform (HasExactAlong: the rope), the error is
  // read at every error_stride-th step and at the last (1: every step). Elsewhere every step.
  long long error_stride = 1;
  MethodSettings settings{};  // a method's that has them (sweeps: core/methods/xpbd.hpp)
  // Stop early once E/E0 leaves [stop_below, stop_above] (0 and inf: never). Above counts as
  // Diverged (the energy blew up); below ends the run as Ok (it has decayed, clearly stable,
  // before round-off flattens ln E).
  double stop_below = 0;
  double stop_above = std::numeric_limits<double>::infinity();
};

template <int D> struct Sample {
  double t;
  Vec<D> x, v;
  double energy;
};

template <int D> struct RunResult {
  RunStatus status = RunStatus::Ok;
  long long steps = 0;          // steps completed with a finite state
  long long failed_step = -1;   // the step (1-based) that diverged or did not converge
  double failed_t = 0;
  double t_final = 0;
  State<D> final = zero_state<D>();
  bool has_exact = false;
  double error_final = 0, error_max = 0, error_rms = 0, error_v_final = 0;
  long long error_reads = 0;    // the steps the errors were read at (the max and RMS are over these)
  double energy0 = 0, energy_ratio_final = 1, energy_ratio_max = 1;
  double energy_rate = std::numeric_limits<double>::quiet_NaN();  // d ln E / dt, least squares
  std::vector<Sample<D>> samples;
};

// A run's result with its states as vectors of run-time size: what a kernel compiled for one
// method and scene hands to the studies (analysis/kernel/kernel.hpp), which are not templates.
using AnyResult = RunResult<Eigen::Dynamic>;

// The same result with its states as vectors of size To (Eigen::Dynamic: run-time size; a fixed
// size: the caller knows the scene's). Copies, so the numbers are the same.
template <int To, int From> RunResult<To> resized(RunResult<From>&& r) {
  RunResult<To> a;
  a.status = r.status, a.steps = r.steps, a.failed_step = r.failed_step, a.failed_t = r.failed_t, a.t_final = r.t_final;
  a.final = {r.final.x, r.final.v};
  a.has_exact = r.has_exact;
  a.error_final = r.error_final, a.error_max = r.error_max, a.error_rms = r.error_rms, a.error_v_final = r.error_v_final;
  a.error_reads = r.error_reads;
  a.energy0 = r.energy0, a.energy_ratio_final = r.energy_ratio_final, a.energy_ratio_max = r.energy_ratio_max;
  a.energy_rate = r.energy_rate;
  a.samples.reserve(r.samples.size());
  for (const Sample<From>& s : r.samples) a.samples.push_back({s.t, s.x, s.v, s.energy});
  return a;
}
template <int D> AnyResult to_any(RunResult<D>&& r) { return resized<Eigen::Dynamic>(std::move(r)); }
template <int D> RunResult<D> to_fixed(AnyResult&& r) { return resized<D>(std::move(r)); }

// The step indices kept as samples: k (n / (N - 1)) rounded, k = 0 .. N-1.
struct SamplePlan {
  long long n, count;
  long long at(long long k) const { return count - 1 >= n ? k : (k * n + (count - 1) / 2) / (count - 1); }
  long long size() const { return count == 0 ? 0 : (count - 1 >= n ? n + 1 : count); }
};

// The number of steps of length dt that cover t_end: round(t_end / dt) when t_end is a whole
// number of steps (to 1e-9 relative), else the next whole number.
inline long long steps_for(double t_end, double dt) {
  const double ratio = t_end / dt;
  const double nearest = std::round(ratio);
  if (std::abs(ratio - nearest) <= 1e-9 * std::max(1.0, ratio)) return static_cast<long long>(nearest);
  return static_cast<long long>(std::ceil(ratio));
}

}  // namespace steplab
