// What a scene is: a mechanical system M x'' = F(x, v), or M x'' = F(t, x, v) if it is driven,
// with a diagonal mass M.
//
// A scene gives (all const, all allocation-free):
//   dim                   number of coordinates (compile time)
//   mass()                the diagonal of M, one entry per coordinate
//   inverse_mass()        its reciprocal, stored (a step multiplies by it)
//   force(x, v)           F(x, v), an autonomous scene's; or force(t, x, v), a driven one's
//                         (Driven): every method evaluates it at each of its stages' own times
//   jacobians(x, v)       dF/dx and dF/dv, optional (HasJacobians): the implicit methods and the
//                         CVODE peers solve with them; a scene without them runs the explicit
//                         methods and the explicit peers only. jacobians(t, x, v) for a driven scene
//   velocity_dependent()  whether F depends on v (damping); F must be affine in v
//   energy(x, v)          the energy whose ratio to its start value the studies track
//   initial()             the start state
// and, where it has one, flow(y, h): the exact state h after state y (HasExact); the exact
// solution is then exact(s, t) = flow(initial(), t). A driven scene's flow depends on when it
// starts, so it gives exact_at(t), the exact solution from its initial state, instead.
//
// Integrators see scenes only through this interface, so a new scene never touches them.
// Parameters come from a table of ParamSpec (name, default, bound, help), which the CLI, the
// JSON writers and the validation all read; a scene is built from the values in that order.
//
// What else a scene offers the studies it declares in its own file, and the studies ask for
// that, never for a scene's name (the kernel table hands it on: analysis/kernel.hpp SceneKernel):
//   flow(y, h)                    an exact solution (HasExact): convergence against it, the
//                                 scaling study's target
//   affine_flow = true            that flow is affine in the state (HasAffineFlow)
//   penetration(x)                ground contact (HasContact): the collision study
//   size_param = "<name>"         run-time size (dim = Eigen::Dynamic), refined by that count
//                                 parameter (ParamSpec::is_count): the scaling study
//   coords_per_mass = c           coordinates of one mass (default 1): N masses = dim / c
//   modes()                       the oscillators of its linearisation (HasModes), slowest first:
//                                 the predicted largest stable step dt* of every method
//                                 (study stability, study scaling)
//   jacobian_bandwidth = b        dF/dx and dF/dv vanish farther than b from the diagonal (the
//                                 peers then use a banded solver, analysis/sized_peers.cpp)
//   stiffness_param, damping_param = "<name>"   which parameters are its stiffness and damping
//   stiff_limit_scene = "<scene>", stiff_limit(params)   what it tends to as its stiffness
//                                 parameter grows without bound: that scene and its parameter
//                                 values (the stiff chain's two masses moving as one spring).
//                                 Work-precision measures the step accuracy alone would allow
//                                 on it (HasStiffLimit)
//   title = "<words>"             the scene in a few words, for a table's heading
//   equation = "<m x'' = ...>"    its equation of motion in one line, for the report's appendix
//   old_name = "<name>"           a name the old framework gave it, also accepted
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <span>
#include <string_view>
#include <vector>

#include "core/state.hpp"

