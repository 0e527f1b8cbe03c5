// A driven scene (core/scene.hpp: force(t, x, v)): the mass pulled to a moving target
// (core/scenes/target.hpp). Every method must evaluate the force at each stage's own time; one
// that evaluated it at the step's start (or end) would be first order on it, whatever its order
// elsewhere. So on the non-stiff target (k = 1: h |lambda| <= 0.37 over the sweep) each method's
// fitted order is its declared one.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/studies/convergence.hpp"
#include "analysis/kernel/kernel.hpp"
#include "core/scenes/target.hpp"
#include "tests/analysis/declared_order.hpp"

namespace steplab {
namespace {

// The convergence study's default sweep (dt 0.1 .. 1e-4 over t = 10), fitted to the largest error
// along the run (the final one alone can be small by a lucky phase).
ConvergenceConfig on_target(double stiffness) {
  ConvergenceConfig c;
  c.scene = *find_scene("target");
  c.params = default_param_values(c.scene);
  c.params[static_cast<std::size_t>(stiffness_param_index<Target>())] = stiffness;
  c.fit_error = ErrorKind::Max;
  for (std::size_t m = 0; m < method_count(); ++m)
    if (in_ode_studies(m)) c.methods.push_back(m);
  return c;
}

// Within 0.01 of the declared order, the declared order inside the fit's bound: the bars the
// spring's convergence test holds every method to (measured: every method within 0.003).
TEST(Driven, EveryMethodKeepsItsOrderOnTheNonStiffTarget) {
  const ConvergenceResult r = convergence_study(on_target(1.0));
  EXPECT_FALSE(r.uses_reference);  // x(t) = sin t exactly
  for (const ConvergenceFit& f : r.fits) ASSERT_NO_FATAL_FAILURE(expect_declared_order(f, 0.01));
}

// The sweep is the study at each value, nothing else: the same fits as each study alone.
TEST(Driven, ASweepIsTheStudyAtEachValue) {
  ConvergenceConfig c = on_target(1.0);
  c.methods = {*find_method("rk4"), *find_method("implicit_euler")};
  const std::size_t stiffness = static_cast<std::size_t>(stiffness_param_index<Target>());
  const ConvergenceSweep s = convergence_sweep(c, stiffness, {1.0, 1e4});
  ASSERT_EQ(s.studies.size(), 2u);
  for (std::size_t v = 0; v < 2; ++v) {
    EXPECT_EQ(s.studies[v].config.params[stiffness], s.values[v]);
    ConvergenceConfig alone = c;
    alone.params[stiffness] = s.values[v];
    const ConvergenceResult r = convergence_study(alone);
    for (std::size_t m = 0; m < r.fits.size(); ++m) EXPECT_EQ(s.studies[v].fits[m].fit.order, r.fits[m].fit.order);
  }
}

// The exact flow of a driven scene steps its closed form: error at round-off.
TEST(Driven, TheExactFlowIsTheTarget) {
  const std::size_t scene = *find_scene("target"), analytic = *find_method("analytic");
  RunSpec spec;
  spec.dt = 0.01;
  spec.steps = 300;
  spec.errors = true;
  const AnyResult r = pair_kernel(analytic, scene).run(default_param_values(scene), spec);
  EXPECT_EQ(r.status, RunStatus::Ok);
  EXPECT_LT(r.error_final, 1e-15);
  EXPECT_LT(r.error_max, 1e-15);
}

// The force at the stage times: on the target at rest on g, F(t, g(t), g'(t)) = m g''(t).
TEST(Driven, TheForceOnTheTargetIsItsAcceleration) {
  const Target s(default_param_values(*find_scene("target")));
  for (double t : {0.0, 0.3, 1.7}) {
    const State<1> y = s.exact_at(t);
    EXPECT_NEAR(acceleration(s, t, y.x, y.v)[0], -std::sin(t), 1e-12) << t;
  }
}

}  // namespace
}  // namespace steplab
