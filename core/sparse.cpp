#include "core/sparse.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

namespace steplab {

struct SparseSolver::Impl {
  Kind kind;
  bool analyzed = false;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
};

SparseSolver::SparseSolver(Kind kind) : impl_(std::make_unique<Impl>()) { impl_->kind = kind; }
SparseSolver::~SparseSolver() = default;

bool SparseSolver::factorize(const Eigen::SparseMatrix<double>& a) {
  Impl& s = *impl_;
  if (s.kind == Kind::Symmetric) {
    if (!s.analyzed) s.ldlt.analyzePattern(a);
    s.analyzed = true;
    s.ldlt.factorize(a);
    return s.ldlt.info() == Eigen::Success;
  }
  if (!s.analyzed) s.lu.analyzePattern(a);
  s.analyzed = true;
  s.lu.factorize(a);
  return s.lu.info() == Eigen::Success;
}

void SparseSolver::solve(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  if (impl_->kind == Kind::Symmetric) z = impl_->ldlt.solve(r);
  else z = impl_->lu.solve(r);
}

}  // namespace steplab
