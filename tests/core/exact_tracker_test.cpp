// Unit tests for ExactTracker (core/scene.hpp): on a scene with an affine flow and a fixed step,
// the tracker steps the exact state (y <- c + Phi y) and goes back to the closed form every
// kResync steps. Checked against the closed form exact_at(t) at every step of long runs, in
// every damping regime of the spring and on the chain (stiff and soft), and that a run's error
// figures match those of a run whose errors are computed from the closed form at every step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/kernel/kernel.hpp"
#include "core/methods/rk4.hpp"
#include "core/scenes/chain.hpp"
#include "core/scenes/spring.hpp"
#include "core/simulate.hpp"

namespace steplab {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// The largest difference between the stepped tracker and the closed form over `steps` steps of
// h, relative to the largest |state| component seen.
template <class S> double worst_relative_gap(const S& s, double h, long long steps) {
  ExactTracker<S> stepped(s, h);
  double gap = 0, scale = 0;
  for (long long i = 1; i <= steps; ++i) {
    const double t = static_cast<double>(i) * h;
    const State<S::dim> a = stepped.at(t), b = s.exact_at(t);
    gap = std::max({gap, (a.x - b.x).cwiseAbs().maxCoeff(), (a.v - b.v).cwiseAbs().maxCoeff()});
    scale = std::max({scale, b.x.cwiseAbs().maxCoeff(), b.v.cwiseAbs().maxCoeff()});
  }
  return gap / scale;
}

// Tolerance, relative to the largest |state|: between two returns to the closed form, at most
// kResync - 1 products y <- c + Phi y, each off by a few ulps of |y| (c and the columns of Phi are
// differences of flow values of size |y|, so they carry a few ulps of |y| too, and 2 D + 1 such
// terms add up in a step): 64 ulps a step over kResync steps, 4.5e-13. The closed form itself is
// exact only to the round-off of its phase, about eps omega t (2e-12 at t = 6000 for omega = 2.2),
// which the tracker meets afresh at every return. Both are round-off: a run of more than a few
// thousand steps carries more in its own state, and a wrong Phi grows without bound.
double tolerance(double omega, double t_end) { return ExactTracker<Spring>::kResync * 64 * kEps + 4 * kEps * omega * t_end; }

TEST(ExactTracker, SteppedSpringMatchesClosedFormInEveryRegime) {
  const double critical = 2 * std::sqrt(5.0);
  // rest length 5, and 1967 (far below the anchor, as in study damping and stability: |y| ~ 2000)
  for (const double rest : {5.0, 1967.0})
    for (const double ratio : {0.0, 0.01, 0.5, 1.0, 1.3, 2.0}) {
      const std::array<double, 5> p{1.0, 5.0, ratio * critical, rest, 9.81};
      for (const double h : {1e-4, 1e-2, 0.3})
        EXPECT_LE(worst_relative_gap(Spring(p), h, 20'000), tolerance(Spring(p).omega(), 20'000 * h))
            << "rest length " << rest << ", damping/critical " << ratio << ", h " << h;
    }
}

TEST(ExactTracker, SteppedChainMatchesClosedForm) {
  for (const double k2 : {5.0, 5e4}) {
    std::vector<double> p = default_param_values<Chain>();
    p[3] = k2;  // Chain::params: mass1, mass2, stiffness1, stiffness2, ...
    const double omega = std::sqrt((p[2] + 2 * k2) / p[0]);  // above the chain's largest frequency
    for (const double h : {1e-4, 1e-2})
      EXPECT_LE(worst_relative_gap(Chain(p), h, 20'000), tolerance(omega, 20'000 * h)) << "k2 " << k2 << ", h " << h;
  }
}

// A run's error figures with the stepped tracker against the same run's states compared with the
// closed form at every step (observer): the same to round-off of the state (|y| ~ 7 here).
TEST(ExactTracker, RunErrorsMatchClosedForm) {
  const Spring s = make_default_scene<Spring>();
  RunSpec spec;
  spec.dt = 1e-3;
  spec.steps = 10'000;
  double error_max = 0;
  const auto closed = [&](long long i, double, const State<1>& y) {
    error_max = std::max(error_max, std::abs(y.x[0] - s.exact_at(static_cast<double>(i) * spec.dt).x[0]));
  };
  const RunResult<1> r = simulate<Rk4>(s, spec, closed);
  ASSERT_EQ(r.status, RunStatus::Ok);
  EXPECT_NEAR(r.error_max, error_max, tolerance(s.omega(), 10.0) * 7);  // |y| <= 7
  EXPECT_GT(error_max, 0);
}

}  // namespace
}  // namespace steplab
