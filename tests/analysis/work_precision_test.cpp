// The work-precision study (analysis/work_precision.hpp), costed by evaluations (timing off, so
// that the figures are exact and the same on every machine).
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/work_precision.hpp"
#include "core/methods.hpp"
#include "core/scenes.hpp"
#include "reports/study_output.hpp"

namespace steplab {
namespace {

const WorkPrecisionResult& study() {
  static const WorkPrecisionResult r = [] {
    WorkPrecisionConfig c;
    for (std::size_t m = 0; m < method_count; ++m)
      if (!method_infos[m].exact_flow) c.methods.push_back(m);
    c.timing = false;
    c.threads = 2;
    return work_precision_study(c);
  }();
  return r;
}

// Counted evaluations are what the methods' formulas say: 4 force evaluations per RK4 step,
// 2 + 6 per attempted step for dopri5 (first same as last), Jacobians only for implicit methods
// and the splittings built on velocity Verlet (it and Yoshida's composition of it), whose closing
// kick is implicit in v on a damped scene: none for the explicit Runge-Kutta and Adams-Bashforth.
TEST(WorkPrecision, CountsWhatTheFormulasSay) {
  for (const WorkPoint& p : study().scenes[0].points) {
    if (p.method == "rk4") {
      EXPECT_EQ(p.force_evaluations, 4 * p.steps) << p.setting;
    }
    const Family f = p.adaptive ? Family::None : method_infos[*find_method(p.method)].family;
    if (f == Family::ExplicitRungeKutta || f == Family::AdamsBashforth) {
      EXPECT_EQ(p.jacobian_evaluations, 0) << p.method;
    }
    if (p.method == "radau_iia5") {
      EXPECT_GT(p.jacobian_evaluations, 0);
    }
    if (p.method == "dopri5") {
      EXPECT_GE(p.force_evaluations, 2 + 6 * p.steps);
    }
  }
}

// Both adaptive solvers reach errors that follow the tolerance on the spring: at tol 1e-9 both are
// below 1e-7 (measured: steplab 1.5e-8, odeint 3e-9 -- odeint's max norm is the stricter).
TEST(WorkPrecision, AdaptiveErrorsFollowTheTolerance) {
  for (const WorkPoint& p : study().scenes[0].points) {
    if (!p.adaptive) continue;
    EXPECT_EQ(p.status, RunStatus::Ok) << p.method;
    EXPECT_LT(p.error, 100 * p.setting) << p.method << " " << p.setting;
  }
}

// On the stiff chain an implicit method is the cheapest at 1e-4 (by evaluations), on the spring
// an explicit one; the stiffness sweep finds a crossover between ratio 10 and 1e5 (measured 1000).
TEST(WorkPrecision, ImplicitPaysOnlyOnTheStiffChain) {
  const WorkPrecisionResult& r = study();
  const auto at = [](const SceneWork& w, double level) {
    for (const Cheapest& c : w.cheapest)
      if (c.error_level == level) return c.by_evaluations;
    return std::string();
  };
  const std::string spring = at(r.scenes[0], 1e-4), chain = at(r.scenes[1], 1e-4);
  ASSERT_FALSE(spring.empty());
  ASSERT_FALSE(chain.empty());
  EXPECT_TRUE(spring == "dopri5" || spring == "odeint_dopri5" || !method_infos[*find_method(spring)].implicit) << spring;
  ASSERT_TRUE(find_method(chain)) << chain;
  EXPECT_TRUE(method_infos[*find_method(chain)].implicit) << chain;
  EXPECT_GE(r.crossover_ratio, 10);
  EXPECT_LE(r.crossover_ratio, 1e5);
  // every explicit method's step on the chain is bounded: none stable at 0.01 (RK4's limit, 2.8 / 316 = 0.009)
  for (const StableStep& l : r.limits) EXPECT_LT(l.largest_stable_dt, 0.01) << l.method;
}

TEST(WorkPrecision, JsonIsTheSameForOneAndTwoThreads) {
  WorkPrecisionConfig c;
  c.methods = {*find_method("rk4"), *find_method("bdf2")};
  c.timing = false;
  c.stiffnesses = {5, 5e4};
  c.threads = 1;
  const std::string one = work_precision_json(work_precision_study(c)).dump();
  c.threads = 2;
  EXPECT_EQ(one, work_precision_json(work_precision_study(c)).dump());
}

}  // namespace
}  // namespace steplab
