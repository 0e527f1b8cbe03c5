// The cannon ball of the 2018 sheet: a 2-D point mass under gravity, no drag.
//
//   m x'' = m g,   g = (0, -g)        exact: x(t) = x0 + v0 t + g t^2 / 2,  v(t) = v0 + g t
//
// The acceleration is constant, so every method of order >= 2 is exact up to round-off.
#pragma once

#include <array>
#include <cmath>
#include <span>

#include "core/scene.hpp"

namespace steplab {

// T = double: one cannon ball; T = Pack<W>: W of them, one per lane (core/batch.hpp). The exact
// flow below is the scalar's.
template <class T> struct CannonballT {
  template <class U> using as = CannonballT<U>;
  static constexpr int dim = 2;
  static constexpr std::string_view name = "cannonball";
  static constexpr std::string_view title = "Cannon ball";
  // The equation of motion, for the report (the math above is its derivation).
  static constexpr std::string_view equation = "m x'' = m g, with g = (0, -g): a parabola";
  // Defaults from the 2018 sheet: mass 1, from the origin at 100 * (cos 1.047, sin 1.047).
  static constexpr std::array<ParamSpec, 4> params{{
      {"mass", 1.0, Bound::Positive, "mass m"},
      {"gravity", 9.81, Bound::NonNegative, "gravitational acceleration g (pointing down)"},
      {"speed", 100.0, Bound::NonNegative, "launch speed |v0|"},
      {"angle", 1.047, Bound::Any, "launch angle in radians from the horizontal"},
  }};

  T m;
  T inv_m = 1 / m;  // initialized after m (declaration order)
  Vec<2, T> g;
  Vec<2, T> v0;

  explicit CannonballT(std::span<const T> p) : m(p[0]), g(T(0.0), -p[1]) {
    using std::cos, std::sin;
    v0 << p[2] * cos(p[3]), p[2] * sin(p[3]);
  }

  Vec<2, T> mass() const { return Vec<2, T>::Constant(m); }
  Vec<2, T> inverse_mass() const { return Vec<2, T>::Constant(inv_m); }
  Vec<2, T> force(const Vec<2, T>&, const Vec<2, T>&) const { return m * g; }
  Jacobians<2, T> jacobians(const Vec<2, T>&, const Vec<2, T>&) const { return {Mat<2, T>::Zero(), Mat<2, T>::Zero()}; }

  // Total mechanical energy: 1/2 m |v|^2 - m g . x.
  T energy(const Vec<2, T>& x, const Vec<2, T>& v) const { return 0.5 * m * v.squaredNorm() - m * g.dot(x); }

  State<2, T> initial() const { return {Vec<2, T>::Zero(), v0}; }

  auto velocity_dependent() const { return MaskOf<T>(false); }

  State<2> exact_at(double t) const { return flow(initial(), t); }
  State<2> flow(const State<2>& y, double t) const { return {y.x + y.v * t + 0.5 * g * t * t, y.v + g * t}; }
};

using Cannonball = CannonballT<double>;

}  // namespace steplab

STEPLAB_SCENE(steplab::Cannonball);
