// The sheet's spring swinging in a plane: its equation (1) in two dimensions, an elastic
// pendulum. The cube (mass m) hangs from an anchor at the origin on a spring of stiffness k and
// rest length L, under gravity, with damping gamma (0 by default here: then its energy is kept):
//
//   m x'' = -k (|x| - L) x / |x| - gamma x' + (0, -m g)
//
// Started at rest at rest length at an angle theta from the vertical, x(0) = L (sin theta,
// -cos theta). Nonlinear: the swing and the stretch exchange energy. Its invariant (gamma = 0) is
// the energy, taken about the hanging equilibrium |x| = l_eq = L + m g / k below the anchor,
//   E = m |v|^2 / 2 + k (|x| - L)^2 / 2 + m g (x_2 + l_eq) - k (m g / k)^2 / 2,
// so that E > 0 away from it (a relative error is then relative to the swing's energy). Its
// linearisation there has two oscillators, the pendulum's omega^2 = g / l_eq and the stretch's
// k / m; the long-time study counts in the slower one's period. No exact solution: the studies
// that need one use their reference solution.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>

#include "core/invariants.hpp"
#include "core/scene.hpp"
#include "core/springs.hpp"
#include "core/scenes/pair_spring.hpp"

namespace steplab {

struct Swing {
  static constexpr int dim = 2;
  static constexpr int coords_per_mass = 2;
  static constexpr std::string_view name = "swing";
  static constexpr std::string_view title = "Spring swinging in a plane";
  static constexpr std::string_view equation = "m x'' = -k (|x| - L) x / |x| - gamma x' + (0, -m g): the sheet's spring in a plane";
  static constexpr std::string_view stiffness_param = "stiffness";
  static constexpr std::string_view damping_param = "damping";
  // The sheet's cube and spring (m = 1, k = 5, L = 5, g = 9.81), undamped, released at 30 degrees.
  static constexpr std::array<ParamSpec, 6> params{{
      {"mass", 1.0, Bound::Positive, "mass m"},
      {"stiffness", 5.0, Bound::Positive, "spring stiffness k"},
      {"damping", 0.0, Bound::NonNegative, "damping coefficient gamma (force -gamma v; 0 keeps the energy)"},
      {"rest-length", 5.0, Bound::Positive, "rest length L"},
      {"gravity", 9.81, Bound::NonNegative, "gravitational acceleration g (pointing down)"},
      {"angle", 30.0, Bound::Any, "release angle from the vertical, in degrees"},
  }};
  static constexpr std::array<std::string_view, 1> invariant_names{"energy"};

  double m, k, gamma, L, g, angle;
  double inv_m = 1 / m, l_eq = L + m * g / k;
  PairSpring spring{k, 0.0};  // the spring alone: the damping is absolute, -gamma v

  explicit Swing(std::span<const double> p) : m(p[0]), k(p[1]), gamma(p[2]), L(p[3]), g(p[4]), angle(p[5]) {}

  Vec<2> mass() const { return Vec<2>::Constant(m); }
  Vec<2> inverse_mass() const { return Vec<2>::Constant(inv_m); }
  bool velocity_dependent() const { return gamma != 0; }

  Vec<2> force(const Vec<2>& x, const Vec<2>& v) const { return spring.force(x, Vec<2>::Zero(), L) - gamma * v + Vec<2>(0, -m * g); }
  Jacobians<2> jacobians(const Vec<2>& x, const Vec<2>&) const {
    return {spring.blocks(x, Vec<2>::Zero(), L).dd, Mat<2>(-gamma * Mat<2>::Identity())};
  }

  double energy(const Vec<2>& x, const Vec<2>& v) const {
    const double sag = m * g / k;
    return 0.5 * m * v.squaredNorm() + spring.energy(x, L) + m * g * (x[1] + l_eq) - 0.5 * k * sag * sag;
  }
  std::array<double, 1> invariants(const Vec<2>& x, const Vec<2>& v) const { return {energy(x, v)}; }
  // Without gravity there is no pendulum: the stretch's period alone.
  double period() const { return 2 * std::numbers::pi / std::sqrt(g > 0 ? std::min(g / l_eq, k / m) : k / m); }
  double extent() const { return l_eq; }

  // As springs (core/springs.hpp): the one spring from the fixed anchor, no dashpot along it;
  // the damping and gravity outside it.
  int links() const { return 1; }
  Link link(int) const { return {0, -1, L, k, 0.0}; }
  double external(int a, double v) const { return -gamma * v - (a == 1 ? m * g : 0.0); }

  State<2> initial() const {
    const double th = angle * std::numbers::pi / 180;
    return {Vec<2>(L * std::sin(th), -L * std::cos(th)), Vec<2>::Zero()};
  }
};

}  // namespace steplab

STEPLAB_SCENE(steplab::Swing);
