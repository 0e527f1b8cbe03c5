#pragma once
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
  template <class S, class T> static StepStatus step(const S& s, State<S::dim, T>& y, Time<T> t, Time<T> h) {
    y.v += h * acceleration(s, t, y.x, y.v);
    y.x += h * y.v;
    return StepStatus::Ok;
  }
};

}  // namespace steplab

STEPLAB_METHOD(steplab::SymplecticEuler);
