#pragma once
#include <cmath>

#include "core/implicit_rk.hpp"

namespace steplab {

// Two-stage Gauss-Legendre collocation, order 4 (Hairer, Norsett & Wanner I, Table II.7.3):
//   c = 1/2 -+ sqrt(3)/6,   A = [[1/4, 1/4 - sqrt(3)/6], [1/4 + sqrt(3)/6, 1/4]],   b = (1/2, 1/2)
// A-stable with |R(z)| = 1 exactly on the imaginary axis (R is the (2,2) Pade approximant of
// e^z), and symplectic. Newton on both stages together (core/implicit_rk.hpp), to round-off, and the
// increments summed compensated: the quadratic invariants it keeps are kept to round-off.
struct GaussLegendre4 {
  static constexpr MethodInfo info{.name = "gauss_legendre4", .order = 4, .family = Family::ImplicitRungeKutta,
                                   .symplectic = true, .implicit = true, .a_stable = true,
                                   .summary = "two-stage Gauss-Legendre collocation, both stages by Newton"};
  static constexpr double r3 = 1.7320508075688772935;  // sqrt(3)
  static constexpr int solve_stages = 2;  // core/method.hpp
  static constexpr ButcherTableau<2> tableau{{{{0.25, 0.25 - r3 / 6}, {0.25 + r3 / 6, 0.25}}}, {0.5, 0.5}};
  static constexpr bool compensated = true;  // its increments summed compensated (core/compensated.hpp)
  // carry: the run's (core/stepper.hpp); none where the step is taken alone (a BDF's start):
  // the increments are then added plainly.
  template <class S, class T, class Carry = NoCarry>
  static Status<T> step(const S& s, State<S::dim, T>& y, Time<T> t, Time<T> h, Carry&& carry = Carry{}) {
    return implicit_rk_step(s, y, t, h, tableau, carry);
  }
};

}  // namespace steplab

STEPLAB_METHOD(steplab::GaussLegendre4);
