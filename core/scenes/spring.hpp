// The hanging cube of the 2018 sheet, modelled on the vertical line only (`spring1d` in the old
// flags): y is the mass's height relative to an anchor at y = 0, so y < 0 while it hangs.
//
//   m y'' = F(y, v) = -k (|y| - L) sign(y) - gamma v - m g        (the sheet's equation (1))
//
// While y < 0 the spring force is -k (y + L): the system is linear, with equilibrium
// y_eq = -L - m g / k. With u = y - y_eq,   m u'' + gamma u' + k u = 0.
#pragma once

#include <array>
#include <cmath>
#include <complex>
#include <span>

#include "core/scene.hpp"
#include "core/springs.hpp"
#include "core/scenes/oscillator.hpp"

namespace steplab {

// T = double: one spring; T = Pack<W>: W springs, one per lane, stepped together (core/batch.hpp).
template <class T> struct SpringT {
  template <class U> using as = SpringT<U>;
  static constexpr int dim = 1;
  static constexpr std::string_view name = "spring";
  static constexpr std::string_view title = "Spring";
  // The equation of motion, for the report (the math above is its derivation).
  static constexpr std::string_view equation = "m y'' = -k (y + L) - gamma y' - m g, while the cube hangs below the anchor (y < 0)";
  static constexpr bool affine_flow = true;  // flow(y, h) below is linear in y - y_eq (core/scene.hpp)
  static constexpr std::string_view old_name = "spring1d";  // the old framework's test case
  static constexpr std::string_view stiffness_param = "stiffness";
  static constexpr std::string_view damping_param = "damping";
  // Defaults from the 2018 sheet: m = 1, k = 5, L = 5, gamma = 0.1, g = 9.81.
  static constexpr std::array<ParamSpec, 5> params{{
      {"mass", 1.0, Bound::Positive, "mass m"},
      {"stiffness", 5.0, Bound::Positive, "spring stiffness k"},
      {"damping", 0.1, Bound::NonNegative, "damping coefficient gamma (force -gamma v)"},
      {"rest-length", 5.0, Bound::NonNegative, "rest length L"},
      {"gravity", 9.81, Bound::NonNegative, "gravitational acceleration g (pointing down)"},
  }};

  T m, k, gamma, L, g;
  T inv_m = 1 / m;  // initialized after m (declaration order)
  T weight = m * g;
  // Stored, not recomputed in each energy(): in a batch of runs the compiler cannot hoist
  // the division out of the stepping loop.
  T equilibrium_y = -L - m * g / k;

  explicit SpringT(std::span<const T> p) : m(p[0]), k(p[1]), gamma(p[2]), L(p[3]), g(p[4]) {}

  // The parameter values it was made from, in table order.
  std::array<double, 5> values() const { return {m, k, gamma, L, g}; }
  T equilibrium() const { return equilibrium_y; }
  double omega() const { return std::sqrt(k / m); }              // undamped angular frequency
  double critical_damping() const { return 2 * std::sqrt(k * m); }  // gamma^2 = 4 k m
  // An eigenvalue of m u'' + gamma u' + k u = 0 (notation of flow below): alpha + i beta when
  // underdamped (the one with Im >= 0), the faster real one alpha - delta when overdamped.
  std::complex<double> eigenvalue() const {
    const double alpha = -gamma / (2 * m), beta2 = (4 * k * m - gamma * gamma) / (4 * m * m);
    return beta2 > 0 ? std::complex<double>(alpha, std::sqrt(beta2)) : std::complex<double>(alpha - std::sqrt(-beta2), 0);
  }

  Vec<1, T> mass() const { return Vec<1, T>::Constant(m); }
  Vec<1, T> inverse_mass() const { return Vec<1, T>::Constant(inv_m); }

  Vec<1, T> force(const Vec<1, T>& x, const Vec<1, T>& v) const {
    using std::abs;
    const T y = x[0];
    const T sign = select(y > 0.0, T(1.0), T(0.0)) - select(y < 0.0, T(1.0), T(0.0));  // sign(y)
    return Vec<1, T>::Constant(-k * (abs(y) - L) * sign - gamma * v[0] - weight);
  }

  // d/dy [-k (|y| - L) sign(y)] = -k away from the anchor; dF/dv = -gamma.
  Jacobians<1, T> jacobians(const Vec<1, T>&, const Vec<1, T>&) const {
    return {Mat<1, T>::Constant(-k), Mat<1, T>::Constant(-gamma)};
  }

  auto velocity_dependent() const { return gamma != 0.0; }  // a Mask for a pack of springs
  // As springs (core/springs.hpp; one run's, T = double): the spring from the anchor above the
  // cube, C = (0 - y) - L, with gamma its dashpot (dC/dt = -v: the force -gamma v); gravity outside it.
  int links() const { return 1; }
  Link link(int) const { return {-1, 0, L, k, gamma}; }
  double external(int, double) const { return -weight; }

  // Oscillation energy about the equilibrium: E = 1/2 m v^2 + 1/2 k (y - y_eq)^2.
  // It is not zero at the rest start (y = -L): E(0) = (m g)^2 / (2 k).
  T energy(const Vec<1, T>& x, const Vec<1, T>& v) const {
    const T u = x[0] - equilibrium();
    return 0.5 * m * v[0] * v[0] + 0.5 * k * u * u;
  }

  // Starts at rest at rest length.
  State<1, T> initial() const { return {Vec<1, T>::Constant(-L), Vec<1, T>::Zero()}; }

  State<1> exact_at(double t) const { return flow(initial(), t); }

  // The exact flow of m u'' + gamma u' + k u = 0 over a time t from any state (y0, v0) below the
  // anchor, in every damping regime (core/scenes/oscillator.hpp), with alpha = -gamma / (2m) and
  // beta^2 = (4 k m - gamma^2) / (4 m^2). From the rest state (u0 = m g / k, v0 = 0) the
  // underdamped form is the sheet's (2) with c1 = m g / k, c2 = -alpha c1 / beta.
  State<1> flow(const State<1>& y, double t) const {
    const double y_eq = equilibrium();
    const double alpha = -gamma / (2 * m);
    const double beta2 = (4 * k * m - gamma * gamma) / (4 * m * m);
    const auto [u, du] = damped_oscillation(y.x[0] - y_eq, y.v[0], alpha, beta2, t);
    return {Vec<1>::Constant(y_eq + u), Vec<1>::Constant(du)};
  }
};

using Spring = SpringT<double>;

}  // namespace steplab

STEPLAB_SCENE(steplab::Spring);
