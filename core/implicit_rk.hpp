// Newton on all stages at once, for an s-stage implicit Runge-Kutta method (Butcher A, b) on
// M x'' = F(x, v). Written on the first-order system y = (x, v), y' = (v, M^-1 F):
//
//   stage velocities V_i (the unknowns, s D of them), stage positions X_i = x0 + h sum_j a_ij V_j,
//   G_i(V) = M (V_i - v0) - h sum_j a_ij F(t0 + c_j h, X_j, V_j) = 0,   c_j = sum_k a_jk,
//   x1 = x0 + h sum_i b_i V_i,   v1 = v0 + h sum_i b_i M^-1 F(X_i, V_i).
//
// The Jacobian of G, block (i, k):  M delta_ik - h a_ik dF/dv(k) - h^2 sum_j a_ij a_jk dF/dx(j).
// Newton from V_i = v0, to round-off by the rule of solve_implicit (core/method.hpp, NewtonSettings:
// a correction at round-off's level, or one that no longer shrinks once |G| is within tolerance);
// full Newton on a fixed size, simplified Newton on a run-time size (below). A force linear in
// (x, v) converges in one Newton step. The force values of the converged stages give v1 directly.
// The increments h sum_i b_i V_i and h sum_i b_i M^-1 F_i are added to (x, v) compensated where
// the method carries its round-off (a symplectic one: core/compensated.hpp), plainly otherwise.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>

#include "core/compensated.hpp"
#include "core/method.hpp"

