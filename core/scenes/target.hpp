// A mass pulled towards a moving target g(t) = sin(w t) by a spring-damper: the second-order form
// of Prothero and Robinson's test problem (Math. Comp. 28, 1974), the one on which implicit
// Runge-Kutta methods lose order as the system stiffens (Hairer & Wanner II, IV.15):
//
//   m x'' = F(t, x, v) = -k (x - g(t)) - c (v - g'(t)) + m g''(t),   c = 2 zeta sqrt(k m)
//
// Started on the target, x(0) = g(0), v(0) = g'(0), it stays there: x(t) = g(t) exactly for
// every k and c, so the stiffness is a free parameter and the exact solution never changes. The
// deviation u = x - g obeys m u'' + c u' + k u = 0: with zeta > 1 its two eigenvalues are real,
//   lambda = sqrt(k/m) (-zeta -+ sqrt(zeta^2 - 1)),
// both growing as sqrt(k): h |lambda| large is the stiff limit, small the non-stiff one. The
// force depends on t (Driven, core/scene.hpp): each method evaluates it at its stages' times,
// which is where order reduction comes from. Not autonomous, so no flow(y, h): exact_at(t).
#pragma once

#include <array>
#include <cmath>
#include <span>
#include <vector>

#include "core/scene.hpp"

namespace steplab {

struct Target {
  static constexpr int dim = 1;
  static constexpr std::string_view name = "target";
  static constexpr std::string_view title = "Mass pulled to a moving target";
  // The equation of motion, for the report (the math above is its derivation).
  static constexpr std::string_view equation = "m x'' = -k (x - g(t)) - c (x' - g'(t)) + m g''(t),  g(t) = sin(w t),  c = 2 zeta sqrt(k m)";
  static constexpr std::string_view stiffness_param = "stiffness";
  static constexpr std::array<ParamSpec, 4> params{{
      {"mass", 1.0, Bound::Positive, "mass m"},
      {"stiffness", 100.0, Bound::Positive, "spring stiffness k towards the target"},
      {"damping-ratio", 2.0, Bound::NonNegative, "zeta = c / (2 sqrt(k m)); above 1 both eigenvalues are real"},
      {"frequency", 1.0, Bound::Positive, "the target's angular frequency w: g(t) = sin(w t)"},
  }};

  double m, k, zeta, w;
  double c = 2 * zeta * std::sqrt(k * m);  // initialised after k, m, zeta (declaration order)
  double inv_m = 1 / m;

  explicit Target(std::span<const double> p) : m(p[0]), k(p[1]), zeta(p[2]), w(p[3]) {}

  Vec<1> mass() const { return Vec<1>::Constant(m); }
  Vec<1> inverse_mass() const { return Vec<1>::Constant(inv_m); }

  // g, g', g'' at t.
  std::array<double, 3> target(double t) const {
    const double s = std::sin(w * t), co = std::cos(w * t);
    return {s, w * co, -w * w * s};
  }
  Vec<1> force(double t, const Vec<1>& x, const Vec<1>& v) const {
    const auto [g, dg, ddg] = target(t);
    return Vec<1>::Constant(-k * (x[0] - g) - c * (v[0] - dg) + m * ddg);
  }
  Jacobians<1> jacobians(double, const Vec<1>&, const Vec<1>&) const { return {Mat<1>::Constant(-k), Mat<1>::Constant(-c)}; }
  bool velocity_dependent() const { return c != 0; }
  // Its one mode (core/scene.hpp): the deviation's oscillator, omega = sqrt(k/m), 2 zeta.
  std::vector<Mode> modes() const { return {{std::sqrt(k / m), c / std::sqrt(k * m)}}; }

  // 1/2 m v^2 + 1/2 k x^2: bounded on the exact motion (by 1/2 (m w^2 + k)), growing without
  // bound when a method blows up, which is all the studies ask of it here.
  double energy(const Vec<1>& x, const Vec<1>& v) const { return 0.5 * m * v[0] * v[0] + 0.5 * k * x[0] * x[0]; }
  // That bound, the blow-up rule's scale (core/simulate.hpp): its start's energy, 1/2 m w^2, is
  // k / (m w^2) times smaller than the energy of its exact motion a quarter period later.
  double energy_scale() const { return 0.5 * (m * w * w + k); }

  State<1> initial() const { return exact_at(0); }
  State<1> exact_at(double t) const {
    const auto [g, dg, ddg] = target(t);
    return {Vec<1>::Constant(g), Vec<1>::Constant(dg)};
  }
};

}  // namespace steplab

STEPLAB_SCENE(steplab::Target);
