// The adaptive Dormand-Prince 5(4) (core/dopri5.hpp) against SciPy's RK45, which runs the same
// method, error norm and controller (so its step counts are a published reference), against
// Boost.Odeint's controlled runge_kutta_dopri5, and against the exact solutions.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include <boost/numeric/odeint.hpp>

#include "core/dopri5.hpp"
#include "analysis/kernel/kernel.hpp"
#include "core/scenes/chain.hpp"
#include "core/scenes/spring.hpp"
#include "tests/core/chain_ode.hpp"

namespace steplab {
namespace {

namespace odeint = boost::numeric::odeint;

AdaptiveResult<2> on_chain(double rtol, double atol, long long samples = 0) {
  AdaptiveSpec spec;
  spec.tol = {rtol, atol};
  spec.t_end = 10;
  spec.max_samples = samples;
  return simulate_dopri5(make_default_scene<Chain>(), spec);
}

// scipy.integrate.solve_ivp(method='RK45') 1.10.1 on the default chain, t in [0, 10], from
// (1, 1, 0, 0): accepted steps, force evaluations (nfev), |u(10) - exact| (scipy.linalg.expm).
// The counts agree to within a few rejected steps, not exactly: a step whose error norm lands
// within round-off of 1 goes either way, and SciPy computes A z where the scene computes -Ku - Cv.
TEST(Dopri5, TakesTheStepsSciPysRk45TakesOnTheChain) {
  const struct {
    double rtol, atol;
    long long steps, nfev;
    double error;
  } scipy[] = {{1e-3, 1e-6, 1455, 11138, 4.880e-06},
               {1e-3, 1e-3, 1426, 10928, 8.304e-05},
               {1e-6, 1e-6, 1497, 11558, 6.761e-08},
               {1e-9, 1e-9, 1978, 14858, 6.514e-11},
               {1e-8, 1e-10, 1867, 14060, 7.022e-11}};
  for (const auto& ref : scipy) {
    const AdaptiveResult<2> r = on_chain(ref.rtol, ref.atol);
    SCOPED_TRACE(testing::Message() << "rtol " << ref.rtol << " atol " << ref.atol << ": steps " << r.stats.accepted
                                    << " nfev " << r.stats.force_evaluations << " error " << r.run.error_final);
    EXPECT_EQ(r.run.status, RunStatus::Ok);
    EXPECT_NEAR(static_cast<double>(r.stats.accepted), static_cast<double>(ref.steps), 0.02 * ref.steps);
    EXPECT_NEAR(static_cast<double>(r.stats.force_evaluations), static_cast<double>(ref.nfev), 0.03 * ref.nfev);
    // the errors are sums of a thousand local errors of either sign: equal in size, not in digits
    EXPECT_GT(r.run.error_final, ref.error / 2);
    EXPECT_LT(r.run.error_final, ref.error * 2);
  }
}

// The acceptance run: rtol 1e-8, atol 1e-10 ends within its tolerance of the exact
// solution (measured 8.4e-11 against rtol |u(10)| + atol = 7.9e-9).
TEST(Dopri5, EndsWithinItsToleranceOnTheChain) {
  const AdaptiveResult<2> r = on_chain(1e-8, 1e-10);
  const Chain c = make_default_scene<Chain>();
  EXPECT_EQ(r.run.t_final, 10.0);
  EXPECT_LT(r.run.error_final, 1e-8 * exact(c, 10).x.norm() + 1e-10);
  EXPECT_EQ(r.stats.force_evaluations, 2 + 6 * (r.stats.accepted + r.stats.rejected));
}

// Boost.Odeint's controlled runge_kutta_dopri5 at rtol = atol = tol. Its controller differs (max
// norm over the components, error scaled by |y| and h |y'|, step growth capped at 5x), so the
// steps differ; both must land near the tolerance. Measured on the chain (steplab / odeint):
//   tol 1e-3: steps 1426 / 1495, force evaluations 10964 / 12619, error 7.4e-5 / 6.2e-5
//   tol 1e-6: steps 1497 / 1578, force evaluations 11564 / 13273, error 6.5e-8 / 8.8e-9
//   tol 1e-9: steps 1979 / 2100, force evaluations 14846 / 16777, error 6.4e-11 / 1.7e-11
// odeint's max norm is stricter than the RMS norm on four components: a few more steps, up to 7x
// less error at 1e-6; hence a factor 20 between the two errors, and 30 % between the step counts.
TEST(Dopri5, ReachesTheErrorOdeintsControlledDopri5Reaches) {
  for (const double tol : {1e-3, 1e-6, 1e-9}) {
    Z z{1, 1, 0, 0};
    long long odeint_steps = 0;
    odeint::integrate_adaptive(odeint::make_controlled(tol, tol, odeint::runge_kutta_dopri5<Z>()),
                               ChainOde{1, 1, 5, 5e4, 0.1, 10}, z, 0.0, 10.0, 1e-4,
                               [&](const Z&, double t) { odeint_steps += t > 0; });
    const Chain c = make_default_scene<Chain>();
    const State<2> ex = exact(c, 10);
    const double odeint_error = std::hypot(z[0] - ex.x[0], z[1] - ex.x[1]);
    const AdaptiveResult<2> r = on_chain(tol, tol);
    SCOPED_TRACE(testing::Message() << "tol " << tol << ": steps " << r.stats.accepted << " / " << odeint_steps
                                    << ", error " << r.run.error_final << " / " << odeint_error);
    EXPECT_LT(r.run.error_final, 10 * tol);
    EXPECT_LT(odeint_error, 10 * tol);
    EXPECT_GT(r.run.error_final, odeint_error / 20);
    EXPECT_LT(r.run.error_final, odeint_error * 20);
    EXPECT_NEAR(static_cast<double>(r.stats.accepted), static_cast<double>(odeint_steps), 0.3 * odeint_steps);
  }
}

// Samples come from the fourth-order continuous extension between the steps: on the spring at
// rtol 1e-9 they are as close to the exact solution as the step ends are (measured: max over 1001
// samples 1.47e-8, at the steps 1.47e-8; a linear interpolation over steps of 0.03 would be ~1e-3 off).
TEST(Dopri5, DenseOutputIsAsAccurateAsTheSteps) {
  const Spring s = make_default_scene<Spring>();
  AdaptiveSpec spec;
  spec.tol = {1e-9, 1e-9};
  spec.max_samples = 1001;
  const AdaptiveResult<1> r = simulate_dopri5(s, spec);
  ASSERT_EQ(r.run.samples.size(), 1001u);
  double worst = 0;
  for (std::size_t k = 0; k < r.run.samples.size(); ++k) {
    const auto& smp = r.run.samples[k];
    EXPECT_DOUBLE_EQ(smp.t, 10.0 * static_cast<double>(k) / 1000);
    worst = std::max(worst, std::abs(smp.x[0] - exact(s, smp.t).x[0]));
  }
  EXPECT_LT(worst, 3 * r.run.error_max);
  EXPECT_GT(r.run.error_max, 0.0);
  EXPECT_EQ(r.run.samples.back().x, r.run.final.x);
}

// Tolerance proportionality: a thousand times tighter, the error drops about a thousand times
// (global error ~ tol for an error-per-step controller; measured on the spring 1e-3 -> 1e-6: 357x,
// 1e-6 -> 1e-9: 1040x). The bound [100, 10000] says "proportional", not "a bit better".
TEST(Dopri5, ErrorFollowsTheTolerance) {
  const Spring s = make_default_scene<Spring>();
  double last = 0;
  for (const double tol : {1e-3, 1e-6, 1e-9}) {
    AdaptiveSpec spec;
    spec.tol = {tol, tol};
    const double e = simulate_dopri5(s, spec).run.error_final;
    if (last > 0) {
      EXPECT_GT(last / e, 100) << tol;
      EXPECT_LT(last / e, 10000) << tol;
    }
    last = e;
  }
}

}  // namespace
}  // namespace steplab
