// Unit tests for analysis/fit.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "analysis/fits/fit.hpp"

namespace steplab {
namespace {

TEST(FitLine, ExactLine) {
  const std::vector<double> x{1, 2, 3, 4}, y{3, 5, 7, 9};
  const LineFit f = fit_line(x, y);
  EXPECT_DOUBLE_EQ(f.slope, 2.0);
  EXPECT_DOUBLE_EQ(f.intercept, 1.0);
  EXPECT_DOUBLE_EQ(f.r2, 1.0);
  EXPECT_NEAR(f.ci95_lo, 2.0, 1e-12);
  EXPECT_NEAR(f.ci95_hi, 2.0, 1e-12);
}

TEST(FitLine, StudentQuantiles) {
  // Tabulated two-sided 95 % values.
  EXPECT_NEAR(student_t95(1), 12.706, 1e-3);
  EXPECT_NEAR(student_t95(5), 2.571, 1e-3);
  EXPECT_NEAR(student_t95(30), 2.042, 1e-3);
}

TEST(FitLine, KnownInterval) {
  // x = 0..4, y = 2x + (0, 1, -1, 1, -1): Sxx = 10, slope = 2 + (0*-2 + 1*-1 + -1*0 + 1*1 + -1*2)/10 = 1.8
  const std::vector<double> x{0, 1, 2, 3, 4}, y{0, 3, 3, 7, 7};
  const LineFit f = fit_line(x, y);
  EXPECT_NEAR(f.slope, 1.8, 1e-12);
  // residual sum of squares: intercept 0.6 -> residuals (-0.6, 0.6, -1.2, 1.0, -0.8): 3.6
  const double se = std::sqrt(3.6 / 3 / 10);
  EXPECT_NEAR(f.slope_se, se, 1e-12);
  EXPECT_NEAR(f.ci95_hi - f.slope, student_t95(3) * se, 1e-12);
}

}  // namespace
}  // namespace steplab
