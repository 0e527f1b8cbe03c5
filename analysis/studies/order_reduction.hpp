// Does the order hold when the system is stiff? The order each method keeps in the non-stiff and
// the stiff limit, from theory, and the measured order against stiffness (a convergence sweep,
// analysis/studies/convergence.hpp) marked against both.
//
// The theory (Prothero & Robinson, Math. Comp. 28, 1974; Hairer & Wanner, Solving ODEs II, IV.15).
// On y' = lambda (y - phi(t)) + phi'(t), whose solution is y = phi whatever lambda, a Runge-Kutta
// method (A, b, c; order p, stage order q: c^k = k A c^(k-1) for k <= q) with z = h lambda makes
// the error e_n = y_n - phi(t_n) obey
//
//   e_{n+1} = R(z) e_n + delta_n,    delta_n = -z b^T (I - z A)^-1 D0 - D1,
//   D0_i = phi(t_n + c_i h) - phi(t_n) - h sum_j a_ij phi'(t_n + c_j h)
//        = sum_{k > q} h^k / k! (c^k - k A c^(k-1))_i phi^(k)      (the stages' defects, O(h^(q+1)))
//   D1   = phi(t_n + h) - phi(t_n) - h b^T phi'(t_n + c h)   (the quadrature's, O(h^(p+1)))
//
// For |z| small delta = O(h^(p+1)) and the order is p (the non-stiff limit). For |z| -> infinity,
// -z b^T (I - z A)^-1 = b^T A^-1 + z^-1 b^T A^-2 + O(z^-2) and R(z) -> R(inf) = 1 - b^T A^-1 1:
//   - stiffly accurate (b^T = the last row of A, so b^T A^-1 = e_s^T, c_s = 1): b^T A^-1 D0 = D1
//     exactly, so delta = z^-1 b^T A^-2 D0 = O(h^(q+1) / z) = O(h^q / lambda), and with
//     |R(inf)| < 1 the errors do not pile up: e = O(h^q / lambda), order q at a fixed lambda
//     (Radau IIA 5: q = 3, b^T A^-2 (c^4 - 4 A c^3) / 4! = -1/80; implicit Euler: q = p = 1);
//   - otherwise delta = O(h^(q+1)) (b^T A^-1 (c^(q+1) - (q+1) A c^q) is not 0 for the Gauss or
//     midpoint rules) and
//       |R(inf)| < 1: e = O(delta), order q + 1;
//       R(inf) = -1: successive errors alternate in sign and nearly cancel, e = O(delta), order
//         q + 1 (implicit midpoint: q = 1, order 2, no loss);
//       R(inf) = +1: nothing damps them, e ~ (t / h) delta, order q (Gauss-Legendre 4: q = 2).
//         Only once h^2 |lambda| >= C t, though: 1 - R(z) ~ C / |z| (C = |b^T A^-2 1|, 12 for
//         Gauss-Legendre 4) damps the sum over about |z| / C steps, so while t / h exceeds that
//         e ~ delta |z| / C = O(h^(q+2) lambda): the classical order 4, its error growing as lambda.
//   each capped at p.
// A linear multistep method (BDF) evaluates f at the grid only: its local error sum_j alpha_j
// phi(t_{n+j}) - h beta_k phi'(t_{n+k}) = O(h^(p+1)) is the same for every lambda, and as z grows
// the roots of rho(zeta) - z sigma(zeta) tend to those of sigma = beta_k zeta^k, all 0: e ~
// -(h beta_k lambda)^-1 tau = O(h^p / lambda), order p but vanishing as lambda grows. What stays
// is the error of its first steps, made by a one-step method (its Starter): Gauss-Legendre 4 for
// the BDF, whose local error in the stiff limit is O(h^(q+1)) = O(h^3), then damped by the BDF.
// So the largest error along the run has order 3 in the stiff limit, for BDF2 too (the error at
// t_end keeps p). An explicit method is unstable once h |lambda| passes its stability interval:
// it has no stiff limit.
//
// A scene of second order (x'' = ...) is this problem with lambda a 2 x 2 matrix; its eigenvalues
// set the stiffness. The stiffest mode's eigenvalue of smallest modulus is the one that must be
// large for the stiff limit (stiff_rate); the orders above hold per eigenvalue.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "analysis/studies/convergence.hpp"
#include "analysis/studies/defaults.hpp"

