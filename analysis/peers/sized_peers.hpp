// The peers (analysis/peers/peers.hpp) of the scaling study (analysis/studies/scaling.cpp) on the scenes of
// run-time size, each on the first-order system with the state of run-time size, the scene
// reached through the kernel table (SceneKernel::made):
//   SUNDIALS CVODE (Adams or BDF as the peer's settings say), Newton on the scene's analytic
//   Jacobian, with
//     a banded linear solver where the scene declares dF/dx and dF/dv banded (jacobian_bandwidth
//       b: the rope's are tridiagonal, b = 1): SUNBandMatrix, SUNLinSol_Band (LAPACK-style banded
//       LU). The state interleaved, z = (x_1, v_1, x_2, v_2, ...), makes the Jacobian a band: row
//       2i (x_i' = v_i) reaches column 2i+1, row 2i+1 (v_i') columns 2(i-b) .. 2(i+b)+1: upper
//       bandwidth 2b, lower 2b+1.
//     KLU elsewhere (the soft body: its grid's bandwidth ~ 2n would make a band solver pay n^2 per
//       row): SUNSparseMatrix in CSR, SUNLinSol_KLU (SuiteSparse's sparse LU for circuit-like
//       matrices, its ordering and symbolic analysis once, refactorised after), z = (x, v),
//       J = [[0, I], [M^-1 dF/dx, M^-1 dF/dv]].
//   Boost.Odeint's controlled runge_kutta_dopri5 on an Eigen::VectorXd state (vector-space algebra,
//     odeint's external/eigen support), z = (x, v).
// All at rtol = atol = tol, from the scene's start to t_end; they return the end state and count
// (analysis/kernel/counts.hpp).
#pragma once

#include <functional>

#include "analysis/kernel/kernel.hpp"
#include "analysis/peers/peers.hpp"

namespace steplab {

// Output at frames: the positions at t_k = k t_end / count, k = 1 .. count, handed to `at` as each
// is reached. CVODE interpolates them in its normal mode (its steps nearly those of a run without
// output); Boost.Odeint's controlled stepper steps to each, as its integrate_times does.
struct PeerFrames {
  int count = 0;  // 0: no frames, the run steps straight to t_end
  std::function<void(int k, const Eigen::VectorXd& x)> at;
};

// `peer` one of peers_on(peer_scenes(scene)) but dopri5 (steplab's own runs through the kernel
// table), on the scene `made` by scene.make(params).
State<Eigen::Dynamic> run_sized_peer(const PeerInfo& peer, const SceneKernel& scene, const void* made, double tol, double t_end,
                                     PeerCounts& n, const PeerFrames& frames = {});
// The libraries' code behind it (their rows, analysis/peers/peers.cpp).
State<Eigen::Dynamic> run_sized_odeint(const PeerInfo& peer, const SceneKernel& scene, const void* made, double tol, double t_end,
                                       PeerCounts& n, const PeerFrames& frames);
State<Eigen::Dynamic> run_sized_sundials(const PeerInfo& peer, const SceneKernel& scene, const void* made, double tol,
                                         double t_end, PeerCounts& n, const PeerFrames& frames);
State<Eigen::Dynamic> run_sized_radau5(const PeerInfo& peer, const SceneKernel& scene, const void* made, double tol, double t_end,
                                       PeerCounts& n, const PeerFrames& frames);
// The same on scene `scene` of the table with these parameters, made here.
State<Eigen::Dynamic> run_sized_peer(const PeerInfo& peer, std::size_t scene, std::span<const double> params, double tol,
                                     double t_end, PeerCounts& n);

}  // namespace steplab
