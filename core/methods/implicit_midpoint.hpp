#pragma once
#include "core/compensated.hpp"
#include "core/method.hpp"

namespace steplab {

// Implicit midpoint rule, second order, symplectic and A-stable (|R(z)| = 1 on the imaginary axis):
//   x_{n+1} = x_n + h v_m,   v_{n+1} = v_n + h a(x_m, v_m),   x_m = (x_n + x_{n+1})/2, v_m = (v_n + v_{n+1})/2
// The midpoint (x_m, v_m) is exactly one backward Euler step of h/2 from (x_n, v_n):
//   M (v_m - v_n) = h/2 F(x_n + h/2 v_m, v_m)
// solved by Newton to round-off (core/method.hpp), and the step ends by extrapolating, its
// increments summed compensated (core/compensated.hpp): x += h v_m, v += 2 (v_m - v_n). (The
// increment of v from the stage's force, h a(x_m, v_m), is the same in exact arithmetic, but at a
// stiff step it multiplies the round-off of x_m by h k / m: the step map's entries then carry
// 1e-4 at h^2 k / m = 1e12, where 2 (v_m - v_n) carries an ulp.)
struct ImplicitMidpoint {
  static constexpr MethodInfo info{.name = "implicit_midpoint", .order = 2, .family = Family::ImplicitRungeKutta,
                                   .symplectic = true, .implicit = true, .a_stable = true,
                                   .summary = "y_(n+1) = y_n + h f((y_n + y_(n+1)) / 2): backward Euler for h/2 to the midpoint, then extrapolated to h"};
  static constexpr int solve_stages = 1;  // core/method.hpp
  static constexpr bool compensated = true;  // core/compensated.hpp
  static constexpr ButcherTableau<1> tableau{{{{0.5}}}, {1.0}};  // c = 1/2
  template <class S, class T, class Carry = NoCarry>
  static Status<T> step(const S& s, State<S::dim, T>& y, Time<T> t, Time<T> h, Carry&& carry = Carry{}) {
    using V = Temp<S::dim, T>;
    V vm = temp_like<S::dim, T>(y.v);
    const Status<T> status = solve_implicit(s, t + 0.5 * h, y.x, 0.5 * h, y.v, 0.5 * h, vm);
    const V dv = 2 * (vm - y.v);
    add_compensated(y.x, V(h * vm), carry.x);
    add_compensated(y.v, dv, carry.v);
    return status;
  }
};

}  // namespace steplab

STEPLAB_METHOD(steplab::ImplicitMidpoint);
