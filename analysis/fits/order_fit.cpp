#include "analysis/fits/order_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

namespace steplab {
namespace {

struct Corrected {
  double p, se, rss;
  int dof;
};

// ln e = a + p ln dt + b (dt / dt_hi)^q by least squares (QR), with se(p) from the residuals.
Corrected fit_corrected(const std::vector<ErrorPoint>& pts, int q) {
  const int n = static_cast<int>(pts.size());
  Eigen::MatrixXd X(n, 3);
  Eigen::VectorXd y(n);
  const double top = pts.front().dt;
  for (int i = 0; i < n; ++i) {
    X(i, 0) = 1;
    X(i, 1) = std::log(pts[i].dt);
    X(i, 2) = std::pow(pts[i].dt / top, q);
    y[i] = std::log(pts[i].error);
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(X);
  const Eigen::VectorXd beta = qr.solve(y);
  const double rss = (X * beta - y).squaredNorm();
  const int dof = n - 3;
  const Eigen::MatrixXd cov = (X.transpose() * X).inverse();
  return {beta[1], dof > 0 ? std::sqrt(rss / dof * cov(1, 1)) : 0.0, rss, dof};
}

// Step 6 on the window's points (by decreasing dt).
void asymptotic_order(const std::vector<ErrorPoint>& window, OrderFit& out) {
  if (window.size() < kCorrectedFitPoints) {
    out.order = out.line.slope;
    out.bound_lo = out.line.ci95_lo;
    out.bound_hi = out.line.ci95_hi;
    out.correction_power = 0;
    return;
  }
  const Corrected c1 = fit_corrected(window, 1), c2 = fit_corrected(window, 2);
  const bool second = c2.rss < c1.rss;
  const Corrected& c = second ? c2 : c1;
  out.correction_power = second ? 2 : 1;
  const std::vector<ErrorPoint> upper(window.begin(), window.end() - (window.size() >= 6 ? 2 : 1));
  const double shifted = fit_corrected(upper, out.correction_power).p;
  // noise: the larger of the two models' standard errors (choosing the model by its residual
  // makes the chosen one's look smaller than it is); truncation: the larger of the window shift
  // and the disagreement between the two models of the next term
  const double noise = student_t95(c.dof) * std::max(c1.se, c2.se);
  const double truncation = std::max(std::abs(c.p - shifted), std::abs(c1.p - c2.p));
  const double half = noise + truncation;
  out.order = c.p;
  out.bound_lo = c.p - half;
  out.bound_hi = c.p + half;
}

}  // namespace

OrderFit fit_order(std::span<const ErrorPoint> points) {
  OrderFit out;
  std::vector<ErrorPoint> kept;
  bool any_diverged = false;
  for (const ErrorPoint& p : points) {
    if (p.diverged || !std::isfinite(p.error)) any_diverged = true, ++out.diverged_skipped;
    else if (p.error > p.floor) kept.push_back(p);
  }
  if (kept.empty()) {
    out.exact = !any_diverged && !points.empty();
    out.note = out.exact ? "every error at the round-off floor" : "no finite error above the round-off floor";
    return out;
  }
  std::sort(kept.begin(), kept.end(), [](const ErrorPoint& a, const ErrorPoint& b) { return a.dt > b.dt; });
  for (std::size_t k = 0; k + 1 < kept.size(); ++k)
    out.local_slopes.push_back(std::log(kept[k + 1].error / kept[k].error) / std::log(kept[k + 1].dt / kept[k].dt));

  const auto& s = out.local_slopes;
  if (s.size() < 2) {
    out.note = "fewer than 3 points above the round-off floor";
    return out;
  }
  std::vector<double> tail(s.end() - std::min<std::ptrdiff_t>(3, static_cast<std::ptrdiff_t>(s.size())), s.end());
  std::sort(tail.begin(), tail.end());
  const double reference = tail[tail.size() / 2];
  // Noise of the local slopes, from their second differences over the last six (at the smallest
  // steps, where the range is anchored; further out a pre-asymptotic trend's curvature would pass
  // for noise): a settling trend hardly moves them, noise of standard deviation sigma makes them
  // N(0, 6 sigma^2), whose median |.| is 0.6745 sqrt(6) sigma.
  double sigma = 0;
  if (s.size() >= 3) {
    std::vector<double> d2;
    for (std::size_t k = s.size() - std::min<std::size_t>(s.size(), 6); k + 2 < s.size(); ++k)
      d2.push_back(std::abs(s[k + 2] - 2 * s[k + 1] + s[k]));
    std::nth_element(d2.begin(), d2.begin() + d2.size() / 2, d2.end());
    sigma = d2[d2.size() / 2] / (0.6745 * std::sqrt(6.0));
  }
  const double tol = std::max(kSettleTolerance * std::max(1.0, std::abs(reference)), kSettleNoiseFactor * sigma);
  std::size_t first = s.size();  // first settled local slope (index into s)
  // A single local slope out of tolerance between settled ones is noise, not a trend: the range
  // ends at two in a row (a smooth pre-asymptotic trend, once out, stays out).
  const auto settled = [&](std::size_t k) { return std::abs(s[k] - reference) <= tol; };
  for (std::size_t k = s.size(); k-- > 0;) {
    if (settled(k)) first = k;
    else if (!(k > 0 && settled(k - 1))) break;
  }
  const std::size_t n_points = s.size() - first + 1;  // slopes first..end span these points
  if (static_cast<int>(n_points) < kMinFitPoints) {
    out.note = "fewer than 3 points in a settled range";
    return out;
  }
  const std::size_t best_i = first;
  // Aitken's delta-squared presumes the local slopes approach their limit geometrically: their
  // successive changes shrink by a ratio in (0, 1). Where noise set the tolerance, or the
  // changes do not shrink, there is no trend to extrapolate and the estimate is left out.
  out.extrapolated = std::numeric_limits<double>::quiet_NaN();
  const bool noisy = kSettleNoiseFactor * sigma > kSettleTolerance * std::max(1.0, std::abs(reference));
  if (s.size() - first >= 3 && !noisy) {
    const double s1 = s[s.size() - 3], s2 = s[s.size() - 2], s3 = s[s.size() - 1];
    const double ratio = (s3 - s2) / (s2 - s1);
    if (ratio > 0 && ratio < 1) out.extrapolated = s3 - (s3 - s2) * (s3 - s2) / ((s3 - s2) - (s2 - s1));
  }
  std::vector<double> lx, ly;
  for (std::size_t k = best_i; k < best_i + n_points; ++k) {
    lx.push_back(std::log(kept[k].dt));
    ly.push_back(std::log(kept[k].error));
  }
  out.line = fit_line(lx, ly);
  out.fitted = true;
  asymptotic_order(std::vector<ErrorPoint>(kept.begin() + best_i, kept.begin() + best_i + n_points), out);
  out.dt_hi = kept[best_i].dt;
  out.dt_lo = kept[best_i + n_points - 1].dt;
  out.few_points = static_cast<int>(n_points) < kCorrectedFitPoints;
  for (std::size_t k = best_i; k + 1 < best_i + n_points; ++k) out.non_monotone = out.non_monotone || !(kept[k + 1].error < kept[k].error);
  const double turn = kSettleTolerance * std::max(1.0, std::abs(reference));  // the window's slopes: s[first .. end)
  for (std::size_t k = first; k + 2 < s.size(); ++k) {
    const double d1 = s[k + 1] - s[k], d2 = s[k + 2] - s[k + 1];
    if (d1 * d2 < 0 && std::min(std::abs(d1), std::abs(d2)) > turn) out.non_monotone = true;
  }
  out.wide = out.bound_hi - out.bound_lo > 2 * kWideBound;
  return out;
}

}  // namespace steplab
