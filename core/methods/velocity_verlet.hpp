#pragma once
#include "core/compensated.hpp"
#include "core/method.hpp"

namespace steplab {

// Velocity Verlet (kick-drift-kick), second order, symplectic for conservative forces:
//   x_{n+1} = x_n + h v_n + h^2/2 a(x_n, v_n)
//   v_{n+1} = v_n + h/2 (a(x_n, v_n) + a(x_{n+1}, v_{n+1}))
// Without damping a does not depend on v and the closing kick is explicit; this is then
// Boost.Odeint's velocity_verlet step for step. With damping the closing kick is implicit in
// v_{n+1} (trapezoidal in the velocity), solved by solve_implicit at fixed x_{n+1}; the force
// is affine in v for every scene here, so one Newton step solves it. Odeint instead evaluates
// a(x_{n+1}, v_n), which drops the method to first order as soon as there is damping.
struct VelocityVerlet {
  static constexpr MethodInfo info{.name = "velocity_verlet", .order = 2, .family = Family::Splitting,
                                   .symplectic = true,
                                   .summary = "v += h/2 a(x, v); x += h v; v += h/2 a(x, v) at the new x (implicit in v where the force is damped)"};
  static constexpr int solve_stages = 1;  // the implicit kick (core/method.hpp)
  static constexpr bool compensated = true;  // its sums carry their round-off (core/compensated.hpp)
  // Without damping the increments are summed compensated: dx = h v + h^2/2 a0, dv = h/2 (a0 + a1)
  // (core/compensated.hpp). With damping (no invariant to keep) the kick is solved for v itself;
  // the velocity's carry, zero from the run's start, stays so in those lanes.
  template <class S, class T, class Carry = NoCarry>
  static Status<T> step(const S& s, State<S::dim, T>& y, Time<T> t, Time<T> h, Carry&& carry = Carry{}) {
    using V = Temp<S::dim, T>;  // a step's temporaries (core/scratch.hpp)
    const V a0 = acceleration(s, t, y.x, y.v);
    const V v0 = y.v;
    add_compensated(y.x, V(h * y.v + (0.5 * h * h) * a0), carry.x);
    const auto implicit = s.velocity_dependent();  // a Mask for a pack of springs, some damped
    // the damped lanes' closing kick, implicit in v: M (v - v0 - h/2 a0) = h/2 F(x1, v)
    const auto implicit_kick = [&] { return solve_implicit(s, t + h, y.x, 0.0, V(v0 + (0.5 * h) * a0), 0.5 * h, y.v); };
    if (all(implicit)) return implicit_kick();
    const V dv = (0.5 * h) * (a0 + acceleration(s, t + h, y.x, v0));  // the undamped lanes' kicks
    if (!any(implicit)) {
      add_compensated(y.v, dv, carry.v);
      return status_of(MaskOf<T>(false));
    }
    // a pack, some lanes damped: each lane its kick, the damped ones' carry left at zero
    V explicit_v = v0;
    if constexpr (kCarries<Carry>) {
      Vec<S::dim, T> lost = carry.v;
      add_compensated(explicit_v, dv, lost);
      carry.v = select(implicit, carry.v, lost);
    } else {
      explicit_v += dv;
    }
    const Status<T> st = implicit_kick();
    y.v = select(implicit, y.v, Vec<S::dim, T>(explicit_v));
    return status_of(implicit && failed(st));
  }
};

}  // namespace steplab

STEPLAB_METHOD(steplab::VelocityVerlet);
