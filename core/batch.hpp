// Runs stepped W at a time: the run loop of core/simulate.hpp on packs (core/pack.hpp), one run
// per lane, structure of arrays. Each lane's numbers are the bits its run gives alone (Run):
// the same operations in the same order, lane by lane; what depends on the lane becomes a
// select on a mask.
//
//   live   = active lanes whose step left a finite state       (a diverged lane ends here)
//   y      = next  (a diverged lane's result takes its last finite state: run() below)
//   E/E0, its largest, the ln E fit (Welford) and the errors against the stepped exact state,
//          each updated where live
//   a lane ends when its steps are done or E/E0 leaves [stop_below, stop_above]; its result
//   is written and the lane refilled with the next run of the batch (DiffEqGPU.jl masks a
//   finished lane off; refilling it is what makes packs pay when runs end at different times:
//   Hentschel et al., EGPGV 2015). The loop ends when no lane has a run.
//
// Samples and observers are not kept here: a batch is for the studies' summary runs (run_all,
// analysis/kernel.hpp, runs a spec that asks for samples one at a time).
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
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

inline bool cpu_has_width(int width) {
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

// The studies' default: AVX2's 4 lanes where the CPU has it, else SSE2's 2. Not AVX-512's 8:
// on the machine the README quotes (AMD EPYC, Zen 4, which executes a 512-bit operation as two
// 256-bit halves) its loop ran 2x slower than AVX2's (README, SIMD packs); --lanes 8 asks for it.
inline int best_width() {
  static const int best = cpu_has_width(4) ? 4 : cpu_has_width(2) ? 2 : 1;
  return best;
}

// One run of a batch: its scene's parameter values (table order) and its spec.
struct BatchRun {
  std::span<const double> params;
  RunSpec spec;
};

// Whether M steps packs of runs of S: S is Packable, M's step (with its memory, for a multistep
// method) is written over the scalar (core/method.hpp), and an exact flow, where S has one, is
// stepped as an affine map.
template <class M, class S>
concept PackedStep = Packable<S> &&
                     (!HasExact<S> || (HasAffineFlow<S> && requires(const S& s) { s.exact_at(0.0); })) &&
                     requires(Stepper<M, PackScene<S, Pack<8>>, Pack<8>>& st, const PackScene<S, Pack<8>>& s,
                              State<S::dim, Pack<8>>& y, Pack<8> h) {
                       st.step(s, y, h, h);  // a StepStatus, or the lanes that failed (a Mask)
                     };

template <class M, Packable S, class T> class BatchRunner {
  static constexpr int W = T::width;
  using PS = PackScene<S, T>;
  using Mk = decltype(T() < T());
  static constexpr int D = S::dim;
  static constexpr std::size_t P = S::params.size();

 public:
  BatchRunner(std::span<const BatchRun> runs, AnyResult* out) : runs_(runs), out_(out) { start(); }

  // Steps until every run of the batch has ended. The state is stepped in a local, y = next in
  // every lane: the test of the new state is off the chain from one step to the next (a select
  // on it lengthened that chain), and the local stays in registers where a member went through
  // memory each step (throughput_w4 in make bench: 302 us before the two, 210 us after). A lane
  // whose step diverged gets its last finite state back (y_ below) before its result is
  // written; an idle lane steps a finite state with h = 0 (refill). What holds for the whole
  // pack between two refills (a lane with an energy fit, a lane with errors, E0 != 0, a lane
  // still running) is set by refilled(), not tested each step.
  [[gnu::always_inline]] inline void run() {
    State<D, T> y = y_;
    if (!any(active_)) return;
    for (;;) {
      const T t_prev = (i_ - 1.0) * h_, t = i_ * h_;
      State<D, T> next = y;
      const Mk failed = active_ && Mk(steplab::failed(stepper_.step(*scene_, next, t_prev, h_)));  // Newton gave up
      const Mk live = all_finite(next) && active_ && !failed;
      const Mk diverged = active_ && !live;  // or failed
      const State<D, T> last = y;
      y = next;
      const T e = scene_->energy(y.x, y.v);
      const Mk has_e0 = live && e0_nonzero_;
      const T ratio = e / e0_;
      ratio_max_ = select(has_e0, max(ratio_max_, ratio), ratio_max_);
      ratio_ = select(has_e0, ratio, ratio_);
      if (some_rate_) fit_.add(t, e, live && rate_ && e > 0.0 && finite(e));
      if constexpr (HasExact<S>)
        if (some_errors_) track_errors(y, live && errors_, t);  // a lane not `on` keeps its values
      i_ = select(live, i_ + 1.0, i_);
      const Mk out = ratio_ > above_ || ratio_ < below_;
      const Mk ended = diverged || (live && (out || i_ > steps_));
      if (any(ended)) {
        y_.x = select(diverged, last.x, y.x);
        y_.v = select(diverged, last.v, y.v);
        end_lanes(ended, diverged, failed, t);
        if (!any(active_)) return;
        y = y_;
      }
    }
  }

 private:
  // The exact state, one step on: the affine map, or the closed form every kResync-th step
  // (ExactTracker::at, lane by lane); the position and velocity errors of y against it.
  [[gnu::always_inline]] inline void track_errors(const State<D, T>& y, const Mk& on, const T& t) {
    const Vec<D, T> x = ex_c_.x + ex_xx_ * ex_.x + ex_xv_ * ex_.v;
    const Vec<D, T> v = ex_c_.v + ex_vx_ * ex_.x + ex_vv_ * ex_.v;
    ex_.x = select(on, x, ex_.x);
    ex_.v = select(on, v, ex_.v);
    const Mk closed = on && left_ <= 1.0;  // 1: the closed form now, then kResync - 1 steps again; 0: always
    const T next_left = select(left_ > 1.0, left_ - 1.0, select(left_ == T(1.0), T(double(ExactTracker<S>::kResync)), T(0.0)));
    left_ = select(on, next_left, left_);
    if (any(closed)) [[unlikely]] closed_form(closed, t);
    error_sums_.add(y, ex_, on);
  }

  [[gnu::noipa]] void closed_form(const Mk& closed, const T& t) {
    for (int l = 0; l < W; ++l)
      if (closed[l]) set_lane(ex_, l, scalar_[l]->exact_at(t[l]));
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
  template <class B> static void set_block(Mat<D, T>& to, int l, const B& from) {
    for (int r = 0; r < D; ++r)
      for (int c = 0; c < D; ++c) to(r, c).set(l, from(r, c));
  }

  // The lanes' first runs. This and the other bookkeeping of a lane are kept out of the stepping
  // loop (noipa: not inlined, not cloned with its arguments changed), so that the loop compiled
  // for one instruction set stays small enough for the method's step to be inlined into it.
  [[gnu::noipa]] void start() {
    for (int l = 0; l < W; ++l) {
      for (std::size_t p = 0; p < P; ++p) params_[p].set(l, S::params[p].fallback);  // idle lanes: a valid scene
      job_[l] = -1;
    }
    for (int l = 0; l < W; ++l) refill(l);
    refilled();
  }

  // Writes the results of the lanes that ended, refills them, and remakes the pack's scene.
  [[gnu::noipa]] void end_lanes(const Mk& ended, const Mk& diverged, const Mk& failed, const T& t) {
    for (int l = 0; l < W; ++l) {
      if (!ended[l]) continue;
      AnyResult& r = out_[job_[l]];
      if (diverged[l]) {
        r.status = failed[l] ? RunStatus::NoConvergence : RunStatus::Diverged;
        r.failed_step = static_cast<long long>(i_[l]), r.failed_t = t[l];
      } else if (ratio_[l] > above_[l]) {
        r.status = RunStatus::Diverged, r.failed_step = static_cast<long long>(i_[l]) - 1, r.failed_t = t[l];
      }
      finish(l);
      refill(l);
    }
    refilled();
  }

  // Run::finish for lane l.
  void finish(int l) {
    AnyResult& r = out_[job_[l]];
    const RunSpec& spec = runs_[job_[l]].spec;
    r.steps = static_cast<long long>(i_[l]) - 1;
    r.t_final = r.steps * spec.dt;
    r.final.x.resize(D), r.final.v.resize(D);
    for (int j = 0; j < D; ++j) r.final.x[j] = y_.x[j][l], r.final.v[j] = y_.v[j][l];
    r.energy0 = e0_[l];
    finish_run(r, HasExact<S> && spec.errors, lane(error_sums_, l), ratio_[l], ratio_max_[l]);
    if (spec.energy_rate) r.energy_rate = lane(fit_, l).slope();
  }

  // Loads the next run of the batch into lane l (the Run constructor), finishing at once a run
  // of no steps; none left: the lane goes idle.
  void refill(int l) {
    for (;;) {
      if (next_ >= runs_.size()) {  // idle: a finite state that a step of 0 leaves as it is
        job_[l] = -1;
        active_.set(l, false);
        set_lane(y_, l, make_default_scene<S>().initial());
        h_.set(l, 0);
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
      e0_.set(l, e0), ratio_.set(l, 1), ratio_max_.set(l, 1);
      h_.set(l, run.spec.dt), i_.set(l, 1), steps_.set(l, static_cast<double>(run.spec.steps));
      above_.set(l, run.spec.stop_above), below_.set(l, run.spec.stop_below);
      rate_.set(l, run.spec.energy_rate);
      errors_.set(l, HasExact<S> && run.spec.errors);
      EnergyFit<double> fit;  // as Run's constructor starts it
      if (run.spec.energy_rate) fit.add(0.0, e0, e0 > 0 && std::isfinite(e0));
      set_lane(fit_, l, fit);
      set_lane(error_sums_, l, ErrorSums<double>{});
      if constexpr (HasExact<S>) {
        if (errors_[l]) load_tracker(l, s, run.spec.dt);
      }
      if constexpr (Multistep<M>) stepper_.memory.count.set(l, 0);  // the lane starts itself again
      if (run.spec.steps >= 1) {
        active_.set(l, true);
        return;
      }
      finish(l);
    }
  }

  void load_tracker(int l, const S& s, double h) {
    const ExactTracker<S> tracker(s, h);
    set_lane(ex_c_, l, tracker.offset());
    set_block(ex_xx_, l, tracker.xx()), set_block(ex_xv_, l, tracker.xv());
    set_block(ex_vx_, l, tracker.vx()), set_block(ex_vv_, l, tracker.vv());
    set_lane(ex_, l, s.initial());
    left_.set(l, tracker.stepping() ? ExactTracker<S>::kResync : 0);
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
  std::array<T, P> params_{};
  std::optional<PS> scene_;
  Stepper<M, PS, T> stepper_;  // a multistep method's memory, lane by lane
  Mk active_{}, rate_{}, errors_{}, e0_nonzero_{};
  bool some_rate_ = false, some_errors_ = false;
  State<D, T> y_ = zero_state<D, T>();
  T h_ = 0, i_ = 1, steps_ = 0, above_ = 0, below_ = 0;
  T e0_ = 0, ratio_ = 1, ratio_max_ = 1;
  EnergyFit<T> fit_;
  ErrorSums<T> error_sums_;
  State<D, T> ex_ = zero_state<D, T>(), ex_c_ = zero_state<D, T>();
  Mat<D, T> ex_xx_ = Mat<D, T>::Zero(), ex_xv_ = Mat<D, T>::Zero(), ex_vx_ = Mat<D, T>::Zero(), ex_vv_ = Mat<D, T>::Zero();
  T left_ = 0;
};

}  // namespace steplab
