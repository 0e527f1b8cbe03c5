// steplab check (analysis/studies/check.hpp): every row of the table holds its claims; rows made wrong
// here (a first-order method declared second order, a non-symplectic one declared symplectic, ...)
// fail exactly the claim that is wrong; the energy drift matches |R(i omega h)| from theory.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analysis/studies/check.hpp"
#include "analysis/kernel/kernel.hpp"
#include "reports/cli/check_command.hpp"

namespace steplab {
namespace {

std::size_t index_of(std::string_view name) { return *find_method(name); }

CheckResult check_as(std::string_view name, MethodInfo claims) { return check_method(index_of(name), claims, Workers{2}); }

class EveryRow : public ::testing::TestWithParam<std::size_t> {};

TEST_P(EveryRow, HoldsEveryClaim) {
  const std::size_t m = GetParam();
  const CheckResult r = check_method(m, method_info(m), Workers{2});
  EXPECT_TRUE(r.all_hold()) << check_text(r);
  const bool on_springs = method_info(m).on_springs;  // the spring alone: neither the cannon ball nor the target
  ASSERT_EQ(r.orders.size(), on_springs ? 1u : 3u);
  if (method_info(m).order > 0) {  // the spring's order is fitted, within 0.01 for every row
    EXPECT_TRUE(r.orders[0].fit.fitted);
    EXPECT_NEAR(r.orders[0].fit.order, method_info(m).order, 0.01) << method_info(m).name;
    // the driven target's too: each stage's force at its own time (within the claim's 0.1)
    if (!on_springs) {
      EXPECT_EQ(r.orders[2].scene, "target");
      EXPECT_TRUE(r.orders[2].fit.fitted);
      EXPECT_NEAR(r.orders[2].fit.order, method_info(m).order, kOrderTolerance) << method_info(m).name;
    }
  }
  EXPECT_EQ(r.stability.size(), std::size(kCheckDampings));
  const auto lines = check_lines(r);
  const std::size_t orbit = r.orbit.ran ? 1 : 0;  // the symplectic claim on Kepler's orbit: every method but those on springs
  EXPECT_EQ(r.orbit.ran, !on_springs) << method_info(m).name;
  if (method_info(m).converges) EXPECT_EQ(lines.size(), 2 * r.orders.size() + 2 + orbit + r.stability.size() + 1);
  else EXPECT_EQ(lines.size(), r.orders.size() + 2 + orbit + 1);  // PBD: no order, no dt* prediction

}

INSTANTIATE_TEST_SUITE_P(Table, EveryRow, ::testing::Range<std::size_t>(0, method_count()),
                         [](const auto& row) { return std::string(method_info(row.param).name); });

// The energy's drift over kDriftSteps at omega h = y is kDriftSteps ln|R(iy)|^2 for a one-step
// method whose stability function is R; least squares on an exact exponential returns its rate.
TEST(Check, EnergyDriftIsTheStabilityFunctionsModulus) {
  const double y = kDriftOmegaH, n = kDriftSteps;
  const double y2 = y * y, y4 = y2 * y2, y6 = y4 * y2, y8 = y4 * y4;
  // RK4: |R(iy)|^2 = 1 - y^6/72 + y^8/576; RK3: 1 - y^4/12 + y^6/36; implicit Euler: 1 / (1 + y^2);
  // Radau IIA: |(1 + 2z/5 + z^2/20) / (1 - 3z/5 + 3z^2/20 - z^3/60)|^2 at z = iy
  const double radau = (std::pow(1 - y2 / 20, 2) + 0.16 * y2) / (std::pow(1 - 3 * y2 / 20, 2) + std::pow(-0.6 * y + y * y2 / 60, 2));
  const struct {
    const char* name;
    double theory;
  } cases[] = {{"rk4", n * std::log(1 - y6 / 72 + y8 / 576)},
               {"rk3", n * std::log(1 - y4 / 12 + y6 / 36)},
               {"implicit_euler", -n * std::log(1 + y2)},
               {"radau_iia5", n * std::log(radau)}};
  for (const auto& c : cases) {
    const CheckResult r = check_as(c.name, method_info(index_of(c.name)));
    EXPECT_NEAR(r.energy.drift, c.theory, 1e-3 * std::abs(c.theory)) << c.name;
  }
}

TEST(Check, FirstOrderDeclaredSecondOrderFailsItsOrderOnly) {
  MethodInfo wrong = method_info(index_of("explicit_euler"));
  wrong.order = 2;
  const CheckResult r = check_as("explicit_euler", wrong);
  EXPECT_FALSE(r.all_hold());
  for (const OrderCheck& o : r.orders) {
    EXPECT_FALSE(o.order_holds) << o.scene;
    EXPECT_NEAR(o.fit.order, 1, 0.01) << o.scene;
    EXPECT_TRUE(o.converges) << o.scene;
  }
  EXPECT_TRUE(r.energy.holds);
  EXPECT_TRUE(r.a_stable_holds);
  EXPECT_TRUE(r.rest.holds);
  const std::string text = check_text(r);
  EXPECT_NE(text.find("FAIL  order 2 on the spring: fitted 1.000"), std::string::npos) << text;
  EXPECT_NE(text.find("3 of 14 claims fail"), std::string::npos) << text;
  EXPECT_TRUE(r.orbit.holds);
}

// RK4 declared third order: the spring refutes it; the cannon ball (exact for any order >= 2) cannot.
TEST(Check, FourthOrderDeclaredThirdFailsOnTheSpring) {
  MethodInfo wrong = method_info(index_of("rk4"));
  wrong.order = 3;
  const CheckResult r = check_as("rk4", wrong);
  EXPECT_FALSE(r.orders[0].order_holds);
  EXPECT_TRUE(r.orders[1].fit.exact);
  EXPECT_TRUE(r.orders[1].order_holds);
}

TEST(Check, NonSymplecticDeclaredSymplecticFails) {
  for (const char* name : {"explicit_euler", "rk4", "implicit_euler", "bdf2"}) {
    MethodInfo wrong = method_info(index_of(name));
    wrong.symplectic = true;
    const CheckResult r = check_as(name, wrong);
    EXPECT_FALSE(r.energy.holds) << name;
    EXPECT_FALSE(r.energy.bounded) << name;
    EXPECT_FALSE(r.all_hold()) << name;
    EXPECT_NE(check_text(r).find("FAIL  symplectic: energy"), std::string::npos) << name;
    // and on Kepler's orbit over 10^4 periods: a drift (RK4: 1.00 [1.00, 1.00]), a lost orbit
    // (explicit Euler) or a Newton iteration that gave up (implicit Euler, BDF2)
    EXPECT_FALSE(r.orbit.bounded) << name;
    EXPECT_FALSE(r.orbit.holds) << name;
    EXPECT_NE(check_text(r).find("FAIL  symplectic: on Kepler's orbit"), std::string::npos) << name;
  }
  const CheckResult rk4 = check_as("rk4", [] {
    MethodInfo w = method_info(index_of("rk4"));
    w.symplectic = true;
    return w;
  }());
  EXPECT_NEAR(rk4.orbit.growth, 1, 0.05);
  EXPECT_GT(rk4.orbit.lo, 0.5);
}

TEST(Check, SymplecticDeclaredNotFails) {
  MethodInfo wrong = method_info(index_of("velocity_verlet"));
  wrong.symplectic = false;
  const CheckResult r = check_as("velocity_verlet", wrong);
  EXPECT_TRUE(r.energy.bounded);
  EXPECT_FALSE(r.energy.holds);
  EXPECT_TRUE(r.orbit.bounded);  // 0.00 [0.00, 0.00] on Kepler's orbit, error 7.4e-3
  EXPECT_FALSE(r.orbit.holds);
  EXPECT_FALSE(r.all_hold());
}

TEST(Check, AStabilityDeclaredWronglyFailsBothWays) {
  for (const char* name : {"rk4", "bdf3"}) {  // bdf3: infinite dt* at damping 1 and 4, not at 0 and 0.1
    MethodInfo wrong = method_info(index_of(name));
    wrong.a_stable = true;
    EXPECT_FALSE(check_as(name, wrong).a_stable_holds) << name;
  }
  MethodInfo wrong = method_info(index_of("implicit_euler"));
  wrong.a_stable = false;
  const CheckResult r = check_as("implicit_euler", wrong);
  EXPECT_FALSE(r.a_stable_holds);
  for (const StabilityCheck& s : r.stability) EXPECT_TRUE(std::isinf(s.measured.dt_star)) << s.damping;
}

// The same result whatever the number of threads.
TEST(Check, ThreadCountDoesNotChangeTheText) {
  const std::size_t m = index_of("bdf3");
  EXPECT_EQ(check_text(check_method(m, method_info(m), Workers{1})), check_text(check_method(m, method_info(m), Workers{2})));
}

}  // namespace
}  // namespace steplab
