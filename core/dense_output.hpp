// Output between steps for the fixed-step methods: the state at any time inside a step, from the
// states at its two ends (core/simulate.hpp asks for it where RunSpec::outputs is set).
//
// On the step [t0, t0 + h], s = (t - t0)/h in [0, 1]:
//
//   cubic Hermite (positions and velocities at both ends; no force evaluated)
//     x(s) = H00 x0 + H10 h v0 + H01 x1 + H11 h v1,
//     H00 = 1 - 3s^2 + 2s^3, H10 = s - 2s^2 + s^3, H01 = 3s^2 - 2s^3, H11 = -s^2 + s^3;
//
//   quintic Hermite (and the accelerations a = M^-1 F at both ends: two force evaluations, or one
//   where the step before held an output too and its end's is kept: core/simulate.hpp)
//     x(s) = Q0 x0 + Q1 h v0 + Q2 h^2 a0 + Q3 h^2 a1 + Q4 h v1 + Q5 x1,
//     Q0 = 1 - 10s^3 + 15s^4 - 6s^5,  Q1 = s - 6s^3 + 8s^4 - 3s^5,  Q2 = (s^2 - 3s^3 + 3s^4 - s^5)/2,
//     Q5 = 10s^3 - 15s^4 + 6s^5,      Q4 = -4s^3 + 7s^4 - 3s^5,     Q3 = (s^3 - 2s^4 + s^5)/2;
//
// the velocity is the interpolant's derivative, v = dx/ds / h. Each reproduces a polynomial of
// degree 3 (5) exactly, so on the exact solution its error is O(h^4) (O(h^6)); on a method's
// states, whose errors are O(h^p) at the ends, the error inside a step is O(h^min(p, 4)) (cubic)
// or O(h^min(p, 6)) (quintic). A method of order p <= 2 takes the cubic (its own error is the
// larger), one of order >= 3 the quintic: the output keeps the method's order. The collocation
// methods (Gauss-Legendre, Radau IIA) also take the quintic: their collocation polynomial is of
// degree s, order s inside the step (Hairer & Wanner II.7: 3 for Radau IIA 5, against its step's
// 5), below the quintic's; RADAU5's own output is that polynomial (analysis/peers/radau5.hpp).
#pragma once

#include "core/scene.hpp"

namespace steplab {

// Whether a method of order p takes the quintic (the accelerations at both ends).
constexpr bool quintic_output(int order) { return order >= 3; }

// The order of the output inside a step: min(p, 4) cubic, min(p, 6) quintic.
constexpr int dense_output_order(int order) { return quintic_output(order) ? (order < 6 ? order : 6) : (order < 4 ? order : 4); }

// x and v at s in [0, 1] of a step of length h from (x0, v0) to (x1, v1), cubic.
template <class V> void hermite3(const V& x0, const V& v0, const V& x1, const V& v1, double h, double s, V& x, V& v) {
  const double s2 = s * s, s3 = s2 * s;
  const double h00 = 1 - 3 * s2 + 2 * s3, h10 = s - 2 * s2 + s3, h01 = 3 * s2 - 2 * s3, h11 = -s2 + s3;
  const double d00 = -6 * s + 6 * s2, d10 = 1 - 4 * s + 3 * s2, d01 = 6 * s - 6 * s2, d11 = -2 * s + 3 * s2;
  x = h00 * x0 + (h10 * h) * v0 + h01 * x1 + (h11 * h) * v1;
  v = (d00 / h) * x0 + d10 * v0 + (d01 / h) * x1 + d11 * v1;
}

// The same, quintic, with the accelerations a0, a1 at the ends.
template <class V>
void hermite5(const V& x0, const V& v0, const V& a0, const V& x1, const V& v1, const V& a1, double h, double s, V& x, V& v) {
  const double s2 = s * s, s3 = s2 * s, s4 = s3 * s, s5 = s4 * s;
  const double q0 = 1 - 10 * s3 + 15 * s4 - 6 * s5, q1 = s - 6 * s3 + 8 * s4 - 3 * s5, q2 = (s2 - 3 * s3 + 3 * s4 - s5) / 2;
  const double q3 = (s3 - 2 * s4 + s5) / 2, q4 = -4 * s3 + 7 * s4 - 3 * s5, q5 = 10 * s3 - 15 * s4 + 6 * s5;
  const double d0 = -30 * s2 + 60 * s3 - 30 * s4, d1 = 1 - 18 * s2 + 32 * s3 - 15 * s4, d2 = (2 * s - 9 * s2 + 12 * s3 - 5 * s4) / 2;
  const double d3 = (3 * s2 - 8 * s3 + 5 * s4) / 2, d4 = -12 * s2 + 28 * s3 - 15 * s4, d5 = 30 * s2 - 60 * s3 + 30 * s4;
  x = q0 * x0 + (q1 * h) * v0 + (q2 * h * h) * a0 + (q3 * h * h) * a1 + (q4 * h) * v1 + q5 * x1;
  v = (d0 / h) * x0 + d1 * v0 + (d2 * h) * a0 + (d3 * h) * a1 + d4 * v1 + (d5 / h) * x1;
}

}  // namespace steplab
