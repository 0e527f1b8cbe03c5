// Hairer's RADAU5 as the studies call it (analysis/peers/peers.hpp; built by tools/radau5.cmake):
// Radau IIA of order 5 (three stages), Newton on the transformed stage system (one real and one
// complex linear system of the size n of z), its own step-size control (Gustafsson's predictive
// controller, its default), the Jacobian refreshed when Newton's contraction asks for it (its
// WORK(3) = 0.001, the default), the step kept when h_new / h lies in [1, 1.2] (saving a
// factorisation), at rtol = atol = tol as given (RADAU5 maps them to 0.1 tol^(2/3) itself).
//
// A mechanical system is given as Hairer advises for second-order systems (IWORK(9) = M1,
// IWORK(10) = M2): z = (x, v), x' = v, so M1 = M2 = n/2 and RADAU5 eliminates the trivial half of
// every linear system (its systems are n/2, not n, unknowns); the Jacobian it takes is then the
// non-trivial rows only, [M^-1 dF/dx, M^-1 dF/dv] (n/2 x n), full or, where the scene declares its
// Jacobians banded, the two n/2 x n/2 blocks stored diagonal-wise (LAPACK's band layout, bandwidth
// b below and above).
//
// Output between steps is RADAU5's collocation polynomial (its CONTR5): after a step from t_o to t
// of length h, with s = (tau - t)/h in [-1, 0] and c1, c2 the first two Radau nodes,
//   z(tau) = c_0 + s (c_1 + (s - c2 + 1) (c_2 + (s - c1 + 1) c_3)),
// c_k the four n-vectors RADAU5 hands to its output routine (CONT).
#pragma once

#include <cmath>
#include <functional>
#include <span>

#include "analysis/peers/peers.hpp"

namespace steplab {

// What RADAU5 solves, by callbacks on the caller's context.
struct Radau5Problem {
  int n = 0;          // the size of z = (x, v)
  int bandwidth = -1; // of dF/dx and dF/dv: -1 full; b >= 0 banded
  const void* context = nullptr;
  // z' = f(t, z), all n entries
  void (*f)(const void* context, double t, const double* z, double* dz) = nullptr;
  // the Jacobian's non-trivial rows: full, dfy(i, j) = d(v'_i)/dz_j at dfy[i + j ld];
  // banded, d(v'_i)/dz_(j + k n/2) at dfy[(i - j + b) + (j + k n/2) ld], k = 0 (x), 1 (v)
  void (*jacobian)(const void* context, double t, const double* z, double* dfy, int ld) = nullptr;
};

// After every accepted step, from t_old to t: z at t and the collocation polynomial's coefficients.
struct Radau5Step {
  double t_old, t;
  std::span<const double> z, cont;  // cont: 4 n entries
  // z(tau), tau in [t_old, t], into out (n entries)
  void dense(double tau, double* out) const {
    static const double c1m1 = (4 - std::sqrt(6.0)) / 10 - 1, c2m1 = (4 + std::sqrt(6.0)) / 10 - 1;
    const std::size_t n = z.size();
    const double s = (tau - t) / (t - t_old);
    for (std::size_t i = 0; i < n; ++i)
      out[i] = cont[i] + s * (cont[i + n] + (s - c2m1) * (cont[i + 2 * n] + (s - c1m1) * cont[i + 3 * n]));
  }
};

// RADAU5 from z (the start, at t = 0; left at t_end) to t_end; `after_step` after each accepted
// step. Counts into n: steps accepted, rejected (every step computed and not accepted: error test
// or Newton failure), right-side and Jacobian evaluations, LU decompositions (one real and one
// complex each), Newton iterations (each one solve of both systems). n.failed if RADAU5 stopped
// before t_end. One run at a time in a process: RADAU5 keeps its band sizes and output scaling in
// COMMON blocks (the runs take a lock).
void radau5_solve(const Radau5Problem& problem, double* z, double tol, double t_end, PeerCounts& n,
                  const std::function<void(const Radau5Step&)>& after_step = {});

// Whether this steplab has RADAU5 (tools/radau5.cmake).
bool have_radau5();

}  // namespace steplab
