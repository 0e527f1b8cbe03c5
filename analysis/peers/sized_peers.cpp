#include "analysis/peers/sized_peers.hpp"

#include <algorithm>
#include <functional>
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

#include "analysis/peers/arkode.hpp"
#include "analysis/peers/cvode.hpp"
#include "analysis/peers/fixed_peers.hpp"  // odeint_adaptive
#include "analysis/peers/radau5.hpp"

namespace steplab {
namespace {

// A scene of run-time size as the templates below (and core/scene.hpp's acceleration) ask for it,
// reached through the kernel table.
struct MadeScene {
  static constexpr int dim = Eigen::Dynamic;
  const MadeSceneCode& code;
  const void* scene;
  Eigen::VectorXd force(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const { return code.force(scene, x, v); }
  Jacobians<Eigen::Dynamic> jacobians(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const { return code.jacobians(scene, x, v); }
  const Eigen::VectorXd& inverse_mass() const { return code.inverse_mass(scene); }
  State<Eigen::Dynamic> initial() const { return code.initial(scene); }
};

// z' = (v, M^-1 F(x, v)), z = (x_1, v_1, x_2, v_2, ...) interleaved.
int interleaved_rhs(sunrealtype t, N_Vector z, N_Vector dz, void* data) {
  const MadeScene& s = *static_cast<const MadeScene*>(data);
  const Eigen::Index d = N_VGetLength(z) / 2;
  const Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<2>> x(N_VGetArrayPointer(z), d), v(N_VGetArrayPointer(z) + 1, d);
  const Eigen::VectorXd a = acceleration(s, t, Eigen::VectorXd(x), Eigen::VectorXd(v));
  double* out = N_VGetArrayPointer(dz);
  for (Eigen::Index i = 0; i < d; ++i) out[2 * i] = v[i], out[2 * i + 1] = a[i];
  return 0;
}

// Rows and columns interleaved: x_i at 2i, v_i at 2i+1. d(x_i')/d(v_i) = 1; d(v_i')/d(x_j, v_j) =
// M^-1 dF/dx, M^-1 dF/dv (banded).
int band_jacobian(sunrealtype, N_Vector z, N_Vector, SUNMatrix J, void* data, N_Vector, N_Vector, N_Vector) {
  const MadeScene& s = *static_cast<const MadeScene*>(data);
  const Eigen::Index d = N_VGetLength(z) / 2;
  const Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<2>> x(N_VGetArrayPointer(z), d), v(N_VGetArrayPointer(z) + 1, d);
  const Jacobians<Eigen::Dynamic> j = s.jacobians(Eigen::VectorXd(x), Eigen::VectorXd(v));
  const Eigen::VectorXd& w = s.inverse_mass();
  SUNMatZero(J);
  for (Eigen::Index i = 0; i < d; ++i) SM_ELEMENT_B(J, 2 * i, 2 * i + 1) = 1;
  for (int c = 0; c < j.dx.outerSize(); ++c)
    for (SparseMat::InnerIterator e(j.dx, c); e; ++e) SM_ELEMENT_B(J, 2 * e.row() + 1, 2 * e.col()) = w[e.row()] * e.value();
  for (int c = 0; c < j.dv.outerSize(); ++c)
    for (SparseMat::InnerIterator e(j.dv, c); e; ++e) SM_ELEMENT_B(J, 2 * e.row() + 1, 2 * e.col() + 1) = w[e.row()] * e.value();
  return 0;
}

// z' = (v, M^-1 F(x, v)), z = (x, v) in blocks of d entries: CVODE's and ARKODE's right side
// (blocked_rhs) and RADAU5's.
void blocked_derivative(const MadeScene& s, double t, const double* z, double* dz, Eigen::Index d) {
  const Eigen::Map<const Eigen::VectorXd> a(z, 2 * d);
  Eigen::Map<Eigen::VectorXd> da(dz, 2 * d);
  da.head(d) = a.tail(d);
  da.tail(d) = acceleration(s, t, Eigen::VectorXd(a.head(d)), Eigen::VectorXd(a.tail(d)));
}
int blocked_rhs(sunrealtype t, N_Vector z, N_Vector dz, void* data) {
  blocked_derivative(*static_cast<const MadeScene*>(data), t, N_VGetArrayPointer(z), N_VGetArrayPointer(dz), N_VGetLength(z) / 2);
  return 0;
}

// J = [[0, I], [M^-1 dF/dx, M^-1 dF/dv]] in CSR, every stored entry of the scene's Jacobians kept
// (their pattern does not change: KLU analyses it once).
int csr_jacobian(sunrealtype, N_Vector z, N_Vector, SUNMatrix J, void* data, N_Vector, N_Vector, N_Vector) {
  const MadeScene& s = *static_cast<const MadeScene*>(data);
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

State<Eigen::Dynamic> odeint_dopri5(const MadeScene& s, double tol, double t_end, PeerCounts& n, const PeerFrames& frames) {
  namespace odeint = boost::numeric::odeint;
  using Z = Eigen::VectorXd;
  n = {};
  const State<Eigen::Dynamic> y0 = s.initial();
  const Eigen::Index d = y0.x.size();
  Z z(2 * d);
  z << y0.x, y0.v;
  const auto rhs = [&](const Z& a, Z& da, double t) {
    ++n.forces;
    da.resize(a.size());
    da.head(d) = a.tail(d);
    da.tail(d) = acceleration(s, t, Eigen::VectorXd(a.head(d)), Eigen::VectorXd(a.tail(d)));
  };
  using Stepper = odeint::runge_kutta_dopri5<Z, double, Z, double, odeint::vector_space_algebra>;
  if (frames.count > 0)
    odeint_times(odeint::make_controlled(tol, tol, Stepper()), rhs, z, t_end, frames.count, 1e-6 * t_end, n,
                 [&](const Z& a, int k) { frames.at(k, a.head(d)); });
  else
    odeint_adaptive(odeint::make_controlled(tol, tol, Stepper()), rhs, z, t_end, 1e-6 * t_end, n, [](const Z&, double) {});
  return {z.head(d), z.tail(d)};
}

// CVODE or ARKODE (as the peer is) to t_end, or through the frames when there are any,
// `positions()` the run's x (a copy). The sized scenes are not linear in their state.
template <class Positions>
void sundials_frames_or_end(CvodeRun& c, CVRhsFn rhs, CVLsJacFn jac, const MadeScene& s, const PeerInfo& peer, double tol,
                            double t_end, PeerCounts& n, const PeerFrames& frames, Positions&& positions) {
  const auto at = [&](int k) { frames.at(k, positions()); };
  if (peer.is_arkode()) {
    if (frames.count > 0) arkode_solve_frames(c, rhs, jac, &s, peer.arkode, false, tol, t_end, frames.count, n, at);
    else arkode_solve(c, rhs, jac, &s, peer.arkode, false, tol, t_end, n, [](double) {});
  } else if (frames.count > 0) {
    cvode_solve_frames(c, rhs, jac, &s, peer.cvode, tol, t_end, frames.count, n, at);
  } else {
    cvode_solve(c, rhs, jac, &s, peer.cvode, tol, t_end, n, [](double) {});
  }
}

// RADAU5 on z = (x, v), M1 = M2 = d, its Jacobian's two d x d blocks stored as bands of width b
// (radau5.hpp): the scene's declared bandwidth, or on a scene without one (the soft body) the
// widest its Jacobians' pattern at the start reaches (their pattern does not change).
struct Radau5Sized {
  // What RADAU5's callbacks read: the scene and the Jacobian's stored bandwidth.
  struct Call {
    const MadeScene& scene;
    int band;
  };
  static void rhs(const void* data, double t, const double* z, double* dz) {
    const MadeScene& s = static_cast<const Call*>(data)->scene;
    blocked_derivative(s, t, z, dz, s.inverse_mass().size());
  }
  static int width(const Jacobians<Eigen::Dynamic>& j) {
    Eigen::Index b = 0;
    for (const SparseMat* m : {&j.dx, &j.dv})
      for (int c = 0; c < m->outerSize(); ++c)
        for (SparseMat::InnerIterator e(*m, c); e; ++e) b = std::max(b, std::abs(e.row() - e.col()));
    return static_cast<int>(b);
  }
  static void jacobian(const void* data, double, const double* z, double* dfy, int ld) {
    const Call& call = *static_cast<const Call*>(data);
    const MadeScene& s = call.scene;
    const Eigen::Index d = s.inverse_mass().size();
    const Eigen::Map<const Eigen::VectorXd> a(z, 2 * d);
    const Jacobians<Eigen::Dynamic> j = s.jacobians(Eigen::VectorXd(a.head(d)), Eigen::VectorXd(a.tail(d)));
    const Eigen::VectorXd& w = s.inverse_mass();
    std::fill(dfy, dfy + static_cast<std::ptrdiff_t>(ld) * 2 * d, 0.0);
    for (int k = 0; k < 2; ++k) {
      const SparseMat& m = k == 0 ? j.dx : j.dv;
      for (int c = 0; c < m.outerSize(); ++c)
        for (SparseMat::InnerIterator e(m, c); e; ++e)
          dfy[(e.row() - e.col() + call.band) + (e.col() + k * d) * ld] = w[e.row()] * e.value();
    }
  }
  static State<Eigen::Dynamic> run(const MadeScene& s, int bandwidth, double tol, double t_end, PeerCounts& n,
                                    const PeerFrames& frames) {
    const State<Eigen::Dynamic> y0 = s.initial();
    const Eigen::Index d = y0.x.size();
    Eigen::VectorXd z(2 * d), out(2 * d);
    z << y0.x, y0.v;
    const Call call{s, bandwidth >= 0 ? bandwidth : width(s.jacobians(y0.x, y0.v))};
    const Radau5Problem p{static_cast<int>(2 * d), call.band, &call, rhs, jacobian};
    int k = 1;
    std::function<void(const Radau5Step&)> after;
    if (frames.count > 0)  // each frame in the step that reaches it, from the collocation polynomial
      after = [&](const Radau5Step& step) {
        for (; k <= frames.count; ++k) {
          const double tk = frame_time(k, frames.count, t_end);
          if (tk > step.t) break;
          step.dense(tk, out.data());
          frames.at(k, out.head(d));
        }
      };
    radau5_solve(p, z.data(), tol, t_end, n, after);
    return {z.head(d), z.tail(d)};
  }
};

State<Eigen::Dynamic> sundials_band(const MadeScene& s, int bandwidth, const PeerInfo& peer, double tol, double t_end,
                                    PeerCounts& n, const PeerFrames& frames) {
  const State<Eigen::Dynamic> y0 = s.initial();
  const Eigen::Index d = y0.x.size();
  CvodeRun c(2 * d);
  double* a = c.data();
  for (Eigen::Index i = 0; i < d; ++i) a[2 * i] = y0.x[i], a[2 * i + 1] = y0.v[i];
  c.J = SUNBandMatrix(2 * d, 2 * bandwidth, 2 * bandwidth + 1, c.ctx);
  c.ls = SUNLinSol_Band(c.z, c.J, c.ctx);
  sundials_frames_or_end(c, interleaved_rhs, band_jacobian, s, peer, tol, t_end, n, frames, [&] {
    return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<2>>(a, d));
  });
  State<Eigen::Dynamic> end{Eigen::VectorXd(d), Eigen::VectorXd(d)};
  for (Eigen::Index i = 0; i < d; ++i) end.x[i] = a[2 * i], end.v[i] = a[2 * i + 1];
  return end;
}

// CVODE or ARKODE on z = (x, v) in blocks: with KLU on the CSR Jacobian where the peer is
// implicit, without a linear solver where it is explicit (ARKODE's explicit table).
State<Eigen::Dynamic> sundials_blocked(const MadeScene& s, const PeerInfo& peer, double tol, double t_end, PeerCounts& n,
                                       const PeerFrames& frames) {
  const State<Eigen::Dynamic> y0 = s.initial();
  const sunindextype d = y0.x.size();
  CvodeRun c(2 * d);
  Eigen::Map<Eigen::VectorXd>(c.data(), 2 * d) << y0.x, y0.v;
#if STEPLAB_HAVE_KLU
  if (peer.implicit) {
    const Jacobians<Eigen::Dynamic> j0 = s.jacobians(y0.x, y0.v);
    c.J = SUNSparseMatrix(2 * d, 2 * d, d + j0.dx.nonZeros() + j0.dv.nonZeros(), CSR_MAT, c.ctx);
    c.ls = SUNLinSol_KLU(c.z, c.J, c.ctx);
  }
#endif
  sundials_frames_or_end(c, blocked_rhs, peer.implicit ? csr_jacobian : nullptr, s, peer, tol, t_end, n, frames,
                         [&] { return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(c.data(), d)); });
  const Eigen::Map<const Eigen::VectorXd> a(c.data(), 2 * d);
  return {a.head(d), a.tail(d)};
}

[[noreturn]] void not_here(const PeerInfo& peer, const SceneKernel& scene) {
  throw std::logic_error("run_sized_peer: " + std::string(peer.name) + " does not run on the " + std::string(scene.name));
}

}  // namespace

State<Eigen::Dynamic> run_sized_odeint(const PeerInfo&, const SceneKernel& scene, const void* made, double tol, double t_end,
                                       PeerCounts& n, const PeerFrames& frames) {
  return odeint_dopri5({*scene.made, made}, tol, t_end, n, frames);
}

// CVODE or ARKODE, explicit or with the peer's linear solver: band on z interleaved, KLU on z blocked.
State<Eigen::Dynamic> run_sized_sundials(const PeerInfo& peer, const SceneKernel& scene, const void* made, double tol,
                                         double t_end, PeerCounts& n, const PeerFrames& frames) {
  const MadeScene s{*scene.made, made};
  if (peer.linear_solver == LinearSolver::Band) return sundials_band(s, scene.jacobian_bandwidth, peer, tol, t_end, n, frames);
  return sundials_blocked(s, peer, tol, t_end, n, frames);
}

State<Eigen::Dynamic> run_sized_radau5(const PeerInfo&, const SceneKernel& scene, const void* made, double tol, double t_end,
                                       PeerCounts& n, const PeerFrames& frames) {
  return Radau5Sized::run({*scene.made, made}, scene.jacobian_bandwidth, tol, t_end, n, frames);
}

State<Eigen::Dynamic> run_sized_peer(const PeerInfo& peer, const SceneKernel& scene, const void* made, double tol, double t_end,
                                     PeerCounts& n, const PeerFrames& frames) {
  if (!scene.made || !peer.built || !peer.lib->run_sized || !peer_runs_on(peer, peer_scenes(scene))) not_here(peer, scene);
  return peer.lib->run_sized(peer, scene, made, tol, t_end, n, frames);
}

State<Eigen::Dynamic> run_sized_peer(const PeerInfo& peer, std::size_t scene, std::span<const double> params, double tol,
                                     double t_end, PeerCounts& n) {
  const SceneKernel& s = scene_kernel(scene);
  if (!s.make) throw std::logic_error("run_sized_peer: the " + std::string(s.name) + " is not of run-time size");
  const std::shared_ptr<const void> made = s.make(params);
  return run_sized_peer(peer, s, made.get(), tol, t_end, n);
}

}  // namespace steplab
