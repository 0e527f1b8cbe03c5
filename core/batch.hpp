// Runs stepped W at a time: the run loop of core/simulate.hpp on packs (core/pack.hpp), one run
// per lane, structure of arrays. A step is take_step (core/simulate.hpp), the one definition a
// single run (Run) takes its steps by too: each lane's numbers are the bits its run gives alone,
// the same operations in the same order, lane by lane; what depends on the lane is a select on a
// mask. What is this driver's own: the lanes' masks, their end, and refilling them.
//
//   live   = active lanes whose step left a finite state       (a diverged lane ends here)
//   y      = next  (a diverged lane's result takes its last finite state: run() below)
//   E/E0, its largest and the ln E fit (Welford), updated where live by RunTally::account, the
//          definition one run's loop uses (core/simulate.hpp); the errors against the stepped
//          exact state, added where live by ErrorSums::add, also one run's
//   a lane ends when its steps are done or E/E0 leaves [stop_below, stop_above]; its result
//   is written and the lane refilled with the next run of the batch (DiffEqGPU.jl masks a
//   finished lane off; refilling it is what makes packs pay when runs end at different times:
//   Hentschel et al., EGPGV 2015). The loop ends when no lane has a run.
//
// Samples and observers are not kept here: a batch is for the studies' summary runs (run_all,
// analysis/kernel/kernel.hpp, runs a spec that asks for samples one at a time).
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>

#include "core/simulate.hpp"
#include "core/stepper.hpp"

