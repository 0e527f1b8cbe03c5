// Unit tests for core/scenes/bounce.hpp, falling.hpp and ground.hpp.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "analysis/kernel/kernel.hpp"
#include "core/scenes/bounce.hpp"
#include "core/scenes/falling.hpp"

namespace steplab {
namespace {

// Central differences with step e = 1e-6 on forces of size ~k * 1: truncation e^2 |F'''| is
// tiny for these smooth (away from contact) forces, round-off ~eps |F| / e ~ 1e-9 * 10.
// 1e-6 relative to the largest entry leaves a margin of 100.
template <class S> void expect_jacobians_match(const S& s, const Vec<S::dim>& x, const Vec<S::dim>& v) {
  constexpr int D = S::dim;
  const Jacobians<D> jac = s.jacobians(x, v);
  Mat<D> fdx, fdv;
  const double e = 1e-6;
  for (int j = 0; j < D; ++j) {
    Vec<D> dp = Vec<D>::Zero();
    dp[j] = e;
    fdx.col(j) = (s.force(x + dp, v) - s.force(x - dp, v)) / (2 * e);
    fdv.col(j) = (s.force(x, v + dp) - s.force(x, v - dp)) / (2 * e);
  }
  const double scale = std::max({1.0, jac.dx.cwiseAbs().maxCoeff(), jac.dv.cwiseAbs().maxCoeff()});
  EXPECT_LT((jac.dx - fdx).cwiseAbs().maxCoeff(), 1e-6 * scale) << "dF/dx\n" << jac.dx << "\nvs\n" << fdx;
  EXPECT_LT((jac.dv - fdv).cwiseAbs().maxCoeff(), 1e-6 * scale) << "dF/dv\n" << jac.dv << "\nvs\n" << fdv;
}

TEST(Falling, StartShapeAndRestLength) {
  const Falling f = make_default_scene<Falling>();
  const State<6> y = f.initial();
  EXPECT_NEAR(f.rest, std::sqrt(3.0), 1e-15);
  EXPECT_EQ(y.x[1], 1.0);
  EXPECT_NEAR(y.x[3], -0.5, 1e-15);  // sin 210 deg
  EXPECT_TRUE(f.force(y.x, y.v).segment<2>(0).isApprox(Eigen::Vector2d(0, -f.m * f.g)));  // springs at rest
}

TEST(Falling, JacobiansMatchFiniteDifferences) {
  std::array<double, 6> p{0.3, 17.0, 0.7, 9.81, 100.0, 2.0};
  const Falling f(p);
  Vec<6> x, v;
  x << 0.1, 0.9, -0.8, -0.4, 0.95, -1.2;  // third particle 0.2 below the ground
  v << 0.3, -1.0, 0.5, 0.2, -0.7, -0.4;
  expect_jacobians_match(f, x, v);
}

TEST(Bounce, JacobiansMatchFiniteDifferences) {
  std::array<double, 4> p{1.0, 9.81, 100.0, 3.0};
  const Bounce b(p);
  expect_jacobians_match(b, Vec<1>::Constant(-1.2), Vec<1>::Constant(-2.0));
  expect_jacobians_match(b, Vec<1>::Constant(0.5), Vec<1>::Constant(-2.0));
}

// Undamped: first contact after sqrt(2 / g) s of free fall; in contact u = y - y_c starts at
// u0 = m g / k_g with u' = -sqrt(2 g) and follows R cos(w t + phi), tan(phi) = sqrt(2 g) / (w u0),
// leaving the ground when w t + phi = 2 pi - phi; then it flies back up to exactly y = 0.
TEST(Bounce, ExactEventsAgainstClosedForms) {
  const Bounce b = make_default_scene<Bounce>();
  const double g = 9.81, w = 10.0, u0 = g / 100, v_hit = std::sqrt(2 * g);
  const double t_hit = std::sqrt(2 / g);
  const double phi = std::atan2(v_hit / w, u0);
  const double t_exit = t_hit + (2 * std::numbers::pi - 2 * phi) / w;
  // just before and after the first contact
  EXPECT_GE(exact(b, t_hit * (1 - 1e-12)).x[0], -1.0);
  EXPECT_LT(exact(b, t_hit * (1 + 1e-9)).x[0], -1.0);
  EXPECT_LT(exact(b, t_exit - 1e-9).x[0], -1.0);
  EXPECT_GT(exact(b, t_exit + 1e-9).x[0], -1.0);
  const State<1> out = exact(b, t_exit);
  EXPECT_NEAR(out.x[0], -1.0, 1e-12);
  EXPECT_NEAR(out.v[0], v_hit, 1e-11);  // leaves as fast as it came
  const State<1> apex = exact(b, t_exit + v_hit / g);
  EXPECT_NEAR(apex.x[0], 0.0, 1e-11);
  EXPECT_NEAR(apex.v[0], 0.0, 1e-11);
}

TEST(Bounce, ExactFlowConservesEnergyAndComposes) {
  const Bounce b = make_default_scene<Bounce>();
  const double e0 = b.energy(b.initial().x, b.initial().v);
  State<1> stepped = b.initial();
  for (int i = 1; i <= 1000; ++i) {
    stepped = b.flow(stepped, 0.01);
    const State<1> direct = exact(b, i * 0.01);
    ASSERT_NEAR(b.energy(direct.x, direct.v), e0, 1e-10 * e0) << i;
    ASSERT_NEAR(stepped.x[0], direct.x[0], 1e-9) << i;  // flow(h) n times = flow(n h)
  }
}

TEST(Bounce, GroundDampingLosesEnergyEveryBounce) {
  std::array<double, 4> p{1.0, 9.81, 100.0, 2.0};
  const Bounce b(p);
  double previous = b.energy(b.initial().x, b.initial().v);
  for (double t : {1.0, 2.0, 3.0}) {
    const State<1> y = exact(b, t);
    const double e = b.energy(y.x, y.v);
    EXPECT_LT(e, previous);
    previous = e;
  }
}

}  // namespace
}  // namespace steplab
