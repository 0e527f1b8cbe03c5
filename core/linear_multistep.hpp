// Linear multistep methods on y' = f(y) = (v, a(x, v)), from their coefficients. Each keeps a
// memory of K past entries (core/stepper.hpp) and starts itself with one-step steps of order 4
// until the memory is full, so the start costs no order.
//
//   Adams-Bashforth, explicit, memory f_{n-1} .. f_{n-K}, started by RK4:
//     y_{n+1} = y_n + h (b_0 f_n + b_1 f_{n-1} + ... + b_K f_{n-K})
//   BDF, implicit, memory y_{n-1} .. y_{n-K}, started by Gauss-Legendre (A-stable, so a start at
//   a step far beyond any explicit method's limit does not blow up what the BDF would damp):
//     y_{n+1} = w + beta h f(y_{n+1}),   w = a_0 y_n + a_1 y_{n-1} + ... + a_K y_{n-K}
//   in (x, v): x_{n+1} = w_x + beta h v_{n+1},  M (v_{n+1} - w_v) = beta h F(w_x + beta h v_{n+1}, v_{n+1}),
//   which is solve_implicit (core/method.hpp) with x0 = w_x, cx = c = beta h.
#pragma once

#include <array>
#include <cstddef>

#include "core/methods/gauss_legendre4.hpp"
#include "core/methods/rk4.hpp"
#include "core/stepper.hpp"

namespace steplab {

// Sum_j c[j] e_j over e_0 = `now` and the memory's entries e_1 .. e_K.
// Held in a step's temporaries (core/scratch.hpp); `now` a State or such temporaries.
template <auto C, int D, int K, class T, class Now> TempState<D, T> combination(const Now& now, const History<D, K, T>& mem) {
  static_assert(C.size() == K + 1);
  TempState<D, T> out{Temp<D, T>(C[0] * now.x), Temp<D, T>(C[0] * now.v)};
  for (int j = 1; j <= K; ++j) {
    out.x += C[j] * mem.past[j - 1].x;
    out.v += C[j] * mem.past[j - 1].v;
  }
  return out;
}

// B: b_0 .. b_K.
template <auto B> struct AdamsBashforthMethod {
  using Starter = Rk4;  // the one-step method of its first steps
  static constexpr int history = static_cast<int>(B.size()) - 1;
  // Memory of a run whose state k steps back, at t0 - k h, was past(k): the derivatives there
  // (t0 and h matter to a driven scene only).
  template <Scene S, class Past>
  static History<S::dim, history> remember(const S& s, Past&& past, double t0 = 0, double h = 0) {
    return history_of<S::dim, history>([&](int k) { return derivative(s, t0 - k * h, past(k)); });
  }
  // Also on packs (core/batch.hpp), where lanes start at different steps: RK4 where a lane is
  // still starting, the Adams-Bashforth sum where it is not, each only where some lane needs it.
  template <class S, class T>
  static StepStatus step(const S& s, State<S::dim, T>& y, Time<T> t, Time<T> h, History<S::dim, history, T>& mem) {
    const TempState<S::dim, T> f = derivative(s, t, y);
    const auto starting = mem.count < double(history);
    if (all(starting)) {
      mem.push(f);
      return Starter::step(s, y, t, h);
    }
    const TempState<S::dim, T> sum = combination<B>(f, mem);
    if (any(starting)) {  // some lanes of a pack (one run is all or none)
      State<S::dim, T> started = y;
      Starter::step(s, started, t, h);
      y.x = select(starting, started.x, Vec<S::dim, T>(y.x + h * sum.x));
      y.v = select(starting, started.v, Vec<S::dim, T>(y.v + h * sum.v));
    } else {
      y.x += h * sum.x;
      y.v += h * sum.v;
    }
    mem.push(f);
    return StepStatus::Ok;
  }
};

// A: a_0 .. a_K; Beta: beta.
template <auto A, double Beta> struct BdfMethod {
  using Starter = GaussLegendre4;  // the one-step method of its first steps
  static constexpr int history = static_cast<int>(A.size()) - 1;
  static constexpr int solve_stages = Starter::solve_stages;  // its start (core/method.hpp)
  // Memory of a run whose state k steps back was past(k): those states.
  template <Scene S, class Past> static History<S::dim, history> remember(const S&, Past&& past, double = 0, double = 0) {
    return history_of<S::dim, history>(past);
  }
  // Also on packs: Gauss-Legendre where a lane is still starting, the BDF step where it is not.
  template <class S, class T>
  static Status<T> step(const S& s, State<S::dim, T>& y, Time<T> t, Time<T> h, History<S::dim, history, T>& mem) {
    const TempState<S::dim, T> now{Temp<S::dim, T>(y.x), Temp<S::dim, T>(y.v)};
    const auto starting = mem.count < double(history);
    if (all(starting)) {
      mem.push(now);
      return Starter::step(s, y, t, h);
    }
    const TempState<S::dim, T> w = combination<A>(now, mem);
    mem.push(now);
    if (!any(starting)) {
      const Status<T> st = solve_implicit(s, t + h, w.x, Beta * h, w.v, Beta * h, y.v);
      y.x = w.x + (Beta * h) * y.v;
      return st;
    }
    State<S::dim, T> started = y;  // some lanes of a pack (one run is all or none)
    const Status<T> start_st = Starter::step(s, started, t, h);
    const Status<T> st = solve_implicit(s, t + h, w.x, Beta * h, w.v, Beta * h, y.v);
    y.x = select(starting, started.x, Vec<S::dim, T>(w.x + (Beta * h) * y.v));
    y.v = select(starting, started.v, y.v);
    return status_of((starting && failed(start_st)) || (!starting && failed(st)));
  }
};

}  // namespace steplab
