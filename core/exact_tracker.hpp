// The exact state along a run, for its errors against the exact solution (core/simulate.hpp,
// core/batch.hpp, core/dopri5.hpp).
#pragma once

#include <algorithm>
#include <cmath>

#include "core/scene.hpp"

namespace steplab {

// The exact state along a run, step by step: a closed form exact_at(t) where the scene has one
// (no accumulated round-off), else the flow map applied to the previous exact state (a scene
// with events, like the bounce, then finds each event once).
//
// A run of fixed step h (h > 0: at(t) is then called at t = h, 2h, 3h, ... in turn) on a scene
// with an affine flow steps the exact state instead: c and Phi once from the flow (c = flow(0, h),
// column i of Phi = flow(e_i, h) - c), then y <- c + Phi y, a matrix-vector product a step, and
// every kResync-th step the closed form again, so that round-off accumulates over kResync steps
// at most (a few ulps of |y| each). The spring's closed form costs exp, sin and cos: about 250
// instructions a step, five times explicit Euler's step with its run loop (callgrind).
template <HasExact S> class ExactTracker {
  static constexpr int D = S::dim;
  using Block = Eigen::Matrix<double, D, D>;

 public:
  // Whether it can step the affine map (given h > 0); else at(t) is the closed form or the flow.
  static constexpr bool kCanStep = D != Eigen::Dynamic && HasAffineFlow<S> && requires(const S& s) { s.exact_at(0.0); };
  static constexpr int kResync = 32;

  explicit ExactTracker(const S& s, double h = 0) : s_(s), y_(s.initial()) {
    if constexpr (kCanStep) {
      if (!(h > 0)) return;
      c_ = s.flow({Vec<D>::Zero(), Vec<D>::Zero()}, h);
      // Phi's columns from steps of size a, a power of two of the size of the states: a column's
      // error is then a few ulps of the flow's values over a, a few ulps of 1, where unit steps
      // would make it a few ulps of |y| (the spring 2000 below its anchor: y <- c + Phi y off by
      // 1e-9 a step, eps |y|^2).
      const double size = std::max({1.0, c_.x.cwiseAbs().maxCoeff(), c_.v.cwiseAbs().maxCoeff(),
                                    y_.x.cwiseAbs().maxCoeff(), y_.v.cwiseAbs().maxCoeff()});
      const double a = std::exp2(std::ceil(std::log2(size)));
      for (int i = 0; i < D; ++i) {
        const State<D> from_x = s.flow({a * Vec<D>::Unit(i), Vec<D>::Zero()}, h);
        const State<D> from_v = s.flow({Vec<D>::Zero(), a * Vec<D>::Unit(i)}, h);
        xx_.col(i) = (from_x.x - c_.x) / a, vx_.col(i) = (from_x.v - c_.v) / a;
        xv_.col(i) = (from_v.x - c_.x) / a, vv_.col(i) = (from_v.v - c_.v) / a;
      }
      until_closed_form_ = kResync;
    }
  }

  // The fixed step's affine map, where it steps (core/batch.hpp copies it into a pack's lanes).
  bool stepping() const { return until_closed_form_ != 0; }
  const State<D>& offset() const { return c_; }
  const Block& xx() const { return xx_; }
  const Block& xv() const { return xv_; }
  const Block& vx() const { return vx_; }
  const Block& vv() const { return vv_; }

  // Inline where it steps the affine map (a run's hot path); the closed form or the flow, called
  // once every kResync steps there, out of line.
  [[gnu::always_inline]] inline const State<D>& at(double t) {
    if constexpr (kCanStep) {
      if (until_closed_form_ > 1) {
        --until_closed_form_;
        const Vec<D> x = c_.x + xx_ * y_.x + xv_ * y_.v;
        y_.v = c_.v + vx_ * y_.x + vv_ * y_.v;
        y_.x = x;
        return y_;
      }
      if (until_closed_form_ == 1) until_closed_form_ = kResync;  // the closed form now, then kResync - 1 steps again
    }
    return from_scene(t);
  }

 private:
  [[gnu::noinline]] const State<D>& from_scene(double t) {
    if constexpr (requires { s_.exact_at(t); }) y_ = s_.exact_at(t);
    else y_ = s_.flow(y_, t - t_);
    t_ = t;
    return y_;
  }

  const S& s_;
  State<D> y_;
  double t_ = 0;
  // the fixed step's affine map, in blocks: x <- c.x + xx x + xv v, v <- c.v + vx x + vv v
  int until_closed_form_ = 0;  // 1 + the steps left before the closed form again; 0: not stepping
  static Block zero_block() {
    if constexpr (D == Eigen::Dynamic) return {};
    else return Block::Zero();
  }
  State<D> c_ = zero_state<D>();
  Block xx_ = zero_block(), xv_ = zero_block(), vx_ = zero_block(), vv_ = zero_block();
};

// A scene of run-time size whose exact motion is cheaper to follow step by step than to evaluate
// afresh offers `exact_along(h)`: an object whose at(t), called at t = h, 2h, 3h, ... in turn,
// gives the exact positions, jump() makes the next at(t) take any t, and velocities() the
// velocities at the last of those times (the rope: its modes stepped one by one,
// core/scenes/rope.hpp). A run then reads the velocities once, at its end; and since the positions
// still cost a transform, it may read them every few steps (RunSpec::error_stride), h apart.
template <class S>
concept HasExactAlong = HasExact<S> && requires(const S& s, double h) {
  s.exact_along(h);
  s.exact_along(h).jump();
};

}  // namespace steplab
