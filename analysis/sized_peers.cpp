#include "analysis/sized_peers.hpp"

#include <stdexcept>
#include <string>

#include <boost/numeric/odeint.hpp>
#include <boost/numeric/odeint/external/eigen/eigen.hpp>
#include <sunlinsol/sunlinsol_band.h>
#if STEPLAB_HAVE_KLU
#include <sunlinsol/sunlinsol_klu.h>
#endif
#include <sunmatrix/sunmatrix_band.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include "analysis/cvode.hpp"
#include "analysis/fixed_peers.hpp"  // odeint_adaptive

namespace steplab {
namespace {

int rope_rhs(sunrealtype, N_Vector z, N_Vector dz, void* data) {
  const Rope& r = *static_cast<const Rope*>(data);
  const Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<2>> x(N_VGetArrayPointer(z), r.n), v(N_VGetArrayPointer(z) + 1, r.n);
  const Eigen::VectorXd a = acceleration(r, Eigen::VectorXd(x), Eigen::VectorXd(v));
  double* d = N_VGetArrayPointer(dz);
  for (int i = 0; i < r.n; ++i) d[2 * i] = v[i], d[2 * i + 1] = a[i];
  return 0;
}

// Rows and columns interleaved: x_i at 2i, v_i at 2i+1. d(x_i')/d(v_i) = 1; d(v_i')/d(x_j, v_j) =
// M^-1 dF/dx, M^-1 dF/dv (tridiagonal).
int rope_jacobian(sunrealtype, N_Vector z, N_Vector, SUNMatrix J, void* data, N_Vector, N_Vector, N_Vector) {
  const Rope& r = *static_cast<const Rope*>(data);
  const Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<2>> x(N_VGetArrayPointer(z), r.n), v(N_VGetArrayPointer(z) + 1, r.n);
  const Jacobians<Eigen::Dynamic>& j = r.jacobians(Eigen::VectorXd(x), Eigen::VectorXd(v));
  SUNMatZero(J);
  for (int i = 0; i < r.n; ++i) SM_ELEMENT_B(J, 2 * i, 2 * i + 1) = 1;
  for (int c = 0; c < j.dx.outerSize(); ++c)
    for (SparseMat::InnerIterator e(j.dx, c); e; ++e) SM_ELEMENT_B(J, 2 * e.row() + 1, 2 * e.col()) = r.inv_m * e.value();
  for (int c = 0; c < j.dv.outerSize(); ++c)
    for (SparseMat::InnerIterator e(j.dv, c); e; ++e) SM_ELEMENT_B(J, 2 * e.row() + 1, 2 * e.col() + 1) = r.inv_m * e.value();
  return 0;
}

// z' = (v, M^-1 F(x, v)), z = (x, v) in blocks.
template <class S> int blocked_rhs(sunrealtype, N_Vector z, N_Vector dz, void* data) {
  const S& s = *static_cast<const S*>(data);
  const Eigen::Index d = N_VGetLength(z) / 2;
  const Eigen::Map<const Eigen::VectorXd> a(N_VGetArrayPointer(z), 2 * d);
  Eigen::Map<Eigen::VectorXd> da(N_VGetArrayPointer(dz), 2 * d);
  da.head(d) = a.tail(d);
  da.tail(d) = acceleration(s, Eigen::VectorXd(a.head(d)), Eigen::VectorXd(a.tail(d)));
  return 0;
}

// J = [[0, I], [M^-1 dF/dx, M^-1 dF/dv]] in CSR, every stored entry of the scene's Jacobians kept
// (their pattern does not change: KLU analyses it once).
template <class S> int csr_jacobian(sunrealtype, N_Vector z, N_Vector, SUNMatrix J, void* data, N_Vector, N_Vector, N_Vector) {
  const S& s = *static_cast<const S*>(data);
  const Eigen::Index d = N_VGetLength(z) / 2;
  const Eigen::Map<const Eigen::VectorXd> a(N_VGetArrayPointer(z), 2 * d);
  const Jacobians<Eigen::Dynamic> j = s.jacobians(Eigen::VectorXd(a.head(d)), Eigen::VectorXd(a.tail(d)));
  const Eigen::SparseMatrix<double, Eigen::RowMajor> dx = j.dx, dv = j.dv;
  const Eigen::VectorXd& w = s.inverse_mass();
  sunindextype* start = SUNSparseMatrix_IndexPointers(J);
  sunindextype* col = SUNSparseMatrix_IndexValues(J);
  double* val = SUNSparseMatrix_Data(J);
  sunindextype k = 0;
  for (Eigen::Index r = 0; r < d; ++r) start[r] = k, col[k] = d + r, val[k++] = 1;
  for (Eigen::Index r = 0; r < d; ++r) {
    start[d + r] = k;
    for (decltype(dx)::InnerIterator e(dx, r); e; ++e) col[k] = e.col(), val[k++] = w[r] * e.value();
    for (decltype(dv)::InnerIterator e(dv, r); e; ++e) col[k] = d + e.col(), val[k++] = w[r] * e.value();
  }
  start[2 * d] = k;
  return k <= SUNSparseMatrix_NNZ(J) ? 0 : -1;
}

template <class S> State<Eigen::Dynamic> odeint_dopri5(const S& s, double tol, double t_end, PeerCounts& n) {
  namespace odeint = boost::numeric::odeint;
  using Z = Eigen::VectorXd;
  n = {};
  const State<Eigen::Dynamic> y0 = s.initial();
  const Eigen::Index d = y0.x.size();
  Z z(2 * d);
  z << y0.x, y0.v;
  const auto rhs = [&](const Z& a, Z& da, double) {
    ++n.forces;
    da.resize(a.size());
    da.head(d) = a.tail(d);
    da.tail(d) = acceleration(s, Eigen::VectorXd(a.head(d)), Eigen::VectorXd(a.tail(d)));
  };
  using Stepper = odeint::runge_kutta_dopri5<Z, double, Z, double, odeint::vector_space_algebra>;
  odeint_adaptive(odeint::make_controlled(tol, tol, Stepper()), rhs, z, t_end, 1e-6 * t_end, n, [](const Z&, double) {});
  return {z.head(d), z.tail(d)};
}

State<Eigen::Dynamic> cvode_band_rope(const Rope& r, const CvodeSettings& settings, double tol, double t_end, PeerCounts& n) {
  const sunindextype size = 2 * r.n;
  CvodeRun c(size);
  const State<Eigen::Dynamic> y0 = r.initial();
  double* a = c.data();
  for (int i = 0; i < r.n; ++i) a[2 * i] = y0.x[i], a[2 * i + 1] = y0.v[i];
  c.J = SUNBandMatrix(size, 2, 3, c.ctx);
  c.ls = SUNLinSol_Band(c.z, c.J, c.ctx);
  cvode_solve(c, rope_rhs, rope_jacobian, &r, settings, tol, t_end, n, [](double) {});
  State<Eigen::Dynamic> end{Eigen::VectorXd(r.n), Eigen::VectorXd(r.n)};
  for (int i = 0; i < r.n; ++i) end.x[i] = a[2 * i], end.v[i] = a[2 * i + 1];
  return end;
}

#if STEPLAB_HAVE_KLU
State<Eigen::Dynamic> cvode_klu_softbody(const SoftBody& s, const CvodeSettings& settings, double tol, double t_end, PeerCounts& n) {
  const State<Eigen::Dynamic> y0 = s.initial();
  const sunindextype d = y0.x.size();
  CvodeRun c(2 * d);
  Eigen::Map<Eigen::VectorXd>(c.data(), 2 * d) << y0.x, y0.v;
  const Jacobians<Eigen::Dynamic> j0 = s.jacobians(y0.x, y0.v);
  c.J = SUNSparseMatrix(2 * d, 2 * d, d + j0.dx.nonZeros() + j0.dv.nonZeros(), CSR_MAT, c.ctx);
  c.ls = SUNLinSol_KLU(c.z, c.J, c.ctx);
  cvode_solve(c, blocked_rhs<SoftBody>, csr_jacobian<SoftBody>, &s, settings, tol, t_end, n, [](double) {});
  const Eigen::Map<const Eigen::VectorXd> a(c.data(), 2 * d);
  return {a.head(d), a.tail(d)};
}
#endif

[[noreturn]] void not_here(const PeerInfo& peer, std::string_view scene) {
  throw std::logic_error("run_sized_peer: " + std::string(peer.name) + " does not run on the " + std::string(scene));
}

}  // namespace

State<Eigen::Dynamic> run_sized_peer(const PeerInfo& peer, const Rope& r, double tol, double t_end, PeerCounts& n) {
  if (peer.name == "odeint_dopri5") return odeint_dopri5(r, tol, t_end, n);
  if (peer.linear_solver == "band") return cvode_band_rope(r, peer.cvode, tol, t_end, n);
  not_here(peer, "rope");
}

State<Eigen::Dynamic> run_sized_peer(const PeerInfo& peer, const SoftBody& s, double tol, double t_end, PeerCounts& n) {
  if (peer.name == "odeint_dopri5") return odeint_dopri5(s, tol, t_end, n);
#if STEPLAB_HAVE_KLU
  if (peer.linear_solver == "KLU" && peer.built) return cvode_klu_softbody(s, peer.cvode, tol, t_end, n);
#endif
  not_here(peer, "soft body");
}

}  // namespace steplab
