#pragma once
#include <cmath>

#include "core/method.hpp"
#include "core/springs.hpp"

namespace steplab {

// Baraff and Witkin's large steps ("Large steps in cloth simulation", SIGGRAPH 1998, section 4):
// implicit Euler linearised about the step's start, one Newton step, on a mass-spring scene's
// springs (core/springs.hpp). With f, df/dx, df/dv at (x_n, v_n), their equation (17) times M:
//   (M - h df/dv - h^2 df/dx) dv = h (f + h df/dx v_n),   v_(n+1) = v_n + dv,   x_(n+1) = x_n + h v_(n+1)
// solved by conjugate gradients preconditioned by the matrix's diagonal, matrix-free: the product
// with A = M - h df/dv - h^2 df/dx is summed spring by spring, never assembled. Per spring, with
// n = grad_i C (core/springs.hpp), u_r = u_i - u_j, tension t = k C + c dC/dt and length l:
//   df_i/dx u = -k n (n . u_r) - (t / l) (u_r - n (n . u_r))     (the second term in two or three coordinates)
//   df_i/dv u = -c n (n . u_r),   df_j = -df_i
// The dashpot's dependence on x (the turning of n in c dC/dt) is left out, as Baraff and Witkin do,
// which keeps A symmetric; the external forces and the ground add their diagonal derivatives.
// On a linear scene (the chain, the rope) one Newton step is the implicit Euler step: with CG
// run to convergence the two agree (tests/core/baraff_witkin_test.cpp). CG stops after
// cg_iterations or once |r| <= cg_tolerance |b| (MethodSettings); a capped CG is the method a
// simulator ships, and the frame-budget study measures what the cap costs. A Counted scene is
// told the CG iterations as the step's linear solves (count_iteration): each is one product with A.
// Eigen's ConjugateGradient takes a matrix-free operator, but its solve allocates its four
// work vectors on every call; this loop takes them from the run's scratch pool instead.
struct BaraffWitkin {
  static constexpr MethodInfo info{.name = "baraff_witkin", .order = 1, .family = Family::ImplicitRungeKutta,
                                   .a_stable = true, .on_springs = true,
                                   .summary = "implicit Euler linearised: one Newton step (M - h df/dv - h^2 df/dx) dv = h (f + h "
                                              "df/dx v), by preconditioned CG, matrix-free"};

