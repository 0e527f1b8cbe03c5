#pragma once
#include "core/method.hpp"

namespace steplab {

// Explicit midpoint (RK2, Butcher tableau c = (0, 1/2), a21 = 1/2, b = (0, 1)), second order:
//   x_m = x_n + h/2 v_n,            v_m = v_n + h/2 a(x_n, v_n)
//   x_{n+1} = x_n + h v_m,          v_{n+1} = v_n + h a(x_m, v_m)
// Undamped oscillator: |R(i w h)|^2 = 1 + (w h)^4 / 4 > 1, unstable at every step.
struct ExplicitMidpoint {
  static constexpr MethodInfo info{.name = "explicit_midpoint", .order = 2, .family = Family::ExplicitRungeKutta,
                                   .summary = "y_(n+1) = y_n + h f(y_n + h/2 f(y_n)), y = (x, v), f = (v, a)"};
  template <class S, class T> static StepStatus step(const S& s, State<S::dim, T>& y, Time<T> t, Time<T> h) {
    const Temp<S::dim, T> xm = y.x + 0.5 * h * y.v;
    const Temp<S::dim, T> vm = y.v + 0.5 * h * acceleration(s, t, y.x, y.v);
    y.x += h * vm;
    y.v += h * acceleration(s, t + 0.5 * h, xm, vm);
    return StepStatus::Ok;
  }
};

}  // namespace steplab

STEPLAB_METHOD(steplab::ExplicitMidpoint);
