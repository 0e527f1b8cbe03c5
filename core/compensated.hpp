// Compensated summation of a step's increments, for the methods whose invariants round-off would
// otherwise wear away (the symplectic and symmetric ones).
//
// A step adds a small increment d to a large state y: y_{n+1} = y_n + d_n. Each addition rounds
// to the last bit of y, and those roundings, biased or not, add up over 10^7 steps to what the
// method itself keeps exactly (a quadratic invariant, the energy's bounded error). Kahan's
// compensated summation carries what each addition lost, c, into the next (Higham, Accuracy and
// Stability of Numerical Algorithms, 4.3; Hairer, Lubich and Wanner, Geometric Numerical
// Integration, VIII.5):
//     e = d + c,   s = y + e,   c = e - (s - y),   y = s
// so that y + c is the exact sum to about the working precision of the increments, not of y.
// The carry belongs to the run: a method that declares `static constexpr bool compensated = true`
// takes it as the last argument of its step, step(s, y, t, h, carry) (core/stepper.hpp holds it,
// zero at a run's start); called without one (NoCarry below) it sums plainly.
#pragma once

#include <type_traits>

#include <Eigen/Core>

#include "core/state.hpp"

namespace steplab {

template <class M> concept Compensated = requires { requires M::compensated; };

// No carry: a compensated method's step taken alone (called as M::step(s, y, t, h): a test, a
// BDF's start), or a method that is not compensated. Its sums are then plain, y += d: from a zero
// carry a single step is that anyway.
struct NoCarry {
  struct Part {};
  [[no_unique_address]] Part x, v;
};
template <class Y, class Dv> [[gnu::always_inline]] inline void add_compensated(Y& y, const Dv& d, NoCarry::Part) { y += d; }
template <class Carry> inline constexpr bool kCarries = !std::is_same_v<std::remove_cvref_t<Carry>, NoCarry>;

// y += d, compensated by c (the run's carry for y; sized like y, zero at a run's start, sized and
// zeroed here on a run-time size's first step). d: a vector, or an expression of vectors whose
// coefficients can be read one by one. Coefficient by coefficient, as written above: the same
// operations in the same order for one run and for each lane of a pack.
template <class Y, class Dv, class C> [[gnu::always_inline]] inline void add_compensated(Y& y, const Dv& d, C& c) {
  if constexpr (std::is_same_v<C, Eigen::VectorXd>)
    if (c.size() != y.size()) c.setZero(y.size());  // a run's first step (allocates once)
  for (Eigen::Index i = 0; i < y.size(); ++i) {
    const auto e = d[i] + c[i];
    const auto s = y[i] + e;
    c[i] = e - (s - y[i]);
    y[i] = s;
  }
}

}  // namespace steplab
