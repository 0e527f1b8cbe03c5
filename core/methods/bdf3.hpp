#pragma once
#include "core/methods/gauss_legendre4.hpp"
#include "core/stepper.hpp"

namespace steplab {

// Third-order backward differentiation formula:
//   y_{n+1} - 18/11 y_n + 9/11 y_{n-1} - 2/11 y_{n-2} = 6/11 h f(y_{n+1})
// solved as BDF2 is (core/methods/bdf2.hpp) with w = 18/11 y_n - 9/11 y_{n-1} + 2/11 y_{n-2},
// beta = 6/11. Memory: y_{n-1}, y_{n-2}; the first two steps are
// Gauss-Legendre steps (order 4 and A-stable, as for BDF2). Not A-stable
// (A(alpha)-stable with alpha ~ 86 degrees): its unstable set pokes into the left half-plane
// next to the imaginary axis, so an undamped oscillator grows at small steps and is damped
// again at large ones.
struct Bdf3 {
  static constexpr MethodInfo info{"bdf3", 3, Family::Bdf, false, true, false,
                                   "BDF of order 3 (three past states), by Newton, started by Gauss-Legendre"};
  static constexpr int history = 2;
  // Memory of a run whose state k steps back was past(k): those states.
  template <Scene S, class Past> static History<S::dim, 2> remember(const S&, Past&& past) {
    return history_of<S::dim, 2>(past);
  }
  template <Scene S> static StepStatus step(const S& s, State<S::dim>& y, double t, double h, History<S::dim, 2>& mem) {
    const State<S::dim> now = y;
    if (mem.count < history) {
      mem.push(now);
      return GaussLegendre4::step(s, y, t, h);
    }
    constexpr double a0 = 18.0 / 11, a1 = -9.0 / 11, a2 = 2.0 / 11, beta = 6.0 / 11;
    const Vec<S::dim> wx = a0 * y.x + a1 * mem.past[0].x + a2 * mem.past[1].x;
    const Vec<S::dim> wv = a0 * y.v + a1 * mem.past[0].v + a2 * mem.past[1].v;
    const StepStatus st = solve_implicit(s, wx, beta * h, wv, beta * h, y.v);
    y.x = wx + (beta * h) * y.v;
    mem.push(now);
    return st;
  }
};

}  // namespace steplab
