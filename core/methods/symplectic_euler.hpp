#pragma once
#include "core/compensated.hpp"
#include "core/method.hpp"

namespace steplab {

// Symplectic (semi-implicit) Euler, first order: the new velocity first, then the position with it.
//   v_{n+1} = v_n + h a(x_n, v_n)
//   x_{n+1} = x_n + h v_{n+1}
// Undamped oscillator: stable (|eigenvalues| = 1) for h <= 2 / omega, omega = sqrt(k/m).
struct SymplecticEuler {
  static constexpr MethodInfo info{.name = "symplectic_euler", .order = 1, .family = Family::Splitting,
                                   .symplectic = true,
                                   .summary = "v += h a(x, v), then x += h v with the new v"};
  static constexpr bool compensated = true;  // its sums carry their round-off (core/compensated.hpp)
  template <class S, class T, class Carry = NoCarry>
  static StepStatus step(const S& s, State<S::dim, T>& y, Time<T> t, Time<T> h, Carry&& carry = Carry{}) {
    add_compensated(y.v, Temp<S::dim, T>(h * acceleration(s, t, y.x, y.v)), carry.v);
    add_compensated(y.x, Temp<S::dim, T>(h * y.v), carry.x);
    return StepStatus::Ok;
  }
};

}  // namespace steplab

STEPLAB_METHOD(steplab::SymplecticEuler);
