// A method that remembers: linear multistep methods need the last steps. Such a method declares
//   static constexpr int history = K;                    how many past entries it keeps
//   template <Scene S> static StepStatus step(const S&, State<S::dim>& y, double t, double h,
//                                             History<S::dim, K>& memory);
//   template <Scene S, class Past> static History<S::dim, K> remember(const S&, Past&& past);
// remember: the memory of a run whose state k steps back (k = 1 .. K) was past(k); the stability
// analysis builds it at rest and perturbs it, the local-error table from the exact solution.
// A one-step method declares none of this and is called exactly as before.
//
// Stepper<M, S> is what a run loop holds: it carries the memory of a multistep method and, on a
// scene of run-time size, the run's Newton workspace (core/sparse.hpp: the kept iteration
// matrices), installed while it steps. On a fixed size it is an empty wrapper around M::step for
// a one-step method, so one-step runs cost what they did.
#pragma once

#include <algorithm>
#include <array>
#include <type_traits>
#include <utility>

#include "core/compensated.hpp"
#include "core/method.hpp"

namespace steplab {

// The last K entries (states or derivatives, as the method chooses), past[0] the most recent;
// T a pack for runs stepped together (core/batch.hpp), each lane its own count.
template <int D, int K, class T = double> struct History {
  std::array<State<D, T>, K> past;
  T count = 0;  // how many are filled; a method starts itself (one-step steps) until count == K
  // Zeroed (Eigen leaves a vector uninitialised): never read before count says so, but the
  // compiler cannot see that through a method's start-up branch.
  History() { past.fill(zero_state<D, T>()); }
  template <class St> void push(const St& s) {
    using std::min;
    if constexpr (D == Eigen::Dynamic) {
      if (past[0].x.size() != s.x.size())  // the first push sizes every entry (not read before count says)
        for (State<D, T>& p : past) p.x.resize(s.x.size()), p.v.resize(s.v.size());
      for (int i = K - 1; i > 0; --i) std::swap(past[i], past[i - 1]);  // the vectors, not their values: no copy, no allocation
      past[0].x = s.x, past[0].v = s.v;                                   // into the oldest entry's storage
    } else {
      for (int i = K - 1; i > 0; --i) past[i] = past[i - 1];
      past[0] = State<D, T>{s.x, s.v};
    }
    count = min(count + 1.0, T(double(K)));
  }
};

// A History from entry(k), k = 1 .. K steps back.
template <int D, int K, class Entry> History<D, K> history_of(Entry&& entry) {
  History<D, K> h;
  for (int k = K; k >= 1; --k) h.push(entry(k));
  return h;
}

template <class M> concept Multistep = requires { M::history; };

// What a run keeps for Newton's method: nothing on a fixed size (full Newton, dense); the
// workspace on a run-time size, installed for the step (use()).
template <int D> struct RunWorkspace {
  struct Use {};
  Use use() { return {}; }
};
// On a run-time size also the run's scratch pool (core/scratch.hpp: a step's temporaries) and the
// state a step is taken on (core/simulate.hpp, take_step): a run allocates in its first step only.
template <> struct RunWorkspace<Eigen::Dynamic> {
  NewtonWorkspace newton;
  ScratchPool scratch;
  State<Eigen::Dynamic> next;
  struct Use {
    UseWorkspace newton;
    UseScratch scratch;
  };
  Use use() { return {UseWorkspace(newton), UseScratch(scratch)}; }
};

// S: a scene, or the scene of a pack of runs with T its pack (step is then there only where M's
// step is written over the scalar: core/batch.hpp's PackedStep asks).
// forget(): back to a run's start (a multistep method's memory emptied) on the same scene and
// step, the workspace kept (what holds for the scene and step still holds).
// A method with settings (TakesSettings, core/method.hpp) has the run's here, set by the run loop
// from its RunSpec (core/simulate.hpp), the defaults elsewhere; any other method nothing.
struct NoSettings {};
template <class M> using SettingsOf = std::conditional_t<TakesSettings<M>, MethodSettings, NoSettings>;
// A compensated method's carry (core/compensated.hpp): what its sums lost so far, for x and v.
template <class M, int D, class T> using CarryOf = std::conditional_t<Compensated<M>, State<D, T>, NoCarry>;

template <class M, class S, class T = double> struct Stepper {
  [[no_unique_address]] SettingsOf<M> settings{};
  [[no_unique_address]] CarryOf<M, S::dim, T> carry = no_carry();
  [[no_unique_address]] RunWorkspace<S::dim> work;
  auto step(const S& s, State<S::dim, T>& y, Time<T> t, Time<T> h)
    requires requires { M::step(s, y, t, h); } || requires { M::step(s, y, t, h, settings); }
  {
    [[maybe_unused]] const auto in_use = work.use();
    if constexpr (TakesSettings<M>) return M::step(s, y, t, h, settings);
    else if constexpr (Compensated<M>) return M::step(s, y, t, h, carry);
    else return M::step(s, y, t, h);
  }
  // Back to a run's start: the carry zero (its vectors kept on a run-time size).
  void forget() {
    if constexpr (Compensated<M>) carry.x.setZero(), carry.v.setZero();
  }

 private:
  // Zero on a fixed size; empty on a run-time size, sized at the first step (add_compensated).
  static CarryOf<M, S::dim, T> no_carry() {
    if constexpr (!Compensated<M>) return {};
    else if constexpr (S::dim == Eigen::Dynamic) return State<S::dim, T>{};
    else return zero_state<S::dim, T>();
  }
};

template <Multistep M, class S, class T> struct Stepper<M, S, T> {
  History<S::dim, M::history, T> memory{};
  [[no_unique_address]] RunWorkspace<S::dim> work;
  auto step(const S& s, State<S::dim, T>& y, Time<T> t, Time<T> h)
    requires requires { M::step(s, y, t, h, memory); }
  {
    [[maybe_unused]] const auto in_use = work.use();
    return M::step(s, y, t, h, memory);
  }
  void forget() {
    if constexpr (S::dim == Eigen::Dynamic) memory.count = 0;  // its vectors kept: a restart allocates nothing
    else memory = {};
  }
};

// The derivative of the first-order system at time t, f(t, y) = (v, a(t, x, v)), stored as a State.
// Its vectors are a step's temporaries (core/scratch.hpp).
template <class S, class T> TempState<S::dim, T> derivative(const S& s, Time<T> t, const State<S::dim, T>& y) {
  return {Temp<S::dim, T>(y.v), acceleration(s, t, y.x, y.v)};
}

}  // namespace steplab
