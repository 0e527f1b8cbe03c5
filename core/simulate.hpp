// One run: a method stepping a scene from its initial state for a fixed number of steps.
//
// After every step the state is checked (MuJoCo's mj_checkPos in spirit): a non-finite value, or
// an energy that has left the run's blow-up bound (blow_up_energy below), ends the run with
// status Diverged and the step and time where it happened, and the last state before as the final one. An implicit step whose Newton iteration did not converge
// ends it with NoConvergence. Neither is an error: both are results.
//
// Along the way, without allocating (the sample buffer is reserved before the loop):
//   - up to max_samples states, evenly decimated over the steps, first and last always kept; or
//     `outputs` states at evenly spaced times, each interpolated inside the step that holds it
//     (core/dense_output.hpp: output between steps, so that a step need not divide the frames;
//     on a scene of run-time size an output's state is a new vector, allocated at the output);
//   - the energy ratio E/E0 (final and max) and, if asked, the least-squares slope of ln E
//     against t (the energy growth rate), accumulated online with Welford's update;
//   - against the exact solution where the scene has one: the position error (Euclidean norm)
//     at the end, its maximum and RMS over the steps, and the velocity error at the end.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <limits>
#include <utility>
#include <vector>

#include "core/dense_output.hpp"
#include "core/exact_tracker.hpp"
#include "core/run_result.hpp"
#include "core/stepper.hpp"

