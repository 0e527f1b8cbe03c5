// Tests of analysis/studies/stability.cpp on the default spring (m = 1, k = 5, gamma = 0.1, L = 5).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "analysis/studies/stability.hpp"
#include "analysis/kernel/kernel.hpp"
#include "core/scenes/spring.hpp"
#include "reports/studies/studies.hpp"

namespace steplab {
namespace {

std::vector<double> spring_params(double gamma) { return {1.0, 5.0, gamma, 5.0, 9.81}; }

std::vector<std::size_t> numerical_methods() {
  std::vector<std::size_t> m;
  for (std::size_t i = 0; i < method_count(); ++i)
    if (in_ode_studies(i)) m.push_back(i);
  return m;
}

std::size_t id(std::string_view name) { return *find_method(name); }

// The default spring, every numerical method; each test sets the study it runs.
StabilityConfig default_spring_config() {
  StabilityConfig c;
  c.params = spring_params(0.1);
  c.methods = numerical_methods();
  return c;
}

// M(h) written out by hand for the sheet's four methods, with A = [[0, 1], [-k/m, -gamma/m]].
// The differenced matrix carries round-off of ~eps |y_eq| / delta ~ 1e-14: 1e-11 is ample.
TEST(StepMatrix, MatchesTheSheetMethodsByHand) {
  for (double gamma : {0.0, 0.1, 3.0}) {
    const Spring s(spring_params(gamma));
    for (double h : {0.01, 0.05, 0.3, 1.1}) {
      Mat<2> A;
      A << 0, 1, -5.0, -gamma;
      const Mat<2> I = Mat<2>::Identity();
      Mat<2> se;  // v1 = v + h a(y, v); y1 = y + h v1
      se << 1 - h * h * 5, h * (1 - h * gamma), -h * 5, 1 - h * gamma;
      const std::pair<const char*, Mat<2>> cases[] = {
          {"explicit_euler", I + h * A},
          {"symplectic_euler", se},
          {"explicit_midpoint", I + h * A + 0.5 * h * h * A * A},
          {"implicit_euler", (I - h * A).inverse()},
      };
      for (const auto& [name, want] : cases) {
        const Mat<2> got = step_matrix(id(name), s, h);
        EXPECT_LT((got - want).cwiseAbs().maxCoeff(), 1e-11 * std::max(1.0, want.cwiseAbs().maxCoeff()))
            << name << " gamma " << gamma << " h " << h << "\n" << got << "\nvs\n" << want;
      }
    }
  }
}

TEST(Threshold, PredictedMatchesClosedForms) {
  const double w = std::sqrt(5.0);
  const Spring undamped(spring_params(0));
  EXPECT_EQ(predicted_threshold(id("explicit_euler"), undamped), 0.0);
  EXPECT_EQ(predicted_threshold(id("explicit_midpoint"), undamped), 0.0);
  EXPECT_NEAR(predicted_threshold(id("symplectic_euler"), undamped), 2 / w, 1e-8);
  EXPECT_NEAR(predicted_threshold(id("velocity_verlet"), undamped), 2 / w, 1e-8);
  EXPECT_NEAR(predicted_threshold(id("rk4"), undamped), 2 * std::sqrt(2.0) / w, 1e-8);
  EXPECT_TRUE(std::isinf(predicted_threshold(id("implicit_euler"), undamped)));
  EXPECT_TRUE(std::isinf(predicted_threshold(id("implicit_midpoint"), undamped)));
  // explicit Euler with damping: |1 + h lambda|^2 <= 1  <=>  h <= gamma / k (m = 1)
  for (double gamma : {0.1, 1.0, 4.0})
    EXPECT_NEAR(predicted_threshold(id("explicit_euler"), Spring(spring_params(gamma))), gamma / 5, 1e-9);
}

// The families' methods against theory. Undamped, z = i w h runs up the imaginary axis, so dt* is
// where each method's stability region leaves it:
//   rk3: |1 + z + z^2/2 + z^3/6| = 1 at w h = sqrt(3);  rk4: 2 sqrt(2) (above);
//   yoshida4: trace of the three Verlet matrices = 2 at w h = 1.5734 (root of that degree-6
//     polynomial in w h, found in exact rational arithmetic outside this code);
//   adams_bashforth3: its boundary locus rho(zeta)/sigma(zeta) crosses the axis at 0.723627
//     (Hairer & Wanner II, fig. V.1.1); adams_bashforth2's touches it at 0 only;
//   bdf3: Re of its boundary locus is (1 - c)^2 (1 - 4c) / 3 with c = cos theta, so it crosses the
//     axis at c = 1/4, Im = 2 sin theta = sqrt(15)/2: unstable below, stable again above;
//   gauss_legendre4, bdf2: A-stable.
TEST(Threshold, FamiliesMatchTheory) {
  const double w = std::sqrt(5.0);
  const Spring undamped(spring_params(0));
  EXPECT_NEAR(predicted_threshold(id("rk3"), undamped), std::sqrt(3.0) / w, 1e-8);
  EXPECT_NEAR(predicted_threshold(id("yoshida4"), undamped), 1.5734 / w, 1e-4 / w);
  EXPECT_NEAR(predicted_threshold(id("adams_bashforth3"), undamped), 0.723627 / w, 1e-6 / w);
  EXPECT_EQ(predicted_threshold(id("adams_bashforth2"), undamped), 0.0);
  const StableSet bdf3 = predicted_stable_set(id("bdf3"), undamped);
  EXPECT_EQ(bdf3.dt_star, 0.0);
  EXPECT_NEAR(bdf3.again, std::sqrt(15.0) / 2 / w, 1e-8);
  for (double gamma : {0.0, 0.1, 4.0})
    for (const char* name : {"gauss_legendre4", "bdf2"}) {
      const StableSet set = predicted_stable_set(id(name), Spring(spring_params(gamma)));
      EXPECT_TRUE(std::isinf(set.dt_star)) << name << " " << gamma;
      EXPECT_TRUE(std::isinf(set.again)) << name << " " << gamma;
    }
  // with the default damping the ray leaves the imaginary axis: bdf3 is stable up to a finite
  // dt*, unstable beyond, and stable again before sqrt(15)/2 / w
  const StableSet damped = predicted_stable_set(id("bdf3"), Spring(spring_params(0.1)));
  EXPECT_GT(damped.dt_star, 0.0);
  EXPECT_LT(damped.again, std::sqrt(15.0) / 2 / w);
  EXPECT_GT(damped.again, damped.dt_star);
}

// The bar: measured thresholds within 1 % of dt* for gamma in {0.1, 1, 4}, every
// conditionally stable method; at gamma = 0 the measured statements the sheet asks about.
TEST(Threshold, MeasuredWithinOnePercentOfPredicted) {
  StabilityConfig c = default_spring_config();
  c.threshold_dampings = {0.0, 0.1, 1.0, 4.0};
  for (const ThresholdRow& r : threshold_study(c)) {
    const auto name = method_info(r.method).name;
    if (std::isinf(r.dt_theory)) {
      EXPECT_TRUE(std::isinf(r.dt_measured)) << name << " " << r.damping;
    } else if (r.dt_theory == 0) {
      EXPECT_EQ(r.dt_measured, 0.0) << name << " " << r.damping;
    } else {
      EXPECT_NEAR(r.dt_measured / r.dt_theory, 1.0, 0.01) << name << " " << r.damping;
    }
    if (std::isinf(r.again_theory)) {
      EXPECT_TRUE(std::isinf(r.again_measured)) << name << " " << r.damping;
    } else {
      EXPECT_NEAR(r.again_measured / r.again_theory, 1.0, 0.01) << name << " " << r.damping;
    }
    if (r.damping == 0) {
      if (name == "explicit_euler" || name == "explicit_midpoint") {
        EXPECT_EQ(r.dt_measured, 0.0) << name;
      }
      if (name == "symplectic_euler") {
        EXPECT_NEAR(r.dt_measured, 2 / std::sqrt(5.0), 0.01 * 2 / std::sqrt(5.0));
      }
      if (name == "implicit_euler") {
        EXPECT_TRUE(std::isinf(r.dt_measured));
      }
    }
  }
}

// Asking ahead (stable_set_batched) changes how many verdicts are asked at once, not which steps
// decide: on sets whose edges are known (an unstable band with a stable window above it, every
// step stable, unstable from the start) every `ahead` gives the bits of asking one at a time, and
// the edges it finds are the known ones to the precision asked.
TEST(Threshold, AskingAheadFindsWhatAskingOneAtATimeFinds) {
  const double inf = std::numeric_limits<double>::infinity();
  struct Case {
    double edge, window_lo, window_hi;  // unstable on [edge, window_lo) and [window_hi, inf)
  };
  for (const Case& c : {Case{0.37, 1.9, 2.3}, Case{0.37, inf, inf}, Case{inf, inf, inf}, Case{1e-9, 5.0, 7.0}}) {
    const auto unstable = [&](double h) { return h >= c.edge && !(h >= c.window_lo && h < c.window_hi); };
    const StableSet one = stable_set(0.01, 100.0, 2.0, 1e-6, unstable);
    for (int ahead = 1; ahead <= 8; ++ahead) {
      int asked = 0;
      const StableSet batched = stable_set_batched(0.01, 100.0, 2.0, 1e-6, ahead, [&](const std::vector<double>& hs) {
        EXPECT_LE(hs.size(), static_cast<std::size_t>(std::max(ahead, 3)));
        asked += static_cast<int>(hs.size());
        std::vector<char> v;
        for (double h : hs) v.push_back(unstable(h));
        return v;
      });
      EXPECT_EQ(batched.dt_star, one.dt_star) << c.edge << " ahead " << ahead;
      EXPECT_EQ(batched.again, one.again) << c.edge << " ahead " << ahead;
      EXPECT_GT(asked, 0);
    }
    if (c.edge == inf) {
      EXPECT_TRUE(std::isinf(one.dt_star));
    } else if (c.edge < 0.01) {
      EXPECT_EQ(one.dt_star, 0.0);
    } else {
      EXPECT_NEAR(one.dt_star / c.edge, 1.0, 2e-6);
    }
    if (std::isinf(c.window_lo)) {
      EXPECT_TRUE(std::isinf(one.again));
    } else {
      EXPECT_NEAR(one.again / c.window_lo, 1.0, 2e-6);
    }
  }
}

// The measured searches ask ahead in packs (threshold_study's pack width): the same thresholds,
// bit for bit, as one run at a time, for methods with one edge, none (implicit Euler), and
// stable windows past dt* (Yoshida 4 and BDF 3 undamped).
TEST(Threshold, MeasuredTheSameAtEveryPackWidth) {
  for (double gamma : {0.0, 1.0}) {
    const Spring s = linear_spring(spring_params(gamma), gamma);
    for (const char* name : {"explicit_euler", "rk4", "implicit_euler", "yoshida4", "bdf3"}) {
      const StableSet one = measured_stable_set(id(name), s, 1);
      for (int width : {2, 4, 8}) {
        if (!cpu_has_width(width)) continue;
        const StableSet packed = measured_stable_set(id(name), s, width);
        EXPECT_EQ(packed.dt_star, one.dt_star) << name << " " << gamma << " width " << width;
        EXPECT_EQ(packed.again, one.again) << name << " " << gamma << " width " << width;
      }
    }
  }
}

// Regression: at a huge step with strong damping the exact flow's energy vanishes in one step;
// too few energies to fit gave a NaN rate, once counted as growth (measured dt* = 187 at damping 4).
TEST(Threshold, VanishingEnergyIsNotGrowth) {
  for (double gamma : {0.0, 0.1, 4.0}) {
    const Spring s(spring_params(gamma));
    EXPECT_TRUE(std::isinf(measured_threshold(id("analytic"), s))) << gamma;
    EXPECT_TRUE(std::isinf(measured_threshold(id("implicit_euler"), s))) << gamma;
  }
}

// Measured growth rates within 2 % of 2 ln(rho)/h, or 1e-6 absolute where that is larger.
TEST(DampingSweep, MeasuredRatesMatchPredicted) {
  StabilityConfig c = default_spring_config();
  c.sweep_dts = {0.01, 0.05, 0.2};
  c.sweep_dampings = {0.0, 0.1};
  for (const SweepRow& r : damping_sweep(c)) {
    const double tol = std::max(0.02 * std::abs(r.rate_theory), 1e-6);
    EXPECT_NEAR(r.run.rate, r.rate_theory, tol) << method_info(r.method).name << " dt " << r.dt << " gamma " << r.damping;
  }
}

TEST(DampingSweep, UndampedVerdictsOfTheSheet) {
  StabilityConfig c = default_spring_config();
  c.sweep_dts = {0.01, 0.05, 0.2};
  c.sweep_dampings = {0.0};
  for (const SweepRow& r : damping_sweep(c)) {
    const auto name = method_info(r.method).name;
    // unstable on the imaginary axis near 0 (bdf3 up to w h = sqrt(15)/2 = 1.94, w h <= 0.45 here)
    if (name == "explicit_euler" || name == "explicit_midpoint" || name == "adams_bashforth2" || name == "bdf3") {
      EXPECT_FALSE(r.run.stable()) << name << " " << r.dt;
    } else {
      EXPECT_TRUE(r.run.stable()) << name << " " << r.dt;  // the others: all three steps are below their dt*
    }
  }
}

// Every cell against its own prediction (rho <= 1 there), and below dt* every cell is predicted
// stable: a stable set need not be an interval (bdf3, yoshida4), so beyond dt* it can be either.
TEST(StabilityMap, MeasuredCellsAgreeWithPredictedBoundary) {
  StabilityConfig c = default_spring_config();
  c.map_dt_points = 12;
  c.map_damping_points = 9;
  const StabilityMap map = stability_map(c);
  for (std::size_t i = 0; i < map.methods.size(); ++i)
    for (std::size_t g = 0; g < map.damping.size(); ++g)
      for (std::size_t d = 0; d < map.dt.size(); ++d) {
        EXPECT_EQ(map.stable[i][g][d], map.predicted[i][g][d])
            << method_info(map.methods[i]).name << " dt " << map.dt[d] << " gamma " << map.damping[g];
        if (map.dt[d] <= map.boundary[i][g]) {
          EXPECT_TRUE(map.predicted[i][g][d]);
        }
      }
}

TEST(StabilityJson, SameForOneAndTwoThreads) {
  StabilityConfig c = default_spring_config();
  c.map_dt_points = 8;
  c.map_damping_points = 5;
  c.threshold_dampings = {0.1};
  c.sweep_dampings = {0.0, 0.1, 2.0};
  const auto doc = [&](unsigned threads) {
    c.workers.threads = threads;
    const StabilityMap map = stability_map(c);
    return stability_json(c.params, threshold_study(c), damping_sweep(c), &map).dump();
  };
  EXPECT_EQ(doc(1), doc(2));
}

// The old framework's stability_measurement: the exact undamped motion swings to 2 L + 2 m g / k.
TEST(AmplitudeTable, AnalyticAmplitudeAndBlowUps) {
  const std::vector<double> old_defaults{0.1, 10.0, 0.0, 1.0, 9.81};
  const AmplitudeTable t = amplitude_table(old_defaults, {id("analytic"), id("explicit_euler"), id("implicit_euler")}, 0.003, 10);
  ASSERT_EQ(t.steps.size(), 10u);
  EXPECT_DOUBLE_EQ(t.steps.back(), 0.003 * 512);
  for (const auto& row : t.amplitude) {
    EXPECT_NEAR(row[0], 2.1962, 1e-4);
    EXPECT_LT(row[2], 2.1962);  // implicit Euler damps
  }
  EXPECT_TRUE(std::isinf(t.amplitude.back()[1]));
}

}  // namespace
}  // namespace steplab
