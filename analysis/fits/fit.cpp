#include "analysis/fits/fit.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <boost/math/distributions/students_t.hpp>

namespace steplab {

double student_t95(int dof) {
  if (dof < 1) return std::numeric_limits<double>::infinity();
  return boost::math::quantile(boost::math::students_t_distribution<double>(dof), 0.975);
}

// With means x̄, ȳ:  slope = Sxy / Sxx,  Sxx = Σ (x - x̄)^2,  Sxy = Σ (x - x̄)(y - ȳ);
// residual variance s^2 = Σ r^2 / (n - 2);  se(slope) = s / sqrt(Sxx);
// 95 % interval: slope ± t_{0.975, n-2} se;  R^2 = 1 - Σ r^2 / Syy.
LineFit fit_line(std::span<const double> x, std::span<const double> y) {
  const std::size_t n = x.size();
  if (n != y.size() || n < 2) throw std::invalid_argument("fit_line needs at least two points");
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) mx += x[i], my += y[i];
  mx /= static_cast<double>(n), my /= static_cast<double>(n);
  double sxx = 0, sxy = 0, syy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
    syy += (y[i] - my) * (y[i] - my);
  }
  if (!(sxx > 0)) throw std::invalid_argument("fit_line needs distinct x");
  LineFit f;
  f.n = static_cast<int>(n);
  f.slope = sxy / sxx;
  f.intercept = my - f.slope * mx;
  double ssr = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = y[i] - (f.intercept + f.slope * x[i]);
    ssr += r * r;
  }
  f.r2 = syy > 0 ? 1 - ssr / syy : 1;
  if (n > 2) {
    f.slope_se = std::sqrt(ssr / static_cast<double>(n - 2) / sxx);
    const double half = student_t95(static_cast<int>(n - 2)) * f.slope_se;
    f.ci95_lo = f.slope - half;
    f.ci95_hi = f.slope + half;
  } else {
    f.ci95_lo = -std::numeric_limits<double>::infinity();
    f.ci95_hi = std::numeric_limits<double>::infinity();
  }
  return f;
}

}  // namespace steplab
