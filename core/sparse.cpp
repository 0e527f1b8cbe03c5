#include "core/sparse.hpp"

#include <algorithm>
#include <vector>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

namespace steplab {

struct SparseSolver::Impl {
  Kind kind;
  bool analyzed = false;
  std::vector<int> outer, inner;  // the pattern analysed
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
};

SparseSolver::SparseSolver(Kind kind) : impl_(std::make_unique<Impl>()) { impl_->kind = kind; }
SparseSolver::~SparseSolver() = default;

namespace {
bool same_pattern(const std::vector<int>& outer, const std::vector<int>& inner, const Eigen::SparseMatrix<double>& a) {
  return outer.size() == static_cast<std::size_t>(a.outerSize() + 1) && inner.size() == static_cast<std::size_t>(a.nonZeros()) &&
         std::equal(outer.begin(), outer.end(), a.outerIndexPtr()) && std::equal(inner.begin(), inner.end(), a.innerIndexPtr());
}
}  // namespace

bool SparseSolver::factorize(const Eigen::SparseMatrix<double>& a) {
  Impl& s = *impl_;
  const bool again = s.analyzed && same_pattern(s.outer, s.inner, a);
  if (!again) {
    s.outer.assign(a.outerIndexPtr(), a.outerIndexPtr() + a.outerSize() + 1);
    s.inner.assign(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros());
    s.analyzed = true;
  }
  if (s.kind == Kind::Symmetric) {
    if (!again) s.ldlt.analyzePattern(a);
    s.ldlt.factorize(a);
    return s.ldlt.info() == Eigen::Success;
  }
  if (!again) s.lu.analyzePattern(a);
  s.lu.factorize(a);
  return s.lu.info() == Eigen::Success;
}

void SparseSolver::solve(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  if (impl_->kind == Kind::Symmetric) z = impl_->ldlt.solve(r);
  else z = impl_->lu.solve(r);
}

SparseSolver& local_solver(SparseSolver::Kind kind) {
  thread_local SparseSolver symmetric(SparseSolver::Kind::Symmetric), general(SparseSolver::Kind::General);
  return kind == SparseSolver::Kind::Symmetric ? symmetric : general;
}

}  // namespace steplab
