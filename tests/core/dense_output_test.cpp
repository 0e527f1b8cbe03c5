// Output between steps (core/dense_output.hpp, RunSpec::outputs in core/simulate.hpp): the Hermite
// interpolants reproduce the polynomials they are exact for, and a run's outputs are at the times
// asked, equal to the step's state where a time falls on a step, with the quintic's force
// evaluations counted.
#include <gtest/gtest.h>

#include <cmath>

#include "core/dense_output.hpp"
#include "core/methods/explicit_euler.hpp"
#include "core/methods/rk4.hpp"
#include "core/scenes/spring.hpp"
#include "core/simulate.hpp"

namespace steplab {
namespace {

// A polynomial x(t) = sum c_k t^k and its first two derivatives.
struct Poly {
  std::vector<double> c;
  double at(double t, int d = 0) const {
    double sum = 0;
    for (std::size_t k = static_cast<std::size_t>(d); k < c.size(); ++k) {
      double f = 1;
      for (int j = 0; j < d; ++j) f *= static_cast<double>(k - static_cast<std::size_t>(j));
      sum += f * c[k] * std::pow(t, static_cast<double>(k) - d);
    }
    return sum;
  }
};

// Each interpolant is exact on the polynomials of its degree (3, 5), and not on the next: the
// error of its degree + 1 term is what sets the order.
TEST(DenseOutput, HermiteIsExactOnItsDegree) {
  const double t0 = 0.3, h = 0.7;
  const auto check = [&](const Poly& p, bool quintic) {
    double worst = 0;
    for (double s = 0; s <= 1.0001; s += 0.125) {
      Vec<1> x, v;
      const Vec<1> x0(p.at(t0)), v0(p.at(t0, 1)), a0(p.at(t0, 2)), x1(p.at(t0 + h)), v1(p.at(t0 + h, 1)), a1(p.at(t0 + h, 2));
      if (quintic) hermite5(x0, v0, a0, x1, v1, a1, h, s, x, v);
      else hermite3(x0, v0, x1, v1, h, s, x, v);
      worst = std::max({worst, std::abs(x[0] - p.at(t0 + s * h)), std::abs(v[0] - p.at(t0 + s * h, 1))});
    }
    return worst;
  };
  EXPECT_LT(check({{1.5, -2, 0.5, 3}}, false), 1e-13);
  EXPECT_GT(check({{0, 0, 0, 0, 1}}, false), 1e-3);
  EXPECT_LT(check({{1.5, -2, 0.5, 3, -1.25, 0.75}}, true), 1e-13);
  EXPECT_GT(check({{0, 0, 0, 0, 0, 0, 1}}, true), 1e-4);
}

// outputs = 21 over 10 steps of 0.1: t_k = k / 20, every other one on a step (there the state
// itself, to the last bit: s = 0 or 1 weights the end exactly), the rest halfway; the
// quintic's two force evaluations per step that holds an output are counted by the scene.
TEST(DenseOutput, RunGivesTheOutputsAtTheirTimes) {
  const Spring s(std::vector<double>{1, 5, 0.1, 5, 9.81});
  RunSpec spec;
  spec.dt = 0.1, spec.steps = 10, spec.outputs = 21, spec.errors = false;
  RunSpec plain = spec;
  plain.outputs = 0, plain.max_samples = 11;
  const RunResult<1> r = simulate<Rk4>(s, spec), p = simulate<Rk4>(s, plain);
  ASSERT_EQ(r.samples.size(), 21u);
  ASSERT_EQ(p.samples.size(), 11u);
  for (std::size_t k = 0; k < 21; ++k) {
    EXPECT_NEAR(r.samples[k].t, 0.05 * static_cast<double>(k), 1e-15);
    if (k % 2 == 0) {
      EXPECT_EQ(r.samples[k].x[0], p.samples[k / 2].x[0]) << k;
    }
  }
  // halfway through a step, within the method's error of the exact motion
  for (std::size_t k = 1; k < 21; k += 2) EXPECT_NEAR(r.samples[k].x[0], exact(s, r.samples[k].t).x[0], 1e-4) << k;
  // the same steps: the final states agree to the bit
  EXPECT_EQ(r.final.x[0], p.final.x[0]);
  EXPECT_EQ(quintic_output(Rk4::info.order), true);
  EXPECT_EQ(quintic_output(ExplicitEuler::info.order), false);
  EXPECT_EQ(dense_output_order(5), 5);
  EXPECT_EQ(dense_output_order(1), 1);
}

}  // namespace
}  // namespace steplab
