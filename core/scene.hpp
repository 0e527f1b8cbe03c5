// What a scene is: a mechanical system M x'' = F(x, v), or M x'' = F(t, x, v) if it is driven,
// with a diagonal mass M.
//
// A scene gives (all const, all allocation-free):
//   dim                   number of coordinates (compile time)
//   mass()                the diagonal of M, one entry per coordinate
//   inverse_mass()        its reciprocal, stored (a step multiplies by it)
//   force(x, v)           F(x, v), an autonomous scene's; or force(t, x, v), a driven one's
//                         (Driven): every method evaluates it at each of its stages' own times.
//                         A scene of run-time size writes it into the run's vector instead,
//                         force(x, v, f) (ForceInto): a step then allocates nothing
//   jacobians(x, v)       dF/dx and dF/dv, optional (HasJacobians): the implicit methods and the
//                         CVODE peers solve with them; a scene without them runs the explicit
//                         methods and the explicit peers only. jacobians(t, x, v) for a driven scene;
//                         jacobians(x, v, j) into the run's j on a run-time size (JacobiansInto)
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
// that, never for a scene's name (the kernel table hands it on: analysis/kernel/kernel.hpp SceneKernel):
//   flow(y, h)                    an exact solution (HasExact): convergence against it, the
//                                 scaling study's target
//   affine_flow = true            that flow is affine in the state (HasAffineFlow)
//   exact_along(h)                its exact motion along a run of fixed step h, cheaper a step
//                                 than the flow afresh (HasExactAlong, core/exact_tracker.hpp)
//   advance(y, h)                 the flow in place: the exact method's step without allocating
//   penetration(x)                ground contact (HasContact): the collision study
//   size_param = "<name>"         run-time size (dim = Eigen::Dynamic), refined by that count
//                                 parameter (ParamSpec::is_count): the scaling study
//   coords_per_mass = c           coordinates of one mass (default 1): N masses = dim / c
//   modes()                       the oscillators of its linearisation (HasModes), slowest first:
//                                 the predicted largest stable step dt* of every method
//                                 (study stability, study scaling)
//   jacobian_bandwidth = b        dF/dx and dF/dv vanish farther than b from the diagonal (the
//                                 peers then use a banded solver, analysis/peers/sized_peers.cpp)
//   stiffness_param, damping_param = "<name>"   which parameters are its stiffness and damping
//   stiff_limit_scene = "<scene>", stiff_limit(params)   what it tends to as its stiffness
//                                 parameter grows without bound: that scene and its parameter
//                                 values (the stiff chain's two masses moving as one spring).
//                                 Work-precision measures the step accuracy alone would allow
//                                 on it (HasStiffLimit)
//   energy_scale()                the size of the energies its exact motion reaches, where its
//                                 start's energy understates it (the driven target): the scale of
//                                 a run's blow-up bound (core/simulate.hpp, blow_up_energy)
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
#include <type_traits>
#include <vector>

#include "core/scratch.hpp"
#include "core/state.hpp"

