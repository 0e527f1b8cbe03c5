// Unit tests for analysis/fits/order_fit.cpp: synthetic error tables of known slope.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "analysis/fits/order_fit.hpp"

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

// Smooth truncation, no noise: e = dt^p (1 + c1 dt + c2 dt^2), or a symmetric method's
// dt^p (1 + c2 dt^2 + c4 dt^4). The window's plain slope is biased and its Student-t interval
// misses p; the headline order must be within 0.01 of p and its bound must hold p.
TEST(OrderFit, AsymptoticOrderAndBoundHoldTheTrueOrderUnderSmoothTruncation) {
  for (double p : {1.0, 2.0, 3.0, 4.0})
    for (const auto& [c1, c2] : {std::pair{5.0, 0.0}, std::pair{-3.0, 40.0}, std::pair{0.0, 30.0}, std::pair{20.0, -100.0}}) {
      std::vector<ErrorPoint> pts;
      for (int i = 0; i < 16; ++i) {
        const double dt = 0.1 * std::pow(1e-3, i / 15.0);
        pts.push_back({dt, std::pow(dt, p) * (1 + c1 * dt + c2 * dt * dt + (c1 == 0 ? 500 * std::pow(dt, 4) : 0)), 0, false});
      }
      const OrderFit f = fit_order(pts);
      ASSERT_TRUE(f.fitted) << p << " " << c1 << " " << c2;
      EXPECT_NEAR(f.order, p, 0.01) << p << " " << c1 << " " << c2;
      EXPECT_LE(f.bound_lo, p) << p << " " << c1 << " " << c2;
      EXPECT_GE(f.bound_hi, p) << p << " " << c1 << " " << c2;
    }
}

// With noise as well (lognormal 2 %, a first-order correction): the bound holds p at least as often
// as a 95 % interval would (at most 18 misses in 200, as above).
TEST(OrderFit, BoundHoldsTheTrueOrderWithNoise) {
  for (double p : {1.0, 2.0, 4.0}) {
    int misses = 0;
    for (unsigned seed = 1; seed <= 200; ++seed) {
      std::vector<ErrorPoint> pts = table(p, 0.02, seed);
      for (ErrorPoint& pt : pts) pt.error *= 1 + 3 * pt.dt;
      const OrderFit f = fit_order(pts);
      ASSERT_TRUE(f.fitted);
      if (p < f.bound_lo || p > f.bound_hi) ++misses;
    }
    EXPECT_LE(misses, 18) << p;
  }
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
