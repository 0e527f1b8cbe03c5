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

struct Cannonball {
  static constexpr int dim = 2;
  static constexpr std::string_view name = "cannonball";
  // Defaults from the 2018 sheet: mass 1, from the origin at 100 * (cos 1.047, sin 1.047).
  static constexpr std::array<ParamSpec, 4> params{{
      {"mass", 1.0, Bound::Positive, "mass m"},
      {"gravity", 9.81, Bound::NonNegative, "gravitational acceleration g (pointing down)"},
      {"speed", 100.0, Bound::NonNegative, "launch speed |v0|"},
      {"angle", 1.047, Bound::Any, "launch angle in radians from the horizontal"},
  }};

  double m;
  double inv_m = 1 / m;  // initialized after m (declaration order)
  Vec<2> g;
  Vec<2> v0;

  explicit Cannonball(std::span<const double> p)
      : m(p[0]), g(0.0, -p[1]), v0(p[2] * std::cos(p[3]), p[2] * std::sin(p[3])) {}

  Vec<2> mass() const { return Vec<2>::Constant(m); }
  Vec<2> inverse_mass() const { return Vec<2>::Constant(inv_m); }
  Vec<2> force(const Vec<2>&, const Vec<2>&) const { return m * g; }
  Jacobians<2> jacobians(const Vec<2>&, const Vec<2>&) const { return {Mat<2>::Zero(), Mat<2>::Zero()}; }

  // Total mechanical energy: 1/2 m |v|^2 - m g . x.
  double energy(const Vec<2>& x, const Vec<2>& v) const { return 0.5 * m * v.squaredNorm() - m * g.dot(x); }

  State<2> initial() const { return {Vec<2>::Zero(), v0}; }

  bool velocity_dependent() const { return false; }

  State<2> exact_at(double t) const { return flow(initial(), t); }
  State<2> flow(const State<2>& y, double t) const { return {y.x + y.v * t + 0.5 * g * t * t, y.v + g * t}; }
};

}  // namespace steplab

STEPLAB_SCENE(steplab::Cannonball);
