#include "core/sparse.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <klu.h>

namespace steplab {

// CVODE's rule for KLU (sunlinsol_klu.c): after a refactorisation on the old pivot order, a
// reciprocal pivot growth below eps^(2/3) means that order no longer suits the values: factorise
// afresh, choosing pivots again.
static const double kMinRcond = std::pow(std::numeric_limits<double>::epsilon(), 2.0 / 3.0);

// ---------------------------------------------------------------- the stage transform

StageTransform StageTransform::of(std::span<const double> a, int stages) {
  Eigen::MatrixXd m(stages, stages);
  for (int i = 0; i < stages; ++i)
    for (int j = 0; j < stages; ++j) m(i, j) = a[static_cast<std::size_t>(i * stages + j)];
  Eigen::EigenSolver<Eigen::MatrixXd> eig(m);
  Eigen::MatrixXcd t = eig.eigenvectors();
  StageTransform tr;
  tr.stages = stages;
  for (int i = 0; i < stages; ++i) {
    const Complex l = eig.eigenvalues()[i];
    tr.lambda[i] = l;
    tr.real[i] = std::abs(l.imag()) <= 1e-12 * std::abs(l);
    tr.first_of_pair[i] = l.imag() > 0 && !tr.real[i];
    if (tr.real[i]) {  // a real eigenvector, up to Eigen's phase: rotate it back to the real line
      Eigen::Index k;
      t.col(i).cwiseAbs().maxCoeff(&k);
      t.col(i) *= std::conj(t(k, i)) / std::abs(t(k, i));
      t.col(i) = t.col(i).real().cast<Complex>();
      tr.lambda[i] = l.real();
    }
  }
  const Eigen::MatrixXcd t_inv = t.inverse();
  for (int i = 0; i < stages; ++i)
    for (int j = 0; j < stages; ++j) tr.t[i][j] = t(i, j), tr.t_inv[i][j] = t_inv(i, j);
  return tr;
}

// ---------------------------------------------------------------- the kept matrices

namespace {

template <class V> bool same_indices(const std::vector<int>& kept, const V* p, Eigen::Index n) {
  return kept.size() == static_cast<std::size_t>(n) && std::equal(kept.begin(), kept.end(), p);
}

// One factorised E(a, b): by LDL^T (real, symmetric) or by KLU (otherwise).
struct Slot {
  bool used = false, complex = false;
  Complex a, b;
  long version = -1, last_use = 0;
  std::unique_ptr<Eigen::SimplicialLDLT<SparseMat>> ldlt;  // its ordering and analysis: made once
  Eigen::VectorXd inv_d;  // 1 / D of its LDL^T, kept at each factorisation (Eigen's vectorD() returns a copy)
  klu_numeric* numeric = nullptr;
  std::vector<double> values;  // E's values in E's pattern (real) or as (re, im) pairs (complex)
};

}  // namespace

struct IterationMatrices::Impl {
  // E's pattern: dF/dx's and dF/dv's and the diagonal; where each of their entries sits in it.
  std::vector<int> dx_outer, dx_inner, dv_outer, dv_inner;
  SparseMat e;
  std::vector<int> dx_at, dv_at, diag_at;
  Eigen::VectorXd dx, dv, mass;  // the kept values
  bool symmetric = false;
  klu_common common;
  klu_symbolic* symbolic = nullptr;
  std::array<Slot, kSlots> slots;
  long clock = 0;
  std::array<Eigen::VectorXd, 4> wr;      // the transformed stages, real eigenvalues
  std::array<Eigen::VectorXcd, 4> wc;     // and complex pairs
  Eigen::VectorXd permuted;               // LDL^T's work vector, P r, solved in place

  Impl() { klu_defaults(&common); }
  ~Impl() {
    drop_factorisations();
    if (symbolic) klu_free_symbolic(&symbolic, &common);
  }
  void drop_factorisations() {
    for (Slot& s : slots) {
      if (s.numeric) klu_free_numeric(&s.numeric, &common);
      s = Slot{};
    }
  }

  int n() const { return static_cast<int>(e.rows()); }

  // Where (row, col) sits in E's values (it is there: E's pattern holds it).
  int at(Eigen::Index row, Eigen::Index col) const {
    const int* begin = e.innerIndexPtr() + e.outerIndexPtr()[col];
    const int* end = e.innerIndexPtr() + e.outerIndexPtr()[col + 1];
    return static_cast<int>(std::lower_bound(begin, end, static_cast<int>(row)) - e.innerIndexPtr());
  }

