// The scaling study on the soft body (analysis/studies/scaling.hpp, its modes in core/scenes/softbody.hpp,
// analysis/peers/sized_peers.hpp): its fastest mode against a dense symmetric eigensolver, omega_max
// growing as n, the predicted dt* against runs, the peers against the reference solution, and
// rows that meet the target against a run of their own.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Eigenvalues>

#include "analysis/studies/convergence.hpp"
#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/scaling.hpp"
#include "analysis/peers/sized_peers.hpp"
#include "analysis/studies/mode_stability.hpp"
#include "core/scenes/softbody.hpp"

namespace steplab {
namespace {

std::vector<double> grid(int n) {
  std::vector<double> p = default_param_values(*find_scene("softbody"));
  p[0] = n;
  return p;
}

// Power iteration's omega_max against the largest eigenvalue of the dense K = -dF/dx at the same
// state (Eigen's SelfAdjointEigenSolver): the Rayleigh quotient to 1e-6 relative (measured 1e-9 at
// worst); 2 zeta from the eigenvector's damping, 1e-4 relative.
TEST(SoftBodyScaling, FastestModeMatchesADenseEigensolver) {
  for (int n : {2, 3, 4, 6}) {
    const SoftBody s(grid(n));
    const State<Eigen::Dynamic> y = s.lowered_onto_ground();
    const Jacobians<Eigen::Dynamic> j = s.jacobians(y.x, y.v);
    const Eigen::MatrixXd K = -Eigen::MatrixXd(j.dx), C = -Eigen::MatrixXd(j.dv);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(K);
    const Eigen::VectorXd u = eig.eigenvectors().col(K.rows() - 1);
    const double omega = std::sqrt(eig.eigenvalues()[K.rows() - 1] / s.m);
    const Mode f = s.modes().front();
    EXPECT_NEAR(f.omega, omega, 1e-6 * omega) << n;
    EXPECT_NEAR(f.two_zeta, u.dot(C * u) / (s.m * omega), 1e-4 * f.two_zeta) << n;
  }
}

// The lattice's modulus is kept under refinement, each mass is M / n^2: omega_max ~ n, so doubling
// n doubles it (to 10 %: the boundary rows and the ground's k_g / n per mass shift it).
TEST(SoftBodyScaling, FastestModeGrowsAsTheGridSide) {
  const double w8 = SoftBody(grid(8)).modes().front().omega, w16 = SoftBody(grid(16)).modes().front().omega;
  EXPECT_NEAR(w16 / w8, 2.0, 0.2);
}

// RK4's predicted dt* against runs of the body, dropped onto the ground for 4000 steps: bounded
// at 0.9 dt*, blown up (E/E0 past 1e4) at 1.1 dt* (measured: bounded at 1.0, blown up at 1.05).
TEST(SoftBodyScaling, PredictedStableStepSeparatesRuns) {
  const std::vector<double> p = grid(6);
  const std::size_t rk4 = *find_method("rk4");
  const double dt = modes_predicted_threshold(rk4, SoftBody(p).modes());
  const auto blows_up = [&](double h) {
    RunSpec spec;
    spec.dt = h;
    spec.steps = 4000;
    spec.errors = false;
    spec.stop_above = 1e4;
    return pair_kernel(rk4, *find_scene("softbody")).run(p, spec).status != RunStatus::Ok;
  };
  EXPECT_FALSE(blows_up(0.9 * dt));
  EXPECT_TRUE(blows_up(1.1 * dt));
}

// CVODE with KLU and odeint's dopri5 at tolerance 1e-9 against the reference solution (dopri5 at
// 1e-13): within a thousand times the tolerance (a global error may exceed a local tolerance).
TEST(SoftBodyScaling, PeersConvergeToTheReferenceSolution) {
  const std::vector<double> p = grid(4);
  const std::vector<double> ref = reference_solution(scene_kernel(*find_scene("softbody")), p, 1.0).x;
  const Eigen::Map<const Eigen::VectorXd> x(ref.data(), std::ssize(ref));
  const std::size_t s = *find_scene("softbody");
  for (const char* cvode : {"cvode_adams_klu", "cvode_bdf_klu", "cvode_bdf_max2_klu"}) {
    PeerCounts n;
    EXPECT_LT((run_sized_peer(*find_peer(cvode), s, p, 1e-9, 1.0, n).x - x).cwiseAbs().maxCoeff(), 1e-6) << cvode;
    EXPECT_FALSE(n.failed) << cvode;
    EXPECT_GT(n.jacobians, 0) << cvode;
  }
  PeerCounts n;
  EXPECT_LT((run_sized_peer(*find_peer("odeint_dopri5"), s, p, 1e-9, 1.0, n).x - x).cwiseAbs().maxCoeff(), 1e-6);
}

// Rows of the study at grids 3 and 5: each reached row's error at or below the target, and a
// run of our own at its step, a state at every frame, gives the same error, the largest over the
// coordinates and the frames against the reference solution there (dopri5 at rtol 1e-13 through
// its dense output).
TEST(SoftBodyScaling, RowsReachTheTarget) {
  ScalingConfig c;
  c.scene = "softbody";
  c.params = grid(4);
  c.sizes = {3, 5};
  c.max_steps = 200'000;
  for (const char* m : {"rk4", "implicit_midpoint"}) c.methods.push_back(*find_method(m));
  c.adaptive = scaling_adaptive_solvers("softbody");  // dopri5, odeint_dopri5 and CVODE's three
  c.timing = false;
  c.workers.threads = 2;
  const ScalingResult r = scaling_study(c);
  ASSERT_EQ(c.adaptive.size(), 9u);  // dopri5, odeint_dopri5, ARKODE's Verner, CVODE's three, RADAU5, ARKODE's two
  ASSERT_EQ(r.rows.size(), (c.methods.size() + c.adaptive.size()) * c.sizes.size());
  const std::size_t scene = *find_scene("softbody");
  for (const ScalingRow& w : r.rows) {
    ASSERT_TRUE(w.reached()) << w.solver << " n " << w.n;
    EXPECT_EQ(w.masses, w.n * w.n);
    EXPECT_LE(w.error, c.targets[0].value) << w.solver << " n " << w.n;
    if (w.adaptive) continue;
    const std::vector<double> p = grid(w.n);
    RunSpec spec;
    spec.dt = w.dt;
    spec.steps = w.steps;
    spec.errors = false;
    spec.outputs = c.frames + 1;  // each frame interpolated in its step, as the study does
    const AnyResult run = pair_kernel(*find_method(w.solver), scene).run(p, spec);
    AdaptiveSpec fine;
    fine.tol = {1e-13, 1e-13};
    fine.t_end = c.t_end, fine.errors = false, fine.max_samples = c.frames + 1;
    const AnyAdaptiveResult ref = scene_kernel(scene).dopri5(p, fine);
    ASSERT_EQ(run.samples.size(), ref.run.samples.size());
    double e = 0;
    for (std::size_t k = 1; k < run.samples.size(); ++k) {
      EXPECT_NEAR(run.samples[k].t, ref.run.samples[k].t, 1e-12);
      e = std::max(e, (run.samples[k].x - ref.run.samples[k].x).cwiseAbs().maxCoeff());
    }
    EXPECT_EQ(e, w.error)        << w.solver;
  }
}

}  // namespace
}  // namespace steplab
