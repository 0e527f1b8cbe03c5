// Convergence order from an error table: the least-squares slope of log(error) on log(dt) over
// the asymptotic range, found from the data alone (the declared order is never used to choose).
//
//   1. Drop diverged runs and points at the round-off floor (error <= floor, given per point).
//   2. If no point is left above the floor and none diverged, the method is exact here.
//   3. Local slopes between neighbours (by dt): s_k = ln(e_{k+1}/e_k) / ln(dt_{k+1}/dt_k).
//      The reference slope is the median of the (up to) three local slopes at the smallest steps.
//      The asymptotic range grows from the smallest step towards larger ones while each local
//      slope stays within the tolerance of the reference: kSettleTolerance relative (of
//      max(1, |reference|)), or kSettleNoiseFactor times the local slopes' own noise if larger
//      (estimated from their second differences, which a smooth trend hardly moves); a single
//      slope out of tolerance between settled ones is taken as noise, two in a row end the range;
//      larger steps are pre-asymptotic (the slope has not settled).
//   4. Fit that range (at least 3 points): slope, 95 % interval (Student t), R^2.
//   5. Extrapolated order: the local slopes approach the order like s(dt) = p + c dt^q; Aitken's
//      delta-squared on the last three settled local slopes estimates the limit p, where that
//      trend is there to see (changes shrinking by a ratio in (0, 1), not noise).
//   6. The headline order: the asymptotic one. Truncation error is smooth, not random, so the
//      window's least-squares slope is biased by the next error term, and its Student-t interval
//      (whose width comes from the same smooth curvature) misses the true order as often as not:
//      1.005 [1.003, 1.007] for explicit Euler on the spring. So the next term is modelled:
//         ln e = a + p ln dt + b (dt / dt_hi)^q,   q = 1 or 2 (a symmetric method's error
//      expands in dt^2), whichever fits the window better: linear least squares in (a, p, b).
//      Its interval is named for what it is, a bound and not a confidence interval:
//         p +- (t95 max(se_1, se_2) + max(|p - p'|, |p_1 - p_2|))
//      round-off noise (95 %, n - 3 degrees of freedom, the larger standard error of the two
//      models) plus the truncation left over: p' is the same fit without the window's two
//      smallest steps (its bias is larger than p's by the factor (dt ratio)^(2q) at least, so
//      |p - p'| bounds p's own), and p_1, p_2 are the two models' estimates (which next term).
//      Fewer than 5 points in the window: the plain slope and its interval stand in, and
//      correction_power is 0.
//   7. What the fit cannot vouch for, said beside it: a window of fewer than 5 points (q = 0: the
//      plain slope's Student-t interval, which a smooth next term biases; it can exclude the true
//      order); errors that do not approach their order monotonically in the window (an error not
//      below the one at the next larger step, or local orders that turn, down then up or up then
//      down, by more than kSettleTolerance each way: the error crosses zero or changes regime,
//      and a slope through it is not an order); a bound wider than +-kWideBound (the fit says
//      too little to be a finding).
// SUNDIALS' ark_kepler --check-order also reports the pairwise orders; we keep them too.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "analysis/fits/fit.hpp"

namespace steplab {

struct ErrorPoint {
  double dt;
  double error;
  double floor;   // round-off floor for this point; error <= floor is not fitted
  bool diverged;
};

struct OrderFit {
  bool exact = false;        // every point at the round-off floor
  bool fitted = false;       // enough points in an asymptotic range
  double order = 0;          // the headline: the asymptotic order (step 6)
  double bound_lo = 0, bound_hi = 0;  // its bound: noise (95 %) plus truncation left over
  int correction_power = 0;  // q of the modelled next term; 0: too few points, the plain slope
  LineFit line;              // the window's least-squares slope and its Student-t interval
  double dt_lo = 0, dt_hi = 0;
  std::vector<double> local_slopes;  // pairwise orders over the kept points, by decreasing dt
  double extrapolated = 0;   // Aitken delta-squared limit of the local slopes (NaN if not defined)
  std::string note;          // why there is no order, if there is none
  int diverged_skipped = 0;  // diverged runs (non-finite state) left out of the fit
  bool few_points = false;   // fitted over fewer than 5 points: the plain slope (step 7)
  bool non_monotone = false; // the errors do not approach their order monotonically in the window (step 7)
  bool wide = false;         // the bound is wider than +-kWideBound (step 7)
  bool trusted() const { return fitted && !few_points && !non_monotone && !wide; }
};

inline constexpr int kCorrectedFitPoints = 5;  // fewer: the plain slope stands in (step 6)
inline constexpr double kWideBound = 0.5;      // a bound wider than +-0.5 is not a finding (step 7)

inline constexpr double kSettleTolerance = 0.01;   // local slopes within 1 % of the reference
inline constexpr double kSettleNoiseFactor = 4;   // ... or within 4 sigma of their noise
inline constexpr int kMinFitPoints = 3;

OrderFit fit_order(std::span<const ErrorPoint> points);

}  // namespace steplab