  void make_pattern(const SparseMat& jx, const SparseMat& jv) {
    drop_factorisations();
    if (symbolic) klu_free_symbolic(&symbolic, &common);
    const Eigen::Index n = jx.rows();
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(static_cast<std::size_t>(jx.nonZeros() + jv.nonZeros() + n));
    for (const SparseMat* j : {&jx, &jv})
      for (Eigen::Index c = 0; c < j->outerSize(); ++c)
        for (SparseMat::InnerIterator it(*j, c); it; ++it) entries.emplace_back(it.row(), it.col(), 0.0);
    for (Eigen::Index i = 0; i < n; ++i) entries.emplace_back(i, i, 0.0);
    e.resize(n, n);
    e.setFromTriplets(entries.begin(), entries.end());
    e.makeCompressed();
    const auto where = [&](const SparseMat& j, std::vector<int>& out) {
      out.clear();
      for (Eigen::Index c = 0; c < j.outerSize(); ++c)
        for (SparseMat::InnerIterator it(j, c); it; ++it) out.push_back(at(it.row(), it.col()));
    };
    where(jx, dx_at);
    where(jv, dv_at);
    diag_at.resize(static_cast<std::size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i) diag_at[static_cast<std::size_t>(i)] = at(i, i);
    dx_outer.assign(jx.outerIndexPtr(), jx.outerIndexPtr() + jx.outerSize() + 1);
    dx_inner.assign(jx.innerIndexPtr(), jx.innerIndexPtr() + jx.nonZeros());
    dv_outer.assign(jv.outerIndexPtr(), jv.outerIndexPtr() + jv.outerSize() + 1);
    dv_inner.assign(jv.innerIndexPtr(), jv.innerIndexPtr() + jv.nonZeros());
  }

  // E(a, b)'s values in E's pattern: -a dF/dv - b dF/dx, then + M on the diagonal, entry by entry
  // in the order Eigen's expression -a Jv - b Jx + M would add them.
  template <class S> void fill(S a, S b, S* out) const {
    std::fill(out, out + e.nonZeros(), S(0));
    for (std::size_t k = 0; k < dv_at.size(); ++k) out[dv_at[k]] = -a * dv[static_cast<Eigen::Index>(k)];
    for (std::size_t k = 0; k < dx_at.size(); ++k) out[dx_at[k]] -= b * dx[static_cast<Eigen::Index>(k)];
    for (std::size_t i = 0; i < diag_at.size(); ++i) out[diag_at[i]] += mass[static_cast<Eigen::Index>(i)];
  }

  // The slot keeping E(a, b), factorised for the kept Jacobians (version); nullptr if singular.
  Slot* factorised(Complex a, Complex b, bool complex, long version, int& factorisations) {
    Slot* s = nullptr;
    for (Slot& c : slots)
      if (c.used && c.complex == complex && c.a == a && c.b == b) s = &c;
    if (!s) {  // the least recently used
      s = &*std::min_element(slots.begin(), slots.end(), [](const Slot& x, const Slot& y) { return x.last_use < y.last_use; });
      if (s->numeric) klu_free_numeric(&s->numeric, &common);
      *s = Slot{};
      s->used = true, s->complex = complex, s->a = a, s->b = b;
    }
    s->last_use = ++clock;
    if (s->version == version) return s;
    ++factorisations;
    s->version = -1;
    const std::size_t nnz = static_cast<std::size_t>(e.nonZeros());
    int* ap = e.outerIndexPtr();
    int* ai = e.innerIndexPtr();
    s->values.resize(complex ? 2 * nnz : nnz);
    if (complex) fill(a, b, reinterpret_cast<Complex*>(s->values.data()));
    else fill(a.real(), b.real(), s->values.data());
    double* x = s->values.data();
    if (!complex && symmetric) {
      const Eigen::Map<const SparseMat> m(n(), n(), e.nonZeros(), ap, ai, x);
      if (!s->ldlt) {
        s->ldlt = std::make_unique<Eigen::SimplicialLDLT<SparseMat>>();
        s->ldlt->analyzePattern(m);
      }
      s->ldlt->factorize(m);
      if (s->ldlt->info() != Eigen::Success) return nullptr;
      s->inv_d = s->ldlt->vectorD().cwiseInverse();
      s->version = version;
      return s;
    }
    if (!symbolic && !(symbolic = klu_analyze(n(), ap, ai, &common))) return nullptr;
    const auto fresh = [&] {
      if (s->numeric) klu_free_numeric(&s->numeric, &common);
      s->numeric = complex ? klu_z_factor(ap, ai, x, symbolic, &common) : klu_factor(ap, ai, x, symbolic, &common);
      return s->numeric != nullptr;
    };
    if (!s->numeric) {
      if (!fresh()) return nullptr;
    } else {
      const int ok = complex ? klu_z_refactor(ap, ai, x, symbolic, s->numeric, &common)
                             : klu_refactor(ap, ai, x, symbolic, s->numeric, &common);
      if (ok) complex ? klu_z_rcond(symbolic, s->numeric, &common) : klu_rcond(symbolic, s->numeric, &common);
      if ((!ok || common.rcond < kMinRcond) && !fresh()) return nullptr;
    }
    s->version = version;
    return s;
  }

