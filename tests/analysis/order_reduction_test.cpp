// Order reduction (analysis/studies/order_reduction.hpp): the theory read from each method's tableau,
// checked against the values worked by hand from the tableaux in Hairer & Wanner II (IV.5, IV.15),
// and the order measured on the stiffened target (core/scenes/target.hpp, whose exact solution is
// sin t at every stiffness) held to that theory in both limits.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analysis/studies/defaults.hpp"
#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/order_reduction.hpp"

namespace steplab {
namespace {

StiffTheory theory(const char* name) { return stiff_theory(*find_method(name)); }

// Stage order q (c^k = k A c^(k-1) for k <= q) and R(inf) = 1 - b^T A^-1 1, by hand:
//   implicit Euler A = [1], b = [1]: q = 1, R(inf) = 0, stiffly accurate;
//   implicit midpoint A = [1/2], b = [1]: c = 1/2 = A c^0, but c^2 = 1/4 != 2 A c = 1/2: q = 1; R(inf) = 1 - 2 = -1;
//   Gauss-Legendre 4: q = s = 2, R = Pade (2,2) = (1 + z/2 + z^2/12) / (1 - z/2 + z^2/12), R(inf) = 1,
//     1 - R(z) = -z / (1 - z/2 + z^2/12) ~ 12 / |z| on the negative axis: C = 12;
//   Radau IIA 5: q = s = 3, R(inf) = 0 (L-stable), b = the last row of A.
TEST(OrderReductionTheory, RungeKuttaFromTheTableaux) {
  const StiffTheory ie = theory("implicit_euler"), im = theory("implicit_midpoint"), gl = theory("gauss_legendre4"),
                    ra = theory("radau_iia5");
  EXPECT_EQ(ie.stage_order, 1);
  EXPECT_NEAR(ie.r_infinity, 0, 1e-14);
  EXPECT_TRUE(ie.stiffly_accurate);
  EXPECT_EQ(ie.stiff, 1);

  EXPECT_EQ(im.stage_order, 1);
  EXPECT_NEAR(im.r_infinity, -1, 1e-14);
  EXPECT_FALSE(im.stiffly_accurate);
  EXPECT_EQ(im.stiff, 2);  // q + 1: the alternating errors cancel

  EXPECT_EQ(gl.stage_order, 2);
  EXPECT_NEAR(gl.r_infinity, 1, 1e-14);
  EXPECT_NEAR(gl.long_run, 12, 1e-12);
  EXPECT_EQ(gl.stiff, 2);  // q: the errors add up

  EXPECT_EQ(ra.stage_order, 3);
  EXPECT_NEAR(ra.r_infinity, 0, 1e-13);
  EXPECT_TRUE(ra.stiffly_accurate);
  EXPECT_EQ(ra.stiff, 3);
  EXPECT_EQ(ra.long_run, 0);
}

// BDF: its own error O(h^p / lambda) vanishes; its Gauss-Legendre start's local error O(h^3)
// stays. Explicit methods have no stiff limit (their step map's spectral radius at h lambda =
// -2.7e5 is far above 1).
TEST(OrderReductionTheory, MultistepAndExplicit) {
  EXPECT_EQ(theory("bdf2").stiff, 3);
  EXPECT_EQ(theory("bdf3").stiff, 3);
  for (const char* m : {"explicit_euler", "rk4", "velocity_verlet", "yoshida4", "adams_bashforth2", "symplectic_euler"})
    EXPECT_EQ(theory(m).stiff, -1) << m;
}

// The report's sweep (analysis/studies/defaults.hpp): stiffness 1e-2 .. 1e12 on the target, steps 0.2 ..
// 0.01. Each implicit method's order at the first value within 0.05 of its classical order and at
// the last within 0.15 of the theory's stiff order, each bound containing it (the bars).
OrderReduction report_sweep(const std::vector<double>& params_override = {}) {
  const StiffOrderDefaults d;
  const std::size_t scene = *find_scene(kStiffenedScene);
  std::vector<std::size_t> methods;
  for (std::size_t m = 0; m < method_count(); ++m)
    if (in_ode_studies(m)) methods.push_back(m);
  return order_reduction(
      stiff_order_config(scene, params_override.empty() ? default_param_values(scene) : params_override, d, methods),
      d.stiffnesses);
}

void expect_limits_hold(const OrderReduction& r) {
  for (const MethodReduction& m : r.methods) {
    const std::string n(method_info(m.method).name);
    EXPECT_TRUE(m.non_stiff.reached) << n;
    EXPECT_TRUE(m.non_stiff.holds) << n << ": " << m.non_stiff.order << " [" << m.non_stiff.bound_lo << ", " << m.non_stiff.bound_hi << "]";
    EXPECT_NEAR(m.non_stiff.order, m.theory.classical, kNonStiffTolerance) << n;
    if (m.theory.stiff < 0) continue;
    EXPECT_TRUE(m.stiff.reached) << n;
    EXPECT_TRUE(m.stiff.holds) << n << ": " << m.stiff.order << " [" << m.stiff.bound_lo << ", " << m.stiff.bound_hi << "]";
    EXPECT_NEAR(m.stiff.order, m.theory.stiff, kStiffTolerance) << n;
  }
}

TEST(OrderReduction, BothLimitsHoldOnTheTarget) { expect_limits_hold(report_sweep()); }

// The theory does not depend on the scene's other parameters: a heavier mass and damping ratio 3
// (eigenvalues -0.17 and -5.8 sqrt(k / m)). (The target's frequency stays: it sets the time scale
// the steps resolve, and the report's steps are chosen for 1.)
TEST(OrderReduction, BothLimitsHoldUnderChangedParameters) {
  const std::size_t s = *find_scene(kStiffenedScene);
  std::vector<double> p = default_param_values(s);
  p[0] = 2, p[2] = 3;  // mass, damping-ratio
  expect_limits_hold(report_sweep(p));
}

// Radau IIA 5 keeps 5 while h |lambda| is small and is at 3 once it is large. The theory's two
// expansions, in z and in 1 / z, hold for |z| < 1 and |z| > 1: the order is kept only below
// h |lambda| = 1, the stiff order shows only above it.
TEST(OrderReduction, RadauTransitionStraddlesHLambdaOne) {
  const OrderReduction r = report_sweep();
  int rows = 0;
  for (const MethodReduction& m : r.methods) {
    if (method_info(m.method).name != "radau_iia5") continue;
    ++rows;
    ASSERT_FALSE(std::isnan(m.keeps_to));
    ASSERT_FALSE(std::isnan(m.reduced_from));
    EXPECT_LT(m.keeps_to, m.reduced_from);
    EXPECT_LT(m.keeps_to, 1);
    EXPECT_GT(m.reduced_from, 1);
  }
  EXPECT_EQ(rows, 1);  // the sweep has Radau IIA's row
}

// Where the sweep stops short of the stiff regime, the limit is not claimed.
TEST(OrderReduction, StiffLimitNotReachedAtLowStiffness) {
  ConvergenceConfig c;
  c.scene = *find_scene(kStiffenedScene);
  c.params = default_param_values(c.scene);
  c.dt_max = 0.2, c.dt_min = 0.01, c.points = 9;
  c.fit_error = ErrorKind::Max;
  c.methods = {*find_method("radau_iia5")};
  const OrderReduction r = order_reduction(c, {1e-2, 1});
  EXPECT_FALSE(r.methods.front().stiff.reached);
  EXPECT_FALSE(r.methods.front().stiff.holds);
}

}  // namespace
}  // namespace steplab
