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
// SUNDIALS' ark_kepler --check-order also reports the pairwise orders; we keep them too.
//
// A caveat the report states: truncation error is smooth, not random. Over any window the
// slope's bias and the interval's width both come from the same curvature, so their ratio is
// fixed by the window's shape (about 2.2 for a first-order correction c dt): the interval
// covers the declared order only where round-off noise, not truncation, dominates the residuals.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "analysis/fit.hpp"

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
  LineFit line;              // slope = order
  double dt_lo = 0, dt_hi = 0;
  std::vector<double> local_slopes;  // pairwise orders over the kept points, by decreasing dt
  double extrapolated = 0;   // Aitken delta-squared limit of the local slopes (NaN if not defined)
  std::string note;          // why there is no order, if there is none
  int diverged_skipped = 0;  // diverged runs (non-finite state) left out of the fit
};

inline constexpr double kSettleTolerance = 0.01;   // local slopes within 1 % of the reference
inline constexpr double kSettleNoiseFactor = 4;   // ... or within 4 sigma of their noise
inline constexpr int kMinFitPoints = 3;

OrderFit fit_order(std::span<const ErrorPoint> points);

}  // namespace steplab