  // z = E^-1 r; r and z may be the same vector (LDL^T solves in its work vector; KLU in place).
  bool solve_real(Slot& s, const Eigen::VectorXd& r, Eigen::VectorXd& z) {
    if (s.ldlt) {
      // E = P^T L D L^T P:  z = P^T L^-T D^-1 L^-1 P r, the steps and the order of Eigen's own
      // solve (SimplicialCholeskyBase::_solve_impl), so the same bits; but its last permutation is
      // made in place, which allocates a mask each solve: here it is made out of place, from the
      // work vector the matrices keep.
      // The permutations as the copies they are (P r: entry i of r to P(i)), the diagonal as
      // Eigen's inverse times (1/d_i, kept, then the product): the same values, no temporary.
      const Eigen::SimplicialLDLT<SparseMat>& f = *s.ldlt;
      if (f.info() != Eigen::Success) return false;
      const Eigen::Index n = r.size();
      const bool ordered = f.permutationP().size() > 0;
      permuted.resize(n);  // sized in a run's first solve
      if (ordered) {
        const auto& p = f.permutationP().indices();
        for (Eigen::Index i = 0; i < n; ++i) permuted[p[i]] = r[i];
      } else {
        permuted = r;
      }
      f.matrixL().solveInPlace(permuted);
      for (Eigen::Index i = 0; i < n; ++i) permuted[i] = s.inv_d[i] * permuted[i];
      f.matrixU().solveInPlace(permuted);
      if (ordered) {
        const auto& q = f.permutationPinv().indices();
        z.resize(n);  // r's size: no allocation once sized, and r itself when z is r
        for (Eigen::Index i = 0; i < n; ++i) z[q[i]] = permuted[i];
      } else {
        z = permuted;
      }
      return true;
    }
    if (&r != &z) z = r;
    return klu_solve(symbolic, s.numeric, n(), 1, z.data(), &common) != 0;
  }
  bool solve_complex(Slot& s, Eigen::VectorXcd& z) {
    return klu_z_solve(symbolic, s.numeric, n(), 1, reinterpret_cast<double*>(z.data()), &common) != 0;
  }
};

IterationMatrices::IterationMatrices() : impl_(std::make_unique<Impl>()) {}
IterationMatrices::~IterationMatrices() = default;
IterationMatrices::IterationMatrices(IterationMatrices&&) noexcept = default;
IterationMatrices& IterationMatrices::operator=(IterationMatrices&&) noexcept = default;

void IterationMatrices::keep(const SparseMat& dx, const SparseMat& dv, const Eigen::VectorXd& mass, bool symmetric) {
  Impl& m = *impl_;
  const bool same = m.e.rows() == dx.rows() && dx.isCompressed() && dv.isCompressed() &&
                    same_indices(m.dx_outer, dx.outerIndexPtr(), dx.outerSize() + 1) &&
                    same_indices(m.dx_inner, dx.innerIndexPtr(), dx.nonZeros()) &&
                    same_indices(m.dv_outer, dv.outerIndexPtr(), dv.outerSize() + 1) &&
                    same_indices(m.dv_inner, dv.innerIndexPtr(), dv.nonZeros());
  if (!same) {
    if (!dx.isCompressed() || !dv.isCompressed()) {  // a scene's own, uncompressed: compressed copies
      SparseMat cx = dx, cv = dv;
      cx.makeCompressed(), cv.makeCompressed();
      keep(cx, cv, mass, symmetric);
      return;
    }
    m.make_pattern(dx, dv);
  }
  m.dx = Eigen::Map<const Eigen::VectorXd>(dx.valuePtr(), dx.nonZeros());
  m.dv = Eigen::Map<const Eigen::VectorXd>(dv.valuePtr(), dv.nonZeros());
  m.mass = mass;
  m.symmetric = symmetric;
  dx_norm_ = dx.norm();
  dv_norm_ = dv.norm();
  ++version_;
}

SolveCounts IterationMatrices::solve(double a, double b, const Eigen::VectorXd& r, Eigen::VectorXd& z) {
  SolveCounts n;
  Slot* s = impl_->factorised(a, b, false, version_, n.factorisations);
  if (!s) return {n.factorisations, 0, false};
  n.ok = impl_->solve_real(*s, r, z);
  n.solves = 1;
  return n;
}

SolveCounts IterationMatrices::solve_stages(const StageTransform& tr, double h, std::span<const Eigen::VectorXd> r,
                                            std::span<Eigen::VectorXd> dv) {
  Impl& m = *impl_;
  const Eigen::Index n = m.n();
  const int s = tr.stages;
  SolveCounts counts;
  for (int k = 0; k < s; ++k) dv[k].setZero(n);
  for (int i = 0; i < s; ++i) {
    if (!tr.real[i] && !tr.first_of_pair[i]) continue;  // the conjugate of a pair: its conjugate's
    const Complex z = h * tr.lambda[i];
    Slot* slot = m.factorised(z, z * z, !tr.real[i], version_, counts.factorisations);
    if (!slot) return {counts.factorisations, counts.solves, false};
    ++counts.solves;
    if (tr.real[i]) {  // w = (T^-1 (x) I) r, row i; z = E^-1 w; dV += T[:, i] z
      Eigen::VectorXd& w = m.wr[i];
      w.setZero(n);
      for (int j = 0; j < s; ++j) w += tr.t_inv[i][j].real() * r[j];
      if (!m.solve_real(*slot, w, w)) return {counts.factorisations, counts.solves, false};
      for (int k = 0; k < s; ++k) dv[k] += tr.t[k][i].real() * w;
    } else {  // the pair: T[:, i] z + conj(T[:, i] z) = 2 Re(T[:, i] z)
      Eigen::VectorXcd& w = m.wc[i];
      w.setZero(n);
      for (int j = 0; j < s; ++j) w += tr.t_inv[i][j] * r[j].cast<Complex>();
      if (!m.solve_complex(*slot, w)) return {counts.factorisations, counts.solves, false};
      for (int k = 0; k < s; ++k) dv[k] += 2.0 * (tr.t[k][i] * w).real();
    }
  }
  return counts;
}

SolveCounts solve_coupled_stages(std::span<const double> a, int s, double h, std::span<const SparseMat* const> dx,
                                 std::span<const SparseMat* const> dv, const Eigen::VectorXd& mass,
                                 std::span<const Eigen::VectorXd> r, std::span<Eigen::VectorXd> dv_out) {
  const Eigen::Index n = mass.size();
  const auto at = [&](int i, int j) { return a[static_cast<std::size_t>(i * s + j)]; };
  std::vector<Eigen::Triplet<double>> entries;
  const auto add = [&](const SparseMat& m, double coef, Eigen::Index row, Eigen::Index col) {
    if (coef == 0) return;
    for (Eigen::Index c = 0; c < m.outerSize(); ++c)
      for (SparseMat::InnerIterator e(m, c); e; ++e) entries.emplace_back(row + e.row(), col + e.col(), coef * e.value());
  };
  for (int i = 0; i < s; ++i)
    for (int k = 0; k < s; ++k) {
      add(*dv[k], -(h * at(i, k)), i * n, k * n);
      for (int j = 0; j < s; ++j) add(*dx[j], -(h * h * at(i, j) * at(j, k)), i * n, k * n);
      if (i == k)
        for (Eigen::Index c = 0; c < n; ++c) entries.emplace_back(i * n + c, k * n + c, mass[c]);
    }
  SparseMat g(s * n, s * n);
  g.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<SparseMat, Eigen::COLAMDOrdering<int>> lu(g);
  if (lu.info() != Eigen::Success) return {1, 0, false};
  Eigen::VectorXd rhs(s * n);
  for (int i = 0; i < s; ++i) rhs.segment(i * n, n) = r[i];
  const Eigen::VectorXd z = lu.solve(rhs);
  for (int i = 0; i < s; ++i) dv_out[i] = z.segment(i * n, n);
  return {1, 1, true};
}

// ---------------------------------------------------------------- the run's workspace

namespace {
thread_local NewtonWorkspace* t_current = nullptr;
}

NewtonWorkspace& newton_workspace() {
  if (t_current) return *t_current;
  thread_local NewtonWorkspace scratch;
  scratch = NewtonWorkspace{};
  return scratch;
}

UseWorkspace::UseWorkspace(NewtonWorkspace& w) : previous_(t_current) { t_current = &w; }
UseWorkspace::~UseWorkspace() { t_current = previous_; }

}  // namespace steplab
