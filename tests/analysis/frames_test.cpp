// The frame-budget study (analysis/studies/frames.hpp) through the kernel table, against the
// numbers its parts must give: "Small steps" XPBD errors as an independent implementation measured
// them on this rope (tests/core/xpbd_test.cpp holds the method itself to them), Baraff-Witkin
// with its CG converged equal to implicit Euler on the linear rope, the explicit methods unstable
// where the rope's fastest mode is past their limit, and each family's front.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/studies/convergence.hpp"
#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/frames.hpp"

namespace steplab {
namespace {

const FramesResult& study() {
  static const FramesResult r = [] {
    FramesConfig c = default_frames_config();
    c.timing = false;
    c.workers.threads = 2;
    return frames_study(c);
  }();
  return r;
}

const FrameRun& find(std::string_view method, int substeps) {
  for (const FrameRun& r : study().runs)
    if (method_info(r.setup.method).name == method && r.setup.substeps == substeps) return r;
  throw std::logic_error("no such run");
}

// The independent implementation's 4.5e-3 (30 x 1) and 7.3e-2 (1 x 30), to 10 %; 16x apart.
TEST(Frames, SubstepsBeatSweepsAsSmallStepsMeasured) {
  const FrameRun &small = find("xpbd", 30), &one = find("xpbd", 1);
  EXPECT_EQ(small.setup.settings.sweeps, 1);
  EXPECT_EQ(one.setup.settings.sweeps, 30);
  EXPECT_NEAR(small.error, 4.5e-3, 4.5e-4);
  EXPECT_NEAR(one.error, 7.3e-2, 7.3e-3);
  EXPECT_GT(one.error / small.error, 10);
  EXPECT_GT(one.stretch, small.stretch);  // the unconverged sweeps let the springs give
  // the same work a frame at every split: 30 sweeps of the 32 springs
  EXPECT_EQ(small.projections, one.projections);
  EXPECT_EQ(small.spring_visits, 30.0 * study().springs);
}

// How far the rope moves: released at rest from its unstretched line, it falls to the static sag
// M g (N + 1) / (2 K N) at its free end (the sum of the springs' extensions) and, lightly damped,
// overshoots to nearly twice that (a step load on a linear system: each mode to 1 - cos). The
// best position-based error (PBD's, 2.24e-3) is not below it: a rope at rest meets it.
TEST(Frames, MotionIsTheSagsOvershoot) {
  const FramesConfig& c = study().config;
  const double n = 32, sag = 1.0 * 9.81 * (n + 1) / (2 * 5000 * n);
  ASSERT_EQ(c.params[0], n);
  EXPECT_GT(study().motion, 1.8 * sag);
  EXPECT_LT(study().motion, 2.1 * sag);
  double best = INFINITY;
  for (const FrameRun& r : study().runs)
    if (r.stable && method_info(r.setup.method).family == Family::PositionBased) best = std::min(best, r.error);
  EXPECT_GT(best, study().motion);
}

// One substep of Baraff-Witkin with 30 CG iterations is implicit Euler's step on the linear rope:
// the same error to 1e-5 of it (CG stops at 1e-8 of each step's right-hand side: 2e-6 measured);
// symplectic Euler and RK4 at one substep a frame are far past their limits (the rope's fastest mode: omega h ~ 80 at 1/60 s), unstable.
TEST(Frames, LargeStepsAreImplicitEulerAndExplicitStepsBlowUp) {
  EXPECT_NEAR(find("baraff_witkin", 1).error, find("implicit_euler", 1).error, 1e-5 * find("implicit_euler", 1).error);
  EXPECT_FALSE(find("symplectic_euler", 1).stable);
  EXPECT_FALSE(find("rk4", 1).stable);
  EXPECT_TRUE(find("rk4", 30).stable);  // omega h ~ 2.7 < 2.83
  for (const FrameRun& r : study().runs)
    if (method_info(r.setup.method).on_springs) {
      EXPECT_TRUE(r.stable) << method_info(r.setup.method).name;
    }
}

// A front: cost rising, error falling, every member stable and of its family.
TEST(Frames, FrontsFallInErrorAsTheCostRises) {
  ASSERT_FALSE(study().fronts.empty());
  for (const FamilyFront& f : study().fronts) {
    for (std::size_t k = 0; k < f.runs.size(); ++k) {
      const FrameRun& r = study().runs[f.runs[k]];
      EXPECT_EQ(method_info(r.setup.method).family, f.family);
      EXPECT_TRUE(r.stable);
      if (k == 0) continue;
      const FrameRun& before = study().runs[f.runs[k - 1]];
      EXPECT_GE(frame_cost(r), frame_cost(before));
      EXPECT_LT(r.error, before.error);
    }
  }
}

// The orders in h where the rope's modes are resolved: XPBD with one sweep converges at first
// order (one Gauss-Seidel sweep nearly solves once k h^2 / m is small); PBD does not converge
// (its springs stiffen towards rods as h shrinks: the error levels off), slope within 0.1 of 0.
TEST(Frames, XpbdConvergesInHAndPbdDoesNot) {
  for (const FrameOrder& o : study().orders) {
    const std::string_view name = method_info(o.setup.method).name;
    if (name == "xpbd" && o.setup.settings.sweeps == 1) {
      EXPECT_NEAR(o.order, 1, 0.15);
    }
    if (name == "pbd") {
      EXPECT_NEAR(o.order, 0, 0.1);
    } else {
      EXPECT_GT(o.order, 0.5) << name;
    }
  }
}

// The convergence study takes a method's settings: XPBD on the stiff rope at steps of 1/7680 ..
// 1/960 s with one sweep a step is far from implicit Euler at the largest step and near it at the
// smallest (the sweep nearly solves once k h^2 / m is small); with 50 sweeps it is within 5 % of
// implicit Euler at every step (the rope's absolute damping, which XPBD takes at the step's start,
// is the difference).
TEST(Frames, ConvergenceTakesTheSweeps) {
  const FramesConfig f = default_frames_config();
  ConvergenceConfig c;
  c.scene = f.scene, c.params = f.params, c.t_end = 1, c.dt_max = 1.0 / 960, c.dt_min = 1.0 / 7680, c.points = 4;
  c.methods = {*find_method("xpbd"), *find_method("implicit_euler")};
  c.workers.threads = 2;
  const ConvergenceResult one = convergence_study(c);
  c.settings.sweeps = 50;
  const ConvergenceResult fifty = convergence_study(c);
  const std::size_t n = one.dts.size();
  ASSERT_EQ(one.records.size(), 2 * n);
  const auto error = [&](const ConvergenceResult& r, std::size_t method, std::size_t i) { return r.records[method * n + i].error_final; };
  EXPECT_GT(std::abs(error(one, 0, 0) - error(one, 1, 0)), 0.1 * error(one, 1, 0)) << "one sweep at the largest step";
  for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(error(fifty, 0, i), error(fifty, 1, i), 0.05 * error(fifty, 1, i)) << one.dts[i];
}

// A run that ends finite can still have flown apart. Baraff-Witkin at one substep a frame on the
// cloth of 32 a side (one linearised step of 1/60 s across its stiff springs) sends masses tens of
// metres off a sheet 1 m wide: the kernel's own run, read here without the study, puts a mass
// more than 20 m from the origin (the sheet's pinned corners are at (0, 0, 0) and (1, 0, 0)). The
// study calls it unstable though its status is ok, and every other split stable: their errors
// below the span of the reference's box (a swing of about a metre and a half).
TEST(Frames, AFlownApartRunIsUnstable) {
  FramesConfig c;
  c.scene = *find_scene("cloth");
  c.params = default_param_values(c.scene);
  c.params[static_cast<std::size_t>(param_index(scene_kernel(c.scene).params, "grid"))] = 32;
  c.t_end = 0.5, c.reference_substeps = 200, c.timing = false, c.orders = false;
  c.methods = {*find_method("baraff_witkin")};
  c.workers.threads = 2;
  const FramesResult r = frames_study(c);
  ASSERT_EQ(r.runs.size(), 8u);
  EXPECT_GT(r.span, 1.0);
  EXPECT_LT(r.span, 2.0);
  const FrameRun& one = r.runs.front();
  ASSERT_EQ(one.setup.substeps, 1);
  EXPECT_EQ(one.status, RunStatus::Ok);
  EXPECT_FALSE(one.stable);
  RunSpec spec;
  spec.dt = 1.0 / 60, spec.steps = 30, spec.settings = one.setup.settings;
  const AnyResult run = pair_kernel(one.setup.method, c.scene).run(c.params, spec);
  ASSERT_EQ(run.status, RunStatus::Ok);
  EXPECT_GT(run.final.x.cwiseAbs().maxCoeff(), 20.0);
  for (std::size_t k = 1; k < r.runs.size(); ++k) {
    EXPECT_TRUE(r.runs[k].stable) << r.runs[k].setup.substeps;
    EXPECT_LT(r.runs[k].error, r.span) << r.runs[k].setup.substeps;
  }
}

}  // namespace
}  // namespace steplab
