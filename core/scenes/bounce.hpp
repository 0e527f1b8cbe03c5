// A mass dropped from rest at y = 0 onto the ground y = -1 (core/scenes/ground.hpp), 1-D.
//
//   m y'' = -m g + F_ground(y, v)
//
// Its exact motion is piecewise:
//   free flight (y >= -1):  y(t) = y0 + v0 t - g t^2 / 2, until y = -1 (a quadratic's root);
//   contact (y < -1):       m y'' + c_g y' + k_g (y + 1) = -m g, a damped oscillator about
//                           y_c = -1 - m g / k_g: exactly the hanging spring with k = k_g,
//                           gamma = c_g and its anchor L = 1 above the ground, so Spring::flow
//                           gives it; the exit (y back to -1, moving up) is found by bisection
//                           to round-off, after scanning in eighths of a period for the crossing.
// flow(y, h) chains these phases over any h. Without ground damping no energy is lost: every
// bounce returns to y = 0.
#pragma once

#include <array>
#include <cmath>
#include <numbers>
#include <span>

#include "core/scene.hpp"
#include "core/scenes/ground.hpp"
#include "core/scenes/spring.hpp"

namespace steplab {

// T = double: one bounce; T = Pack<W>: W bounces, one per lane (core/batch.hpp). The exact flow
// below is the scalar's (a pack's errors are taken lane by lane).
template <class T> struct BounceT {
  template <class U> using as = BounceT<U>;
  static constexpr int dim = 1;
  static constexpr std::string_view name = "bounce";
  // The equation of motion, for the report (the math above is its derivation).
  static constexpr std::string_view equation = "m y'' = -m g + F_g,  F_g = k_g p - c_g y' while the penetration p = -1 - y > 0, else 0";
  static constexpr std::array<ParamSpec, 4> params{{
      {"mass", 1.0, Bound::Positive, "mass m"},
      {"gravity", 9.81, Bound::Positive, "gravitational acceleration g (pointing down)"},
      {"ground-stiffness", 100.0, Bound::Positive, "stiffness k_g of the ground's penalty spring"},
      {"ground-damping", 0.0, Bound::NonNegative, "damping c_g of the ground's penalty spring"},
  }};

  T m, g;
  T inv_m = 1 / m;  // initialized after m (declaration order)
  GroundT<T> ground;
  SpringT<T> contact;  // the contact phase as a hanging spring: k_g, c_g, L = 1

  explicit BounceT(std::span<const T> p)
      : m(p[0]), g(p[1]), ground{p[2], p[3]}, contact(std::array<T, 5>{p[0], p[2], p[3], T(1.0), p[1]}) {}

  Vec<1, T> mass() const { return Vec<1, T>::Constant(m); }
  Vec<1, T> inverse_mass() const { return Vec<1, T>::Constant(inv_m); }
  Vec<1, T> force(const Vec<1, T>& x, const Vec<1, T>& v) const { return Vec<1, T>::Constant(-m * g + ground.force(x[0], v[0])); }
  Jacobians<1, T> jacobians(const Vec<1, T>& x, const Vec<1, T>&) const {
    return {Mat<1, T>::Constant(ground.dforce_dy(x[0])), Mat<1, T>::Constant(ground.dforce_dv(x[0]))};
  }
  auto velocity_dependent() const { return ground.c != 0.0; }  // a Mask for a pack
  double penetration(const Vec<1>& x) const { return ground.penetration(x[0]); }

  // Total mechanical energy, height measured from the ground (so E0 = m g > 0 at the drop):
  // 1/2 m v^2 + m g (y + 1) + 1/2 k_g p^2.
  T energy(const Vec<1, T>& x, const Vec<1, T>& v) const {
    return 0.5 * m * v[0] * v[0] + m * g * (x[0] - Ground::level) + ground.energy(x[0]);
  }

  State<1, T> initial() const { return {Vec<1, T>::Zero(), Vec<1, T>::Zero()}; }

  State<1> flow(State<1> y, double h) const {
    for (int phase = 0; h > 0 && phase < 100000; ++phase) {
      const bool in_contact = y.x[0] < Ground::level || (y.x[0] == Ground::level && y.v[0] < 0);
      const double t_event = in_contact ? exit_time(y, h) : hit_time(y);
      if (t_event >= h) return in_contact ? contact.flow(y, h) : free_flight(y, h);
      y = in_contact ? contact.flow(y, t_event) : free_flight(y, t_event);
      y.x[0] = Ground::level;  // exactly on the ground at the event
      h -= t_event;
    }
    return y;
  }

 private:
  State<1> free_flight(const State<1>& y, double t) const {
    return {Vec<1>::Constant(y.x[0] + y.v[0] * t - 0.5 * g * t * t), Vec<1>::Constant(y.v[0] - g * t)};
  }

  // First t > 0 with y0 + v0 t - g t^2/2 = -1: t = (v0 + sqrt(v0^2 + 2 g (y0 + 1))) / g, written
  // without cancellation for v0 < 0.
  double hit_time(const State<1>& y) const {
    const double v0 = y.v[0], d = std::max(0.0, y.x[0] - Ground::level);
    const double root = std::sqrt(v0 * v0 + 2 * g * d);
    return v0 >= 0 ? (v0 + root) / g : 2 * d / (root - v0);
  }

  // First t in (0, h) at which the contact motion returns to the ground; h (or more) if none.
  double exit_time(const State<1>& y, double h) const {
    const auto above = [&](double t) { return contact.flow(y, t).x[0] >= Ground::level; };
    const double w = std::sqrt(ground.k / m);
    const double scan = std::numbers::pi / (4 * w);  // an eighth of a period
    double lo = 0;
    for (double hi = std::min(scan, h);; hi = std::min(hi + scan, h)) {
      if (above(hi)) {
        for (int i = 0; i < 200 && hi - lo > 4 * std::numeric_limits<double>::epsilon() * hi; ++i) {
          const double mid = 0.5 * (lo + hi);
          (above(mid) ? hi : lo) = mid;
        }
        return hi;
      }
      if (hi >= h) return h + 1;  // stays in contact for all of h
      lo = hi;
    }
  }
};

using Bounce = BounceT<double>;

}  // namespace steplab

STEPLAB_SCENE(steplab::Bounce);
