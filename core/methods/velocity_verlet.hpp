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
                                   .summary = "kick h/2, drift h, kick h/2 with the new acceleration"};
  template <Scene S> static StepStatus step(const S& s, State<S::dim>& y, double /*t*/, double h) {
    const Vec<S::dim> a0 = acceleration(s, y.x, y.v);
    y.x += h * y.v + (0.5 * h * h) * a0;
    const Vec<S::dim> kicked = y.v + (0.5 * h) * a0;
    if (!s.velocity_dependent()) {
      y.v = kicked + (0.5 * h) * acceleration(s, y.x, y.v);
      return StepStatus::Ok;
    }
    return solve_implicit(s, y.x, 0.0, kicked, 0.5 * h, y.v);
  }
};

}  // namespace steplab

STEPLAB_METHOD(steplab::VelocityVerlet);
