#pragma once
#include "core/method.hpp"

namespace steplab {

// Classic fourth-order Runge-Kutta on the first-order system y' = (v, a(x, v)):
//   k1 = f(y_n), k2 = f(y_n + h/2 k1), k3 = f(y_n + h/2 k2), k4 = f(y_n + h k3)
//   y_{n+1} = y_n + h/6 (k1 + 2 k2 + 2 k3 + k4)
// Undamped oscillator: stable up to w h = 2 sqrt(2).
struct Rk4 {
  static constexpr MethodInfo info{.name = "rk4", .order = 4, .family = Family::ExplicitRungeKutta,
                                   .summary = "k1 = f(y_n), k2 = f(y_n + h/2 k1), k3 = f(y_n + h/2 k2), k4 = f(y_n + h k3); y_(n+1) = y_n + h/6 (k1 + 2 k2 + 2 k3 + k4)"};
  template <class S, class T> static StepStatus step(const S& s, State<S::dim, T>& y, Time<T> t, Time<T> h) {
    using V = Temp<S::dim, T>;  // a step's temporaries (core/scratch.hpp)
    const auto& kx1 = y.v;  // k1's position part is v itself: no copy
    const V kv1 = acceleration(s, t, y.x, y.v);
    const V kx2 = y.v + 0.5 * h * kv1, kv2 = acceleration(s, t + 0.5 * h, V(y.x + 0.5 * h * kx1), kx2);
    const V kx3 = y.v + 0.5 * h * kv2, kv3 = acceleration(s, t + 0.5 * h, V(y.x + 0.5 * h * kx2), kx3);
    const V kx4 = y.v + h * kv3, kv4 = acceleration(s, t + h, V(y.x + h * kx3), kx4);
    y.x += (h / 6) * (kx1 + 2 * kx2 + 2 * kx3 + kx4);
    y.v += (h / 6) * (kv1 + 2 * kv2 + 2 * kv3 + kv4);
    return StepStatus::Ok;
  }
};

}  // namespace steplab

STEPLAB_METHOD(steplab::Rk4);
