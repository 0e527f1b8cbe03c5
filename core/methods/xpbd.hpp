#pragma once
#include <algorithm>

#include "core/method.hpp"
#include "core/springs.hpp"

namespace steplab {

// XPBD, extended position-based dynamics (Macklin, Mueller, Chentanez, "XPBD: Position-Based
// Simulation of Compliant Constrained Dynamics", MIG 2016), on a mass-spring scene's springs
// (core/springs.hpp): each spring a distance constraint C with compliance alpha = 1/k, its
// dashpot c the constraint's damping. One step of h (a substep of a frame):
//   predict       x~ = x_n + h v_n + h^2 M^-1 f_ext(v_n)          (gravity, absolute damping)
//   lambda_q = 0, then `sweeps` Gauss-Seidel sweeps over the springs (and the ground), each
//   spring q, with alpha~ = alpha / h^2 and gamma = alpha~ (h^2 c) / h (the paper's (26)):
//     dlambda = (-C - alpha~ lambda_q - gamma grad C . (x - x_n)) / ((1 + gamma) grad C M^-1 grad C^T + alpha~)
//     x += M^-1 grad C^T dlambda,   lambda_q += dlambda
//   velocity      v_(n+1) = (x - x_n) / h
// Numerator and denominator are multiplied here by k h^2, which leaves dlambda as it is and
// admits k = 0 (a dashpot alone):
//     dlambda = (-k h^2 C - lambda_q - c h grad C . (x - x_n)) / ((k h^2 + c h) grad C M^-1 grad C^T + 1).
// The ground is a one-sided constraint C = y - level on each mass's vertical coordinate, with the
// ground's compliance 1 / k_g and damping c_g, acting while the mass is below it or lambda > 0,
// lambda kept >= 0 (it only pushes).
// Carried to convergence, lambda_q = -h^2 (k C + c dC/dt) at the end of the step: the springs'
// force at x_(n+1), v_(n+1), and the step is implicit Euler on the springs, with f_ext taken at
// v_n (tests/core/xpbd_test.cpp), where the springs do not turn within the step (a line, the
// rope). Where they turn, each correction moved the masses along its spring's gradient at the
// iterate it was made at, not at x_(n+1) (the residual the paper's section 3.3 drops), so the
// converged step differs from implicit Euler's by O(h^3), O(h^2) over a run (the cloth: 4.2
// times less a halving of h, tests/core/cloth_test.cpp). At a fixed number of sweeps it is not
// implicit Euler at all: the sweeps stop short of the implicit solve by a factor that depends on h, k and the spring count, which is what the
// substeps-against-sweeps comparison measures. On one spring (the linear test equation, the
// sheet's spring) one sweep solves its one linear constraint exactly: implicit Euler, A-stable.
struct Xpbd {
  static constexpr MethodInfo info{.name = "xpbd", .order = 1, .family = Family::PositionBased,
                                   .a_stable = true, .on_springs = true,
                                   .summary = "x~ = x + h v + h^2 M^-1 f_ext; sweeps of Gauss-Seidel over the springs as "
                                              "constraints of compliance 1/k; v = (x - x_n) / h"};

  template <MassSpring S> static StepStatus step(const S& s, State<S::dim>& y, double, double h, const MethodSettings& set) {
    constexpr int d = coords_per_mass<S>();
    decltype(auto) w = s.inverse_mass();  // per coordinate
    const Temp<S::dim> start = y.x;
    for (Eigen::Index a = 0; a < y.x.size(); ++a) y.x[a] += h * y.v[a] + h * h * w[a] * s.external(static_cast<int>(a), y.v[a]);
    const int links = s.links(), masses = static_cast<int>(y.x.size()) / d, grounds = HasGround<S> ? masses : 0;
    // lambda of the springs, then of the ground; then each spring's 1 / ((k h^2 + c h) w + 1), the
    // same in every sweep: computed in one pass, so that no division waits in the sweeps' chain
    // (each projection reads the positions the one before it moved).
    auto numbers = spring_numbers<S::dim, 3>(2 * links + grounds);
    numbers.setZero();
    double* lambda = numbers.data();
    double* inverse = numbers.data() + links + grounds;
    for (int q = 0; q < links; ++q) {
      const Link l = s.link(q);
      inverse[q] = 1 / ((l.k * h * h + l.c * h) * (at_end<d>(w, l.i, 0) + at_end<d>(w, l.j, 0)) + 1);
    }
    for (int sweep = 0; sweep < set.sweeps; ++sweep) {
      for (int q = 0; q < links; ++q) project<d>(s.link(q), y.x, start, w, h, inverse[q], lambda[q]);
      if constexpr (HasGround<S>)
        for (int i = 0; i < masses; ++i) project_ground(s.ground, d * i + d - 1, y.x, start, w, h, lambda[links + i]);
    }
    y.v = (y.x - start) / h;
    return StepStatus::Ok;
  }

 private:
  // dlambda of a constraint of stiffness k and damping c at C, having moved `moved` along grad C
  // this step, with grad C M^-1 grad C^T = `inverse_mass` (the formula above, times k h^2).
  static double correction(double k, double c, double h, double constraint, double lambda, double moved, double inverse_mass) {
    const double kh2 = k * h * h, ch = c * h;
    return (-kh2 * constraint - lambda - ch * moved) / ((kh2 + ch) * inverse_mass + 1);
  }
  // One spring's correction (see above); a fixed end (-1) has no position to move.
  // `inverse`: 1 / ((k h^2 + c h) (w_i + w_j) + 1), the correction's denominator.
  template <int d, class X, class St, class W>
  static void project(const Link& l, X& x, const St& start, const W& w, double h, double inverse, double& lambda) {
    const LinkAt at = link_at<d>(l, x);
    if (!at.has_direction) return;
    const double wi = at_end<d>(w, l.i, 0), wj = at_end<d>(w, l.j, 0);
    const double dl = (-l.k * h * h * at.c - lambda - l.c * h * along<d>(l, at, x, start)) * inverse;
    lambda += dl;
    for (int axis = 0; axis < d; ++axis) {
      if (l.i >= 0) x[d * l.i + axis] += wi * at.g[axis] * dl;
      if (l.j >= 0) x[d * l.j + axis] -= wj * at.g[axis] * dl;
    }
  }
  template <class X, class St, class W>
  static void project_ground(const Ground& ground, int a, X& x, const St& start, const W& w, double h, double& lambda) {
    const double c = x[a] - Ground::level;
    if (c >= 0 && lambda <= 0) return;
    const double dl = std::max(correction(ground.k, ground.c, h, c, lambda, x[a] - start[a], double(w[a])), -lambda);  // lambda >= 0
    lambda += dl;
    x[a] += double(w[a]) * dl;
  }
};

}  // namespace steplab

STEPLAB_METHOD(steplab::Xpbd);
