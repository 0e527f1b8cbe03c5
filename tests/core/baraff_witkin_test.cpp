// Baraff and Witkin's large steps (core/methods/baraff_witkin.hpp) and PBD (core/methods/pbd.hpp)
// against what they must be: one Newton step of implicit Euler is implicit Euler itself on a
// linear scene (steplab's own, by Newton with a sparse factorisation: another code path); a
// capped CG approaches it as the cap grows; PBD's one sweep at a frame is XPBD's, and its
// per-sweep stiffness makes the sweeps' count no matter on a lone constraint.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "core/methods/baraff_witkin.hpp"
#include "core/methods/implicit_euler.hpp"
#include "core/methods/pbd.hpp"
#include "core/methods/xpbd.hpp"
#include "core/scenes/chain.hpp"
#include "core/scenes/rope.hpp"
#include "core/scenes/softbody.hpp"
#include "core/scenes/spring.hpp"
#include "core/simulate.hpp"

namespace steplab {
namespace {

template <class M, class S> RunResult<S::dim> run(const S& s, double h, long long steps, MethodSettings set = {}) {
  RunSpec spec;
  spec.dt = h, spec.steps = steps, spec.errors = false, spec.settings = set;
  return simulate<M>(s, spec);
}

MethodSettings cg(int iterations, double tolerance) {
  MethodSettings s;
  s.cg_iterations = iterations, s.cg_tolerance = tolerance;
  return s;
}

// The rope (its dashpots on) and the chain are linear: the one Newton step solves implicit Euler's
// system, and CG run to 1e-14 of its right-hand side leaves the two within round-off of the
// solves (1e-11 of the motion's size over 200 steps).
TEST(BaraffWitkin, ConvergedCgIsImplicitEulerOnALinearScene) {
  std::vector<double> p = default_param_values<Rope>();
  p[param_index(Rope::params, "masses")] = 32, p[param_index(Rope::params, "spring-damping")] = 0.3;
  const Rope rope(p);
  const auto ie = run<ImplicitEuler>(rope, 0.01, 200), bw = run<BaraffWitkin>(rope, 0.01, 200, cg(1000, 1e-14));
  EXPECT_GT((ie.final.x - rope.initial().x).cwiseAbs().maxCoeff(), 0.1) << "the rope has moved";
  EXPECT_LE((ie.final.x - bw.final.x).cwiseAbs().maxCoeff(), 1e-11 * 5);
  EXPECT_LE((ie.final.v - bw.final.v).cwiseAbs().maxCoeff(), 1e-10);

  const Chain chain(default_param_values<Chain>());
  const auto ie2 = run<ImplicitEuler>(chain, 1e-3, 1000), bw2 = run<BaraffWitkin>(chain, 1e-3, 1000, cg(100, 1e-14));
  EXPECT_LE((ie2.final.x - bw2.final.x).cwiseAbs().maxCoeff(), 1e-11);
}

// On the soft body the springs turn (nonlinear): one Newton step is not implicit Euler, but near
// it (the linearisation's error is O(h^2) a step); with the CG capped the step approaches the
// converged one as the cap grows, each cap closer than the one before.
TEST(BaraffWitkin, CappedCgApproachesTheConvergedStep) {
  std::vector<double> p = default_param_values<SoftBody>();
  p[param_index(SoftBody::params, "grid")] = 8;
  const SoftBody body(p);
  const double h = 1.0 / 60;
  const auto converged = run<BaraffWitkin>(body, h, 60, cg(10000, 1e-14));
  const auto ie = run<ImplicitEuler>(body, h, 60);
  const double to_ie = (converged.final.x - ie.final.x).cwiseAbs().maxCoeff();
  std::printf("soft body 8 x 8, 60 steps of 1/60: Baraff-Witkin (CG converged) against implicit Euler %.2e\n", to_ie);
  EXPECT_LT(to_ie, 0.05);
  double previous = INFINITY;
  for (int cap : {1, 3, 10, 30}) {
    const auto capped = run<BaraffWitkin>(body, h, 60, cg(cap, 1e-14));
    const double e = (capped.final.x - converged.final.x).cwiseAbs().maxCoeff();
    std::printf("  CG capped at %2d iterations: %.2e from the converged step's run\n", cap, e);
    EXPECT_LT(e, previous) << cap;
    previous = e;
  }
  EXPECT_LT(previous, 1e-3);
}

// PBD's k_s is set so that one sweep at a step of 1/60 s moves a spring as XPBD's first sweep does
// (without a dashpot, whose PBD takes explicitly): the same steps to round-off. And on a lone
// linear constraint n sweeps of k' = 1 - (1 - k_s)^(1/n) close what one sweep of k_s does.
TEST(Pbd, OneSweepAtAFrameIsXpbdsAndTheSweepsCountNotOnOneSpring) {
  std::vector<double> p = default_param_values<Spring>();
  p[param_index(Spring::params, "damping")] = 0;
  const Spring s(p);
  const double h = Pbd::kFrame;
  const auto pbd = run<Pbd>(s, h, 120), xpbd = run<Xpbd>(s, h, 120);
  EXPECT_NEAR(pbd.final.x[0], xpbd.final.x[0], 1e-12 * std::abs(xpbd.final.x[0]));
  EXPECT_NEAR(pbd.final.v[0], xpbd.final.v[0], 1e-11);
  MethodSettings five;
  five.sweeps = 5;
  const auto pbd5 = run<Pbd>(s, h, 120, five);
  EXPECT_NEAR(pbd5.final.x[0], pbd.final.x[0], 1e-12 * std::abs(pbd.final.x[0]));
  // At a tenth of the step the same k_s is another material: stiffer, the sag at rest smaller.
  const auto fine = run<Pbd>(s, h / 10, 1200), exact = run<Xpbd>(s, h / 10, 1200);
  EXPECT_GT(std::abs(fine.final.x[0] - exact.final.x[0]), 0.1) << "PBD's stiffness changes with the step";
}

}  // namespace
}  // namespace steplab
