#pragma once
#include "core/methods/velocity_verlet.hpp"

namespace steplab {

// Yoshida's fourth-order triple jump (Phys. Lett. A 150, 1990): three velocity Verlet steps of
// w1 h, w0 h, w1 h with
//   w1 = 1 / (2 - 2^(1/3)) ~ 1.3512,   w0 = -2^(1/3) / (2 - 2^(1/3)) ~ -1.7024   (2 w1 + w0 = 1).
// Composing a symmetric second-order method this way cancels its h^3 error term. Velocity Verlet
// here is symmetric with damping too (its closing kick is trapezoidal), so the composition stays
// fourth order on every scene. Symplectic without damping; the middle step runs backwards.
struct Yoshida4 {
  static constexpr MethodInfo info{.name = "yoshida4", .order = 4, .family = Family::Splitting,
                                   .symplectic = true,
                                   .summary = "velocity Verlet steps of w1 h, w0 h, w1 h (triple jump)"};
  static constexpr double cbrt2 = 1.2599210498948731648;  // 2^(1/3)
  static constexpr double w1 = 1 / (2 - cbrt2), w0 = -cbrt2 / (2 - cbrt2);
  template <Scene S> static StepStatus step(const S& s, State<S::dim>& y, double t, double h) {
    for (const double w : {w1, w0, w1})
      if (const StepStatus st = VelocityVerlet::step(s, y, t, w * h); st != StepStatus::Ok) return st;
    return StepStatus::Ok;
  }
};

}  // namespace steplab

STEPLAB_METHOD(steplab::Yoshida4);
