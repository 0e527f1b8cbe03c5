#pragma once
#include "core/methods/gauss_legendre4.hpp"
#include "core/stepper.hpp"

namespace steplab {

// Second-order backward differentiation formula:
//   y_{n+1} - 4/3 y_n + 1/3 y_{n-1} = 2/3 h f(y_{n+1})
// With w = 4/3 y_n - 1/3 y_{n-1} and beta = 2/3, in (x, v):  x_{n+1} = w_x + beta h v_{n+1},
//   M (v_{n+1} - w_v) = beta h F(w_x + beta h v_{n+1}, v_{n+1})
// which is solve_implicit with x0 = w_x, cx = c = beta h. Memory: y_{n-1}. The first step is a
// Gauss-Legendre step: order 4, so the start costs no order, and A-stable, so a start at a step
// far beyond any explicit method's limit does not blow up what BDF2 would damp. A-stable (and L-stable): the highest order an A-stable linear multistep method can
// have (Dahlquist's second barrier).
struct Bdf2 {
  static constexpr MethodInfo info{"bdf2", 2, Family::Bdf, false, true, false,
                                   "y' = 3/2 y_(n+1) - 2 y_n + 1/2 y_(n-1) = h f(y_(n+1)), by Newton, started by Gauss-Legendre"};
  static constexpr int history = 1;
  // Memory of a run whose state k steps back was past(k): those states.
  template <Scene S, class Past> static History<S::dim, 1> remember(const S&, Past&& past) {
    return history_of<S::dim, 1>(past);
  }
  template <Scene S> static StepStatus step(const S& s, State<S::dim>& y, double t, double h, History<S::dim, 1>& mem) {
    const State<S::dim> now = y;
    if (mem.count < history) {
      mem.push(now);
      return GaussLegendre4::step(s, y, t, h);
    }
    constexpr double beta = 2.0 / 3;
    const Vec<S::dim> wx = (4.0 / 3) * y.x - (1.0 / 3) * mem.past[0].x, wv = (4.0 / 3) * y.v - (1.0 / 3) * mem.past[0].v;
    const StepStatus st = solve_implicit(s, wx, beta * h, wv, beta * h, y.v);
    y.x = wx + (beta * h) * y.v;
    mem.push(now);
    return st;
  }
};

}  // namespace steplab
