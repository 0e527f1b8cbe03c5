// The peers of the scaling study (analysis/scaling.cpp) on the rope of N masses, each on the
// first-order system of the rope with the state of run-time size:
//   SUNDIALS CVODE, BDF with Newton on its banded linear solver (SUNBandMatrix, SUNLinSol_Band:
//     LAPACK-style banded LU) and the rope's analytic Jacobian. The state interleaved,
//     z = (x_1, v_1, x_2, v_2, ...), makes the Jacobian a band: row 2i (x_i' = v_i) reaches
//     column 2i+1, row 2i+1 (v_i') columns 2i-2 .. 2i+3: upper bandwidth 2, lower 3.
//   Boost.Odeint's controlled runge_kutta_dopri5 on an Eigen::VectorXd state (vector-space algebra,
//     odeint's external/eigen support), z = (x, v).
// Both at rtol = atol = tol, from the rope's start to t_end; they return the end state and count
// steps, right side and Jacobian evaluations.
#pragma once

#include <Eigen/Core>

#include "analysis/peers.hpp"
#include "core/scenes/rope.hpp"

namespace steplab {

State<Eigen::Dynamic> cvode_band_rope(const Rope& r, double tol, double t_end, PeerCounts& n);
State<Eigen::Dynamic> odeint_dopri5_rope(const Rope& r, double tol, double t_end, PeerCounts& n);

}  // namespace steplab
