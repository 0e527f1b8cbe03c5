#pragma once
#include "core/method.hpp"

namespace steplab {

// Explicit (forward) Euler, first order, neither symplectic nor stable for an undamped
// oscillator at any step (its amplification factor has modulus sqrt(1 + h^2 k/m) > 1):
//   x_{n+1} = x_n + h v_n
//   v_{n+1} = v_n + h a(x_n, v_n)
struct ExplicitEuler {
  static constexpr MethodInfo info{.name = "explicit_euler", .order = 1, .family = Family::ExplicitRungeKutta,
                                   .summary = "x += h v, v += h a(x, v), both from the old state", .first_of = Family::AdamsBashforth};
  template <class S, class T> static StepStatus step(const S& s, State<S::dim, T>& y, Time<T> t, Time<T> h) {
    const Temp<S::dim, T> a = acceleration(s, t, y.x, y.v);
    y.x += h * y.v;
    y.v += h * a;
    return StepStatus::Ok;
  }
};

}  // namespace steplab

STEPLAB_METHOD(steplab::ExplicitEuler);
