#include "analysis/rope_peers.hpp"

#include <boost/numeric/odeint/external/eigen/eigen.hpp>
#include <sunlinsol/sunlinsol_band.h>
#include <sunmatrix/sunmatrix_band.h>

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

}  // namespace

State<Eigen::Dynamic> cvode_band_rope(const Rope& r, double tol, double t_end, PeerCounts& n) {
  SUNContext ctx = nullptr;
  if (SUNContext_Create(nullptr, &ctx) != 0) throw std::runtime_error("CVODE: no context");
  const sunindextype size = 2 * r.n;
  N_Vector z = N_VNew_Serial(size, ctx);
  const State<Eigen::Dynamic> y0 = r.initial();
  double* a = N_VGetArrayPointer(z);
  for (int i = 0; i < r.n; ++i) a[2 * i] = y0.x[i], a[2 * i + 1] = y0.v[i];
  SUNMatrix J = SUNBandMatrix(size, 2, 3, ctx);
  SUNLinearSolver ls = SUNLinSol_Band(z, J, ctx);
  cvode_bdf(ctx, z, rope_rhs, rope_jacobian, J, ls, &r, tol, t_end, n, [](double) {});
  State<Eigen::Dynamic> end{Eigen::VectorXd(r.n), Eigen::VectorXd(r.n)};
  for (int i = 0; i < r.n; ++i) end.x[i] = a[2 * i], end.v[i] = a[2 * i + 1];
  SUNLinSolFree(ls);
  SUNMatDestroy(J);
  N_VDestroy(z);
  SUNContext_Free(&ctx);
  return end;
}

State<Eigen::Dynamic> odeint_dopri5_rope(const Rope& r, double tol, double t_end, PeerCounts& n) {
  namespace odeint = boost::numeric::odeint;
  using Z = Eigen::VectorXd;
  n = {};
  const State<Eigen::Dynamic> y0 = r.initial();
  Z z(2 * r.n);
  z << y0.x, y0.v;
  const auto rhs = [&](const Z& a, Z& da, double) {
    ++n.evaluations;
    da.resize(a.size());
    da.head(r.n) = a.tail(r.n);
    da.tail(r.n) = acceleration(r, Eigen::VectorXd(a.head(r.n)), Eigen::VectorXd(a.tail(r.n)));
  };
  using Stepper = odeint::runge_kutta_dopri5<Z, double, Z, double, odeint::vector_space_algebra>;
  n.steps = static_cast<long long>(
      odeint::integrate_adaptive(odeint::make_controlled(tol, tol, Stepper()), rhs, z, 0.0, t_end, 1e-6 * t_end));
  return {z.head(r.n), z.tail(r.n)};
}

}  // namespace steplab
