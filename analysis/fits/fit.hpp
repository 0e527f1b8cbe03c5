// Straight-line least squares with its quality (Google Benchmark's LeastSq in spirit): the
// slope, its 95 % confidence interval from Student's t with n - 2 degrees of freedom, R^2.
#pragma once

#include <span>

namespace steplab {

struct LineFit {
  double slope = 0, intercept = 0;
  double slope_se = 0;          // standard error of the slope
  double ci95_lo = 0, ci95_hi = 0;
  double r2 = 0;
  int n = 0;
};

// Fits y = intercept + slope x. Needs n >= 2 points with distinct x; with n = 2 the interval is
// unbounded (reported as -inf, inf).
LineFit fit_line(std::span<const double> x, std::span<const double> y);

// Two-sided 95 % quantile of Student's t with `dof` degrees of freedom (12.706 for 1, 1.96 as dof -> inf).
double student_t95(int dof);

}  // namespace steplab
