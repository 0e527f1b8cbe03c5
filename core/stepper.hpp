// A method that remembers: linear multistep methods need the last steps. Such a method declares
//   static constexpr int history = K;                    how many past entries it keeps
//   template <Scene S> static StepStatus step(const S&, State<S::dim>& y, double t, double h,
//                                             History<S::dim, K>& memory);
//   template <Scene S, class Past> static History<S::dim, K> remember(const S&, Past&& past);
// remember: the memory of a run whose state k steps back (k = 1 .. K) was past(k); the stability
// analysis builds it at rest and perturbs it, the local-error table from the exact solution.
// A one-step method declares none of this and is called exactly as before.
//
// Stepper<M, S> is what a run loop holds: it carries the memory of a multistep method and is an
// empty wrapper around M::step for a one-step method, so one-step runs cost what they did.
#pragma once

#include <algorithm>
#include <array>

#include "core/method.hpp"

namespace steplab {

// The last K entries (states or derivatives, as the method chooses), past[0] the most recent.
template <int D, int K> struct History {
  std::array<State<D>, K> past;
  int count = 0;  // how many are filled; a method starts itself (one-step steps) until count == K
  // Zeroed (Eigen leaves a vector uninitialised): never read before count says so, but the
  // compiler cannot see that through a method's start-up branch.
  History() { past.fill(zero_state<D>()); }
  void push(const State<D>& s) {
    for (int i = K - 1; i > 0; --i) past[i] = past[i - 1];
    past[0] = s;
    count = std::min(count + 1, K);
  }
};

// A History from entry(k), k = 1 .. K steps back.
template <int D, int K, class Entry> History<D, K> history_of(Entry&& entry) {
  History<D, K> h;
  for (int k = K; k >= 1; --k) h.push(entry(k));
  return h;
}

template <class M> concept Multistep = requires { M::history; };

template <class M, Scene S> struct Stepper {
  StepStatus step(const S& s, State<S::dim>& y, double t, double h) { return M::step(s, y, t, h); }
};

template <Multistep M, Scene S> struct Stepper<M, S> {
  History<S::dim, M::history> memory{};
  StepStatus step(const S& s, State<S::dim>& y, double t, double h) { return M::step(s, y, t, h, memory); }
};

// The derivative of the first-order system, f(y) = (v, a(x, v)), stored as a State.
template <Scene S> State<S::dim> derivative(const S& s, const State<S::dim>& y) {
  return {y.v, acceleration(s, y.x, y.v)};
}

}  // namespace steplab
