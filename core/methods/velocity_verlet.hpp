#pragma once
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
  template <class S, class T> static Status<T> step(const S& s, State<S::dim, T>& y, Time<T> t, Time<T> h) {
    using V = Temp<S::dim, T>;  // a step's temporaries (core/scratch.hpp)
    const V a0 = acceleration(s, t, y.x, y.v);
    y.x += h * y.v + (0.5 * h * h) * a0;
    const V kicked = y.v + (0.5 * h) * a0;
    const auto implicit = s.velocity_dependent();  // a Mask for a pack of springs, some damped
    if (!any(implicit)) {
      y.v = kicked + (0.5 * h) * acceleration(s, t + h, y.x, y.v);
      return status_of(MaskOf<T>(false));
    }
    if (all(implicit)) return solve_implicit(s, t + h, y.x, 0.0, kicked, 0.5 * h, y.v);
    const V explicit_kick = kicked + (0.5 * h) * acceleration(s, t + h, y.x, y.v);  // a pack: each lane its kick
    const Status<T> st = solve_implicit(s, t + h, y.x, 0.0, kicked, 0.5 * h, y.v);
    y.v = select(implicit, y.v, Vec<S::dim, T>(explicit_kick));
    return status_of(implicit && failed(st));
  }
};

}  // namespace steplab

STEPLAB_METHOD(steplab::VelocityVerlet);