namespace steplab {

// The pack widths a batch is stepped with, each its instruction set's register (PairKernel::
// run_batch compiles the loop for each): 2 lanes on plain x86-64 (SSE2), 4 with AVX2 and FMA,
// 8 with AVX-512. All give the bits of one run at a time (no FMA contraction: -ffp-contract=off;
// a pack is not passed in registers across calls: core/pack.hpp). 1 is one run at a time.
inline constexpr int kPackWidths[] = {1, 2, 4, 8};

// The widest loop compiled: STEPLAB_MAX_PACK_WIDTH (CMakeLists.txt), 4 (AVX2) by default; 8
// (AVX-512) where the build is configured so; 2 in the sanitized build. The loop is one template
// at every width, and each width more is another copy of it in every method's file.
#if defined(STEPLAB_MAX_PACK_WIDTH)
inline constexpr int kMaxPackWidth = STEPLAB_MAX_PACK_WIDTH;
#else
inline constexpr int kMaxPackWidth = 4;
#endif

inline bool cpu_has_width(int width) {
  if (width > kMaxPackWidth) return false;
#if defined(__x86_64__) && defined(__GNUC__)
  if (width == 4) return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  if (width == 8)
    return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
           __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512bw");
  return width == 1 || width == 2;
#else
  return width == 1;
#endif
}

// The studies' default: AVX2's 4 lanes where the CPU has it, else SSE2's 2. Not AVX-512's 8 (in
// a build configured with STEPLAB_MAX_PACK_WIDTH=8): on the machine docs/performance.md quotes
// (AMD EPYC, Zen 4, which executes a 512-bit operation as two 256-bit halves) its loop ran 3x
// slower than AVX2's, GCC 12 doing its comparisons lane by lane; --lanes 8 asks for it there.
inline int best_width() {
  static const int best = cpu_has_width(4) ? 4 : cpu_has_width(2) ? 2 : 1;
  return best;
}

// One run of a batch: its scene's parameter values (table order) and its spec.
struct BatchRun {
  std::span<const double> params;
  RunSpec spec;
};

// Whether M steps packs of runs of S: S is Packable and M's step (with its memory, for a
// multistep method) is written over the scalar (core/method.hpp).
// Its stages' dense solves, if any, are up to kPackLuSize unknowns (core/method.hpp).
// Asked of the 2-lane pack, which every build compiles: Stepper::step's return type is deduced,
// so the question instantiates the method's step over that pack, which the 2-lane loop then
// shares (asked of an 8-lane pack, it was one more instantiation per pair: about a tenth of
// each method file's compile time).
template <class M, class S>
concept PackedStep = Packable<S> && solve_stages<M>() * S::dim <= kPackLuSize &&
                     requires(Stepper<M, PackScene<S, Pack<2>>, Pack<2>>& st, const PackScene<S, Pack<2>>& s,
                              State<S::dim, Pack<2>>& y, Pack<2> h) {
                       st.step(s, y, h, h);  // a StepStatus, or the lanes that failed (a mask)
                     };

template <class M, Packable S, class T> class BatchRunner {
  static constexpr int W = T::width;
  using LaneScene = PackScene<S, T>;
  using LaneMask = MaskOf<T>;
  static constexpr int D = S::dim;
  static constexpr std::size_t P = S::params.size();
  template <class U> struct TrackerOf { using type = char; };  // a scene without an exact flow: none
  template <HasExact U> struct TrackerOf<U> { using type = ExactTracker<U>; };
  using LaneTracker = typename TrackerOf<S>::type;

 public:
  BatchRunner(std::span<const BatchRun> runs, AnyResult* out) : runs_(runs), out_(out) { start(); }

  // Steps until every run of the batch has ended. Between two refills the pack is stepped in
  // locals (the scene, the stepper's memory, the state and what the loop accumulates), copied in
  // before and back after: the inner loop makes no call that could reach them (closed_form
  // takes and returns its state by value), so GCC keeps them in registers or in stack slots it
  // only reads, and hoists what the scene's parameters give (0.5 m, -k) out of the loop. The
  // state is stepped with y = next in every lane: the test of the new state is off the chain from
  // one step to the next. A lane whose step diverged gets its last finite state back (y_ below)
  // before its result is written; an idle lane steps a finite state with h = 0 (refill). What
  // holds for the whole pack between two refills (a lane with an energy fit, a lane with errors,
  // E0 != 0, a lane still running) is set by refilled(), not tested each step.
  [[gnu::always_inline]] inline void run() {
    if (!any(active_)) return;
    for (;;) {
      const LaneScene scene = *scene_;
      Stepper<M, LaneScene, T> stepper = stepper_;
      const LaneMask active = active_, rate = rate_, errors = errors_, e0_nonzero = e0_nonzero_;
      const bool some_rate = some_rate_, some_errors = some_errors_;
      const T h = h_, steps = steps_, above = above_, below = below_, e0 = e0_, blow_up = blow_up_;
      State<D, T> y = y_, last = y_;
      T i = i_, t = 0;
      RunTally<T> tally = tally_;
      Exact ex = exact_;
      LaneMask failed, diverged, ended;
      do {
        const Stepped<T> s = take_step(stepper, scene, y, last, i, h, active, tally, e0, blow_up, e0_nonzero, rate, some_rate,
                                       [&](const State<D, T>& now, const LaneMask& live, const T& at, const T&) __attribute__((always_inline)) {
                                         if constexpr (HasExact<S>)  // a lane not `on` keeps its values
                                           if (some_errors) track_errors(ex, now, live && errors, at);
                                       });
        t = s.t, failed = s.failed;
        diverged = active && !s.live;  // or failed
        ended = diverged || (s.live && (tally.left(above, below) || i > steps));
      } while (!any(ended));
      stepper_ = stepper;
      y_.x = select(diverged, last.x, y.x);
      y_.v = select(diverged, last.v, y.v);
      i_ = i, tally_ = tally, exact_ = ex;
      end_lanes(ended, diverged, failed, t);
      if (!any(active_)) return;
    }
  }

 private:
  // The exact state a lane's errors are taken against, stepped with it (ExactTracker: on a scene
  // with an affine flow the map one step on and the closed form every kResync-th step; on the
  // others the lane's own tracker every step, scalar), and the errors' sums.
  struct Exact {
    State<D, T> y = zero_state<D, T>(), c = zero_state<D, T>();
    Mat<D, T> xx = Mat<D, T>::Zero(), xv = Mat<D, T>::Zero(), vx = Mat<D, T>::Zero(), vv = Mat<D, T>::Zero();
    T until_closed_form = 0;  // steps to the closed form: 1 now, then kResync - 1 steps again; 0: always
    ErrorSums<T> sums;
  };

  // The exact state, one step on: the affine map, or ExactTracker::at lane by lane (the closed
  // form every kResync-th step; every step on a scene whose tracker does not step a map, which
  // skips the map); the position and velocity errors of y against it.
  [[gnu::always_inline]] inline void track_errors(Exact& ex, const State<D, T>& y, const LaneMask& on, const T& t) const {
    if constexpr (ExactTracker<S>::kCanStep) {
      const Vec<D, T> x = ex.c.x + ex.xx * ex.y.x + ex.xv * ex.y.v;
      const Vec<D, T> v = ex.c.v + ex.vx * ex.y.x + ex.vv * ex.y.v;
      ex.y.x = select(on, x, ex.y.x);
      ex.y.v = select(on, v, ex.y.v);
      const LaneMask closed = on && ex.until_closed_form <= 1.0;
      const T next_until = select(ex.until_closed_form > 1.0, ex.until_closed_form - 1.0, select(ex.until_closed_form == T(1.0), T(double(ExactTracker<S>::kResync)), T(0.0)));
      ex.until_closed_form = select(on, next_until, ex.until_closed_form);
      if (any(closed)) [[unlikely]] ex.y = closed_form(closed, t, ex.y);
    } else if (any(on)) {
      ex.y = closed_form(on, t, ex.y);  // no map to step: the lane's tracker every step
    }
    ex.sums.add(y, ex.y, on);
  }

  // Its arguments by value: a copy's address escapes into the call, not the loop's locals.
  [[gnu::noipa]] State<D, T> closed_form(LaneMask closed, T t, State<D, T> y) const {
    for (int l = 0; l < W; ++l)
      if (closed[l]) set_lane(y, l, tracker_[l]->at(t[l]));
    return y;
  }

  static void set_lane(State<D, T>& y, int l, const State<D>& s) {
    for (int j = 0; j < D; ++j) y.x[j].set(l, s.x[j]), y.v[j].set(l, s.v[j]);
  }
  // Lane l of a pack's accumulators (ErrorSums, EnergyFit: core/simulate.hpp) as one run's, and back.
  template <template <class> class A> static A<double> lane(const A<T>& a, int l) {
    A<double> one;
    for (std::size_t f = 0; f < A<T>::fields().size(); ++f) one.*A<double>::fields()[f] = (a.*A<T>::fields()[f])[l];
    return one;
  }
  template <template <class> class A> static void set_lane(A<T>& a, int l, const A<double>& one) {
    for (std::size_t f = 0; f < A<T>::fields().size(); ++f) (a.*A<T>::fields()[f]).set(l, one.*A<double>::fields()[f]);
  }
  static RunTally<double> lane(const RunTally<T>& a, int l) { return {a.ratio[l], a.ratio_max[l], lane(a.fit, l)}; }
  static void set_lane(RunTally<T>& a, int l, const RunTally<double>& one) {
    a.ratio.set(l, one.ratio), a.ratio_max.set(l, one.ratio_max);
    set_lane(a.fit, l, one.fit);
  }
  template <class B> static void set_block(Mat<D, T>& to, int l, const B& from) {
    for (int r = 0; r < D; ++r)
      for (int c = 0; c < D; ++c) to(r, c).set(l, from(r, c));
  }

  // The lanes' first runs. This and the other bookkeeping of a lane are kept out of the stepping
  // loop (noipa: not inlined, not cloned with its arguments changed), so that the loop compiled
  // for one instruction set stays small enough for the method's step to be inlined into it.
  [[gnu::noipa]] void start() {
    for (int l = 0; l < W; ++l) {
      for (std::size_t p = 0; p < P; ++p) params_[p].set(l, S::params[p].default_value);  // idle lanes: a valid scene
      job_[l] = -1;
    }
    for (int l = 0; l < W; ++l) refill(l);
    refilled();
  }

  // Writes the results of the lanes that ended, refills them, and remakes the pack's scene.
  // Its arguments by value, like closed_form's.
  [[gnu::noipa]] void end_lanes(LaneMask ended, LaneMask diverged, LaneMask failed, T t) {
    for (int l = 0; l < W; ++l) {
      if (!ended[l]) continue;
      AnyResult& r = out_[job_[l]];
      if (diverged[l]) {
        r.status = failed[l] ? RunStatus::NoConvergence : RunStatus::Diverged;
        r.failed_step = static_cast<long long>(i_[l]), r.failed_t = t[l];
      } else if (tally_.ratio[l] > above_[l]) {
        r.status = RunStatus::Diverged, r.failed_step = static_cast<long long>(i_[l]) - 1, r.failed_t = t[l];
      }
      finish(l);
      refill(l);
    }
    refilled();
  }

  // Lane l's run completed (as Run::finish completes one).
  void finish(int l) {
    AnyResult& r = out_[job_[l]];
    const RunSpec& spec = runs_[job_[l]].spec;
    r.steps = static_cast<long long>(i_[l]) - 1;
    r.t_final = r.steps * spec.dt;
    r.final.x.resize(D), r.final.v.resize(D);
    for (int j = 0; j < D; ++j) r.final.x[j] = y_.x[j][l], r.final.v[j] = y_.v[j][l];
    r.energy0 = e0_[l];
    finish_run(r, HasExact<S> && spec.errors, lane(exact_.sums, l), lane(tally_, l), spec.energy_rate, r.steps);  // read every step
  }

  // Loads the next run of the batch into lane l (as a Run starts one), finishing at once a run of
  // no steps; none left: the lane goes idle.
  void refill(int l) {
    for (;;) {
      if (next_ >= runs_.size()) {  // idle: a finite state that a step of 0 leaves as it is
        job_[l] = -1;
        active_.set(l, false);
        set_lane(y_, l, make_default_scene<S>().initial());
        h_.set(l, 0), blow_up_.set(l, std::numeric_limits<double>::infinity());
        return;
      }
      job_[l] = static_cast<long long>(next_++);
      const BatchRun& run = runs_[job_[l]];
      out_[job_[l]] = AnyResult{};
      const S& s = scalar_[l].emplace(run.params);
      for (std::size_t p = 0; p < P; ++p) params_[p].set(l, run.params[p]);
      const State<D> y0 = s.initial();
      set_lane(y_, l, y0);
      const double e0 = s.energy(y0.x, y0.v);
      e0_.set(l, e0);
      blow_up_.set(l, blow_up_energy(s, y0, e0));
      h_.set(l, run.spec.dt), i_.set(l, 1), steps_.set(l, static_cast<double>(run.spec.steps));
      above_.set(l, run.spec.stop_above), below_.set(l, run.spec.stop_below);
      rate_.set(l, run.spec.energy_rate);
      errors_.set(l, HasExact<S> && run.spec.errors);
      set_lane(tally_, l, RunTally<double>::start(e0, run.spec.energy_rate));
      set_lane(exact_.sums, l, ErrorSums<double>{});
      if constexpr (HasExact<S>) {
        if (errors_[l]) load_tracker(l, s, run.spec.dt);
      }
      if constexpr (Multistep<M>) stepper_.memory.count.set(l, 0);  // the lane starts itself again
      if constexpr (Compensated<M>) set_lane(stepper_.carry, l, zero_state<D>());  // nothing lost yet
      if (run.spec.steps >= 1) {
        active_.set(l, true);
        return;
      }
      finish(l);
    }
  }

  void load_tracker(int l, const S& s, double h) {
    tracker_[l].emplace(s);  // what closed_form asks: at(t) as a tracker that does not step gives it
    set_lane(exact_.y, l, s.initial());
    if constexpr (ExactTracker<S>::kCanStep) {
      const ExactTracker<S> map(s, h);  // the fixed step's map, copied into the lane
      set_lane(exact_.c, l, map.offset());
      set_block(exact_.xx, l, map.xx()), set_block(exact_.xv, l, map.xv());
      set_block(exact_.vx, l, map.vx()), set_block(exact_.vv, l, map.vv());
      exact_.until_closed_form.set(l, map.stepping() ? ExactTracker<S>::kResync : 0);
    }
  }

  // After lanes were (re)filled: the pack's scene, and what holds for the pack until the next refill.
  void refilled() {
    scene_.emplace(std::span<const T>(params_));
    some_rate_ = any(rate_ && active_);
    some_errors_ = any(errors_ && active_);
    e0_nonzero_ = e0_ != T(0.0);
  }

  std::span<const BatchRun> runs_;
  AnyResult* out_;
  std::size_t next_ = 0;
  std::array<long long, W> job_{};
  std::array<std::optional<S>, W> scalar_;  // each lane's scene, for its exact flow
  // on scalar_[l], emplaced after it; stepped by closed_form (const: it leaves the loop's state alone)
  mutable std::array<std::optional<LaneTracker>, W> tracker_;
  std::array<T, P> params_{};
  std::optional<LaneScene> scene_;
  Stepper<M, LaneScene, T> stepper_;  // a multistep method's memory, lane by lane
  LaneMask active_{}, rate_{}, errors_{}, e0_nonzero_{};
  bool some_rate_ = false, some_errors_ = false;
  State<D, T> y_ = zero_state<D, T>();
  T h_ = 0, i_ = 1, steps_ = 0, above_ = 0, below_ = 0;
  T e0_ = 0, blow_up_ = 0;
  RunTally<T> tally_;
  Exact exact_;
};

}  // namespace steplab
