#pragma once
#include "core/methods/rk4.hpp"
#include "core/stepper.hpp"

namespace steplab {

// Two-step Adams-Bashforth, order 2, on y' = f(y) = (v, a(x, v)):
//   y_{n+1} = y_n + h (3/2 f_n - 1/2 f_{n-1})
// Memory: f_{n-1}. The first step is an RK4 step (local error O(h^5), so the start costs no
// order). One force evaluation a step. Stability: |rho| <= 1 only for h lambda in a bounded
// region touching the imaginary axis at 0 alone: an undamped oscillator grows at every step.
struct AdamsBashforth2 {
  static constexpr MethodInfo info{"adams_bashforth2", 2, Family::AdamsBashforth, false, false, false,
                                   "y += h (3/2 f_n - 1/2 f_(n-1)), started by RK4"};
  static constexpr int history = 1;
  // Memory of a run whose state k steps back was past(k): the derivatives there.
  template <Scene S, class Past> static History<S::dim, 1> remember(const S& s, Past&& past) {
    return history_of<S::dim, 1>([&](int k) { return derivative(s, past(k)); });
  }
  template <Scene S> static StepStatus step(const S& s, State<S::dim>& y, double t, double h, History<S::dim, 1>& mem) {
    const State<S::dim> f = derivative(s, y);
    if (mem.count < history) {
      mem.push(f);
      return Rk4::step(s, y, t, h);
    }
    y.x += h * (1.5 * f.x - 0.5 * mem.past[0].x);
    y.v += h * (1.5 * f.v - 0.5 * mem.past[0].v);
    mem.push(f);
    return StepStatus::Ok;
  }
};

}  // namespace steplab
