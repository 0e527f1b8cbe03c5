#pragma once
#include "core/method.hpp"

namespace steplab {

// Kutta's third-order method (1901): c = (0, 1/2, 1), a21 = 1/2, a31 = -1, a32 = 2,
// b = (1/6, 2/3, 1/6), on y' = (v, a(x, v)):
//   k1 = f(y_n), k2 = f(y_n + h/2 k1), k3 = f(y_n - h k1 + 2 h k2)
//   y_{n+1} = y_n + h/6 (k1 + 4 k2 + k3)
// R(z) = 1 + z + z^2/2 + z^3/6: undamped oscillator stable up to w h = sqrt(3).
struct Rk3 {
  static constexpr MethodInfo info{.name = "rk3", .order = 3, .family = Family::ExplicitRungeKutta,
                                   .summary = "k1 = f(y_n), k2 = f(y_n + h/2 k1), k3 = f(y_n - h k1 + 2h k2); y_(n+1) = y_n + h/6 (k1 + 4 k2 + k3)"};
  template <class S, class T> static StepStatus step(const S& s, State<S::dim, T>& y, Time<T> t, Time<T> h) {
    using V = Temp<S::dim, T>;  // a step's temporaries (core/scratch.hpp)
    const V kx1 = y.v, kv1 = acceleration(s, t, y.x, y.v);
    const V kx2 = y.v + 0.5 * h * kv1, kv2 = acceleration(s, t + 0.5 * h, V(y.x + 0.5 * h * kx1), kx2);
    const V kx3 = y.v - h * kv1 + 2 * h * kv2, kv3 = acceleration(s, t + h, V(y.x - h * kx1 + 2 * h * kx2), kx3);
    y.x += (h / 6) * (kx1 + 4 * kx2 + kx3);
    y.v += (h / 6) * (kv1 + 4 * kv2 + kv3);
    return StepStatus::Ok;
  }
};

}  // namespace steplab

STEPLAB_METHOD(steplab::Rk3);
