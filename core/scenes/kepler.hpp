// Kepler's orbit: a unit mass about a fixed centre of GM = 1, the setting of SUNDIALS' ark_kepler
// example. Semi-major axis a = 1, eccentricity e, started at pericentre:
//
//   x'' = -x / |x|^3,   x(0) = (1 - e, 0),   v(0) = (0, sqrt((1 + e) / (1 - e))),   period 2 pi
//
// Its invariants: the energy H = |v|^2 / 2 - 1 / |x| (= -1 / (2 a) = -1/2) and the angular
// momentum L = x1 v2 - x2 v1 (= sqrt(1 - e^2)). Nonlinear: its frequency depends on the energy,
// so an energy error becomes a phase error that grows with t (Hairer, Lubich and Wanner, ch. X).
//
// The exact flow from any bound state y (H < 0), by Kepler's equation. With r0 = |x0|,
// a = -1 / (2 H), n = a^(-3/2), e cos E0 = 1 - r0 / a, e sin E0 = x0.v0 / sqrt(a): the mean
// anomaly M = E0 - e sin E0 + n t; E solves E - e sin E = M (Newton); with dE = E - E0 and
// r = a (1 - e cos E), Lagrange's f and g functions give
//   x = f x0 + g v0,  v = fd x0 + gd v0,  f = 1 - a / r0 (1 - cos dE),  g = t + (sin dE - dE) / n,
//   fd = -sqrt(a) sin dE / (r r0),  gd = 1 - a / r (1 - cos dE).
// The motion is periodic, so t is first reduced modulo the period: after 10^5 periods the exact
// phase is then good to ~1e-10 (the rounding of t), far below any method's error there. An unbound
// state (H >= 0) has no such flow: NaN.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>

#include "core/invariants.hpp"
#include "core/scene.hpp"

namespace steplab {

struct Kepler {
  static constexpr int dim = 2;
  static constexpr std::string_view name = "kepler";
  static constexpr std::string_view title = "Kepler's orbit";
  static constexpr std::string_view equation = "x'' = -x / |x|^3 (GM = 1, unit mass), from pericentre of an orbit of semi-major axis 1";
  static constexpr std::array<ParamSpec, 1> params{{
      {"eccentricity", 0.6, Bound::Fraction, "eccentricity e of the orbit (0: a circle)"},
  }};
  static constexpr std::array<std::string_view, 2> invariant_names{"energy", "angular momentum"};

  double e;
  explicit Kepler(std::span<const double> p) : e(p[0]) {}

  Vec<2> mass() const { return Vec<2>::Ones(); }
  Vec<2> inverse_mass() const { return Vec<2>::Ones(); }
  bool velocity_dependent() const { return false; }

  Vec<2> force(const Vec<2>& x, const Vec<2>&) const {
    const double r2 = x.squaredNorm(), r = std::sqrt(r2);
    return -x / (r2 * r);
  }
  // dF/dx = -I / r^3 + 3 x x^T / r^5; F does not depend on v.
  Jacobians<2> jacobians(const Vec<2>& x, const Vec<2>&) const {
    const double r2 = x.squaredNorm(), r = std::sqrt(r2), r3 = r2 * r;
    return {Mat<2>(-Mat<2>::Identity() / r3 + 3 * x * x.transpose() / (r3 * r2)), Mat<2>::Zero()};
  }

  double energy(const Vec<2>& x, const Vec<2>& v) const { return 0.5 * v.squaredNorm() - 1 / x.norm(); }
  std::array<double, 2> invariants(const Vec<2>& x, const Vec<2>& v) const {
    return {energy(x, v), x[0] * v[1] - x[1] * v[0]};
  }
  double period() const { return 2 * std::numbers::pi; }
  double extent() const { return 1; }  // the semi-major axis

  State<2> initial() const { return {Vec<2>(1 - e, 0), Vec<2>(0, std::sqrt((1 + e) / (1 - e)))}; }

  State<2> flow(const State<2>& y, double t) const {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    const double r0 = y.x.norm(), h = energy(y.x, y.v);
    if (!(h < 0)) return {Vec<2>::Constant(nan), Vec<2>::Constant(nan)};
    const double a = -1 / (2 * h), sqrt_a = std::sqrt(a), n = 1 / (a * sqrt_a);
    const double ecos0 = 1 - r0 / a, esin0 = y.x.dot(y.v) / sqrt_a;
    const double ecc = std::hypot(ecos0, esin0), e0 = std::atan2(esin0, ecos0);
    const double turn = 2 * std::numbers::pi / n, t_in = t - turn * std::floor(t / turn);  // the motion is periodic
    const double m = e0 - esin0 + n * t_in;
    double big_e = m + 0.85 * ecc * (std::sin(m) < 0 ? -1 : 1);  // Danby's start: Newton converges from it for e < 1
    for (int k = 0; k < 60; ++k) {
      const double step = (big_e - ecc * std::sin(big_e) - m) / (1 - ecc * std::cos(big_e));
      big_e -= step;
      if (std::abs(step) <= 4e-16 * std::max(1.0, std::abs(big_e))) break;
    }
    const double de = big_e - e0, r = a * (1 - ecc * std::cos(big_e));
    const double f = 1 - a / r0 * (1 - std::cos(de)), g = t_in + (std::sin(de) - de) / n;
    const double fd = -sqrt_a * std::sin(de) / (r * r0), gd = 1 - a / r * (1 - std::cos(de));
    return {f * y.x + g * y.v, fd * y.x + gd * y.v};
  }
};

}  // namespace steplab

STEPLAB_SCENE(steplab::Kepler);
