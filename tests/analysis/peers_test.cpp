// Unit tests for analysis/peers/peers.cpp, analysis/peers/sized_peers.cpp and the counts of steplab's own runs
// (analysis/kernel/counts.hpp): the peers are the build and the set-up they claim, steplab's CVODE peer
// is CVODE called as plain C would call it, and the counts are what the methods' formulas say.
#include <gtest/gtest.h>

#include <vector>

#include "analysis/kernel/kernel.hpp"
#include "analysis/peers/peers.hpp"
#include "analysis/peers/sized_peers.hpp"
#include "bench/cvode_rope.h"
#include "core/scenes/chain.hpp"
#include "reports/data/inputs.hpp"
#include "reports/data/study_command.hpp"

namespace steplab {
namespace {

// tools/sundials.cmake builds CVODE optimised from Debian's source package, which tools/install-deps
// fetches; Debian's own build has no -O. A build that fell back to it fails here, not silently.
TEST(Peers, CvodeIsTheOptimisedBuild) {
  bool found = false;
  for (const PeerBuild& b : peer_builds())
    if (b.library == "SUNDIALS CVODE") {
      found = true;
      EXPECT_TRUE(b.optimised) << b.flags;
      EXPECT_EQ(b.version.substr(0, 2), "6.");
    }
  EXPECT_TRUE(found);
}

// The peers are the configurations their names say, and each runs where it says.
TEST(Peers, TableSaysWhatEachIs) {
  const PeerInfo* adams = find_peer("cvode_adams_band");
  const PeerInfo* bdf2 = find_peer("cvode_bdf_max2_klu");
  ASSERT_TRUE(adams && bdf2);
  EXPECT_TRUE(adams->cvode.adams);
  EXPECT_EQ(bdf2->cvode.max_order, 2);
  EXPECT_FALSE(bdf2->cvode.adams);
  EXPECT_EQ(find_peer("cvode_band"), nullptr);  // the old name
  for (const PeerInfo* p : peers_on(PeerScenes::Banded)) EXPECT_NE(p->linear_solver, LinearSolver::Klu) << p->name;
  for (const PeerInfo* p : peers_on(PeerScenes::FixedSize)) EXPECT_TRUE(p->linear_solver == LinearSolver::None || p->linear_solver == LinearSolver::Dense) << p->name;
}

// The map's groups: a table method's family, an implicit peer's library, the explicit adaptive
// solvers together (steplab's dopri5 with the explicit peers).
TEST(Peers, GroupsAreFamiliesLibrariesAndTheExplicitAdaptiveOnes) {
  EXPECT_EQ(solver_group("rk4"), "explicit Runge-Kutta");
  EXPECT_EQ(solver_group("rk3"), solver_group("rk4"));
  EXPECT_EQ(solver_group("radau_iia5"), solver_group("gauss_legendre4"));
  EXPECT_NE(solver_group("bdf2"), solver_group("radau_iia5"));
  EXPECT_EQ(solver_group("cvode_bdf_band"), "CVODE");
  EXPECT_EQ(solver_group("cvode_adams_band"), "CVODE");  // Adams with Newton's iteration: implicit
  EXPECT_EQ(solver_group("dopri5"), "adaptive explicit");
  EXPECT_EQ(solver_group("odeint_dopri5"), "adaptive explicit");
  EXPECT_EQ(solver_group("arkode_verner65"), "adaptive explicit");
  EXPECT_NE(solver_group("dopri5"), solver_group("rk4"));
}

// steplab's CVODE peer on the rope against bench/cvode_rope.c, which calls CVODE from C with no
// steplab code: the same settings must give the same run, step for step (the counts equal), and
// the same end state up to the round-off of the right side's order of operations (1e-12 of the
// rope's length, 5).
TEST(Peers, CvodeOnTheRopeIsCvodeAsPlainCCallsIt) {
  constexpr int n = 64;
  const std::size_t rope = *find_scene("rope");
  std::vector<double> p = default_param_values(rope);
  p[scene_kernel(rope).size_param] = n;
  for (const bool adams : {true, false}) {
    const PeerInfo& peer = *find_peer(adams ? "cvode_adams_band" : "cvode_bdf_max2_band");
    PeerCounts ours;
    const State<Eigen::Dynamic> end = run_sized_peer(peer, rope, p, 1e-6, 1.0, ours);
    cvode_rope_counts c{};
    std::vector<double> y(n);
    ASSERT_EQ(cvode_rope_run(n, 1e-6, 1.0, {adams, adams ? 0 : 2, 0, 0, 0}, &c, y.data()), 0);
    EXPECT_EQ(ours.steps, c.steps) << peer.name;
    EXPECT_EQ(ours.rejected, c.error_test_fails + c.solve_fails) << peer.name;
    EXPECT_EQ(ours.forces, c.rhs) << peer.name;
    EXPECT_EQ(ours.jacobians, c.jacobians) << peer.name;
    EXPECT_EQ(ours.factorisations, c.setups) << peer.name;
    EXPECT_EQ(ours.newton, c.newton) << peer.name;
    for (int i = 0; i < n; ++i) EXPECT_NEAR(end.x[i], y[i], 5e-12) << peer.name << " mass " << i;
  }
}

// CVODE's counts hang together as its algorithm says: one linear solve per Newton iteration, at
// least one Newton iteration per step tried, a Jacobian only at a setup (it is reused between),
// and a setup at least every 20 steps (its default setup frequency, kept).
TEST(Peers, CvodeCountsHangTogether) {
  const std::size_t rope = *find_scene("rope");
  std::vector<double> p = default_param_values(rope);
  p[scene_kernel(rope).size_param] = 32;
  for (const PeerInfo* peer : peers_on(PeerScenes::Banded)) {
    if (!peer->is_cvode()) continue;
    PeerCounts n;
    run_sized_peer(*peer, rope, p, 1e-5, 2.0, n);
    EXPECT_FALSE(n.failed);
    EXPECT_EQ(n.solves, n.newton) << peer->name;
    EXPECT_GE(n.newton, n.steps + n.rejected) << peer->name;
    EXPECT_LE(n.jacobians, n.factorisations) << peer->name;
    EXPECT_LE(n.steps, 20 * (n.factorisations + 1)) << peer->name;
    EXPECT_GE(n.forces, n.newton) << peer->name;  // each iteration evaluates the right side once
  }
}

// steplab's implicit methods on the linear chain: full Newton converges in one update a step, and
// Newton's round-off rule (core/method.hpp) takes a second whose correction is round-off's: each
// step factorises twice and solves twice, evaluates the residual twice a stage and the Jacobians
// twice a stage (full Newton evaluates them at every iterate).
TEST(Peers, ImplicitCountsOnALinearScene) {
  const std::size_t chain = *find_scene("chain");
  RunSpec spec;
  spec.dt = 0.01;
  spec.steps = 200;
  spec.errors = false;
  for (const auto& [name, stages] : std::vector<std::pair<const char*, int>>{{"implicit_euler", 1}, {"implicit_midpoint", 1},
                                                                           {"gauss_legendre4", 2}, {"radau_iia5", 3}}) {
    Counts n;
    const AnyResult r = pair_kernel(*find_method(name), chain).run_counted(default_param_values(chain), spec, n);
    ASSERT_EQ(r.status, RunStatus::Ok) << name;
    EXPECT_EQ(n.steps, 200) << name;
    EXPECT_EQ(n.rejected, 0) << name;
    EXPECT_EQ(n.factorisations, 2 * 200) << name;
    EXPECT_EQ(n.solves, 2 * 200) << name;
    EXPECT_EQ(n.newton, 2 * 200) << name;
    EXPECT_EQ(n.jacobians, 2 * 200 * stages) << name;
    EXPECT_EQ(n.forces, 2 * 200 * stages) << name;
  }
  Counts n;  // an explicit method: no Newton at all (at a step within RK4's limit on the chain, 0.009124)
  spec.dt = 0.005;
  pair_kernel(*find_method("rk4"), chain).run_counted(default_param_values(chain), spec, n);
  EXPECT_EQ(n.forces, 4 * 200);
  EXPECT_EQ(n.factorisations + n.solves + n.newton + n.jacobians, 0);
}

// --methods of a study with peers: a peer missing from this build (here a table whose KLU peer
// is not built) is refused with one message naming it, as is one that runs elsewhere.
TEST(Peers, ResolveSolversRefusesAPeerNotBuiltOrElsewhere) {
  std::vector<PeerInfo> table(peers().begin(), peers().end());
  for (PeerInfo& p : table)
    if (p.linear_solver == LinearSolver::Klu) p.built = false;
  const std::vector<std::string> soft{"dopri5", "odeint_dopri5"};
  try {
    resolve_solvers("rk4,cvode_bdf_klu", soft, "soft body", false, table);
    FAIL() << "a peer not built was accepted";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("'cvode_bdf_klu' is not built"), std::string::npos) << e.what();
  }
  EXPECT_THROW(resolve_solvers("cvode_adams_band", soft, "soft body", false), UsageError);
  const Solvers s = resolve_solvers("rk4,odeint_dopri5", {"dopri5", "odeint_dopri5", "cvode_adams_band"}, "rope", false);
  EXPECT_EQ(s.methods.size(), 1u);
  EXPECT_EQ(s.adaptive, std::vector<std::string>{"odeint_dopri5"});
  EXPECT_EQ(resolve_solvers("rk4", {"dopri5", "cvode_adams_band"}, "rope", false).adaptive.size(), 2u);  // none named: all
  EXPECT_TRUE(resolve_solvers("", {"dopri5"}, "rope", true).adaptive.empty());
}

}  // namespace
}  // namespace steplab