namespace steplab {

// (x, v) += the step's increments h sum_i b_i V_i and h sum_i b_i M^-1 F_i: compensated with the
// run's carry (core/compensated.hpp), or, without one, stage by stage into (x, v) as before.
template <int Stages, class S, class T, class Carry, class Vs, class Fs>
[[gnu::always_inline]] inline void add_increments(const S& s, State<S::dim, T>& y, Time<T> h, const ButcherTableau<Stages>& t,
                                                  const Vs& V, const Fs& F, Carry& carry) {
  const auto& inv_m = s.inverse_mass();  // the scene's own on a run-time size: no copy
  if constexpr (std::is_same_v<Carry, NoCarry>) {
    for (int i = 0; i < Stages; ++i) {
      y.x += (h * t.b[i]) * V(i);
      y.v += (h * t.b[i]) * F[i].cwiseProduct(inv_m);
    }
  } else {
    Temp<S::dim, T> dx = (h * t.b[0]) * V(0), dv = (h * t.b[0]) * F[0].cwiseProduct(inv_m);
    for (int i = 1; i < Stages; ++i) {
      dx += (h * t.b[i]) * V(i);
      dv += (h * t.b[i]) * F[i].cwiseProduct(inv_m);
    }
    add_compensated(y.x, dx, carry.x);
    add_compensated(y.v, dv, carry.v);
  }
}

// On a fixed size, also for a pack of runs (T a Pack; S its scene): each lane iterates as its
// run alone would and stops where that run stops, as in solve_implicit (and always inlined, as it is).
template <int Stages, class S, class T, class Carry>
[[gnu::always_inline]] inline Status<T> implicit_rk_step_dense(const S& s, State<S::dim, T>& y, Time<T> t0, Time<T> h,
                                                               const ButcherTableau<Stages>& t, Carry& carry) {
  using std::abs;
  constexpr int D = S::dim, N = Stages * D;
  using Big = Eigen::Matrix<T, N, 1>;
  const Vec<D, T> m = s.mass();
  Big V;
  for (int i = 0; i < Stages; ++i) V.template segment<D>(i * D) = y.v;
  std::array<Vec<D, T>, Stages> X, F;
  F.fill(Vec<D, T>::Zero());
  std::array<Jacobians<D, T>, Stages> J;
  T force_terms = 0;
  RoundOff<T> round_off;
  const T mv0_norms = Stages * m.cwiseProduct(y.v).norm(), v0_norms = Stages * y.v.norm();
  NewtonLanes<T> lanes;
  for (int it = 0;; ++it) {
    for (int i = 0; i < Stages; ++i) {
      X[i] = y.x;
      for (int j = 0; j < Stages; ++j) X[i] += (h * t.a[i][j]) * V.template segment<D>(j * D);
      // a lane that has stopped keeps the forces it stopped with, as its run alone would
      F[i] = select(lanes.done, F[i], Vec<D, T>(force_at(s, t0 + t.c(i) * h, X[i], V.template segment<D>(i * D))));
    }
    Big r;
    T f_norm = 0;
    for (int i = 0; i < Stages; ++i) {
      Vec<D, T> g = m.cwiseProduct(V.template segment<D>(i * D) - y.v);
      for (int j = 0; j < Stages; ++j) g -= (h * t.a[i][j]) * F[j];
      r.template segment<D>(i * D) = g;
      f_norm += F[i].norm();
    }
    const T mV_norm = (m.asDiagonal() * V.reshaped(D, Stages)).norm();
    const T scale = mV_norm + mv0_norms + abs(h) * (f_norm + force_terms);
    const MaskOf<T> small = MaskOf<T>(it > 0) && r.norm() <= NewtonSettings::tolerance * scale;
    if (lanes.give_up(it, r)) break;
    for (int i = 0; i < Stages; ++i) J[i] = jacobians_at(s, t0 + t.c(i) * h, X[i], V.template segment<D>(i * D));
    if (it == 0)
      for (int i = 0; i < Stages; ++i) force_terms += J[i].dx.norm() * X[i].norm() + J[i].dv.norm() * V.template segment<D>(i * D).norm();
    if (lanes.solved(all_zero(r))) break;  // already solved (at rest in equilibrium)
    Eigen::Matrix<T, N, N> G;
    for (int i = 0; i < Stages; ++i)
      for (int k = 0; k < Stages; ++k) {
        Mat<D, T> block = -(h * t.a[i][k]) * J[k].dv;
        for (int j = 0; j < Stages; ++j) block -= (h * h * t.a[i][j] * t.a[j][k]) * J[j].dx;
        if (i == k) block.diagonal() += m;
        G.template block<D, D>(i * D, k * D) = block;
      }
    count_newton_update(s);
    const Big dV = lu_solve(G, r);
    const MaskOf<T> stop = round_off.stop(dV.norm(), V.norm() + v0_norms, scale, G.norm(), small);
    V = select(!lanes.done && !stop, Big(V - dV), V);
    if (lanes.solved(stop)) break;  // at round-off: V, and F its forces
  }
  if (all(lanes.failed)) return lanes.status();  // a failed lane's state is dropped
  add_increments(s, y, h, t, [&](int i) { return V.template segment<D>(i * D); }, F, carry);
  return lanes.status();
}

// On a scene of run-time size n: simplified Newton, as RADAU5 (Hairer and Wanner II, IV.8). The
// iteration matrix I (x) M - h A (x) dF/dv - h^2 A^2 (x) dF/dx is made from the Jacobians the run's
// workspace keeps (evaluated at the last stage's iterate, on a run's first step and whenever an
// iteration reduces the residual by less than kRefreshRate), and solved through the eigenvectors
// of A: one real system of size n per real eigenvalue, one complex per complex pair, each
// factorised once for as long as the Jacobians are kept (core/sparse.hpp). The stopping test and
// its scale are the dense path's, the Jacobians' norms in it the kept ones'. Where simplified
// Newton does not converge (the last iteration, or a residual that grows right after a refresh:
// one Jacobian for all stages misses a change between them, as a contact switching within a
// step), the step starts again by full Newton, each stage with its own Jacobians, as on a fixed
// size: the fixed step has no smaller step to retreat to, as RADAU5 would.
template <int Stages, Scene S, class Carry>
StepStatus implicit_rk_step_sparse(const S& s, State<S::dim>& y, double t0, double h, const ButcherTableau<Stages>& t, Carry& carry) {
  static_assert(Stages <= 4, "core/sparse.hpp keeps up to 4 stages");
  NewtonWorkspace& ws = newton_workspace();
  if (ws.transform_of != &t) ws.transform = StageTransform::of({&t.a[0][0], Stages * Stages}, Stages), ws.transform_of = &t;
  IterationMatrices& kept = ws.matrices;
  const Eigen::VectorXd& m = s.mass();
  std::array<Eigen::VectorXd, 4>&X = ws.stage_x, &V = ws.stage_v, &F = ws.stage_f, &r = ws.stage_r, &dV = ws.stage_dv;
  for (int i = 0; i < Stages; ++i) V[i] = y.v;
  double force_terms = 0, r_last = 0;
  RoundOff<double> round_off;
  const double mv0_norms = Stages * m.cwiseProduct(y.v).norm(), v0_norms = Stages * y.v.norm(), m_norm = m.norm();
  const double a_norm = t.a_norm();
  double dx_max = 0, dv_max = 0;  // the largest Jacobians' norms of this step's updates (since a restart)
  bool fresh = false, full = false;  // Jacobians refreshed for the last update; full Newton
  for (int it = 0;; ++it) {
    for (int i = 0; i < Stages; ++i) {
      X[i] = y.x;
      for (int j = 0; j < Stages; ++j) X[i] += (h * t.a[i][j]) * V[j];
      force_into(s, t0 + t.c(i) * h, X[i], V[i], F[i]);
    }
    double f_norm = 0, r_sq = 0, mv_sq = 0;
    for (int i = 0; i < Stages; ++i) {
      r[i] = m.cwiseProduct(V[i] - y.v);
      for (int j = 0; j < Stages; ++j) r[i] -= (h * t.a[i][j]) * F[j];
      f_norm += F[i].norm();
      r_sq += r[i].squaredNorm();
      mv_sq += m.cwiseProduct(V[i]).squaredNorm();
    }
    const double r_norm = std::sqrt(r_sq);
    const double scale = std::sqrt(mv_sq) + mv0_norms + std::abs(h) * (f_norm + force_terms);
    const bool small = it > 0 && r_norm <= NewtonSettings::tolerance * scale;
    if (it == NewtonSettings::max_iterations || !std::isfinite(r_norm) || (fresh && r_norm > r_last && !small)) {
      if (full) return StepStatus::NoConvergence;
      full = true, fresh = false, force_terms = 0, dx_max = dv_max = 0, it = -1, round_off = {};  // again from V_i = v0, by full Newton
      for (int i = 0; i < Stages; ++i) V[i] = y.v;
      continue;
    }
    SolveCounts n;
    if (full) {
      std::array<const SparseMat*, Stages> dx, dv;
      for (int i = 0; i < Stages; ++i) {
        Jacobians<Eigen::Dynamic>& own = ws.stage_jacobians[i];
        if (const Jacobians<Eigen::Dynamic>& got = jacobians_for_run(s, t0 + t.c(i) * h, X[i], V[i], own); &got != &own) own = got;
        dx[i] = &own.dx, dv[i] = &own.dv;
        dx_max = std::max(dx_max, own.dx.norm()), dv_max = std::max(dv_max, own.dv.norm());
        if (it == 0) force_terms += own.dx.norm() * X[i].norm() + own.dv.norm() * V[i].norm();
      }
      if (r_sq == 0) break;
      n = solve_coupled_stages({&t.a[0][0], Stages * Stages}, Stages, h, dx, dv, m, {r.data(), Stages}, {dV.data(), Stages});
    } else {
      constexpr int last = Stages - 1;
      // Not refreshed once the residual is within tolerance: the iterations that follow only take
      // round-off's corrections, which no longer shrink the residual by the refresh's factor.
      fresh = !small && refresh_if_slow(kept, ws.jacobians, s, t0 + t.c(last) * h, X[last], V[last], it, r_norm, r_last);
      if (it == 0)
        for (int i = 0; i < Stages; ++i) force_terms += kept.force_terms(X[i], V[i]);
      if (r_sq == 0) break;  // already solved (at rest in equilibrium)
      n = kept.solve_stages(ws.transform, h, {r.data(), Stages}, {dV.data(), Stages});
      dx_max = kept.dx_norm(), dv_max = kept.dv_norm();
    }
    count_iteration(s, n);
    if (!n.ok) return StepStatus::NoConvergence;
    double step_sq = 0, v_sq = 0;
    for (int i = 0; i < Stages; ++i) step_sq += dV[i].squaredNorm(), v_sq += V[i].squaredNorm();
    // |K|_F <= sqrt(s) |M| + |h| |A| max|dF/dv| + h^2 |A|^2 max|dF/dx| (Frobenius norms), block by block
    const double j_bound = std::sqrt(double(Stages)) * m_norm + std::abs(h) * a_norm * dv_max + h * h * a_norm * a_norm * dx_max;
    if (round_off.stop(std::sqrt(step_sq), std::sqrt(v_sq) + v0_norms, scale, j_bound, small)) break;  // at round-off: V, and F its forces
    for (int i = 0; i < Stages; ++i) V[i] -= dV[i];
    r_last = r_norm;
  }
  add_increments(s, y, h, t, [&](int i) -> const Eigen::VectorXd& { return V[i]; }, F, carry);
  return StepStatus::Ok;
}

template <int Stages, class S, class T, class Carry = NoCarry>
[[gnu::always_inline]] inline Status<T> implicit_rk_step(const S& s, State<S::dim, T>& y, Time<T> t0, Time<T> h,
                                                         const ButcherTableau<Stages>& t, Carry&& carry = Carry{}) {
  if constexpr (S::dim == Eigen::Dynamic) return implicit_rk_step_sparse(s, y, t0, h, t, carry);
  else return implicit_rk_step_dense(s, y, t0, h, t, carry);
}

}  // namespace steplab
