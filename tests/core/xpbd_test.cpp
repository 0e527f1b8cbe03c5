// XPBD (core/methods/xpbd.hpp) against what it must be: with its sweeps carried to convergence,
// implicit Euler on the springs (steplab's own, by Newton's method: another code path); and the
// substeps-against-sweeps comparison of "Small steps in physics simulation" (Macklin et al.,
// SCA 2019) as an independent implementation measured it on this rope.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/methods/implicit_euler.hpp"
#include "core/methods/xpbd.hpp"
#include "core/scenes/falling.hpp"
#include "core/scenes/rope.hpp"
#include "core/simulate.hpp"

namespace steplab {
namespace {

template <class S> RunResult<S::dim> xpbd(const S& s, double h, long long steps, int sweeps, auto&& observe) {
  RunSpec spec;
  spec.dt = h, spec.steps = steps, spec.errors = false, spec.settings.sweeps = sweeps;
  return simulate<Xpbd>(s, spec, observe);
}

// Converged sweeps: the implicit Euler step on the springs and dashpots. With no absolute damping
// (the one force XPBD takes at the step's start) the two agree to the solves' round-off: the
// rope (linear, 1-D, its dashpots on) to 1e-12 of its length, the falling triangle (springs that
// turn; implicit Euler's Newton stops at its tolerance) to 1e-9 of its size, before it lands.
TEST(Xpbd, ConvergedSweepsAreImplicitEuler) {
  std::vector<double> p = default_param_values<Rope>();
  p[param_index(Rope::params, "damping")] = 0, p[param_index(Rope::params, "spring-damping")] = 0.3;
  const Rope rope(p);
  RunSpec spec;
  spec.dt = 0.01, spec.steps = 200, spec.errors = false;
  const auto ie = simulate<ImplicitEuler>(rope, spec);
  const auto xp = xpbd(rope, 0.01, 200, 400, NoObserver{});
  EXPECT_LE((ie.final.x - xp.final.x).cwiseAbs().maxCoeff(), 1e-12 * 5);
  EXPECT_LE((ie.final.v - xp.final.v).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_GT((ie.final.x - rope.initial().x).cwiseAbs().maxCoeff(), 0.1) << "the rope has moved";

  const Falling tri(default_param_values<Falling>());
  spec.dt = 1e-3, spec.steps = 250;
  const auto ie2 = simulate<ImplicitEuler>(tri, spec);
  const auto xp2 = xpbd(tri, 1e-3, 250, 400, NoObserver{});
  EXPECT_LE((ie2.final.x - xp2.final.x).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LE((ie2.final.v - xp2.final.v).cwiseAbs().maxCoeff(), 1e-6);

  // On the ground too (its penalty spring a one-sided constraint), landed: 1e-6. Through contact
  // implicit Euler's Newton converges more slowly (the penalty force has a kink) and stops at its
  // residual test, where in free flight it ends far below it; converged XPBD is the same to 1e-16
  // with 400 sweeps or 3000. The difference grows with the time in contact (2e-10 after 20 steps
  // in it, 2e-7 after 80).
  spec.steps = 400;
  const auto ie3 = simulate<ImplicitEuler>(tri, spec);
  const auto xp3 = xpbd(tri, 1e-3, 400, 400, NoObserver{});
  EXPECT_GT(tri.penetration(ie3.final.x), 0.05) << "in the ground";
  EXPECT_LE((ie3.final.x - xp3.final.x).cwiseAbs().maxCoeff(), 1e-6);
}

// At a fixed number of sweeps XPBD is not implicit Euler: one sweep a step is far from it.
TEST(Xpbd, OneSweepIsNotConverged) {
  std::vector<double> p = default_param_values<Rope>();
  p[param_index(Rope::params, "masses")] = 32, p[param_index(Rope::params, "stiffness")] = 5000;
  const Rope rope(p);
  RunSpec spec;
  spec.dt = 1.0 / 60, spec.steps = 60, spec.errors = false;
  const auto ie = simulate<ImplicitEuler>(rope, spec);
  const auto one = xpbd(rope, 1.0 / 60, 60, 1, NoObserver{});
  EXPECT_GT((ie.final.x - one.final.x).cwiseAbs().maxCoeff(), 1e-3);
}

// The largest position error over the frames of 60 a second up to t = 2, against the exact
// motion, of XPBD at `substeps` a frame and `sweeps` a substep: the largest over the masses too.
double frame_error(const Rope& rope, int substeps, int sweeps) {
  const double frame = 1.0 / 60, h = frame / substeps;
  double worst = 0;
  xpbd(rope, h, 120LL * substeps, sweeps, [&](long long i, double t, const State<Eigen::Dynamic>& y) {
    if (i % substeps == 0) worst = std::max(worst, (y.x - rope.exact_at(t).x).cwiseAbs().maxCoeff());
  });
  return worst;
}

// "Small steps": at the same cost (30 sweeps a frame), 30 substeps of one sweep against one step
// of 30 sweeps, on the rope of 32 masses, total stiffness 5000. An independent implementation
// (the issue's) measured 4.5e-3 and 7.3e-2 (16x) and the splits between on one line (2 x 15:
// 3.8e-2, 5 x 6: 1.6e-2, 10 x 3: 9.4e-3); held here to 10 %.
TEST(Xpbd, SmallStepsBeatManySweeps) {
  std::vector<double> p = default_param_values<Rope>();
  p[param_index(Rope::params, "masses")] = 32, p[param_index(Rope::params, "stiffness")] = 5000;
  const Rope rope(p);
  const std::array<std::array<double, 3>, 5> published{{{30, 1, 4.5e-3}, {10, 3, 9.4e-3}, {5, 6, 1.6e-2}, {2, 15, 3.8e-2}, {1, 30, 7.3e-2}}};
  for (const auto& [substeps, sweeps, error] : published) {
    const double e = frame_error(rope, int(substeps), int(sweeps));
    std::printf("XPBD on the rope, %2.0f substeps x %2.0f sweeps a frame: largest error %.2e (independent: %.1e)\n", substeps, sweeps, e, error);
    EXPECT_NEAR(e, error, 0.1 * error) << substeps << " substeps x " << sweeps << " sweeps";
  }
}

}  // namespace
}  // namespace steplab