namespace steplab {

enum class Bound { Positive, NonNegative, Fraction, Any };  // Fraction: 0 <= x < 1 (an eccentricity)

struct ParamSpec {
  std::string_view name;  // CLI long option without the dashes, JSON key with '-' -> '_'
  double default_value;
  Bound bound;
  std::string_view help;
  bool is_count = false;  // a whole number from `min_count` to `max_count` (the rope's --masses)
  double max_count = 0;
  double min_count = 1;
};

// The force of an autonomous scene, F(x, v), or of a driven one, F(t, x, v): returned by value,
// or, on a scene of run-time size, written into the caller's vector f (sized; storage the run
// owns, made once: force(x, v, f), force(t, x, v, f)), so that a step allocates nothing. A scene
// of run-time size that returns its force by value still runs; only its steps allocate.
template <class S>
concept ForceByValue = requires(const S& s, const Vec<S::dim>& x, const Vec<S::dim>& v) {
  { s.force(x, v) } -> std::convertible_to<Vec<S::dim>>;
};
template <class S>
concept ForceInto = S::dim == Eigen::Dynamic && requires(const S& s, const Vec<S::dim>& x, const Vec<S::dim>& v, Vec<S::dim>& f) {
  s.force(x, v, f);
};
template <class S>
concept DrivenByValue = requires(const S& s, double t, const Vec<S::dim>& x, const Vec<S::dim>& v) {
  { s.force(t, x, v) } -> std::convertible_to<Vec<S::dim>>;
};
template <class S>
concept DrivenInto = S::dim == Eigen::Dynamic && requires(const S& s, double t, const Vec<S::dim>& x, const Vec<S::dim>& v, Vec<S::dim>& f) {
  s.force(t, x, v, f);
};
// Such a scene may also give M^-1 F into a in the same pass as F, acceleration(x, v, a): the
// values of F times 1/m, a pass over the state fewer (the rope).
template <class S>
concept AccelerationInto = ForceInto<S> && requires(const S& s, const Vec<S::dim>& x, const Vec<S::dim>& v, Vec<S::dim>& a) {
  s.acceleration(x, v, a);
};
template <class S> concept AutonomousForce = ForceByValue<S> || ForceInto<S>;
template <class S> concept Driven = DrivenByValue<S> || DrivenInto<S>;
// Its Jacobians dF/dx and dF/dv, with the force's arguments: what an implicit method's Newton
// iteration solves with. Without them only the explicit methods run on the scene. Returned (by
// value, or a reference to ones the scene keeps: the rope's are constant), or, on a scene of
// run-time size, written into the caller's (jacobians(x, v, j): j holds the scene's pattern after
// the first call, whose values the later ones overwrite).
template <class S>
concept JacobiansInto = S::dim == Eigen::Dynamic && requires(const S& s, double t, const Vec<S::dim>& x, const Vec<S::dim>& v,
                                                             Jacobians<S::dim>& j) {
  requires(Driven<S> && requires { s.jacobians(t, x, v, j); }) || (!Driven<S> && requires { s.jacobians(x, v, j); });
};
template <class S>
concept HasJacobians = JacobiansInto<S> || requires(const S& s, double t, const Vec<S::dim>& x, const Vec<S::dim>& v) {
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

// Acceleration a = M^{-1} F(x, v), written F * (1/m) with 1/m stored by the scene: no division
// in a step (its latency is ~3x a multiplication's, and each step waits on the last). Differs
// from F / m by at most an ulp.
// F(t, x, v) written into f, whichever way the scene gives it (f resized to the state's size
// where it is a vector of its own; a borrowed one, ScratchVec, has it).
template <class S, class Tm, class X, class V, class F>
[[gnu::always_inline]] inline void force_into(const S& s, Tm t, const X& x, const V& v, F& f) {
  if constexpr (DrivenInto<S>) f.resize(x.size()), s.force(t, x, v, f);
  else if constexpr (ForceInto<S>) f.resize(x.size()), s.force(x, v, f);
  else if constexpr (DrivenByValue<S>) f = s.force(t, x, v);
  else f = s.force(x, v);
}

// F(t, x, v) as a value: the scene's own on a fixed size (as it returns it), a vector of the
// run's scratch pool (core/scratch.hpp) on a run-time size.
// x and v are vectors (or Eigen expressions of them) of doubles for one run, of packs where S is
// the scene of a pack of runs (Packable below).
// Always inlined: left out of line (GCC's stack-frame growth limit, on the falling triangle) it was
// compiled for the default instruction set, not the batch's (core/batch.hpp).
// t: the time of the stage the force is evaluated at; an autonomous scene's force does not read it
// (nor is it computed, once inlined).
template <class S, class Tm, class X, class V>
[[gnu::always_inline]] inline auto force_at(const S& s, Tm t, const X& x, const V& v) {
  if constexpr (S::dim == Eigen::Dynamic) {
    ScratchVec f(x.size());
    force_into(s, t, x, v, f);
    return f;
  } else if constexpr (Driven<S>) {
    return s.force(t, x, v);
  } else {
    return s.force(x, v);
  }
}

// F as a vector of its own (outside a step: the peers' right-hand sides).
template <class S, class X, class V> Eigen::VectorXd force_value(const S& s, double t, const X& x, const V& v) {
  Eigen::VectorXd f(x.size());
  force_into(s, t, x, v, f);
  return f;
}

// A fixed-size scene without Jacobians (HasJacobians) is asked for them by one step only: velocity
// Verlet's closing kick where the force is damped, solved at fixed x. There F is affine in v, so
// dF/dv from differences of the force in v is exact up to round-off (a unit step in each velocity);
// dF/dx, which only scales that solve's stopping test, from central differences. (The implicit
// methods do not run on such a scene: analysis/kernel/kernel_impl.hpp, applies.)
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
// The Jacobians for a run on a scene of run-time size: written into the run's `kept` where the
// scene writes them (JacobiansInto), else as the scene gives them (a reference to its own, or a
// value, which `kept` then holds).
template <class S, class Tm, class X, class V>
const Jacobians<Eigen::Dynamic>& jacobians_for_run(const S& s, Tm t, const X& x, const V& v, Jacobians<Eigen::Dynamic>& kept) {
  if constexpr (DrivenInto<S> && JacobiansInto<S>) {
    s.jacobians(t, x, v, kept);
    return kept;
  } else if constexpr (JacobiansInto<S>) {
    s.jacobians(x, v, kept);
    return kept;
  } else if constexpr (std::is_lvalue_reference_v<decltype(jacobians_at(s, t, x, v))>) {
    return jacobians_at(s, t, x, v);
  } else {
    kept = jacobians_at(s, t, x, v);
    return kept;
  }
}
// Written out, not through force_at: one inlined layer less keeps GCC inlining the Eigen
// assignments of a step that calls it several times (RK4 on the spring). On a run-time size a
// vector of the run's scratch pool, F * (1/m) in place.
template <class S, class Tm, class X, class V>
[[gnu::always_inline]] inline Temp<S::dim, typename X::Scalar> acceleration(const S& s, Tm t, const X& x, const V& v) {
  if constexpr (AccelerationInto<S>) {
    ScratchVec a(x.size());
    s.acceleration(x, v, a);
    return a;
  } else if constexpr (S::dim == Eigen::Dynamic) {
    ScratchVec a(x.size());
    force_into(s, t, x, v, a);
    a.array() *= s.inverse_mass().array();
    return a;
  } else if constexpr (Driven<S>) {
    return s.force(t, x, v).cwiseProduct(s.inverse_mass());
  } else {
    return s.force(x, v).cwiseProduct(s.inverse_mass());
  }
}

// The interface before driven scenes, acceleration(s, x, v), as a plug-in method may still call
// it: the same on an autonomous scene; on a driven one the stage's time is required.
template <class S, class X, class V>
[[gnu::always_inline]] inline auto acceleration(const S& s, const X& x, const V& v) {
  static_assert(!Driven<S>, "acceleration(s, x, v): a driven scene's force depends on time; call acceleration(s, t, x, v) "
                            "with the stage's time (core/scene.hpp)");
  return acceleration(s, typename X::Scalar(0.0), x, v);
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

// STEPLAB_SCENE and what it checks of a scene's declarations.
#include "core/scene_checks.hpp"  // IWYU pragma: export
