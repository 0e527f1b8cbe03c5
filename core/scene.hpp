// What a scene is: a mechanical system M x'' = F(x, v) with a diagonal mass M.
//
// A scene gives (all const, all allocation-free):
//   dim                   number of coordinates (compile time)
//   mass()                the diagonal of M, one entry per coordinate
//   inverse_mass()        its reciprocal, stored (a step multiplies by it)
//   force(x, v)           F(x, v); every scene here is autonomous
//   jacobians(x, v)       dF/dx and dF/dv (used by the implicit methods only)
//   velocity_dependent()  whether F depends on v (damping); F must be affine in v
//   energy(x, v)          the energy whose ratio to its start value the studies track
//   initial()             the start state
// and, where it has one, flow(y, h): the exact state h after state y (HasExact); the exact
// solution is then exact(s, t) = flow(initial(), t).
//
// Integrators see scenes only through this interface, so a new scene never touches them.
// Parameters come from a table of ParamSpec (name, default, bound, help), which the CLI, the
// JSON writers and the validation all read; a scene is built from the values in that order.
#pragma once

#include <array>
#include <concepts>
#include <span>
#include <string_view>
#include <vector>

#include "core/state.hpp"

namespace steplab {

enum class Bound { Positive, NonNegative, Any };

struct ParamSpec {
  std::string_view name;  // CLI long option without the dashes, JSON key with '-' -> '_'
  double fallback;        // the default
  Bound bound;
  std::string_view help;
};

template <class S>
concept Scene = requires(const S& s, const Vec<S::dim>& x, const Vec<S::dim>& v, std::span<const double> p) {
  { S::name } -> std::convertible_to<std::string_view>;
  { S::params } -> std::convertible_to<std::span<const ParamSpec>>;
  { S(p) };
  { s.mass() } -> std::convertible_to<Vec<S::dim>>;
  { s.inverse_mass() } -> std::convertible_to<Vec<S::dim>>;
  { s.force(x, v) } -> std::convertible_to<Vec<S::dim>>;
  { s.jacobians(x, v) } -> std::convertible_to<Jacobians<S::dim>>;
  { s.velocity_dependent() } -> std::convertible_to<bool>;
  { s.energy(x, v) } -> std::convertible_to<double>;
  { s.initial() } -> std::convertible_to<State<S::dim>>;
};

template <class S>
concept HasExact = Scene<S> && requires(const S& s, const State<S::dim>& y, double h) {
  { s.flow(y, h) } -> std::convertible_to<State<S::dim>>;
};

template <HasExact S> State<S::dim> exact(const S& s, double t) {
  if constexpr (requires { s.exact_at(t); }) return s.exact_at(t);
  else return s.flow(s.initial(), t);
}

// The exact state along a run, step by step: a closed form exact_at(t) where the scene has one
// (no accumulated round-off), else the flow map applied to the previous exact state (a scene
// with events, like the bounce, then finds each event once).
template <HasExact S> class ExactTracker {
 public:
  explicit ExactTracker(const S& s) : s_(s), y_(s.initial()) {}
  const State<S::dim>& at(double t) {
    if constexpr (requires { s_.exact_at(t); }) y_ = s_.exact_at(t);
    else y_ = s_.flow(y_, t - t_);
    t_ = t;
    return y_;
  }

 private:
  const S& s_;
  State<S::dim> y_;
  double t_ = 0;
};

// Acceleration a = M^{-1} F(x, v), written F * (1/m) with 1/m stored by the scene: no division
// in a step (its latency is ~3x a multiplication's, and each step waits on the last). Differs
// from F / m by at most an ulp.
template <Scene S> Vec<S::dim> acceleration(const S& s, const Vec<S::dim>& x, const Vec<S::dim>& v) {
  return s.force(x, v).cwiseProduct(s.inverse_mass());
}

// Whether the scene has a parameter of that name.
template <Scene S> bool has_param(std::string_view name) {
  for (const ParamSpec& p : S::params)
    if (p.name == name) return true;
  return false;
}

// The scene's default parameter values, in table order.
template <Scene S> auto default_params() {
  std::array<double, S::params.size()> p{};
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = S::params[i].fallback;
  return p;
}

// The same as a vector: what the studies' configurations hold.
template <Scene S> std::vector<double> default_param_values() {
  const auto p = default_params<S>();
  return {p.begin(), p.end()};
}

template <Scene S> S make_default_scene() {
  const auto p = default_params<S>();
  return S(std::span<const double>(p));
}

}  // namespace steplab
