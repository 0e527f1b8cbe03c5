// The peers (analysis/peers.hpp) of the scaling study (analysis/scaling.cpp) on the scenes of
// run-time size, each on the first-order system with the state of run-time size:
//   SUNDIALS CVODE (Adams or BDF as the peer's settings say), Newton on the scene's analytic
//   Jacobian, on
//     the rope: its banded linear solver (SUNBandMatrix, SUNLinSol_Band: LAPACK-style banded LU).
//       The state interleaved, z = (x_1, v_1, x_2, v_2, ...), makes the Jacobian a band: row 2i
//       (x_i' = v_i) reaches column 2i+1, row 2i+1 (v_i') columns 2i-2 .. 2i+3: upper bandwidth 2,
//       lower 3.
//     the soft body: KLU (SUNSparseMatrix in CSR, SUNLinSol_KLU: SuiteSparse's sparse LU for
//       circuit-like matrices, its ordering and symbolic analysis once, refactorised after), z =
//       (x, v), J = [[0, I], [M^-1 dF/dx, M^-1 dF/dv]]; the grid's bandwidth ~ 2n would make a
//       band solver pay n^2 per row.
//   Boost.Odeint's controlled runge_kutta_dopri5 on an Eigen::VectorXd state (vector-space algebra,
//     odeint's external/eigen support), z = (x, v).
// All at rtol = atol = tol, from the scene's start to t_end; they return the end state and count
// (analysis/counts.hpp).
#pragma once

#include <Eigen/Core>

#include "analysis/peers.hpp"
#include "core/scenes/rope.hpp"
#include "core/scenes/softbody.hpp"

namespace steplab {

// `peer` one of peers_on(PeerScenes::Rope) or peers_on(PeerScenes::SoftBody) but dopri5 (steplab's
// own runs through the kernel table).
State<Eigen::Dynamic> run_sized_peer(const PeerInfo& peer, const Rope& r, double tol, double t_end, PeerCounts& n);
State<Eigen::Dynamic> run_sized_peer(const PeerInfo& peer, const SoftBody& s, double tol, double t_end, PeerCounts& n);

}  // namespace steplab
