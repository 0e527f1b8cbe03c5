// Tests of analysis/convergence.cpp: the default studies on the spring and the cannon ball.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/convergence.hpp"
#include "core/scenes.hpp"
#include "reports/study_output.hpp"

namespace steplab {
namespace {

ConvergenceConfig defaults(std::string_view scene) {
  ConvergenceConfig c;
  c.scene = *find_scene(scene);
  c.params = with_scene(c.scene, [&]<class S>() {
    const auto p = default_params<S>();
    return std::vector<double>(p.begin(), p.end());
  });
  for (std::size_t m = 0; m < method_count; ++m)
    if (!method_infos[m].exact_flow) c.methods.push_back(m);
  return c;
}

TEST(SweepSteps, WholeNumberOfStepsAndGeometric) {
  const auto dts = sweep_steps(10.0, 0.1, 1e-4, 16);
  ASSERT_EQ(dts.size(), 16u);
  for (double dt : dts) EXPECT_NEAR(10.0 / dt, std::round(10.0 / dt), 1e-6);
  EXPECT_DOUBLE_EQ(dts.front(), 0.1);
  EXPECT_DOUBLE_EQ(dts.back(), 1e-4);
  // not only halving: ratio 10^(3/15) = 1.585
  EXPECT_NEAR(dts[0] / dts[1], std::pow(10.0, 0.2), 0.01);
}

// The issues' bars: the headline (asymptotic) order within 0.01 of the declared one, with the
// declared order inside its bound; the window's plain slope within 0.05. The extrapolated order
// (limit of the local slopes) must be within 0.02 where it is defined.
TEST(Convergence, SpringDefaultsFitTheDeclaredOrders) {
  const ConvergenceResult r = convergence_study(defaults("spring"));
  for (const ConvergenceFit& f : r.fits) {
    const MethodInfo& info = method_infos[f.method];
    ASSERT_TRUE(f.fit.fitted) << info.name << ": " << f.fit.note;
    EXPECT_NEAR(f.fit.order, info.order, 0.01) << info.name;
    EXPECT_LE(f.fit.bound_lo, info.order) << info.name;
    EXPECT_GE(f.fit.bound_hi, info.order) << info.name;
    EXPECT_NEAR(f.fit.line.slope, info.order, 0.05) << info.name;
    EXPECT_GE(f.fit.line.n, 5) << info.name;
    EXPECT_GT(f.fit.line.r2, 0.9999) << info.name;
    if (std::isfinite(f.fit.extrapolated)) {
      EXPECT_NEAR(f.fit.extrapolated, info.order, 0.02) << info.name;
    }
  }
}

TEST(Convergence, CannonballEulersAreFirstOrderTheRestExact) {
  const ConvergenceResult r = convergence_study(defaults("cannonball"));
  for (const ConvergenceFit& f : r.fits) {
    const MethodInfo& info = method_infos[f.method];
    if (info.order == 1) {  // and Adams-Bashforth and BDF: exact on polynomials of their order
      ASSERT_TRUE(f.fit.fitted) << info.name;
      EXPECT_NEAR(f.fit.line.slope, 1.0, 1e-6) << info.name;  // e = g t dt / 2 exactly, plus round-off
      EXPECT_LE(f.fit.line.ci95_lo, 1.0) << info.name;
      EXPECT_GE(f.fit.line.ci95_hi, 1.0) << info.name;
      EXPECT_FALSE(f.fit.exact);
    } else {
      EXPECT_TRUE(f.fit.exact) << info.name;  // constant acceleration: order >= 2 is exact
    }
  }
}

TEST(Convergence, DivergedRunsAreKeptAndMarked) {
  ConvergenceConfig c = defaults("spring");
  c.params[2] = 0;  // undamped: explicit Euler grows by (1 + h^2 k/m)^(n/2)
  c.methods = {*find_method("explicit_euler")};
  c.t_end = 2000;
  c.dt_max = 1.0;
  c.dt_min = 0.1;
  c.points = 4;
  const ConvergenceResult r = convergence_study(c);
  EXPECT_EQ(r.records.front().status, RunStatus::Diverged);
  EXPECT_GT(r.records.front().failed_step, 0);
  EXPECT_FALSE(r.fits.front().fit.exact);
}

TEST(Convergence, JsonIsTheSameForOneAndTwoThreads) {
  ConvergenceConfig c = defaults("spring");
  c.threads = 1;
  const std::string one = convergence_json(convergence_study(c)).dump();
  c.threads = 2;
  const std::string two = convergence_json(convergence_study(c)).dump();
  c.threads = 5;
  const std::string five = convergence_json(convergence_study(c)).dump();
  EXPECT_EQ(one, two);
  EXPECT_EQ(one, five);
}

}  // namespace
}  // namespace steplab