namespace steplab {

struct StiffTheory {
  int classical = 0;        // p: the order in the non-stiff limit
  int stiff = -1;           // the order in the stiff limit (h |lambda| -> infinity, lambda fixed); -1: none
  int stage_order = -1;     // q, for a method with a Butcher tableau; -1 otherwise
  double r_infinity = 0;    // R(infinity), for a method with a Butcher tableau
  bool stiffly_accurate = false;
  // R(inf) = 1: C in 1 - R(z) ~ C / |z| (|b^T A^-2 1|; 12 for Gauss-Legendre 4): the stiff order
  // shows only where h^2 |lambda| >= C t, the errors then adding up undamped over the run. 0 otherwise.
  double long_run = 0;
  std::string rule;         // the rule above that gives `stiff`, in words
};

// The theory for a method of the table: from its Butcher tableau (core/method.hpp), its family
// (BDF) and its step map's stability as h |lambda| grows on the negative real axis.
StiffTheory stiff_theory(std::size_t method);


// The tolerances: a limit holds when the measured order is within these of the theory's
// (or the fit's bound contains it).
inline constexpr double kNonStiffTolerance = 0.05, kStiffTolerance = 0.15;
// A fit is in the stiff limit when h |lambda| >= this at its smallest step; in the non-stiff limit
// when h |lambda_max| <= kNonStiffRegime at its largest (lambda_max: the largest modulus).
inline constexpr double kStiffRegime = 10, kNonStiffRegime = 0.5;

struct LimitCheck {
  bool reached = false;  // the fit lies in that limit's regime (and, for R(inf) = 1, h^2 |lambda| >= C t)
  bool fitted = false;
  // The fit's order and bound; in the stiff limit the bound is widened by the change from the
  // sweep's value before the last, where that is in the stiff regime too: the order's distance
  // from its limit lambda -> infinity (terms in 1 / (h lambda) the fit cannot model).
  double order = 0, bound_lo = 0, bound_hi = 0;
  bool holds = false;    // reached, fitted, and within tolerance of the theory with the bound containing it
};

struct MethodReduction {
  std::size_t method;
  StiffTheory theory;
  std::vector<double> h_lambda;  // per swept value: h |lambda| at the fit window's geometric centre (NaN: no fit)
  // per swept value: the method's largest stable step on the scene's modes (analysis/
  // mode_stability.hpp; inf where every step is stable), and whether the fit's window reaches
  // past it (its order then mixes stable runs with growing ones: not an order of the method)
  std::vector<double> dt_star;
  std::vector<bool> past_stable;
  LimitCheck non_stiff, stiff;   // at the sweep's first and last value
  // The transition: the order is still p (within kNonStiffTolerance) from the first value up to
  // h|lambda| = keeps_to, and at the stiff order (within kStiffTolerance) from h|lambda| =
  // reduced_from to the last (NaN where not seen).
  double keeps_to = 0, reduced_from = 0;
};

struct OrderReduction {
  ConvergenceSweep sweep;
  // A driven scene's: the theory above applies. An autonomous linear scene's (the chain) numerical
  // flow is R(hA)^n: no forcing is sampled at the stages' times, so nothing reduces the order. Its
  // slow modes converge at p; the fast mode the start excites (amplitude a_f) adds an error
  // a_f |R(h lambda_f)^n - e^(lambda_f t)| that does not shrink with h while |h lambda_f| > 1
  // (at most 2 a_f for an A-stable method): where it exceeds the slow modes' C h^p the fitted
  // order falls towards 0, a plateau, not a lower order. The stiff limit is not checked there.
  bool driven = true;
  // per swept value: |lambda| that sets the stiffness, of the scene's fastest mode (core/scene.hpp,
  // Mode) the eigenvalue of smallest modulus, omega (zeta - sqrt(zeta^2 - 1)) when overdamped,
  // else omega; 0 for a scene that declares no modes
  std::vector<double> rates;
  std::vector<MethodReduction> methods;  // in the sweep's method order
};

// The study each value of the sweep runs: the steps of `d`, on `methods`, fitted to the largest
// position error along the run (the report's section, `steplab study convergence --error max`).
ConvergenceConfig stiff_order_config(std::size_t scene, std::vector<double> params, const StiffOrderDefaults& d,
                                     std::vector<std::size_t> methods);

// The sweep over the scene's stiffness parameter (it must declare one and its modes), each fit
// marked against the theory.
OrderReduction order_reduction(const ConvergenceConfig& config, const std::vector<double>& stiffnesses);
// The same read from a sweep already run (over any parameter that moves the stiffness; checked
// against the stiff limit on a driven scene only).
OrderReduction order_reduction(ConvergenceSweep sweep);

}  // namespace steplab
