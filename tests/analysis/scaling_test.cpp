// The scaling study on the rope (analysis/studies/scaling.hpp): every reached row meets the target error
// over the whole motion against the exact solution (checked here again by a run of its own and by
// the peers' frames), implicit steps cost O(N) force evaluations times a constant, explicit
// methods' stable steps shrink as 1/N, the stiffness axis and the map read their rows as stated,
// and the output is the same for one and two threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "analysis/kernel/kernel.hpp"
#include "analysis/peers/sized_peers.hpp"
#include "analysis/studies/scaling.hpp"
#include "core/scenes/rope.hpp"

namespace steplab {
namespace {

ScalingConfig small_config() {
  ScalingConfig c;
  c.params = default_param_values(*find_scene("rope"));
  c.sizes = {4, 16, 64};
  for (const char* m : {"rk4", "implicit_midpoint", "radau_iia5", "symplectic_euler"}) c.methods.push_back(*find_method(m));
  c.adaptive = scaling_adaptive_solvers("rope");  // dopri5, odeint_dopri5, ARKODE's Verner, CVODE's three, RADAU5, ARKODE's two
  c.timing = false;
  c.workers.threads = 2;
  return c;
}

TEST(Scaling, RowsReachTheTargetAndStableStepsShrinkAsOneOverN) {
  const ScalingConfig c = small_config();
  const ScalingResult r = scaling_study(c);
  ASSERT_EQ(c.adaptive.size(), 9u);
  ASSERT_EQ(r.rows.size(), (c.methods.size() + c.adaptive.size()) * c.sizes.size());
  const std::size_t scene = *find_scene("rope");
  for (const ScalingRow& w : r.rows) {
    ASSERT_TRUE(w.reached()) << w.solver << " N " << w.n;
    EXPECT_LE(w.error, c.targets[0].value) << w.solver << " N " << w.n;
    EXPECT_GT(w.error, 0.0) << w.solver;
    EXPECT_LE(w.runs, kSearchRuns + 1) << w.solver;
    if (w.adaptive) continue;
    // a run of our own at the row's step, each frame interpolated in its step (the output between
    // steps): the largest error over the masses and the frames against the exact solution at
    // each frame's time
    std::vector<double> p = c.params;
    p[0] = w.n;
    RunSpec spec;
    spec.dt = w.dt;
    spec.steps = w.steps;
    spec.errors = false;
    spec.outputs = c.frames + 1;
    const AnyResult run = pair_kernel(*find_method(w.solver), scene).run(p, spec);
    EXPECT_NEAR(run.t_final, c.t_end, 1e-12) << w.solver;
    ASSERT_EQ(run.samples.size(), static_cast<std::size_t>(c.frames + 1)) << w.solver;
    double e = 0;
    for (int k = 1; k <= c.frames; ++k) {
      EXPECT_NEAR(run.samples[k].t, c.t_end * k / c.frames, 1e-12) << w.solver;
      e = std::max(e, (run.samples[k].x - scene_kernel(scene).exact(p, c.t_end * k / c.frames).x).cwiseAbs().maxCoeff());
    }
    EXPECT_NEAR(e, w.error, 1e-12 * e) << w.solver << " N " << w.n;
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
  // a fixed-step implicit method on the linear rope: its Jacobians evaluated and its iteration
  // matrix factorised once a run (core/sparse.hpp), two Newton updates and two solves a step (the
  // second's correction round-off's: Newton's round-off rule, core/method.hpp), the residual
  // evaluated twice
  for (const ScalingRow& w : r.rows)
    if (w.solver == "implicit_midpoint") {
      EXPECT_EQ(w.jacobians, 1) << w.n;
      EXPECT_EQ(w.factorisations, 1) << w.n;
      EXPECT_EQ(w.solves, 2 * w.steps) << w.n;
      EXPECT_EQ(w.forces, 2 * w.steps) << w.n;
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

// Frames from the peers: each of the 10 at its time against the exact solution. CVODE's normal
// mode steps past each frame and interpolates, so its steps are nearly those of the run straight
// to t_end: only its first step, which CVODE estimates from the first output time, differs, and
// the sequences after it (within 2 % here: 571 and 572 steps, 1089 and 1077). Boost.Odeint steps
// to each frame, so it takes at least as many.
TEST(Scaling, PeersGiveTheirFramesAtTheirTimes) {
  std::vector<double> p = default_param_values(*find_scene("rope"));
  p[0] = 20;
  const Rope r(p);
  const std::size_t rope = *find_scene("rope");
  for (const char* peer : {"cvode_adams_band", "cvode_bdf_band", "odeint_dopri5"}) {
    PeerCounts straight, framed;
    run_sized_peer(*find_peer(peer), rope, p, 1e-9, 1.0, straight);
    std::vector<int> seen;
    double e = 0;
    const std::shared_ptr<const void> made = scene_kernel(rope).make(p);
    const State<Eigen::Dynamic> end = run_sized_peer(*find_peer(peer), scene_kernel(rope), made.get(), 1e-9, 1.0, framed,
                                                     {10, [&](int k, const Eigen::VectorXd& x) {
                                                        seen.push_back(k);
                                                        e = std::max(e, (x - r.exact_at(k / 10.0).x).cwiseAbs().maxCoeff());
                                                      }});
    EXPECT_EQ(seen, (std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10})) << peer;
    EXPECT_LT(e, 1e-6) << peer;  // as the end state's bound above
    EXPECT_LT((end.x - r.exact_at(1.0).x).cwiseAbs().maxCoeff(), 1e-6) << peer;
    if (std::string_view(peer).starts_with("cvode")) EXPECT_NEAR(framed.steps, straight.steps, 0.02 * straight.steps) << peer;
    else EXPECT_GE(framed.steps, straight.steps) << peer;
  }
}

// The stiffness axis and the map: the rows of each (target, stiffness) at that stiffness; the
// visual target 1 % of the rope's extent at rest, (N - 1) L / N at the largest N; each cell's
// cheapest solver and margins recomputed from its rows; the motion of the stiff rope, which
// starts unstretched at rest, above its static sag under its own weight (the bottom mass's sag:
// sum over the springs of the weight below / k = M g (N + 1) / (2 K N)), about which it
// oscillates, and below three times it (one mode would reach twice it; the modes superposed
// overshoot that a little: 2.02 times at N = 4).
TEST(Scaling, StiffnessAxisAndMap) {
  ScalingConfig c = small_config();
  c.sizes = {4, 16};
  c.stiffnesses = {5, 5000};
  c.targets = {{1e-4, false}, {0.01, true}};
  const ScalingResult r = scaling_study(c);
  const std::size_t solvers = c.methods.size() + c.adaptive.size();
  ASSERT_EQ(r.rows.size(), 2 * 2 * solvers * c.sizes.size());
  ASSERT_EQ(r.blocks.size(), 4u);
  const double L = c.params[3];
  EXPECT_DOUBLE_EQ(absolute_error(c, c.targets[1], 5), 0.01 * L * 15 / 16);
  for (std::size_t b = 0; b < 4; ++b) {
    const ScalingBlock& block = r.blocks[b];
    EXPECT_EQ(block.target, static_cast<int>(b / 2));
    EXPECT_EQ(block.stiffness, c.stiffnesses[b % 2]);
    EXPECT_EQ(block.error, b < 2 ? 1e-4 : 0.01 * L * 15 / 16);
    for (std::size_t k = 0; k < c.sizes.size(); ++k) {
      const ScalingCell& cell = block.cells[k];
      std::vector<std::pair<double, std::string>> costs;
      for (std::size_t s = 0; s < solvers; ++s) {
        const ScalingRow& w = r.rows_of(b * solvers + s)[k];
        EXPECT_EQ(w.stiffness, block.stiffness);
        EXPECT_EQ(w.target, block.target);
        EXPECT_EQ(w.n, c.sizes[k]);
        if (w.reached()) {
          EXPECT_LE(w.error, block.error) << w.solver;
          costs.emplace_back(scaling_cost(c, w), w.solver);
        }
      }
      std::sort(costs.begin(), costs.end());
      ASSERT_GE(costs.size(), 2u);
      EXPECT_EQ(cell.cheapest, costs[0].second);
      EXPECT_EQ(cell.next, costs[1].second);
      EXPECT_DOUBLE_EQ(cell.margin, costs[1].first / costs[0].first);
      // The rival, which decides the cell: the cheapest run of another group (a family, a peer
      // library, the explicit adaptive solvers), not the runner-up of the cheapest's own family.
      const auto rival = std::find_if(costs.begin(), costs.end(),
                                      [&](const auto& x) { return solver_group(x.second) != solver_group(costs[0].second); });
      if (rival == costs.end()) {
        EXPECT_TRUE(cell.rival.empty());
      } else {
        EXPECT_EQ(cell.rival, rival->second);
        EXPECT_DOUBLE_EQ(cell.rival_margin, rival->first / costs[0].first);
      }
      if (block.stiffness == 5000) {
        const double n = c.sizes[k], sag = 1.0 * 9.81 * (n + 1) / (2 * 5000 * n);
        EXPECT_GT(cell.motion, sag) << n;
        EXPECT_LT(cell.motion, 3 * sag) << n;
      }
    }
  }
}

// The error over the whole motion, not at t_end alone: the stiff rope with strong spring damping
// (K 5000, C_s 20) has settled by t_end, where implicit Euler (L-stable) matches it with one step
// of t_end (frames = 1: the error at t_end alone); over 100 frames, each a step's state (the
// steps divide the frames), its error there is that of the motion it damps, far above its
// error at t_end.
TEST(Scaling, ErrorOverTheWholeMotion) {
  ScalingConfig c = small_config();
  c.steps_divide_frames = true;
  c.sizes = {64};
  c.params[2] = 5000, c.params[5] = 20;  // stiffness, spring-damping
  c.methods = {*find_method("implicit_euler")};
  c.adaptive.clear();
  c.targets = {{1e-2, false}};
  c.frames = 1;
  const ScalingRow at_end = scaling_study(c).rows.front();
  ASSERT_TRUE(at_end.reached());
  EXPECT_EQ(at_end.steps, 1);
  c.frames = 100;
  const ScalingRow whole = scaling_study(c).rows.front();
  ASSERT_TRUE(whole.reached());
  EXPECT_EQ(whole.steps, 100);
  std::vector<double> p = c.params;
  p[0] = 64;
  RunSpec spec;
  spec.dt = 0.02, spec.steps = 100, spec.errors = false;
  const std::size_t rope = *find_scene("rope");
  const AnyResult run = pair_kernel(*find_method("implicit_euler"), rope).run(p, spec);
  const double final_error = (run.final.x - scene_kernel(rope).exact(p, c.t_end).x).cwiseAbs().maxCoeff();
  // settled: at t_end the 100-step run sits at the equilibrium to round-off (8.9e-16), while over
  // the frames its error is the damped transient's (5.2e-4), the largest after the first steps
  EXPECT_LT(final_error, 1e-12);
  EXPECT_GT(whole.error, 1e-4);
  EXPECT_LE(whole.error, 1e-2);
}

// Output between steps lets a fixed step be longer than a frame: on the stiff rope (K 5000, 64
// masses) at 1 % of its extent, implicit Euler with steps dividing the 100 frames needs a step a
// frame at least (100 steps); interpolating its frames it reaches the same target in fewer. Each
// row's error is still the largest over the frames, which the test above checks the measure of.
TEST(Scaling, OutputBetweenStepsFreesTheStepFromTheFrames) {
  ScalingConfig c = small_config();
  c.sizes = {64};
  c.params[2] = 5000;  // stiffness
  c.methods = {*find_method("implicit_euler")};
  c.adaptive.clear();
  c.targets = {{0.01, true}};
  c.steps_divide_frames = true;
  const ScalingRow divided = scaling_study(c).rows.front();
  c.steps_divide_frames = false;
  const ScalingRow dense = scaling_study(c).rows.front();
  ASSERT_TRUE(divided.reached() && dense.reached());
  EXPECT_EQ(divided.steps % c.frames, 0);
  EXPECT_GE(divided.steps, c.frames);
  EXPECT_LT(dense.steps, c.frames);
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

namespace steplab {
namespace {

// The exponent rule (analysis/studies/scaling.hpp): a power law y = 3 N^1.5 is recovered exactly over
// 16 .. 1024 masses (1.8 decades, 4 sizes), its interval closing on it (zero residual); two sizes,
// or three spanning 1.2 decades (8, 32, 128), are not fitted whatever their values; a value not
// known (NaN, 0) is left out and counts for neither rule.
TEST(ScalingExponent, FittedOnlyOverThreeSizesAndOneAndAHalfDecades) {
  const std::vector<double> n{16, 64, 256, 1024};
  std::vector<double> y;
  for (double x : n) y.push_back(3 * std::pow(x, 1.5));
  const Exponent e = fit_exponent(n, y);
  ASSERT_TRUE(e.fitted());
  EXPECT_NEAR(e.value, 1.5, 1e-12);
  EXPECT_NEAR(e.lo, 1.5, 1e-9);
  EXPECT_NEAR(e.hi, 1.5, 1e-9);
  EXPECT_EQ(e.sizes, 4);
  EXPECT_NEAR(e.decades, std::log10(64.0), 1e-12);

  EXPECT_FALSE(fit_exponent(std::vector<double>{16, 1024}, std::vector<double>{1, 100}).fitted());
  const Exponent narrow = fit_exponent(std::vector<double>{8, 32, 128}, std::vector<double>{1, 4, 16});
  EXPECT_FALSE(narrow.fitted());
  EXPECT_EQ(narrow.sizes, 3);
  EXPECT_NEAR(narrow.decades, std::log10(16.0), 1e-12);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(fit_exponent(n, std::vector<double>{1, nan, 0, 64}).fitted());  // two known
  EXPECT_TRUE(fit_exponent(n, std::vector<double>{1, nan, 16, 64}).fitted());   // three over 1.8 decades
}

// With scatter the interval is Student's: y = N (1, 1.2, 0.9, 1.1) over 16 .. 1024. The slope and
// its standard error computed apart (ln N at 4 points, the residuals of the least-squares line,
// se^2 = sum r^2 / (n - 2) / sum (ln N - mean)^2) are 0.99987 and 0.048928, so the interval is
// 0.99987 -+ 4.303 x 0.048928 = [0.7893, 1.2104] (t(2) = 4.303); to 1e-4, the table's rounding of t.
TEST(ScalingExponent, IntervalIsStudentsWithScatter) {
  const std::vector<double> n{16, 64, 256, 1024}, f{1, 1.2, 0.9, 1.1};
  std::vector<double> y;
  for (std::size_t k = 0; k < n.size(); ++k) y.push_back(n[k] * f[k]);
  const Exponent e = fit_exponent(n, y);
  ASSERT_TRUE(e.fitted());
  EXPECT_NEAR(e.value, 0.99987, 1e-5);
  EXPECT_NEAR(e.lo, 0.7893, 1e-4);
  EXPECT_NEAR(e.hi, 1.2104, 1e-4);
}

// Early: a step's cost flat from the smallest size to the next (overheads), or growing as N^0.3,
// is below the asymptotic regime; growing as N^0.9 is not. Unknown costs are skipped.
TEST(ScalingExponent, EarlyWhereAStepsCostIsStillFlat) {
  const std::vector<double> n{16, 64, 256};
  EXPECT_TRUE(begins_early(n, std::vector<double>{1.0, 1.05, 4.0}));
  EXPECT_TRUE(begins_early(n, std::vector<double>{1.0, std::pow(4.0, 0.3), 16.0}));
  EXPECT_FALSE(begins_early(n, std::vector<double>{1.0, std::pow(4.0, 0.9), 16.0}));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(begins_early(n, std::vector<double>{nan, 1.0, 1.2}));
  EXPECT_FALSE(begins_early(n, std::vector<double>{nan, 1.0, nan}));
}

}  // namespace
}  // namespace steplab
