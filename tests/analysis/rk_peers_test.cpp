// The implicit Runge-Kutta peers (analysis/peers/radau5.hpp, analysis/peers/arkode.hpp): RADAU5 is
// RADAU5 as plain C calls it, its output between steps is its collocation polynomial, ARKODE's
// stepper does what its guide says a linear problem costs, and both reach the exact solution
// as their tolerances say.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "analysis/peers/peers.hpp"
#include "analysis/peers/radau5.hpp"
#include "core/scenes/chain.hpp"
#include "core/scenes/spring.hpp"
#include "analysis/kernel/kernel.hpp"
#include "reports/data/inputs.hpp"
#if STEPLAB_HAVE_RADAU5
#include "bench/radau5_chain.h"
#endif

namespace steplab {
namespace {

std::vector<double> defaults_of(std::string_view scene) { return default_param_values(*find_scene(scene)); }

#if STEPLAB_HAVE_RADAU5
// steplab's RADAU5 peer on the chain against bench/radau5_chain.c, which calls the same library
// from C with no steplab code and the same settings: the same run, step for step (every count
// equal), and the same end state up to the round-off of the right side's order of operations.
TEST(Radau5, OnTheChainIsRadau5AsPlainCCallsIt) {
  const PeerInfo& peer = *find_peer("radau5_dense");
  for (const double tol : {1e-4, 1e-8}) {
    PeerCounts ours;
    const State<Eigen::Dynamic> end = run_fixed_peer(peer, "chain", defaults_of("chain"), tol, 10.0, ours);
    radau5_chain_counts c{};
    double z[4];
    radau5_chain_run(tol, 10.0, &c, z);
    ASSERT_EQ(c.idid, 1);
    EXPECT_FALSE(ours.failed);
    EXPECT_EQ(ours.steps, c.accepted) << tol;
    EXPECT_EQ(ours.rejected, c.steps - c.accepted) << tol;
    EXPECT_EQ(ours.forces, c.rhs) << tol;
    EXPECT_EQ(ours.jacobians, c.jacobians) << tol;
    EXPECT_EQ(ours.factorisations, c.decompositions) << tol;
    EXPECT_EQ(ours.newton, c.solves) << tol;
    EXPECT_NEAR(end.x[0], z[0], 1e-12) << tol;
    EXPECT_NEAR(end.x[1], z[1], 1e-12) << tol;
  }
}

// RADAU5's output between steps is the collocation polynomial through the step's start and its
// three stages (Hairer & Wanner IV.8): at a step's end it is the step's result, at its start the
// previous step's (to the round-off of its four coefficients' sum), and in between a cubic
// interpolant of the motion: its error is the interpolation error of a cubic on four nodes in
// [-h, 0], at most max|y''''| h^4 / 4! (the nodes' product is below h^4), plus the nodes' own
// errors. On the spring (eigenvalues of modulus omega = sqrt(k/m), amplitude A about the
// equilibrium, not growing), max|y''''| <= omega^4 A: so the output's order is 3, not the
// step's 5, which is why it is measured apart (the dense-output study).
TEST(Radau5, OutputBetweenStepsIsTheCollocationPolynomial) {
  const Spring spring(defaults_of("spring"));
  const double tol = 1e-8;
  std::vector<double> before(spring.initial().x.size() * 2), at(before.size());
  before = {spring.initial().x[0], spring.initial().v[0]};
  double worst_inside = 0, worst_start = 0, worst_end = 0, worst_ratio = 0;
  const double omega = std::sqrt(5.0 / 1.0), x_eq = -(5.0 + 9.81 / 5.0);
  const double amplitude = std::hypot(spring.initial().x[0] - x_eq, spring.initial().v[0] / omega);
  int steps = 0;
  const auto rhs = [](const void* s, double t, const double* z, double* dz) {
    const Spring& sp = *static_cast<const Spring*>(s);
    const Vec<1> a = acceleration(sp, t, Vec<1>(z[0]), Vec<1>(z[1]));
    dz[0] = z[1], dz[1] = a[0];
  };
  const auto jac = [](const void* s, double t, const double* z, double* dfy, int ld) {
    const Spring& sp = *static_cast<const Spring*>(s);
    const Jacobians<1> j = jacobians_at(sp, t, Vec<1>(z[0]), Vec<1>(z[1]));
    dfy[0] = j.dx(0, 0) * sp.inverse_mass()[0], dfy[ld] = j.dv(0, 0) * sp.inverse_mass()[0];
  };
  double z[2] = {before[0], before[1]};
  PeerCounts n;
  radau5_solve({2, -1, &spring, rhs, jac}, z, tol, 10.0, n, [&](const Radau5Step& step) {
    ++steps;
    step.dense(step.t, at.data());
    worst_end = std::max(worst_end, std::abs(at[0] - step.z[0]));
    step.dense(step.t_old, at.data());
    worst_start = std::max(worst_start, std::abs(at[0] - before[0]));
    const double h = step.t - step.t_old, bound = std::pow(omega * h, 4) * amplitude / 24 + 10 * tol;
    for (const double f : {0.25, 0.5, 0.75}) {
      const double tau = step.t_old + f * h;
      step.dense(tau, at.data());
      const double e = std::abs(at[0] - exact(spring, tau).x[0]);
      worst_inside = std::max(worst_inside, e);
      worst_ratio = std::max(worst_ratio, e / bound);
    }
    before = {step.z[0], step.z[1]};
  });
  EXPECT_FALSE(n.failed);
  EXPECT_EQ(steps, n.steps);
  EXPECT_LT(worst_end, 1e-15);
  EXPECT_LT(worst_start, 1e-13);
  EXPECT_LE(worst_ratio, 1.0);
  EXPECT_GT(worst_inside, 10 * tol);  // and it is the cubic's error, well above the steps'
}

// Hairer maps the tolerance given to 0.1 tol^(2/3) for its local error test so that the global
// error comes out near tol (Hairer & Wanner IV.8, "the tolerances"): on both linear scenes, at
// every tolerance, the largest position error against the exact solution lies within a decade
// of it either way.
TEST(Radau5, GlobalErrorNearTheTolerance) {
  const PeerInfo& peer = *find_peer("radau5_dense");
  for (const char* scene : {"spring", "chain"})
    for (const double tol : {1e-4, 1e-6, 1e-8}) {
      PeerCounts n;
      double error = 0;
      run_fixed_peer(peer, scene, defaults_of(scene), tol, 10.0, n, &error);
      EXPECT_GT(error, 0.1 * tol) << scene << " " << tol;
      EXPECT_LT(error, 10 * tol) << scene << " " << tol;
    }
}
#endif

TEST(Radau5, BuiltAsTheBuildSays) {
  EXPECT_EQ(have_radau5(), STEPLAB_HAVE_RADAU5 != 0);
  EXPECT_EQ(find_peer("radau5_dense")->built, have_radau5());
}

// ARKODE's guide: with ARKStepSetLinear the nonlinear solver takes one Newton iteration per
// implicit stage. SDIRK-5-3-4 has five implicit stages, ARK5(4)8L[2]SA's DIRK table seven (its
// first stage explicit): on the linear scenes the Newton iterations are that many per step tried.
// And each reaches the exact solution: its tolerance bounds the local error, so over the run's
// 10 s, at tol 1e-8, an error below 1e-5 on both.
TEST(Arkode, OneNewtonIterationPerImplicitStageOnALinearScene) {
  for (const auto& [name, stages] : {std::pair{"arkode_sdirk534_dense", 5}, std::pair{"arkode_ark548_dense", 7}})
    for (const char* scene : {"spring", "chain"}) {
      PeerCounts n;
      double error = 0;
      run_fixed_peer(*find_peer(name), scene, defaults_of(scene), 1e-8, 10.0, n, &error);
      EXPECT_FALSE(n.failed);
      EXPECT_EQ(n.newton, stages * (n.steps + n.rejected)) << name << " " << scene;
      EXPECT_LT(error, 1e-5) << name << " " << scene;
    }
}

// The explicit table is explicit: no Jacobian, no factorisation; on the chain, stiff, its steps are
// bounded by the fast mode (|lambda| ~ 316): at least t_end |lambda| / 6 of them (Verner 6(5)'s
// stability interval on the imaginary axis is below 6), however loose the tolerance.
TEST(Arkode, TheExplicitTableIsBoundedByTheChainsFastMode) {
  PeerCounts n;
  run_fixed_peer(*find_peer("arkode_verner65"), "chain", defaults_of("chain"), 1e-2, 10.0, n);
  EXPECT_EQ(n.jacobians + n.factorisations + n.newton, 0);
  EXPECT_GT(n.steps, 10.0 * 316 / 6);
}

}  // namespace
}  // namespace steplab
