// Unit tests for analysis/order_fit.cpp: synthetic error tables of known slope.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "analysis/order_fit.hpp"

namespace steplab {
namespace {

std::vector<ErrorPoint> table(double p, double noise, unsigned seed, int n = 14, double dt_max = 0.1, double ratio = 1.5) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0.0, noise);
  std::vector<ErrorPoint> pts;
  for (int i = 0; i < n; ++i) {
    const double dt = dt_max / std::pow(ratio, i);
    pts.push_back({dt, 3.0 * std::pow(dt, p) * std::exp(gauss(rng)), 0.0, false});
  }
  return pts;
}

// Noisy power laws (lognormal noise, 2 % and 5 %): the interval must hold the true slope. Over
// 200 tables a 95 % interval misses about 10 times; more than 18 has probability 0.005 under
// binomial(200, 0.05), while an interval too narrow by a third would miss ~28 times. The seeds
// are fixed, so the test is deterministic.
TEST(OrderFit, RecoversKnownSlopeWithNoise) {
  for (double p : {1.0, 2.0, 4.0}) {
    for (double noise : {0.02, 0.05}) {
      int misses = 0;
      for (unsigned seed = 1; seed <= 200; ++seed) {
        const OrderFit f = fit_order(table(p, noise, seed));
        ASSERT_TRUE(f.fitted) << p << " " << seed << " " << f.note;
        EXPECT_NEAR(f.line.slope, p, 0.1) << "p " << p << " noise " << noise << " seed " << seed;
        if (p < f.line.ci95_lo || p > f.line.ci95_hi) ++misses;
      }
      EXPECT_LE(misses, 18) << "p " << p << " noise " << noise;
    }
  }
}

TEST(OrderFit, DropsPointsAtTheRoundoffFloorAndDiverged) {
  std::vector<ErrorPoint> pts = table(2.0, 0.0, 1, 10);
  for (auto& pt : pts) pt.floor = 1e-9;
  pts.push_back({0.2, 1e30, 0, true});                     // diverged
  pts.push_back({1e-7, 1.3e-12, 1e-9, false});              // below the floor
  pts.push_back({5e-8, 4e-12, 1e-9, false});
  const OrderFit f = fit_order(pts);
  ASSERT_TRUE(f.fitted);
  EXPECT_NEAR(f.line.slope, 2.0, 1e-9);
  EXPECT_GT(f.dt_lo, 1e-7);
  EXPECT_LE(f.dt_hi, 0.1);
}

TEST(OrderFit, DropsThePreAsymptoticRange) {
  // e = dt (1 + 50 dt): the local slope is far from 1 at large dt, within 1 % below dt ~ 2e-4.
  std::vector<ErrorPoint> pts;
  for (int i = 0; i < 20; ++i) {
    const double dt = 0.1 / std::pow(1.6, i);
    pts.push_back({dt, dt * (1 + 50 * dt), 0, false});
  }
  const OrderFit f = fit_order(pts);
  ASSERT_TRUE(f.fitted);
  EXPECT_LT(f.dt_hi, 2e-3);
  EXPECT_NEAR(f.line.slope, 1.0, 0.01);
  EXPECT_NEAR(f.extrapolated, 1.0, 1e-3);  // Aitken removes the geometric trend
}

TEST(OrderFit, ExactWhenEverythingIsAtTheFloor) {
  std::vector<ErrorPoint> pts;
  for (int i = 0; i < 8; ++i) pts.push_back({0.1 / (i + 1), 1e-14 * (i % 3 + 1), 1e-12, false});
  const OrderFit f = fit_order(pts);
  EXPECT_TRUE(f.exact);
  EXPECT_FALSE(f.fitted);
}

TEST(OrderFit, AllDivergedIsNotExact) {
  std::vector<ErrorPoint> pts{{0.1, 0, 0, true}, {0.05, 0, 0, true}, {0.02, 0, 0, true}};
  const OrderFit f = fit_order(pts);
  EXPECT_FALSE(f.exact);
  EXPECT_FALSE(f.fitted);
}

TEST(OrderFit, TooFewPoints) {
  std::vector<ErrorPoint> pts{{0.1, 0.1, 0, false}, {0.05, 0.05, 0, false}};
  const OrderFit f = fit_order(pts);
  EXPECT_FALSE(f.fitted);
  EXPECT_FALSE(f.note.empty());
}

}  // namespace
}  // namespace steplab
