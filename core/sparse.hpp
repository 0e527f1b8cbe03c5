// The linear solves of Newton's method on scenes of run-time size (D = Eigen::Dynamic), whose
// Jacobians are sparse (core/state.hpp). Compiled once, in core/sparse.cpp (the kernel library),
// so that a method's file does not parse and instantiate Eigen's sparse factorisations.
//
//   Symmetric: A = M - c dF/dv - c cx dF/dx of one implicit stage (solve_implicit) where the
//              scene's Jacobians are symmetric (the rope: dF/dx of springs is the Hessian of the
//              potential, dF/dv of mass damping and of dashpots at fixed directions too, M
//              diagonal): sparse LDL^T (Eigen's SimplicialLDLT, AMD ordering). Positive definite
//              for c > 0; LDL^T needs no definiteness.
//   General:   the coupled stages of an implicit Runge-Kutta method (Gauss-Legendre, Radau IIA),
//              whose block matrix is not symmetric (Butcher's A is not), and one stage where
//              dF/dx is not (the soft body's dashpots turning with their springs): sparse LU
//              (Eigen's SparseLU, COLAMD ordering).
// A solver keeps the ordering and symbolic factorisation of the last pattern it saw and redoes
// them only when the pattern changes (compared entry by entry, O(nnz)): a run's matrices keep
// theirs, so a thread's solver (local_solver) analyses once per run, not once per step.
#pragma once

#include <memory>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace steplab {

class SparseSolver {
 public:
  enum class Kind { Symmetric, General };
  explicit SparseSolver(Kind kind);
  ~SparseSolver();
  SparseSolver(const SparseSolver&) = delete;
  SparseSolver& operator=(const SparseSolver&) = delete;

  // Factorises a (compressed, column-major); false if the factorisation failed (singular).
  bool factorize(const Eigen::SparseMatrix<double>& a);
  // z = A^{-1} r with the last factorisation.
  void solve(const Eigen::VectorXd& r, Eigen::VectorXd& z) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// This thread's solver of that kind, kept between calls (a step's Newton solve borrows it).
SparseSolver& local_solver(SparseSolver::Kind kind);

}  // namespace steplab
