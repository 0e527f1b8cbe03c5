// The soft body (core/scenes/softbody.hpp): totals kept under refinement, free fall before it
// touches the ground against the closed form, its forces against finite differences of its
// energy, its sparse Jacobians against finite differences of its forces, and implicit Euler's
// Newton (sparse LU: dF/dx is not symmetric with dashpots) converging at order 1.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "analysis/kernel/kernel.hpp"
#include "core/scenes/softbody.hpp"
#include "tests/core/differences.hpp"

namespace steplab {
namespace {

// grid, M, k, gamma, side, g, k_g, c_g
SoftBody body(int n, double gamma = 0.01, double cg = 0.0) {
  const std::array<double, 8> p{double(n), 0.3, 10.0, gamma, 1.5, 9.81, 100.0, cg};
  return SoftBody(p);
}

// A state away from rest: every mass moved and moving by a fixed pseudo-random pattern, the
// bottom row pushed below the ground (no mass within 1e-3 of it: the ground's derivative jumps there).
State<Eigen::Dynamic> stirred(const SoftBody& s) {
  State<Eigen::Dynamic> y = s.initial();
  for (int i = 0; i < y.x.size(); ++i) {
    y.x[i] += 0.05 * std::sin(1.7 * i + 0.3) - (i % 2 == 1 ? 0.55 : 0.0);
    y.v[i] = 0.8 * std::cos(2.3 * i);
  }
  for (int i = 1; i < y.x.size(); i += 2) EXPECT_GT(std::abs(y.x[i] + 1), 1e-3);
  return y;
}

TEST(SoftBody, TotalsAreKeptUnderRefinement) {
  for (int n : {2, 3, 5, 8, 13}) {
    const SoftBody s = body(n);
    EXPECT_NEAR(s.mass().sum() / 2, 0.3, 1e-14) << n;                 // x and y of each mass
    EXPECT_NEAR(s.ground.k * n, 100.0, 1e-12) << n;                     // the bottom row carries k_g
    EXPECT_EQ(s.springs.size(), std::size_t(2 * n * (n - 1) + 2 * (n - 1) * (n - 1))) << n;
    const Eigen::VectorXd x = s.initial().x;
    EXPECT_NEAR(x.maxCoeff(), 1.0, 1e-14) << n;  // x in [-0.75, 0.75], y in [-0.5, 1]
    EXPECT_NEAR(x.minCoeff(), -0.75, 1e-14) << n;
    EXPECT_DOUBLE_EQ(s.energy(x, Eigen::VectorXd::Zero(x.size())), 0.3 * 9.81 * 1.25) << n;  // centre 1.25 above the ground
  }
}

// Uniform gravity strains no spring: before the bottom row reaches the ground (t < sqrt(2 * 0.5 /
// g) = 0.319 s) every mass falls as y0 - g t^2 / 2, which velocity Verlet follows exactly for a
// constant acceleration (to round-off: 1e-12 over 300 steps).
TEST(SoftBody, FallsFreelyUntilItTouches) {
  const std::size_t scene = scene_index("softbody");
  std::vector<double> p = default_param_values(scene);
  p[0] = 5;
  RunSpec spec;
  spec.dt = 1e-3;
  spec.steps = 300;
  spec.errors = false;
  const AnyResult r = pair_kernel(*find_method("velocity_verlet"), scene).run(p, spec);
  ASSERT_EQ(r.status, RunStatus::Ok);
  const State<Eigen::Dynamic> y0 = SoftBody(p).initial();
  const double t = 0.3;
  for (int i = 0; i < y0.x.size(); ++i) {
    const double expected = i % 2 == 1 ? y0.x[i] - 0.5 * 9.81 * t * t : y0.x[i];
    EXPECT_NEAR(r.final.x[i], expected, 1e-12) << i;
    EXPECT_NEAR(r.final.v[i], i % 2 == 1 ? -9.81 * t : 0.0, 1e-12) << i;
  }
}

// Undamped, the force is minus the gradient of the potential (energy at v = 0; tests/core/
// differences.hpp).
TEST(SoftBody, ForceIsMinusTheGradientOfItsEnergy) {
  const SoftBody s = body(4, 0.0, 0.0);
  expect_force_is_minus_energy_gradient(s, stirred(s));
}

// dF/dx and dF/dv against central differences of F (F is smooth away from the ground's kink,
// quadratic in v; tests/core/differences.hpp), damped springs and a damped ground included, at a
// state where springs are stretched, turned and moving.
TEST(SoftBody, JacobiansMatchFiniteDifferences) {
  const SoftBody s = body(3, 0.4, 2.0);
  const Eigen::MatrixXd dx = expect_jacobians_match_differences(s, stirred(s));
  EXPECT_GT((dx - dx.transpose()).cwiseAbs().maxCoeff(), 1e-3 * dx.cwiseAbs().maxCoeff());  // not symmetric: LU, not LDL^T
}

// Implicit Euler on the damped body through the ground contact (Newton on the nonsymmetric
// sparse system, by LU): its final error against dopri5 at rtol 1e-12 halves with the step
// (order 1: the slope between dt 2e-3 and 1e-3 within 0.1 of 1; measured 0.988).
TEST(SoftBody, ImplicitEulerConvergesAtOrderOne) {
  const std::size_t scene = scene_index("softbody");
  std::vector<double> p = default_param_values(scene);
  p[0] = 4, p[3] = 0.5;  // damping 0.5
  const double t_end = 0.5;
  AdaptiveSpec a;
  a.tol = {1e-12, 1e-12};
  a.t_end = t_end;
  a.errors = false;
  const Eigen::VectorXd ref = scene_kernel(scene).dopri5(p, a).run.final.x;
  const auto error = [&](double dt) {
    RunSpec spec;
    spec.dt = dt;
    spec.steps = steps_for(t_end, dt);
    spec.errors = false;
    const AnyResult r = pair_kernel(*find_method("implicit_euler"), scene).run(p, spec);
    EXPECT_EQ(r.status, RunStatus::Ok);
    return (r.final.x - ref).cwiseAbs().maxCoeff();
  };
  const double slope = std::log2(error(2e-3) / error(1e-3));
  std::printf("implicit Euler on the soft body: slope %.3f\n", slope);
  EXPECT_NEAR(slope, 1.0, 0.1);
}

}  // namespace
}  // namespace steplab
