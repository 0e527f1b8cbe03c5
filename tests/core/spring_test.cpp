// Unit tests for core/scenes/spring.hpp: the exact solution satisfies its ODE and its initial
// state in every damping regime, and is continuous across critical damping.
#include <gtest/gtest.h>

#include <cmath>

#include "core/scenes/spring.hpp"

namespace steplab {
namespace {

Spring spring_with(double gamma, double m = 1, double k = 5) {
  const std::array<double, 5> p{m, k, gamma, 5.0, 9.81};
  return Spring(p);
}

double critical(double m = 1, double k = 5) { return 2 * std::sqrt(k * m); }

class SpringRegime : public ::testing::TestWithParam<double> {};  // gamma / critical damping

TEST_P(SpringRegime, StartsAtRestAtRestLength) {
  const Spring s = spring_with(GetParam() * critical());
  const State<1> y0 = exact(s, 0.0);
  EXPECT_NEAR(y0.x[0], -5.0, 1e-14 * 5);
  EXPECT_NEAR(y0.v[0], 0.0, 1e-14);
}

// Residual of m v' + gamma v + k (y + L) + m g = 0 with v' from a central difference of the
// exact velocity (step e = 1e-5: truncation e^2 |v'''| ~ 1e-10 * 50, round-off eps |v| / e ~ 1e-10),
// and v against a central difference of the exact position. Forces are of size m g ~ 10, so
// 1e-7 is far above both errors and far below any mistake in a coefficient.
TEST_P(SpringRegime, SatisfiesTheOde) {
  const double gamma = GetParam() * critical();
  const Spring s = spring_with(gamma);
  const double e = 1e-5;
  for (double t : {0.1, 0.7, 1.3, 2.9, 6.0}) {
    const State<1> a = exact(s, t - e), b = exact(s, t), c = exact(s, t + e);
    const double dv = (c.v[0] - a.v[0]) / (2 * e);
    const double dy = (c.x[0] - a.x[0]) / (2 * e);
    const double residual = s.m * dv + gamma * b.v[0] + s.k * (b.x[0] + s.L) + s.m * s.g;
    EXPECT_NEAR(residual, 0.0, 1e-7) << "t = " << t;
    EXPECT_NEAR(dy, b.v[0], 1e-7) << "t = " << t;
  }
}

// 0: undamped; 0.0224: the sheet's gamma = 0.1; 1: critical; 2: overdamped.
INSTANTIATE_TEST_SUITE_P(Regimes, SpringRegime, ::testing::Values(0.0, 0.1 / (2 * std::sqrt(5.0)), 1.0, 2.0));

// Within 1e-12 of critical damping on either side, the under- and overdamped forms must agree
// with the critical one to a few ulps times the condition of the problem (~1e-12 change in gamma
// moves the solution by ~1e-12): 1e-10 absolute on |y| ~ 7 catches any cancellation.
TEST(SpringExact, ContinuousAcrossCriticalDamping) {
  const double gc = critical();
  for (double t : {0.5, 2.0, 10.0}) {
    const State<1> crit = exact(spring_with(gc), t);
    for (double rel : {1 - 1e-12, 1 + 1e-12, 1 - 1e-8, 1 + 1e-8}) {
      const State<1> near = exact(spring_with(gc * rel), t);
      const double tol = rel == 1 - 1e-12 || rel == 1 + 1e-12 ? 1e-10 : 1e-6;
      EXPECT_NEAR(near.x[0], crit.x[0], tol) << "rel " << rel << " t " << t;
      EXPECT_NEAR(near.v[0], crit.v[0], tol) << "rel " << rel << " t " << t;
    }
  }
}

TEST(SpringExact, SheetFormulaUnderdamped) {
  // y(t) = c1 e^{at} cos(bt) + c2 e^{at} sin(bt) - L - m g / k, c1 = m g / k, c2 = -a c1 / b
  const Spring s = spring_with(0.1);
  const double a = -0.1 / 2, b = std::sqrt(4 * 5 - 0.01) / 2, c1 = 9.81 / 5, c2 = -a * c1 / b;
  for (double t : {0.0, 1.0, 3.7, 10.0}) {
    const double y = c1 * std::exp(a * t) * std::cos(b * t) + c2 * std::exp(a * t) * std::sin(b * t) - 5 - 9.81 / 5;
    EXPECT_NEAR(exact(s, t).x[0], y, 1e-13 * 10);
  }
}

TEST(SpringExact, LongOverdampedRunDoesNotOverflow) {
  const Spring s = spring_with(4 * critical());
  const State<1> y = exact(s, 5000.0);
  EXPECT_TRUE(std::isfinite(y.x[0]));
  EXPECT_NEAR(y.x[0], s.equilibrium(), 1e-9);
}

TEST(SpringEnergy, OscillationEnergyAboutEquilibrium) {
  const Spring s = spring_with(0.1);
  const State<1> y0 = s.initial();
  EXPECT_DOUBLE_EQ(s.energy(y0.x, y0.v), 0.5 * 5 * (9.81 / 5) * (9.81 / 5));  // (m g)^2 / (2 k)
}

}  // namespace
}  // namespace steplab
