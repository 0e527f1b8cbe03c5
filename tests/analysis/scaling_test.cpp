// The scaling study on the rope (analysis/scaling.hpp): every reached row meets the target error
// against the exact solution (checked here again by a run of its own and by the peers' end
// states), implicit steps cost O(N) force evaluations times a constant, explicit methods' stable
// steps shrink as 1/N, and the output is the same for one and two threads.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/kernel.hpp"
#include "analysis/sized_peers.hpp"
#include "analysis/scaling.hpp"
#include "core/scenes/rope.hpp"

namespace steplab {
namespace {

ScalingConfig small_config() {
  ScalingConfig c;
  c.params = default_param_values(*find_scene("rope"));
  c.sizes = {4, 16, 64};
  for (const char* m : {"rk4", "implicit_midpoint", "radau_iia5", "symplectic_euler"}) c.methods.push_back(*find_method(m));
  c.adaptive = scaling_adaptive_solvers("rope");  // dopri5, odeint_dopri5 and CVODE's three
  c.timing = false;
  c.workers.threads = 2;
  return c;
}

TEST(Scaling, RowsReachTheTargetAndStableStepsShrinkAsOneOverN) {
  const ScalingConfig c = small_config();
  const ScalingResult r = scaling_study(c);
  ASSERT_EQ(c.adaptive.size(), 5u);
  ASSERT_EQ(r.rows.size(), (c.methods.size() + c.adaptive.size()) * c.sizes.size());
  const std::size_t scene = *find_scene("rope");
  for (const ScalingRow& w : r.rows) {
    ASSERT_TRUE(w.reached()) << w.solver << " N " << w.n;
    EXPECT_LE(w.error, c.target_error) << w.solver << " N " << w.n;
    EXPECT_GT(w.error, 0.0) << w.solver;
    EXPECT_LE(w.runs, kSearchRuns + 1) << w.solver;
    if (w.adaptive) continue;
    // a run of our own at the row's step: its end against the exact solution, max over the masses
    std::vector<double> p = c.params;
    p[0] = w.n;
    RunSpec spec;
    spec.dt = w.dt;
    spec.steps = w.steps;
    spec.errors = false;
    const AnyResult run = pair_kernel(*find_method(w.solver), scene).run(p, spec);
    EXPECT_NEAR(run.t_final, c.t_end, 1e-12) << w.solver;  // a whole number of steps
    const double e = (run.final.x - scene_kernel(scene).exact(p, c.t_end).x).cwiseAbs().maxCoeff();
    EXPECT_EQ(e, w.error) << w.solver << " N " << w.n;
  }
  // explicit: dt* omega_max is the method's constant (2 sqrt 2 for RK4, undamped; the mass
  // damping, whose ratio at the fastest mode falls as 1/N, moves it by 0.22 % at N = 4, 0.05 % at
  // 16), so dt* shrinks as 1/omega_max ~ 1/N
  double last = 1e300;
  for (std::size_t k = 0; k < c.sizes.size(); ++k) {
    const ScalingRow& a = r.rows[k];  // rk4, the first solver
    ASSERT_EQ(a.solver, "rk4");
    std::vector<double> p = c.params;
    p[0] = a.n;
    const Rope rope(p);
    const double constant = a.dt_stable * rope.omega(a.n);
    EXPECT_NEAR(constant, 2 * std::sqrt(2.0), 0.003 * 2 * std::sqrt(2.0)) << a.n;
    EXPECT_LT(constant, last) << a.n;
    last = constant;
  }
  for (const ScalingRow& w : r.rows)
    if (w.solver == "implicit_midpoint" || w.solver == "radau_iia5") {
      EXPECT_TRUE(std::isinf(w.dt_stable));
    }
  // a fixed-step implicit method: one Jacobian and a constant number of force evaluations a step
  for (const ScalingRow& w : r.rows)
    if (w.solver == "implicit_midpoint") {
      EXPECT_EQ(w.jacobians, w.steps) << w.n;  // the rope is linear: one Newton step a step
      EXPECT_EQ(w.forces, 2 * w.steps) << w.n;  // the residual, then its check
    }
}

// The peers' end states at their tolerance against the exact solution (the measure the study
// uses), and CVODE's banded Jacobian against the rope's own: at a tight tolerance it converges.
TEST(Scaling, PeersOnTheRopeConvergeToTheExactSolution) {
  std::vector<double> p = default_param_values(*find_scene("rope"));
  p[0] = 20;
  const Rope r(p);
  const std::size_t rope = *find_scene("rope");
  const Eigen::VectorXd exact = r.exact_at(1.0).x;
  for (const char* cvode : {"cvode_adams_band", "cvode_bdf_band", "cvode_bdf_max2_band"}) {
    PeerCounts n;
    const double e = (run_sized_peer(*find_peer(cvode), rope, p, 1e-9, 1.0, n).x - exact).cwiseAbs().maxCoeff();
    EXPECT_FALSE(n.failed) << cvode;
    EXPECT_GT(n.jacobians, 0) << cvode;
    EXPECT_LT(e, 1e-6) << cvode;  // a thousand times the tolerance: its global error may exceed it
  }
  PeerCounts n;
  const double e_odeint = (run_sized_peer(*find_peer("odeint_dopri5"), rope, p, 1e-9, 1.0, n).x - exact).cwiseAbs().maxCoeff();
  EXPECT_LT(e_odeint, 1e-7);
}

TEST(Scaling, SameRowsForOneAndTwoThreads) {
  ScalingConfig c = small_config();
  c.sizes = {4, 16};
  const ScalingResult two = scaling_study(c);
  c.workers.threads = 1;
  const ScalingResult one = scaling_study(c);
  ASSERT_EQ(one.rows.size(), two.rows.size());
  for (std::size_t i = 0; i < one.rows.size(); ++i) {
    EXPECT_EQ(one.rows[i].dt, two.rows[i].dt);
    EXPECT_EQ(one.rows[i].error, two.rows[i].error);
    EXPECT_EQ(one.rows[i].forces, two.rows[i].forces);
  }
}

}  // namespace
}  // namespace steplab
