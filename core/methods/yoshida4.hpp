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
                                   .summary = "velocity Verlet steps of w1 h, w0 h, w1 h, w1 = 1/(2 - 2^(1/3)), w0 = 1 - 2 w1 (the triple jump)"};
  static constexpr int solve_stages = VelocityVerlet::solve_stages;  // core/method.hpp
  static constexpr bool compensated = true;  // each substep's sums carry their round-off (core/compensated.hpp)
  static constexpr double cbrt2 = 1.2599210498948731648;  // 2^(1/3)
  static constexpr double w1 = 1 / (2 - cbrt2), w0 = -cbrt2 / (2 - cbrt2);
  // A lane of a pack whose Newton failed in one substep takes the others too; its state is dropped.
  template <class S, class T, class Carry = NoCarry>
  static Status<T> step(const S& s, State<S::dim, T>& y, Time<T> t, Time<T> h, Carry&& carry = Carry{}) {
    MaskOf<T> failed_lanes(false);
    T at = t;  // each substep starts where the last ended: t, t + w1 h, t + (w1 + w0) h
    for (const double w : {w1, w0, w1}) {
      failed_lanes = failed_lanes || failed(VelocityVerlet::step(s, y, at, w * h, carry));
      if (all(failed_lanes)) break;
      at += w * h;
    }
    return status_of(failed_lanes);
  }
};

}  // namespace steplab

STEPLAB_METHOD(steplab::Yoshida4);
