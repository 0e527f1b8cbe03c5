// The linear algebra of Newton's method on scenes of run-time size (D = Eigen::Dynamic), whose
// Jacobians are sparse (core/state.hpp): the iteration matrices, kept across steps, as RADAU5
// and CVODE keep theirs. Compiled once, in core/sparse.cpp (the kernel library), so that a
// method's file does not parse and instantiate the sparse factorisations.
//
// Every implicit solve here, one stage or s coupled stages, comes down to matrices of one form,
//
//     E(a, b) = M - a dF/dv - b dF/dx,
//
//   one stage (solve_implicit, core/method.hpp):  a = c, b = c cx (real);
//   s stages of a Runge-Kutta method (core/implicit_rk.hpp): the simplified Newton matrix of the
//   stage velocities, I (x) M - h A (x) dF/dv - h^2 A^2 (x) dF/dx, is block diagonal in the
//   eigenvectors T of Butcher's A = T Lambda T^-1 (Hairer and Wanner II, IV.8):
//     (T^-1 (x) I) K (T (x) I) = blockdiag E(h lambda_i, (h lambda_i)^2),
//   so a Newton update is  dV = (T (x) I) blockdiag(E_i^-1) (T^-1 (x) I) r: one real matrix per
//   real eigenvalue and one complex matrix per complex pair (the conjugate's solution is the
//   conjugate). Radau IIA 5: one real and one complex system of size n, not one of 3n; Gauss-
//   Legendre 4: one complex system.
//
// What is kept (IterationMatrices): dF/dx and dF/dv as last evaluated, and a factorisation of
// E(a, b) for each (a, b) a run uses (up to kSlots, the least recently used replaced), each
// redone only when the Jacobians were refreshed since or it was never made. The pattern of E
// (dF/dx's and dF/dv's together, and the diagonal) and each solver's ordering and symbolic
// analysis are made once per pattern. When the Jacobians are refreshed is the Newton loop's rule
// (kRefreshRate below). The solvers, by case (docs/design.md gives the measurements):
//   real, symmetric dF/dx and dF/dv (the rope): sparse LDL^T (Eigen's SimplicialLDLT, AMD
//     ordering); E is symmetric, and LDL^T needs no definiteness;
//   everything else (the soft body's dashpots make dF/dx unsymmetric; any complex E): sparse LU
//     by KLU (SuiteSparse; SUNDIALS' sparse direct solver): BTF and AMD ordering once, then
//     klu_refactor on the same pivot order (klu_factor again where its reciprocal pivot growth
//     falls below kMinRcond), and solves in place, allocating nothing.
#pragma once

#include <array>
#include <cmath>
#include <complex>
#include <memory>
#include <span>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "core/state.hpp"

namespace steplab {

using Complex = std::complex<double>;

// Simplified Newton's refresh rule (RADAU5's: the Jacobian is kept while the iteration converges
// fast). An iteration whose residual falls by less than this factor refreshes the Jacobians at the
// current iterate, and the matrices made from them; a linear scene's kept matrix is exact and its
// iteration ends after one update, so a run of it factorises each matrix once.
inline constexpr double kRefreshRate = 0.1;

// What one solve did: the factorisations it made (0 where it used the kept ones), the linear
// solves, and false where a matrix was singular.
struct SolveCounts {
  int factorisations = 0, solves = 0;
  bool ok = true;
};

// The eigen-decomposition of an s-stage Butcher matrix, A = T diag(lambda) T^-1, s <= 4.
struct StageTransform {
  int stages = 0;
  std::array<Complex, 4> lambda{};
  std::array<std::array<Complex, 4>, 4> t{}, t_inv{};
  std::array<bool, 4> real{}, first_of_pair{};  // eigenvalue i real; i the first of a conjugate pair
  static StageTransform of(std::span<const double> a, int stages);  // a row-major s x s
};

class IterationMatrices {
 public:
  static constexpr int kSlots = 4;
  IterationMatrices();
  ~IterationMatrices();
  IterationMatrices(IterationMatrices&&) noexcept;
  IterationMatrices& operator=(IterationMatrices&&) noexcept;

