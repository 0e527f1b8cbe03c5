// The peers of the scaling study (analysis/scaling.cpp) on the scenes of run-time size, each on
// the first-order system with the state of run-time size:
//   SUNDIALS CVODE, BDF with Newton and the scene's analytic Jacobian, on
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
// steps, right side and Jacobian evaluations.
#pragma once

#include <Eigen/Core>

#include "analysis/peers.hpp"
#include "core/scenes/rope.hpp"
#include "core/scenes/softbody.hpp"

namespace steplab {

State<Eigen::Dynamic> cvode_band_rope(const Rope& r, double tol, double t_end, PeerCounts& n);
State<Eigen::Dynamic> cvode_klu_softbody(const SoftBody& s, double tol, double t_end, PeerCounts& n);
State<Eigen::Dynamic> odeint_dopri5_rope(const Rope& r, double tol, double t_end, PeerCounts& n);
State<Eigen::Dynamic> odeint_dopri5_softbody(const SoftBody& s, double tol, double t_end, PeerCounts& n);

}  // namespace steplab