namespace steplab {

enum class Bound { Positive, NonNegative, Any };

struct ParamSpec {
  std::string_view name;  // CLI long option without the dashes, JSON key with '-' -> '_'
  double default_value;
  Bound bound;
  std::string_view help;
  bool is_count = false;  // a whole number from 1 to `max_count` (the rope's --masses)
  double max_count = 0;
};

// The force of an autonomous scene, F(x, v), or of a driven one, F(t, x, v).
template <class S>
concept AutonomousForce = requires(const S& s, const Vec<S::dim>& x, const Vec<S::dim>& v) {
  { s.force(x, v) } -> std::convertible_to<Vec<S::dim>>;
};
template <class S>
concept Driven = requires(const S& s, double t, const Vec<S::dim>& x, const Vec<S::dim>& v) {
  { s.force(t, x, v) } -> std::convertible_to<Vec<S::dim>>;
};
// Its Jacobians dF/dx and dF/dv, with the force's arguments: what an implicit method's Newton
// iteration solves with. Without them only the explicit methods run on the scene.
template <class S>
concept HasJacobians = requires(const S& s, double t, const Vec<S::dim>& x, const Vec<S::dim>& v) {
  requires(Driven<S> && requires { { s.jacobians(t, x, v) } -> std::convertible_to<Jacobians<S::dim>>; }) ||
              (!Driven<S> && requires { { s.jacobians(x, v) } -> std::convertible_to<Jacobians<S::dim>>; });
};

template <class S>
concept Scene = requires(const S& s, const Vec<S::dim>& x, const Vec<S::dim>& v, std::span<const double> p) {
  { S::name } -> std::convertible_to<std::string_view>;
  { S::params } -> std::convertible_to<std::span<const ParamSpec>>;
  { S(p) };
  { s.mass() } -> std::convertible_to<Vec<S::dim>>;
  { s.inverse_mass() } -> std::convertible_to<Vec<S::dim>>;
  requires AutonomousForce<S> || Driven<S>;
  { s.velocity_dependent() } -> std::convertible_to<bool>;
  { s.energy(x, v) } -> std::convertible_to<double>;
  { s.initial() } -> std::convertible_to<State<S::dim>>;
};

// A scene file ends with STEPLAB_SCENE(<its type>);, outside any namespace (tools/kernels.cmake).
// Code that takes long to compile and need not be inlined (the chain's long-double
// eigen-decomposition) goes at the end of the file inside #ifdef STEPLAB_SCENE_SOURCE: the scene's
// generated translation unit defines it, so that code is compiled once, not in every method's file.
#define STEPLAB_SCENE(...)                                                                          \
  static_assert(::steplab::Scene<__VA_ARGS__>, "STEPLAB_SCENE: the type is not a Scene (core/scene.hpp)"); \
  static_assert(::steplab::declarations_hold<__VA_ARGS__>(),                                          \
                "STEPLAB_SCENE: a declared size_param, stiffness_param or damping_param names no parameter of the scene, "  \
                "or size_param is not a count of a scene of run-time size (core/scene.hpp)")

// A scene with ground contact says how deep its deepest point is below the ground (negative
// when all are above): it touches the ground where that is > 0. The collision study records it.
template <class S>
concept HasContact = Scene<S> && requires(const S& s, const Vec<S::dim>& x) {
  { s.penetration(x) } -> std::convertible_to<double>;
};

template <class S>
concept HasExact = Scene<S> && (requires(const S& s, const State<S::dim>& y, double h) {
  { s.flow(y, h) } -> std::convertible_to<State<S::dim>>;
} || (Driven<S> && requires(const S& s, double t) {
  { s.exact_at(t) } -> std::convertible_to<State<S::dim>>;
}));

template <HasExact S> State<S::dim> exact(const S& s, double t) {
  if constexpr (requires { s.exact_at(t); }) return s.exact_at(t);
  else return s.flow(s.initial(), t);
}

// Scenes whose exact flow is affine in the state, flow(y, h) = c(h) + Phi(h) y (linear systems:
// the spring, the chain), say so with `static constexpr bool affine_flow = true`.
template <class S>
concept HasAffineFlow = HasExact<S> && requires { requires S::affine_flow; };

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

// Acceleration a = M^{-1} F(x, v), written F * (1/m) with 1/m stored by the scene: no division
// in a step (its latency is ~3x a multiplication's, and each step waits on the last). Differs
// from F / m by at most an ulp.
// x and v are vectors (or Eigen expressions of them) of doubles for one run, of packs where S is
// the scene of a pack of runs (Packable below).
// Always inlined: left out of line (GCC's stack-frame growth limit, on the falling triangle) it was
// compiled for the default instruction set, not the batch's (core/batch.hpp).
// t: the time of the stage the force is evaluated at; an autonomous scene's force does not read it
// (nor is it computed, once inlined).
template <class S, class Tm, class X, class V>
[[gnu::always_inline]] inline auto force_at(const S& s, Tm t, const X& x, const V& v) {
  if constexpr (Driven<S>) return s.force(t, x, v);
  else return s.force(x, v);
}
// A fixed-size scene without Jacobians (HasJacobians) is asked for them by one step only: velocity
// Verlet's closing kick where the force is damped, solved at fixed x. There F is affine in v, so
// dF/dv from differences of the force in v is exact up to round-off (a unit step in each velocity);
// dF/dx, which only scales that solve's stopping test, from central differences. (The implicit
// methods do not run on such a scene: analysis/kernel_impl.hpp, applies.)
template <class S, class Tm, class X, class V>
Jacobians<S::dim, typename X::Scalar> differenced_jacobians(const S& s, Tm t, const X& x, const V& v) {
  using T = typename X::Scalar;
  using std::abs;
  constexpr int D = S::dim;
  Jacobians<D, T> j;
  const Vec<D, T> f = force_at(s, t, x, v);
  for (int k = 0; k < D; ++k) {
    Vec<D, T> vk = v, xp = x, xm = x;
    vk[k] += T(1);
    j.dv.col(k) = force_at(s, t, x, vk) - f;
    const T d = T(1e-6) * (T(1) + abs(x[k]));
    xp[k] += d, xm[k] -= d;
    j.dx.col(k) = (force_at(s, t, xp, v) - force_at(s, t, xm, v)) / (T(2) * d);
  }
  return j;
}

// Asked of the arguments' own types: a pack of runs' scene (Packable) takes packs, not doubles.
template <class S, class Tm, class X, class V>
[[gnu::always_inline]] inline decltype(auto) jacobians_at(const S& s, Tm t, const X& x, const V& v) {
  if constexpr (requires { s.jacobians(t, x, v); }) return s.jacobians(t, x, v);
  else if constexpr (requires { s.jacobians(x, v); }) return s.jacobians(x, v);
  else return differenced_jacobians(s, t, x, v);
}
// Written out, not through force_at: one inlined layer less keeps GCC inlining the Eigen
// assignments of a step that calls it several times (RK4 on the spring).
template <class S, class Tm, class X, class V>
[[gnu::always_inline]] inline Vec<S::dim, typename X::Scalar> acceleration(const S& s, Tm t, const X& x, const V& v) {
  if constexpr (Driven<S>) return s.force(t, x, v).cwiseProduct(s.inverse_mass());
  else return s.force(x, v).cwiseProduct(s.inverse_mass());
}

// A scene whose runs can be stepped W at a time (core/batch.hpp) is a template over its scalar,
// every parameter a Pack of the lanes' values, and names it: `template <class T> using as =
// SpringT<T>;`. Its force, energy and initial state are then written once for both, a branch on
// the state as a select (core/pack.hpp); its exact flow, where it has one, stays scalar.
template <class S>
concept Packable = Scene<S> && requires { typename S::template as<Pack<8>>; };
template <class S, class T> using PackScene = typename S::template as<T>;

// One oscillator u'' + 2 zeta omega u' + omega^2 u = 0 of a scene's linearisation (a mode): a
// method's step on it depends on omega h and zeta alone.
struct Mode {
  double omega;     // angular frequency
  double two_zeta;  // twice the damping ratio
};

template <class S>
concept HasModes = Scene<S> && requires(const S& s) {
  { s.modes() } -> std::convertible_to<std::vector<Mode>>;
};

// The index of the parameter called `name` in a table; -1 if there is none (or `name` is empty).
constexpr int param_index(std::span<const ParamSpec> params, std::string_view name) {
  for (std::size_t i = 0; i < params.size(); ++i)
    if (!name.empty() && params[i].name == name) return static_cast<int>(i);
  return -1;
}

// The indices of what the scene declares (above); -1 where it declares nothing.
template <Scene S> constexpr int size_param_index() {
  if constexpr (requires { S::size_param; }) return param_index(S::params, S::size_param);
  else return -1;
}
template <Scene S> constexpr int stiffness_param_index() {
  if constexpr (requires { S::stiffness_param; }) return param_index(S::params, S::stiffness_param);
  else return -1;
}
template <Scene S> constexpr int damping_param_index() {
  if constexpr (requires { S::damping_param; }) return param_index(S::params, S::damping_param);
  else return -1;
}
template <class S>
concept HasStiffLimit = Scene<S> && requires(std::span<const double> p) {
  { S::stiff_limit_scene } -> std::convertible_to<std::string_view>;
  { S::stiff_limit(p) } -> std::convertible_to<std::vector<double>>;
};

template <Scene S> constexpr std::string_view scene_title() {
  if constexpr (requires { S::title; }) return S::title;
  else return S::name;
}
template <Scene S> constexpr std::string_view scene_equation() {
  if constexpr (requires { S::equation; }) return S::equation;
  else return {};
}
template <Scene S> constexpr std::string_view scene_old_name() {
  if constexpr (requires { S::old_name; }) return S::old_name;
  else return {};
}
template <Scene S> constexpr int coords_per_mass() {
  if constexpr (requires { S::coords_per_mass; }) return S::coords_per_mass;
  else return 1;
}
template <Scene S> constexpr int jacobian_bandwidth() {
  if constexpr (requires { S::jacobian_bandwidth; }) return S::jacobian_bandwidth;
  else return -1;
}

// What STEPLAB_SCENE checks of the declarations: every declared name is a parameter, and a size
// parameter is a count of a scene of run-time size.
template <Scene S> constexpr bool declarations_hold() {
  if constexpr (requires { S::size_param; })
    if (size_param_index<S>() < 0 || !S::params[size_param_index<S>()].is_count || S::dim != Eigen::Dynamic) return false;
  if constexpr (requires { S::stiffness_param; })
    if (stiffness_param_index<S>() < 0) return false;
  if constexpr (requires { S::damping_param; })
    if (damping_param_index<S>() < 0) return false;
  if constexpr (requires { S::stiff_limit_scene; })
    if (!HasStiffLimit<S> || stiffness_param_index<S>() < 0) return false;
  return coords_per_mass<S>() >= 1;
}

// Whether a parameter table (a scene's `params`) has a parameter of that name.
inline bool has_param(std::span<const ParamSpec> params, std::string_view name) {
  for (const ParamSpec& p : params)
    if (p.name == name) return true;
  return false;
}

// A parameter table's default values, in table order: what the studies' configurations hold.
inline std::vector<double> default_values(std::span<const ParamSpec> params) {
  std::vector<double> v;
  for (const ParamSpec& p : params) v.push_back(p.default_value);
  return v;
}

// The scene's default parameter values, in table order.
template <Scene S> auto default_params() {
  std::array<double, S::params.size()> p{};
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = S::params[i].default_value;
  return p;
}

template <Scene S> std::vector<double> default_param_values() { return default_values(S::params); }

template <Scene S> S make_default_scene() {
  const auto p = default_params<S>();
  return S(std::span<const double>(p));
}

}  // namespace steplab
