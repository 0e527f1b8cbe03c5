// Newton on all stages at once, for an s-stage implicit Runge-Kutta method (Butcher A, b) on
// M x'' = F(x, v). Written on the first-order system y = (x, v), y' = (v, M^-1 F):
//
//   stage velocities V_i (the unknowns, s D of them), stage positions X_i = x0 + h sum_j a_ij V_j,
//   G_i(V) = M (V_i - v0) - h sum_j a_ij F(t0 + c_j h, X_j, V_j) = 0,   c_j = sum_k a_jk,
//   x1 = x0 + h sum_i b_i V_i,   v1 = v0 + h sum_i b_i M^-1 F(X_i, V_i).
//
// The Jacobian of G, block (i, k):  M delta_ik - h a_ik dF/dv(k) - h^2 sum_j a_ij a_jk dF/dx(j).
// Full Newton from V_i = v0, with the stopping test of solve_implicit (core/method.hpp): |G| below
// NewtonSettings::tolerance times the size of the terms G balances. A force linear in (x, v)
// converges in one Newton step. The force values of the converged stages give v1 directly.
#pragma once

#include <array>
#include <vector>

#include "core/method.hpp"

namespace steplab {

// On a fixed size, also for a pack of runs (T a Pack; S its scene): each lane iterates as its
// run alone would and stops where that run stops, as in solve_implicit (and always inlined, as it is).
template <int Stages, class S, class T>
[[gnu::always_inline]] inline Status<T> implicit_rk_step_dense(const S& s, State<S::dim, T>& y, Time<T> t0, Time<T> h, const ButcherTableau<Stages>& t) {
  using std::abs;
  constexpr int D = S::dim, N = Stages * D;
  using Big = Eigen::Matrix<T, N, 1>;
  const Vec<D, T> m = s.mass();
  Big V;
  for (int i = 0; i < Stages; ++i) V.template segment<D>(i * D) = y.v;
  std::array<Vec<D, T>, Stages> X, F;
  std::array<Jacobians<D, T>, Stages> J;
  T force_terms = 0;
  NewtonLanes<T> lanes;
  for (int it = 0;; ++it) {
    for (int i = 0; i < Stages; ++i) {
      X[i] = y.x;
      for (int j = 0; j < Stages; ++j) X[i] += (h * t.a[i][j]) * V.template segment<D>(j * D);
      F[i] = force_at(s, t0 + t.c(i) * h, X[i], V.template segment<D>(i * D));
    }
    Big r;
    T f_norm = 0;
    for (int i = 0; i < Stages; ++i) {
      Vec<D, T> g = m.cwiseProduct(V.template segment<D>(i * D) - y.v);
      for (int j = 0; j < Stages; ++j) g -= (h * t.a[i][j]) * F[j];
      r.template segment<D>(i * D) = g;
      f_norm += F[i].norm();
    }
    if (it > 0) {
      const T scale = (m.asDiagonal() * V.reshaped(D, Stages)).norm() + Stages * m.cwiseProduct(y.v).norm() +
                      abs(h) * (f_norm + force_terms);
      lanes.solved(r.norm() <= NewtonSettings::tolerance * scale);
    }
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
    V = select(!lanes.done, Big(V - lu_solve(G, r)), V);
  }
  if (all(lanes.failed)) return lanes.status();  // a failed lane's state is dropped
  const Vec<D, T> inv_m = s.inverse_mass();
  for (int i = 0; i < Stages; ++i) {
    y.x += (h * t.b[i]) * V.template segment<D>(i * D);
    y.v += (h * t.b[i]) * F[i].cwiseProduct(inv_m);
  }
  return lanes.status();
}

// The same Newton iteration on a scene of run-time size n: the stage velocities in one vector of
// Stages n, the block matrix G assembled from the sparse Jacobians (its blocks have their
// pattern: tridiagonal for the rope) and factorised by sparse LU (core/sparse.hpp), its ordering
// computed once per run (the thread's solver keeps it).
template <int Stages, Scene S>
StepStatus implicit_rk_step_sparse(const S& s, State<S::dim>& y, double t0, double h, const ButcherTableau<Stages>& t) {
  const Eigen::Index n = y.x.size(), N = Stages * n;
  const Eigen::VectorXd& m = s.mass();
  Eigen::VectorXd V(N), r(N), dV;
  for (int i = 0; i < Stages; ++i) V.segment(i * n, n) = y.v;
  std::array<Eigen::VectorXd, Stages> X, F;
  std::array<Jacobians<Eigen::Dynamic>, Stages> J;
  SparseSolver& solver = local_solver(SparseSolver::Kind::General);
  SparseMat G(N, N);
  std::vector<Eigen::Triplet<double>> entries;
  const auto add = [&](const SparseMat& a, double coef, Eigen::Index row, Eigen::Index col) {
    if (coef == 0) return;
    for (int c = 0; c < a.outerSize(); ++c)
      for (SparseMat::InnerIterator e(a, c); e; ++e) entries.emplace_back(row + e.row(), col + e.col(), coef * e.value());
  };
  double force_terms = 0;
  for (int it = 0;; ++it) {
    for (int i = 0; i < Stages; ++i) {
      X[i] = y.x;
      for (int j = 0; j < Stages; ++j) X[i] += (h * t.a[i][j]) * V.segment(j * n, n);
      F[i] = force_at(s, t0 + t.c(i) * h, X[i], V.segment(i * n, n));
    }
    double f_norm = 0;
    for (int i = 0; i < Stages; ++i) {
      Eigen::VectorXd g = m.cwiseProduct(V.segment(i * n, n) - y.v);
      for (int j = 0; j < Stages; ++j) g -= (h * t.a[i][j]) * F[j];
      r.segment(i * n, n) = g;
      f_norm += F[i].norm();
    }
    if (it > 0) {
      const double scale = (m.asDiagonal() * V.reshaped(n, Stages)).norm() + Stages * m.cwiseProduct(y.v).norm() +
                           std::abs(h) * (f_norm + force_terms);
      if (r.norm() <= NewtonSettings::tolerance * scale) break;
    }
    if (it == NewtonSettings::max_iterations || !r.allFinite()) return StepStatus::NoConvergence;
    for (int i = 0; i < Stages; ++i) J[i] = jacobians_at(s, t0 + t.c(i) * h, X[i], V.segment(i * n, n));
    if (it == 0)
      for (int i = 0; i < Stages; ++i) force_terms += J[i].dx.norm() * X[i].norm() + J[i].dv.norm() * V.segment(i * n, n).norm();
    if (r.isZero(0.0)) break;  // already solved (at rest in equilibrium)
    entries.clear();
    for (int i = 0; i < Stages; ++i)
      for (int k = 0; k < Stages; ++k) {
        add(J[k].dv, -(h * t.a[i][k]), i * n, k * n);
        for (int j = 0; j < Stages; ++j) add(J[j].dx, -(h * h * t.a[i][j] * t.a[j][k]), i * n, k * n);
        if (i == k)
          for (Eigen::Index c = 0; c < n; ++c) entries.emplace_back(i * n + c, k * n + c, m[c]);
      }
    G.setFromTriplets(entries.begin(), entries.end());
    count_newton_update(s);
    if (!solver.factorize(G)) return StepStatus::NoConvergence;
    solver.solve(r, dV);
    V -= dV;
  }
  const Eigen::VectorXd& inv_m = s.inverse_mass();
  for (int i = 0; i < Stages; ++i) {
    y.x += (h * t.b[i]) * V.segment(i * n, n);
    y.v += (h * t.b[i]) * F[i].cwiseProduct(inv_m);
  }
  return StepStatus::Ok;
}

template <int Stages, class S, class T>
[[gnu::always_inline]] inline Status<T> implicit_rk_step(const S& s, State<S::dim, T>& y, Time<T> t0, Time<T> h,
                                                         const ButcherTableau<Stages>& t) {
  if constexpr (S::dim == Eigen::Dynamic) return implicit_rk_step_sparse(s, y, t0, h, t);
  else return implicit_rk_step_dense(s, y, t0, h, t);
}

}  // namespace steplab
