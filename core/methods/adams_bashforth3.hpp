#pragma once
#include "core/methods/rk4.hpp"
#include "core/stepper.hpp"

namespace steplab {

// Three-step Adams-Bashforth, order 3, on y' = f(y) = (v, a(x, v)):
//   y_{n+1} = y_n + h (23/12 f_n - 16/12 f_{n-1} + 5/12 f_{n-2})
// Memory: f_{n-1}, f_{n-2}. The first two steps are RK4 steps. One force evaluation a step.
// Its stability region holds a piece of the imaginary axis, |Im h lambda| < ~0.72, so unlike
// AB2 it keeps an undamped oscillator bounded at small steps.
struct AdamsBashforth3 {
  static constexpr MethodInfo info{"adams_bashforth3", 3, Family::AdamsBashforth, false, false, false,
                                   "y += h (23 f_n - 16 f_(n-1) + 5 f_(n-2)) / 12, started by RK4"};
  static constexpr int history = 2;
  // Memory of a run whose state k steps back was past(k): the derivatives there.
  template <Scene S, class Past> static History<S::dim, 2> remember(const S& s, Past&& past) {
    return history_of<S::dim, 2>([&](int k) { return derivative(s, past(k)); });
  }
  template <Scene S> static StepStatus step(const S& s, State<S::dim>& y, double t, double h, History<S::dim, 2>& mem) {
    const State<S::dim> f = derivative(s, y);
    if (mem.count < history) {
      mem.push(f);
      return Rk4::step(s, y, t, h);
    }
    constexpr double c0 = 23.0 / 12, c1 = -16.0 / 12, c2 = 5.0 / 12;
    y.x += h * (c0 * f.x + c1 * mem.past[0].x + c2 * mem.past[1].x);
    y.v += h * (c0 * f.v + c1 * mem.past[0].v + c2 * mem.past[1].v);
    mem.push(f);
    return StepStatus::Ok;
  }
};

}  // namespace steplab