  template <MassSpring S> static StepStatus step(const S& s, State<S::dim>& y, double t, double h, const MethodSettings& set) {
    constexpr int d = coords_per_mass<S>();
    decltype(auto) w = s.inverse_mass();
    const Eigen::Index n = y.x.size();
    const int links = s.links();
    // Each spring's direction n and t / l at (x_n, v_n), `per` numbers a spring (n's first two
    // entries and t / l where d < 3); the diagonal derivatives of the rest.
    constexpr int per = d == 3 ? 4 : 3, tl_at = per - 1;
    auto geo = spring_numbers<S::dim, per>(per * links);
    for (int q = 0; q < links; ++q) {
      const Link l = s.link(q);
      const LinkAt at = link_at<d>(l, y.x);
      for (int axis = 0; axis < tl_at; ++axis) geo[per * q + axis] = at.g[axis];
      geo[per * q + tl_at] = 0;
      if (d >= 2 && at.has_direction) geo[per * q + tl_at] = (l.k * at.c + l.c * along<d>(l, at, y.v, Zeros{})) / (at.c + l.rest);
    }
    Temp<S::dim> dfdx = temp_like<S::dim, double>(y.x), dfdv = temp_like<S::dim, double>(y.x), mass = temp_like<S::dim, double>(y.x);
    for (Eigen::Index a = 0; a < n; ++a) {
      const int ai = static_cast<int>(a);
      mass[a] = 1 / w[a];
      dfdv[a] = s.external(ai, 1.0) - s.external(ai, 0.0), dfdx[a] = 0;  // external: affine in v
      if constexpr (HasGround<S>)
        if (a % d == d - 1) dfdx[a] = s.ground.dforce_dy(y.x[a]), dfdv[a] += s.ground.dforce_dv(y.x[a]);
    }
    // out = (ax df/dx + av df/dv) u, the springs and the diagonal parts.
    const auto times_jacobians = [&](const auto& u, auto& out, double ax, double av) {
      for (Eigen::Index a = 0; a < n; ++a) out[a] = (ax * dfdx[a] + av * dfdv[a]) * u[a];
      for (int q = 0; q < links; ++q) {
        const Link l = s.link(q);
        double g[3], ur[3], gu = 0;  // n copied: read through a pointer, it is reloaded after each write to out
        for (int axis = 0; axis < d; ++axis) g[axis] = geo[per * q + axis];
        const double tl = geo[per * q + tl_at];
        for (int axis = 0; axis < d; ++axis) ur[axis] = at_end<d>(u, l.i, axis) - at_end<d>(u, l.j, axis), gu += g[axis] * ur[axis];
        for (int axis = 0; axis < d; ++axis) {
          const double fi = -(ax * l.k + av * l.c) * g[axis] * gu - ax * tl * (ur[axis] - g[axis] * gu);
          if (l.i >= 0) out[d * l.i + axis] += fi;
          if (l.j >= 0) out[d * l.j + axis] -= fi;
        }
      }
    };
    // b = h (f + h df/dx v_n)
    Temp<S::dim> b = temp_like<S::dim, double>(y.x);
    times_jacobians(y.v, b, h * h, 0.0);
    b += h * force_at(s, t, y.x, y.v);
    // A u = M u - (h^2 df/dx + h df/dv) u; its diagonal, the preconditioner.
    const auto times_a = [&](const auto& u, auto& out) {
      times_jacobians(u, out, -h * h, -h);
      for (Eigen::Index a = 0; a < n; ++a) out[a] += mass[a] * u[a];
    };
    Temp<S::dim> diag = temp_like<S::dim, double>(y.x);
    for (Eigen::Index a = 0; a < n; ++a) diag[a] = mass[a] - h * h * dfdx[a] - h * dfdv[a];
    for (int q = 0; q < links; ++q) {
      const Link l = s.link(q);
      for (int axis = 0; axis < d; ++axis) {
        const double g = geo[per * q + axis], add = (h * h * l.k + h * l.c) * g * g + h * h * geo[per * q + tl_at] * (1 - g * g) * (d >= 2);
        if (l.i >= 0) diag[d * l.i + axis] += add;
        if (l.j >= 0) diag[d * l.j + axis] += add;
      }
    }
    // Preconditioned conjugate gradients from dv = 0 (Saad, Iterative Methods, Algorithm 9.1).
    Temp<S::dim> dv = temp_like<S::dim, double>(y.x), r = temp_like<S::dim, double>(y.x), z = temp_like<S::dim, double>(y.x),
                 p = temp_like<S::dim, double>(y.x), ap = temp_like<S::dim, double>(y.x);
    dv.setZero();
    r = b;
    z = r.cwiseQuotient(diag);
    p = z;
    double rz = r.dot(z);
    const double stop = set.cg_tolerance * b.norm();
    int it = 0;
    for (; it < set.cg_iterations && r.norm() > stop; ++it) {
      times_a(p, ap);
      const double pap = p.dot(ap);
      if (!(pap > 0)) break;  // A not positive along p (a spring pressed far below its length): CG stops
      const double alpha = rz / pap;
      dv += alpha * p;
      r -= alpha * ap;
      z = r.cwiseQuotient(diag);
      const double rz_next = r.dot(z);
      p = z + (rz_next / rz) * p;
      rz = rz_next;
    }
    count_iteration(s, SolveCounts{0, it});
    y.v += dv;
    y.x += h * y.v;
    return StepStatus::Ok;
  }
};

}  // namespace steplab

STEPLAB_METHOD(steplab::BaraffWitkin);