  bool has_jacobians() const { return version_ > 0; }
  // Keeps these Jacobians (their values copied) and the masses; every kept factorisation is now stale.
  void keep(const SparseMat& dx, const SparseMat& dv, const Eigen::VectorXd& mass, bool symmetric);
  // |dF/dx| |x| + |dF/dv| |v| with the kept Jacobians (Frobenius norms): the size of the force's
  // terms in Newton's stopping test (core/method.hpp).
  double force_terms(Eigen::Ref<const Eigen::VectorXd> x, Eigen::Ref<const Eigen::VectorXd> v) const { return dx_norm_ * x.norm() + dv_norm_ * v.norm(); }
  // An upper bound on |E(a, b)|_F = |M - a dF/dv - b dF/dx|_F with the kept Jacobians: |M| + |a|
  // |dF/dv| + |b| |dF/dx| (m_norm: |M|), for Newton's round-off size (core/method.hpp).
  double dx_norm() const { return dx_norm_; }
  double dv_norm() const { return dv_norm_; }
  double norm_bound(double m_norm, double a, double b) const { return m_norm + std::abs(a) * dv_norm_ + std::abs(b) * dx_norm_; }

  // z = E(a, b)^-1 r, factorising E(a, b) first where it is not kept.
  SolveCounts solve(double a, double b, const Eigen::VectorXd& r, Eigen::VectorXd& z);
  // The stage update of an s-stage method with this transform and step h: dV = K^-1 r, r and dV
  // s vectors of n, one a stage.
  SolveCounts solve_stages(const StageTransform& tr, double h, std::span<const Eigen::VectorXd> r, std::span<Eigen::VectorXd> dv);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  long version_ = 0;
  double dx_norm_ = 0, dv_norm_ = 0;
};

// Full Newton's update of s coupled stages with each stage's own Jacobians (dx[k], dv[k]): the
// s n system, block (i, k) = M delta_ik - h a_ik dF/dv(k) - h^2 sum_j a_ij a_jk dF/dx(j) (a
// row-major s x s), assembled and factorised by sparse LU at each call: nothing kept. Where
// simplified Newton does not converge (one Jacobian for all stages misses what changes between
// them, as a contact that switches within a step): its fallback, which allocates.
SolveCounts solve_coupled_stages(std::span<const double> a, int s, double h, std::span<const SparseMat* const> dx,
                                 std::span<const SparseMat* const> dv, const Eigen::VectorXd& mass,
                                 std::span<const Eigen::VectorXd> r, std::span<Eigen::VectorXd> dv_out);

// A run's Newton workspace (MuJoCo's mjData in spirit): made with the run (its Stepper, core/
// stepper.hpp), it holds the kept matrices and the vectors a step works in, so that after its
// first step a run's Newton iterations allocate nothing.
struct NewtonWorkspace {
  IterationMatrices matrices;
  Eigen::VectorXd x, r, du, f;  // one stage's
  Jacobians<Eigen::Dynamic> jacobians;  // as last evaluated, where the scene writes them (JacobiansInto)
  std::array<Eigen::VectorXd, 4> stage_x, stage_v, stage_f, stage_r, stage_dv;  // s stages' (s <= 4)
  std::array<Jacobians<Eigen::Dynamic>, 4> stage_jacobians;  // full Newton's, a stage each (the fallback)
  const void* transform_of = nullptr;  // the Butcher matrix `transform` was made from
  StageTransform transform;
};

// The workspace of the run this thread is stepping: installed by its Stepper while it steps
// (UseWorkspace). A step called outside a run gets a scratch one emptied first: it keeps nothing
// from an earlier call.
NewtonWorkspace& newton_workspace();

class UseWorkspace {
 public:
  explicit UseWorkspace(NewtonWorkspace& w);
  ~UseWorkspace();
  UseWorkspace(const UseWorkspace&) = delete;
  UseWorkspace& operator=(const UseWorkspace&) = delete;

 private:
  NewtonWorkspace* previous_;
};

}  // namespace steplab