namespace steplab {

// Does nothing with each step; the default observer.
struct NoObserver {
  template <class... A> void operator()(const A&...) const {}
};

// The errors against the exact solution after each step: the position error (Euclidean norm)
// at the end, its largest and its sum of squares (for the RMS), and the velocity error at the
// end. T a pack for runs stepped together (core/batch.hpp): each lane adds where `take` holds.
// Shared by this run loop, dopri5's (core/dopri5.hpp) and the batch's. add is forced inline:
// left to itself GCC 12 calls the scalar version out of line, a call in every step of the
// cheapest methods.
template <class T> struct ErrorSums {
  T error_max = 0, err_sq_sum = 0, error_final = 0, error_v_final = 0;
  static constexpr auto fields() {
    return std::array{&ErrorSums::error_max, &ErrorSums::err_sq_sum, &ErrorSums::error_final, &ErrorSums::error_v_final};
  }
  template <int D, class C> [[gnu::always_inline]] inline void add(const State<D, T>& y, const State<D, T>& exact, const C& take) {
    using std::max;
    const T err = (y.x - exact.x).norm();
    error_max = select(take, max(error_max, err), error_max);
    err_sq_sum = select(take, err_sq_sum + err * err, err_sq_sum);
    error_final = select(take, err, error_final);
    error_v_final = select(take, (y.v - exact.v).norm(), error_v_final);
  }
  // One run's step against exact positions alone (HasExactAlong: the velocities are read once, at
  // the end, into error_v_final): the same sums as add.
  template <class X, class E> void add_positions(const X& x, const E& exact_x) {
    using std::max;
    const T err = (x - exact_x).norm();
    error_max = max(error_max, err);
    err_sq_sum = err_sq_sum + err * err;
    error_final = err;
  }
};

// The least-squares slope of ln E against t, accumulated with Welford's update: a point (t, l =
// ln E) makes n += 1, dt = t - mean_t, mean_t += dt / n, mean_l += (l - mean_l) / n,
// c_tl += dt (l - mean_l), m2_t += dt (t - mean_t); the slope is c_tl / m2_t. Lanes of a pack
// add where `take` holds. add is forced inline for the same reason as ErrorSums::add.
template <class T> struct EnergyFit {
  T n = 0, mean_t = 0, mean_l = 0, c_tl = 0, m2_t = 0;
  static constexpr auto fields() {
    return std::array{&EnergyFit::n, &EnergyFit::mean_t, &EnergyFit::mean_l, &EnergyFit::c_tl, &EnergyFit::m2_t};
  }
  template <class C> [[gnu::always_inline]] inline void add(const T& t, const T& e, const C& take) {
    if (!any(take)) return;
    using std::log;
    const T l = log(e), n1 = n + 1.0, dt = t - mean_t;
    const T mt = mean_t + dt / n1, ml = mean_l + (l - mean_l) / n1;
    c_tl = select(take, c_tl + dt * (l - ml), c_tl);
    m2_t = select(take, m2_t + dt * (t - mt), m2_t);
    n = select(take, n1, n), mean_t = select(take, mt, mean_t), mean_l = select(take, ml, mean_l);
  }
  // The slope; NaN with fewer than two distinct times.
  double slope() const { return m2_t > 0 ? c_tl / m2_t : std::numeric_limits<double>::quiet_NaN(); }
};

// What a run carries from one step to the next besides its state, its step count and its
// errors: E/E0 and its largest, and the ln E fit. T = double for one run (Run below, dopri5's
// loop), a pack for runs stepped together (BatchRunner, core/batch.hpp), with a lane's mask where
// one run has a bool: how a step is accounted for is this one definition for every run loop.
template <class T> struct RunTally {
  using Mask = MaskOf<T>;
  T ratio = 1, ratio_max = 1;
  EnergyFit<T> fit;

  // A run's tally at its start, from its energy E0: the fit's first point (t = 0) if it fits ln E.
  static RunTally start(double e0, bool energy_rate) {
    RunTally tally;
    if (energy_rate) tally.fit.add(0.0, e0, e0 > 0 && std::isfinite(e0));
    return tally;
  }

  // The step to t left a finite state of energy e in the lanes `live`: E/E0 and its largest
  // where E0 != 0, the fit's point where `rate` asks for it (some_rate: in some lane). One run's
  // select is a branch (it takes the same values; the branch is what GCC compiles best there).
  [[gnu::always_inline]] inline void account(const T& t, const T& e, const T& e0, const Mask& live, const Mask& e0_nonzero,
                                             const Mask& rate, bool some_rate) {
    using std::max;
    if constexpr (std::same_as<Mask, bool>) {
      if (live && e0_nonzero) {
        ratio = e / e0;
        ratio_max = max(ratio_max, ratio);
      }
    } else {
      const Mask has_e0 = live && e0_nonzero;
      const T r = e / e0;
      ratio_max = select(has_e0, max(ratio_max, r), ratio_max);
      ratio = select(has_e0, r, ratio);
    }
    if (some_rate) fit.add(t, e, live && rate && e > 0.0 && finite(e));
  }

  // Where E/E0 has left [below, above]: there the run ends (above: the energy blew up).
  [[gnu::always_inline]] inline Mask left(const T& above, const T& below) const { return ratio > above || ratio < below; }
};

// When a run has blown up: its energy has moved from its start E0 by more than kBlowUp times the
// start's energy scale, the larger of |E0|, its kinetic energy and, where the scene declares it,
// energy_scale(), the size of the energies its exact motion reaches (a driven scene's: the
// target's, started at the energy 1/2 m w^2, reaches 1/2 k); the total mass times 1 m^2/s^2 where
// all are 0. A physical motion stays within a few times that scale; an unstable one grows
// geometrically and passes the bound within some dozens of steps of passing the physical range,
// long before it overflows (RK4 on a rope of 10^5 masses above its step limit: E/E0 3e202 at its
// end). The state's velocities are then 10^6 times the start's scale. Such a run ends as
// Diverged at that step, its last state within the bound kept, as a non-finite state ends it.
inline constexpr double kBlowUp = 1e12;
template <class S, int D> double blow_up_energy(const S& s, const State<D>& y0, double e0) {
  const double kinetic = 0.5 * s.mass().cwiseProduct(y0.v.cwiseProduct(y0.v)).sum();
  double scale = std::max(std::abs(e0), kinetic);
  if constexpr (requires { s.energy_scale(); }) scale = std::max(scale, s.energy_scale());
  return kBlowUp * (scale > 0 ? scale : s.mass().sum());
}
// Whether an energy e is within the run's blow-up bound of its start e0 (false for a NaN energy):
// the test every run loop makes after each step (here, core/dopri5.hpp, long runs).
template <class T> [[gnu::always_inline]] inline auto within_blow_up(const T& e, const T& e0, const T& bound) {
  using std::abs;
  return abs(e - e0) <= bound;
}

// One step of a run loop, for one run (T = double, masks bool: Run below) or a pack of runs
// (BatchRunner, core/batch.hpp; i then counts each lane's steps in a T): the step from
// t_prev = (i - 1) h to t = i h, i 1-based, where `active`, the
// test of the new state, and where it passed (`live`) the step's accounting: E/E0 and the fit
// (RunTally::account), `after(y, live, t, e)` (the errors; one run's samples and observer) and
// the step counted (i + 1). Not live: the method's Newton iteration gave up (`failed`) or the
// state is not finite. One run then keeps its last finite state in y and returns at once; a pack
// steps y on in every lane and keeps the state before in `last` for those lanes.
template <class T> struct Stepped {
  MaskOf<T> live, failed;
  T t;
};

template <class Stp, int D, class T> [[gnu::always_inline]] inline State<D, T>& step_copy(Stp& stepper, const State<D, T>& y, State<D, T>& local) {
  if constexpr (D == Eigen::Dynamic) {
    stepper.work.next = y;
    return stepper.work.next;
  } else {
    local = y;
    return local;
  }
}

template <class Stp, class Sc, int D, class T, class I, class After>
[[gnu::always_inline]] inline Stepped<T> take_step(Stp& stepper, const Sc& scene, State<D, T>& y, State<D, T>& last, I& i,
                                                   const T& h, const MaskOf<T>& active, RunTally<T>& tally, const T& e0,
                                                   const T& blow_up, const MaskOf<T>& e0_nonzero, const MaskOf<T>& rate,
                                                   bool some_rate, After&& after) {
  using Mask = MaskOf<T>;
  const T t_prev = (i - 1.0) * h, t = i * h;
  // The step is taken on a copy, so that one run keeps its last finite state: on the stack for a
  // fixed size, in the run's workspace for a run-time one (sized in its first step).
  State<D, T> local;
  State<D, T>& next = step_copy(stepper, y, local);
  const Mask failed = active && Mask(steplab::failed(stepper.step(scene, next, t_prev, h)));
  // Live: finite, and its energy within the run's blow-up bound of its start (blow_up_energy;
  // false for a NaN energy too).
  const T e = scene.energy(next.x, next.v);
  const Mask live = all_finite(next) && active && !failed && within_blow_up(e, e0, blow_up);
  if constexpr (std::same_as<Mask, bool>) {
    if (!live) return {live, failed, t};
  } else {
    last = y;
  }
  y = next;
  tally.account(t, e, e0, live, e0_nonzero, rate, some_rate);
  after(y, live, t, e);
  if constexpr (std::same_as<Mask, bool>)
    ++i;
  else
    i = select(live, i + 1.0, i);
  return {live, failed, t};
}

// The run's summary once r.steps and r.energy0 are set: the errors, has_exact, the RMS error over
// the `reads` steps the errors were read at, the energy ratios (NaN where E0 = 0: a ratio to
// nothing) and, if fitted, the growth rate.
template <int D>
void finish_run(RunResult<D>& r, bool has_exact, const ErrorSums<double>& e, const RunTally<double>& tally, bool energy_rate,
                long long reads) {
  r.has_exact = has_exact;
  r.error_max = e.error_max, r.error_final = e.error_final, r.error_v_final = e.error_v_final;
  r.error_reads = has_exact ? reads : 0;
  if (r.error_reads > 0) r.error_rms = std::sqrt(e.err_sq_sum / static_cast<double>(r.error_reads));
  double ratio = tally.ratio, ratio_max = tally.ratio_max;
  if (r.energy0 == 0) ratio = ratio_max = std::numeric_limits<double>::quiet_NaN();
  r.energy_ratio_final = ratio;
  r.energy_ratio_max = ratio_max;
  if (energy_rate) r.energy_rate = tally.fit.slope();
}

// One run, step by step: the state of a run between steps (the accumulators above) and the
// step itself; simulate() below drives one to its end. `observe(i, t, state)` is called after every completed
// step (i = 1 .. steps), for studies that need more than the summary (bounces, penetration); it
// must not allocate. The scene and the result `out` must outlive the run; a Run is not copied or
// moved. The result lives outside the Run on purpose: with it as a member (its sample buffer's
// address escaping to the allocator), GCC 12 compiled the loop so that `study stability` took
// twice as long on one thread, per method, for the same instruction count (callgrind).
template <class M, Scene S, class Observer = NoObserver> class Run {
 public:
  static constexpr int D = S::dim;

  Run(const S& scene, const RunSpec& spec, RunResult<D>& out, Observer observe = {})
      : scene_(scene), spec_(spec), observe_(observe), plan_{spec.steps, spec.outputs > 0 ? 0 : spec.max_samples},
        y_(scene.initial()), r_(out), tracker_(make_tracker(scene, spec)) {
    if constexpr (TakesSettings<M>) stepper_.settings = spec.settings;
    if (plan_.size() > 0) r_.samples.reserve(static_cast<std::size_t>(plan_.size()) + 1);
    if (spec.outputs > 0) r_.samples.reserve(static_cast<std::size_t>(spec.outputs)), prev_ = y_;
    e0_ = scene.energy(y_.x, y_.v);
    blow_up_ = blow_up_energy(scene, y_, e0_);
    r_.energy0 = e0_;
    keep(0, 0.0, y_, e0_);
    if (spec.outputs > 0) r_.samples.push_back({0.0, y_.x, y_.v, e0_}), out_k_ = 1;
    tally_ = RunTally<double>::start(e0_, spec.energy_rate);
  }
  Run(const Run&) = delete;
  Run& operator=(const Run&) = delete;

  // Takes step i_ (1-based); false when the run has ended (all steps taken, diverged, Newton
  // failed, or stopped early). After false, call finish(), not advance().
  [[gnu::always_inline]] inline bool advance() {
    if (i_ > spec_.steps) return false;
    const bool output = out_k_ < spec_.outputs && output_time(out_k_) <= static_cast<double>(i_) * spec_.dt * (1 + 1e-12);
    if (output) {  // the step's start, to interpolate from; its acceleration is the last output step's end's if that
      a_prev_kept_ = a_end_step_ == i_ - 1;  // step just before ended where this one starts
      prev_ = y_;
    }
    const Stepped<double> s = take_step(stepper_, scene_, y_, y_, i_, spec_.dt, true, tally_, e0_, blow_up_, e0_ != 0, true, spec_.energy_rate,
                                        [&](const State<D>& y, bool, double t, double e) __attribute__((always_inline)) {
                                          if constexpr (HasExactAlong<S>) {
                                            if (spec_.errors && i_ % stride_ == 0) errors_.add_positions(y.x, tracker_.at(t));
                                          } else if constexpr (HasExact<S>) {
                                            if (spec_.errors) errors_.add(y, tracker_.at(t), true);
                                          }
                                          keep(i_, t, y, e);
                                          if (output) interpolate(t, y);
                                          observe_(i_, t, y);
                                        });
    if (!s.live) {
      r_.status = s.failed ? RunStatus::NoConvergence : RunStatus::Diverged;
      r_.failed_step = i_;
      r_.failed_t = s.t;
      return false;
    }
    if (tally_.left(spec_.stop_above, spec_.stop_below)) {
      if (tally_.ratio > spec_.stop_above) {
        r_.status = RunStatus::Diverged;
        r_.failed_step = i_ - 1;
        r_.failed_t = s.t;
      }
      return false;
    }
    return true;
  }

  // Completes the result, once advance() has returned false (i_ - 1 steps completed). Call once.
  void finish() {
    r_.steps = i_ - 1;
    r_.t_final = r_.steps * spec_.dt;
    r_.final = y_;
    // Read at the multiples of the stride up to the last step, and at the last if it is not one.
    long long reads = r_.steps;
    if constexpr (HasExactAlong<S>) {
      reads = r_.steps / stride_ + (r_.steps % stride_ != 0);
      if (spec_.errors && r_.steps > 0) {
        if (r_.steps % stride_ != 0) tracker_.jump(), errors_.add_positions(y_.x, tracker_.at(r_.t_final));
        errors_.error_v_final = (y_.v - tracker_.velocities()).norm();
      }
    }
    finish_run(r_, HasExact<S> && spec_.errors, errors_, tally_, spec_.energy_rate, reads);
    // The last finite state is always kept, also when the run ended early.
    if (plan_.size() > 0 && (r_.samples.empty() || r_.samples.back().t != r_.t_final))
      r_.samples.push_back({r_.t_final, y_.x, y_.v, scene_.energy(y_.x, y_.v)});
  }

 private:
  static auto make_tracker(const S& scene, const RunSpec& spec) {
    if constexpr (HasExactAlong<S>) return scene.exact_along(spec.errors ? spec.dt * stride_of(spec) : 0);  // reads apart
    else if constexpr (HasExact<S>) return ExactTracker<S>(scene, spec.errors ? spec.dt : 0);
    else return 0;
  }
  static long long stride_of(const RunSpec& spec) { return HasExactAlong<S> ? std::max(1LL, spec.error_stride) : 1; }
  double output_time(long long k) const {
    return k == spec_.outputs - 1 ? static_cast<double>(spec_.steps) * spec_.dt
                                  : static_cast<double>(spec_.steps) * spec_.dt * static_cast<double>(k) /
                                        static_cast<double>(spec_.outputs - 1);
  }
  // s in [0, 1] of output time t in the step from t0; an output within 1e-9 of a step's end is
  // that end (its state itself, to the bit: the weights are then exactly 0 and 1).
  static double fraction(double t, double t0, double h) {
    const double s = std::clamp((t - t0) / h, 0.0, 1.0);
    return s > 1 - 1e-9 ? 1.0 : s < 1e-9 ? 0.0 : s;
  }
  // The outputs in the step just taken, from prev_ (at t1 - dt) to y (at t1).
  void interpolate(double t1, const State<D>& y) {
    const double h = spec_.dt, t0 = t1 - h;
    State<D> o = y;
    if constexpr (quintic_output(M::info.order)) {
      // a at the start: the previous step's end's where that step held an output too (consecutive
      // output steps, a step longer than a frame: one force evaluation a step, not two)
      if (!a_prev_kept_) a_end_ = acceleration(scene_, t0, prev_.x, prev_.v);
      const Vec<D> a0 = a_end_, a1 = acceleration(scene_, t1, y.x, y.v);
      a_end_ = a1, a_end_step_ = i_;
      for (; out_k_ < spec_.outputs && output_time(out_k_) <= t1 * (1 + 1e-12); ++out_k_) {
        const double t = output_time(out_k_);
        hermite5(prev_.x, prev_.v, a0, y.x, y.v, a1, h, fraction(t, t0, h), o.x, o.v);
        r_.samples.push_back({t, o.x, o.v, scene_.energy(o.x, o.v)});
      }
    } else {
      for (; out_k_ < spec_.outputs && output_time(out_k_) <= t1 * (1 + 1e-12); ++out_k_) {
        const double t = output_time(out_k_);
        hermite3(prev_.x, prev_.v, y.x, y.v, h, fraction(t, t0, h), o.x, o.v);
        r_.samples.push_back({t, o.x, o.v, scene_.energy(o.x, o.v)});
      }
    }
  }
  void keep(long long i, double t, const State<D>& s, double e) {
    if (i == next_sample_ && sample_k_ < plan_.size()) {
      r_.samples.push_back({t, s.x, s.v, e});
      next_sample_ = plan_.at(++sample_k_);
    }
  }

  const S& scene_;
  const RunSpec spec_;
  Observer observe_;
  const SamplePlan plan_;
  State<D> y_;
  State<D> prev_ = zero_state<D>();  // a step's start where an output falls in it (outputs > 0)
  Vec<D> a_end_ = zero_state<D>().x;  // the acceleration at the end of output step a_end_step_ (quintic)
  long long a_end_step_ = -1;
  bool a_prev_kept_ = false;
  RunResult<D>& r_;
  double e0_ = 0, blow_up_ = 0;
  RunTally<double> tally_;
  ErrorSums<double> errors_;
  long long i_ = 1, next_sample_ = 0, sample_k_ = 0;  // i_: the next step, 1-based
  long long out_k_ = 0;                                // the next output (outputs > 0)
  const long long stride_ = stride_of(spec_);  // the steps between the error's reads (HasExactAlong)
  [[no_unique_address]] decltype(make_tracker(std::declval<const S&>(), RunSpec{})) tracker_;
  [[no_unique_address]] Stepper<M, S> stepper_;  // a multistep method's memory; nothing for a one-step method
};

template <class M, Scene S, class Observer = NoObserver>
RunResult<S::dim> simulate(const S& scene, const RunSpec& spec, Observer&& observe = {}) {
  RunResult<S::dim> r;
  Run<M, S, Observer> run(scene, spec, r, std::forward<Observer>(observe));
  while (run.advance()) {
  }
  run.finish();
  return r;
}

}  // namespace steplab
