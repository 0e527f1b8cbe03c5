// Tests of analysis/studies/collision.cpp and of the convergence study against the exact bounce.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/studies/collision.hpp"
#include "analysis/studies/convergence.hpp"
#include "analysis/kernel/kernel.hpp"
#include "core/scenes/bounce.hpp"
#include "core/scenes/falling.hpp"

namespace steplab {
namespace {

std::vector<std::size_t> numerical_methods() {
  std::vector<std::size_t> m;
  for (std::size_t i = 0; i < method_count(); ++i)
    if (in_ode_studies(i)) m.push_back(i);
  return m;
}

class CollisionStudy : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    CollisionConfig c;
    c.rebound_params = default_param_values<Bounce>();
    c.body_params = default_param_values<Falling>();
    c.methods = numerical_methods();
    c.dts = {0.001, 0.004};
    result = new CollisionResult(collision_study(c));
  }
  static void TearDownTestSuite() { delete result; }
  static const CollisionRun& bounce(std::string_view method, double dt) {
    for (const auto& r : result->bounce)
      if (method_info(r.method).name == method && r.dt == dt) return r;
    throw std::logic_error("no such run");
  }
  static CollisionResult* result;
};
CollisionResult* CollisionStudy::result = nullptr;

// The bar on the undamped bounce over 10 s.
TEST_F(CollisionStudy, SymplecticEulerKeepsEnergyWithinOnePercent) {
  const CollisionRun& r = bounce("symplectic_euler", 0.001);
  ASSERT_GE(r.bounces.size(), 8u);  // 10 s / (2 sqrt(2/g) + contact 0.31 s) = 8 bounces
  for (const BounceEvent& e : r.bounces) EXPECT_NEAR(e.energy_ratio, 1.0, 0.01);
  EXPECT_NEAR(r.energy_ratio_max, 1.0, 0.01);
}

TEST_F(CollisionStudy, ExplicitEulerGainsAndGainsMoreAtLargerSteps) {
  const CollisionRun& fine = bounce("explicit_euler", 0.001);
  const CollisionRun& coarse = bounce("explicit_euler", 0.004);
  EXPECT_GT(fine.bounces.front().energy_ratio, 1.01);
  EXPECT_GT(fine.bounces.back().energy_ratio, fine.bounces.front().energy_ratio);  // every bounce adds
  EXPECT_GT(coarse.bounces.front().energy_ratio, fine.bounces.front().energy_ratio);
  EXPECT_GT(coarse.energy_ratio_max, fine.energy_ratio_max);
}

TEST_F(CollisionStudy, ImplicitEulerLosesEnergy) {
  const CollisionRun& r = bounce("implicit_euler", 0.001);
  double previous = 1.0;
  for (const BounceEvent& e : r.bounces) {
    EXPECT_LT(e.energy_ratio, previous);
    previous = e.energy_ratio;
  }
  EXPECT_LT(r.energy_ratio_final, 0.9);
}

TEST_F(CollisionStudy, TriangleRunsTenSecondsForEveryMethod) {
  ASSERT_EQ(result->triangle.size(), numerical_methods().size());
  for (const CollisionRun& r : result->triangle) {
    const auto name = method_info(r.method).name;
    if (r.status == RunStatus::Ok) {
      ASSERT_FALSE(r.path.empty()) << name;
      EXPECT_DOUBLE_EQ(r.path.back().t, 10.0) << name;
      for (const auto& s : r.path) ASSERT_TRUE(s.x.allFinite() && s.v.allFinite()) << name << " t " << s.t;
    } else {
      EXPECT_GT(r.failed_step, 0) << name;  // a blow-up is recorded with its step
    }
    EXPECT_LT(r.max_penetration, 0.5) << name;  // the ground holds the triangle up
  }
}

// The triangle's reference (RK4 at dt 5e-5 and 2e-5) against two other methods at dt 1e-5, run
// here: velocity Verlet (symplectic, order 2) ends at E/E0 0.649479 and Gauss-Legendre 4 at
// 0.649482. The references agree with them, and with each other, to 1e-4: the contacts' kinks
// keep every method from its order, so the runs agree to what the kinks allow, not to round-off.
TEST_F(CollisionStudy, TriangleReferenceAgreesWithOtherMethods) {
  ASSERT_EQ(result->triangle_reference.size(), 2u);
  for (const char* other : {"velocity_verlet", "gauss_legendre4"}) {
    RunSpec spec;
    spec.dt = 1e-5, spec.steps = steps_for(10, 1e-5), spec.errors = false;
    const AnyResult r = pair_kernel(*find_method(other), scene_index(Falling::name)).run(default_param_values<Falling>(), spec);
    ASSERT_EQ(r.status, RunStatus::Ok) << other;
    for (const CollisionRun& ref : result->triangle_reference) {
      EXPECT_EQ(ref.status, RunStatus::Ok);
      EXPECT_TRUE(ref.path.empty());
      EXPECT_NEAR(ref.energy_ratio_final, r.energy_ratio_final, 1e-4) << other << " against rk4 at " << ref.dt;
    }
  }
}

// Against the exact bounce the contact's kink (the force's derivative jumps) costs order: the
// fits are reported with intervals. Measured: RK4's interval lies well below 4, and the
// second-order symplectic methods keep 2 inside theirs; symplectic Euler keeps 1.
TEST(BounceConvergence, OrdersWithIntervals) {
  ConvergenceConfig c;
  c.scene = *find_scene("bounce");
  c.params = default_param_values<Bounce>();
  c.methods = numerical_methods();
  const ConvergenceResult r = convergence_study(c);
  for (const ConvergenceFit& f : r.fits) {
    const MethodInfo& info = method_info(f.method);
    ASSERT_TRUE(f.fit.fitted) << info.name << ": " << f.fit.note;
    EXPECT_GE(f.fit.line.n, 4) << info.name;
    EXPECT_LT(f.fit.line.ci95_lo, f.fit.line.ci95_hi) << info.name;
    if (info.name == "rk4") {
      EXPECT_LT(f.fit.line.ci95_hi, 3.5);
    }
    if (info.name == "symplectic_euler" || info.name == "velocity_verlet" || info.name == "implicit_midpoint") {
      EXPECT_LE(f.fit.line.ci95_lo, info.order) << info.name;
      EXPECT_GE(f.fit.line.ci95_hi, info.order) << info.name;
    }
  }
}

}  // namespace
}  // namespace steplab
