// A damped pendulum: a mass m on a rigid massless rod of length L, its angle theta from the
// hanging vertical the one coordinate, under gravity, with damping c per unit inertia:
//
//   theta'' = -(g / L) sin theta - c theta',   as M x'' = F:  m L^2 theta'' = -m g L sin theta - m L^2 c theta'
//
// released at rest at theta_0. The force is bounded (|m g L sin theta| <= m g L): a method that
// is unstable here does not blow up, it makes the pendulum swing wider or spin over the top with
// an energy that rises and stays bounded. That is what the stability study's criterion must see
// (analysis/studies/mode_stability.hpp): a damped scene whose energy ends above its start is
// unstable, however bounded. Its energy, about the hanging rest (zero there),
//   E = m L^2 theta'^2 / 2 + m g L (1 - cos theta),
// decreases along every exact motion with c > 0 (dE/dt = -m L^2 c theta'^2) and is kept with c = 0.
// Its mode: the linearisation about rest, omega_0^2 = g / L, 2 zeta = c / omega_0, which predicts
// every method's dt* for small swings (explicit Euler: 2 zeta / omega_0 = c / omega_0^2). Its
// period: that of the undamped swing of amplitude theta_0, 4 sqrt(L / g) K(sin(theta_0 / 2)), K
// the complete elliptic integral of the first kind, pi / (2 AGM(1, cos(theta_0 / 2))) (longer
// than the small swing's 2 pi sqrt(L / g): 2.139 s at the default 1 rad against 2.006 s). No exact
// solution: the studies measure against their reference solution.
#pragma once

#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include "core/invariants.hpp"
#include "core/scene.hpp"

namespace steplab {

struct Pendulum {
  static constexpr int dim = 1;
  static constexpr std::string_view name = "pendulum";
  static constexpr std::string_view title = "Damped pendulum";
  static constexpr std::string_view equation = "theta'' = -(g / L) sin theta - c theta': a mass on a rigid rod, released at rest at theta_0";
  static constexpr std::string_view damping_param = "damping";
  static constexpr std::array<ParamSpec, 5> params{{
      {"mass", 1.0, Bound::Positive, "mass m"},
      {"length", 1.0, Bound::Positive, "rod length L"},
      {"gravity", 9.81, Bound::Positive, "gravitational acceleration g"},
      {"damping", 0.5, Bound::NonNegative, "damping c per unit inertia, 1/s (the torque -m L^2 c theta'; 0 keeps the energy)"},
      {"amplitude", 1.0, Bound::Any, "release angle theta_0 from the hanging vertical, radians (at rest)"},
  }};
  static constexpr std::array<std::string_view, 1> invariant_names{"energy"};

  double m, L, g, c, theta0;
  double inertia = m * L * L, inv_inertia = 1 / inertia;

  explicit Pendulum(std::span<const double> p) : m(p[0]), L(p[1]), g(p[2]), c(p[3]), theta0(p[4]) {}

  Vec<1> mass() const { return Vec<1>::Constant(inertia); }
  Vec<1> inverse_mass() const { return Vec<1>::Constant(inv_inertia); }
  bool velocity_dependent() const { return c != 0; }
  Vec<1> force(const Vec<1>& x, const Vec<1>& v) const { return Vec<1>::Constant(-m * g * L * std::sin(x[0]) - inertia * c * v[0]); }
  Jacobians<1> jacobians(const Vec<1>& x, const Vec<1>&) const {
    return {Mat<1>::Constant(-m * g * L * std::cos(x[0])), Mat<1>::Constant(-inertia * c)};
  }
  double energy(const Vec<1>& x, const Vec<1>& v) const { return 0.5 * inertia * v[0] * v[0] + m * g * L * (1 - std::cos(x[0])); }
  State<1> initial() const { return {Vec<1>::Constant(theta0), Vec<1>::Zero()}; }

  std::vector<Mode> modes() const {
    const double omega = std::sqrt(g / L);
    return {{omega, c / omega}};
  }

  std::array<double, 1> invariants(const Vec<1>& x, const Vec<1>& v) const { return {energy(x, v)}; }
  double period() const {
    double a = 1, b = std::cos(0.5 * theta0);  // K(k) = pi / (2 AGM(1, sqrt(1 - k^2))), k = sin(theta_0 / 2)
    for (int i = 0; i < 64 && std::abs(a - b) > 1e-16 * a; ++i) {
      const double mean = 0.5 * (a + b);
      b = std::sqrt(a * b), a = mean;
    }
    return 2 * std::numbers::pi * std::sqrt(L / g) / a;  // 4 sqrt(L / g) K
  }
  double extent() const { return std::abs(theta0) > 0 ? std::abs(theta0) : 1.0; }  // radians: the swing's amplitude
};

}  // namespace steplab

STEPLAB_SCENE(steplab::Pendulum);
