// One run: a method stepping a scene from its initial state for a fixed number of steps.
//
// After every step the state is checked for non-finite values (MuJoCo's mj_checkPos in spirit):
// a blow-up ends the run with status Diverged and the step and time where it happened, and the
// last finite state as the final one. An implicit step whose Newton iteration did not converge
// ends it with NoConvergence. Neither is an error: both are results.
//
// Along the way, without allocating (the sample buffer is reserved before the loop):
//   - up to max_samples states, evenly decimated over the steps, first and last always kept;
//   - the energy ratio E/E0 (final and max) and, if asked, the least-squares slope of ln E
//     against t (the energy growth rate), accumulated online with Welford's update;
//   - against the exact solution where the scene has one: the position error (Euclidean norm)
//     at the end, its maximum and RMS over the steps, and the velocity error at the end.
#pragma once

#include <cmath>
#include <limits>
#include <vector>

#include "core/methods.hpp"
#include "core/stepper.hpp"

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
  bool energy_rate = false;    // fit the growth rate of ln E
  bool errors = true;          // compare with the exact solution where there is one
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
  State<D> final{};
  bool has_exact = false;
  double error_final = 0, error_max = 0, error_rms = 0, error_v_final = 0;
  double energy0 = 0, energy_ratio_final = 1, energy_ratio_max = 1;
  double energy_rate = std::numeric_limits<double>::quiet_NaN();  // d ln E / dt, least squares
  std::vector<Sample<D>> samples;
};

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

// Does nothing with each step; the default observer.
struct NoObserver {
  template <class... A> void operator()(const A&...) const {}
};

// After a step that reached y at time t: the position error against the exact solution (final,
// largest, and the sum of squares for the RMS) and the final velocity error. Shared by this run
// loop and dopri5's (core/dopri5.hpp). Forced inline: left to itself GCC 12 calls it, and the
// call costs RK4 on the spring 31 % more instructions a step (callgrind).
template <HasExact S>
[[gnu::always_inline]] inline void track_error(ExactTracker<S>& tracker, double t, const State<S::dim>& y,
                                               RunResult<S::dim>& r, double& err_sq_sum) {
  const State<S::dim> ex = tracker.at(t);
  const double err = (y.x - ex.x).norm();
  r.error_max = std::max(r.error_max, err);
  err_sq_sum += err * err;
  r.error_final = err;
  r.error_v_final = (y.v - ex.v).norm();
}

// The run's summary once r.steps and r.energy0 are set: has_exact, the RMS error, the energy
// ratios (NaN where E0 = 0: a ratio to nothing).
template <int D> void finish_run(RunResult<D>& r, bool has_exact, double err_sq_sum, double ratio, double ratio_max) {
  r.has_exact = has_exact;
  if (r.steps > 0) r.error_rms = std::sqrt(err_sq_sum / static_cast<double>(r.steps));
  if (r.energy0 == 0) ratio = ratio_max = std::numeric_limits<double>::quiet_NaN();
  r.energy_ratio_final = ratio;
  r.energy_ratio_max = ratio_max;
}

// `observe(i, t, state)` is called after every completed step (i = 1 .. steps), for studies that
// need more than the summary (bounces, penetration); it must not allocate.
template <class M, Scene S, class Observer = NoObserver>
RunResult<S::dim> simulate(const S& scene, const RunSpec& spec, Observer&& observe = {}) {
  constexpr int D = S::dim;
  State<D> y = scene.initial();
  RunResult<D> r;
  const double h = spec.dt;
  const SamplePlan plan{spec.steps, spec.max_samples};
  if (plan.size() > 0) r.samples.reserve(static_cast<std::size_t>(plan.size()) + 1);
  long long next_sample = 0, sample_k = 0;

  const double e0 = scene.energy(y.x, y.v);
  r.energy0 = e0;
  double ratio_max = 1, ratio = 1;
  // Welford accumulators for the slope of ln E on t.
  double n_fit = 0, mean_t = 0, mean_l = 0, c_tl = 0, m2_t = 0;
  const auto fit_point = [&](double t, double e) {
    if (!(e > 0) || !std::isfinite(e)) return;
    const double l = std::log(e);
    n_fit += 1;
    const double dt_ = t - mean_t;
    mean_t += dt_ / n_fit;
    mean_l += (l - mean_l) / n_fit;
    c_tl += dt_ * (l - mean_l);
    m2_t += dt_ * (t - mean_t);
  };
  const auto keep = [&](long long i, double t, const State<D>& s, double e) {
    if (i == next_sample && sample_k < plan.size()) {
      r.samples.push_back({t, s.x, s.v, e});
      next_sample = plan.at(++sample_k);
    }
  };
  keep(0, 0.0, y, e0);
  if (spec.energy_rate) fit_point(0.0, e0);

  double err_sq_sum = 0;
  long long i = 0;
  [[maybe_unused]] auto tracker = [&] {
    if constexpr (HasExact<S>) return ExactTracker<S>(scene);
    else return 0;
  }();
  Stepper<M, S> stepper;  // a multistep method's memory; nothing for a one-step method
  for (i = 1; i <= spec.steps; ++i) {
    const double t_prev = (i - 1) * h, t = i * h;
    State<D> next = y;
    const StepStatus st = stepper.step(scene, next, t_prev, h);
    if (!all_finite(next) || st != StepStatus::Ok) {
      r.status = st != StepStatus::Ok ? RunStatus::NoConvergence : RunStatus::Diverged;
      r.failed_step = i;
      r.failed_t = t;
      break;
    }
    y = next;
    const double e = scene.energy(y.x, y.v);
    if (e0 != 0) {
      ratio = e / e0;
      ratio_max = std::max(ratio_max, ratio);
    }
    if (spec.energy_rate) fit_point(t, e);
    if constexpr (HasExact<S>) {
      if (spec.errors) track_error(tracker, t, y, r, err_sq_sum);
    }
    keep(i, t, y, e);
    observe(i, t, y);
    if (ratio > spec.stop_above || ratio < spec.stop_below) {
      if (ratio > spec.stop_above) {
        r.status = RunStatus::Diverged;
        r.failed_step = i;
        r.failed_t = t;
      }
      ++i;
      break;
    }
  }
  r.steps = i - 1;
  r.t_final = r.steps * h;
  r.final = y;
  finish_run(r, HasExact<S> && spec.errors, err_sq_sum, ratio, ratio_max);
  if (spec.energy_rate && m2_t > 0) r.energy_rate = c_tl / m2_t;
  // The last finite state is always kept, also when the run ended early.
  if (plan.size() > 0 && (r.samples.empty() || r.samples.back().t != r.t_final))
    r.samples.push_back({r.t_final, y.x, y.v, scene.energy(y.x, y.v)});
  return r;
}

}  // namespace steplab
