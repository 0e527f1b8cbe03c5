// The stiff two-mass chain (core/scenes/chain.hpp): its exact solution against a 50-digit matrix
// exponential and against Boost.Odeint's Runge-Kutta-Fehlberg 7(8) at tight tolerances, its two
// evaluation paths against each other, its energy, and what the stiffness does to the methods.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <complex>

#include <boost/numeric/odeint.hpp>

#include "analysis/studies/convergence.hpp"
#include "tests/core/chain_ode.hpp"
#include "analysis/kernel/kernel.hpp"
#include "core/scenes/chain.hpp"
#include "core/simulate.hpp"

namespace steplab {
namespace {

namespace odeint = boost::numeric::odeint;

// mass1, mass2, stiffness1, stiffness2, damping1, damping2, u1, u2
Chain chain(double c1 = 0.1, double c2 = 10, double k2 = 5e4) {
  const std::array<double, 8> p{1.0, 1.0, 5.0, k2, c1, c2, 1.0, 1.0};
  return Chain(p);
}

// z(t) = expm(A t) z0 at 50 digits (mpmath 1.3, mp.dps = 50) for the default chain:
//   A = [[0,0,1,0],[0,0,0,1],[-(k1+k2)/m1, k2/m1, -(c1+c2)/m1, c2/m1],[k2/m2, -k2/m2, c2/m2, -c2/m2]]
TEST(Chain, ExactMatchesAFiftyDigitMatrixExponential) {
  const struct {
    double t;
    Z z;
  } reference[] = {
      {1, {0.0055479995119038934757, 0.0055467507716454773169, -1.5421585959010237418, -1.5422349841930644526}},
      {5, {-0.030719052905295146743, -0.030721968750358397114, -1.3936931679522682396, -1.3937627100201559537}},
      {10, {-0.77604728241498908914, -0.77608596289222541102, 0.12447754639818987893, 0.12448568511492648285}}};
  const Chain c = chain();
  ASSERT_TRUE(c.use_eigen);
  for (const auto& r : reference) {
    const State<2> y = c.exact_at(r.t);
    // measured 1.0e-14 at t = 10 (the eigen-decomposition in long double, evaluated in double)
    for (int i = 0; i < 2; ++i) {
      EXPECT_NEAR(y.x[i], r.z[i], 5e-14) << "t " << r.t;
      EXPECT_NEAR(y.v[i], r.z[2 + i], 5e-14) << "t " << r.t;
    }
  }
}

// The matrix-exponential path (used where the eigenvectors are ill-conditioned) and the eigen path
// are computed independently; they agree to round-off.
TEST(Chain, BothExactPathsAgree) {
  const Chain c = chain();
  Chain by_expm = c;
  by_expm.use_eigen = false;
  for (double t : {0.01, 0.5, 3.0, 10.0}) {
    const State<2> a = c.exact_at(t), b = by_expm.exact_at(t);
    EXPECT_LT((a.x - b.x).norm() + (a.v - b.v).norm(), 1e-13) << t;
  }
}

// Against Boost.Odeint's controlled Runge-Kutta-Fehlberg 7(8) at 1e-13, on the default chain and
// on one whose fast mode is overdamped (c2 = 2000: real eigenvalues near -4000 and -0.01... ).
TEST(Chain, ExactMatchesOdeintAtTightTolerance) {
  for (const double c2 : {10.0, 2000.0}) {
    const Chain c = chain(0.1, c2);
    Z z{1, 1, 0, 0};
    const ChainOde ode{1, 1, 5, 5e4, 0.1, c2};
    odeint::integrate_adaptive(odeint::make_controlled(1e-13, 1e-13, odeint::runge_kutta_fehlberg78<Z>()), ode, z,
                               0.0, 10.0, 1e-4);
    const State<2> y = c.exact_at(10);
    for (int i = 0; i < 2; ++i) {
      EXPECT_NEAR(y.x[i], z[i], 1e-10) << "c2 " << c2;
      EXPECT_NEAR(y.v[i], z[2 + i], 1e-10) << "c2 " << c2;
    }
  }
}

TEST(Chain, ExactFlowKeepsTheEnergyWithoutDampingAndLosesItWith) {
  const Chain undamped = chain(0, 0);
  const State<2> y0 = undamped.initial(), y = undamped.exact_at(10);
  EXPECT_NEAR(undamped.energy(y.x, y.v) / undamped.energy(y0.x, y0.v), 1.0, 1e-12);
  const Chain damped = chain();
  double last = damped.energy(y0.x, y0.v);
  for (double t = 1; t <= 10; t += 1) {
    const State<2> z = damped.exact_at(t);
    const double e = damped.energy(z.x, z.v);
    EXPECT_LT(e, last) << t;
    last = e;
  }
  // 1/2 u^T K u at the start: both masses displaced by 1, the stiff spring unstretched: k1 / 2
  EXPECT_DOUBLE_EQ(damped.energy(y0.x, y0.v), 2.5);
}

// The convergence study on the default chain, for these methods, on two threads.
ConvergenceConfig convergence_on_chain(std::initializer_list<std::string_view> methods) {
  ConvergenceConfig c;
  c.scene = *find_scene("chain");
  c.params = default_param_values<Chain>();
  for (const std::string_view m : methods) c.methods.push_back(*find_method(m));
  c.workers.threads = 2;
  return c;
}

// Stiffness in numbers: Radau IIA keeps its order 5 at steps up to 0.5 (omega_fast h ~ 160), where
// RK4, limited to |h lambda_fast| <~ 2.8 (h <~ 0.009), diverges at every step of the sweep above 0.01.
TEST(Chain, ImplicitMethodsKeepTheirOrderFarAboveTheExplicitLimit) {
  ConvergenceConfig c = convergence_on_chain({"radau_iia5", "rk4"});
  c.dt_max = 0.5;
  c.dt_min = 0.005;
  const ConvergenceResult r = convergence_study(c);
  const OrderFit& radau = r.fits[0].fit;
  ASSERT_TRUE(radau.fitted);
  EXPECT_NEAR(radau.order, 5, 0.05);
  EXPECT_GE(radau.dt_hi, 0.4);
  for (const ConvergenceRecord& rec : r.records) {
    if (rec.method == c.methods[1] && rec.dt > 0.01) {  // above its step map's limit, 0.009124: diverged
      EXPECT_NE(rec.status, RunStatus::Ok) << rec.dt;
    }
  }
}

TEST(Chain, BdfAndImplicitEulerFitTheirOrders) {
  const ConvergenceResult r = convergence_study(convergence_on_chain({"bdf2", "implicit_euler"}));
  EXPECT_NEAR(r.fits[0].fit.order, 2, 0.02);
  EXPECT_NEAR(r.fits[1].fit.order, 1, 0.02);
}

// Its modes (the stability studies' prediction) against the eigenvalues of its first-order
// system A, computed apart from them (Eigen, long double): each mode's omega^2 and its modal
// damping zeta omega against |lambda|^2 and -Re lambda of its eigenvalue pair. The modes' damping
// is a projection that leaves out C's coupling of the two modes; on the default chain that is
// about 1e-10 of the damping (the pair's -Re lambda: 0.0249988 and 10.0250012), so 1e-6 checks
// the formulas, not the approximation's limit.
TEST(Chain, ModesAreTheEigenvaluesOfItsSystem) {
  const Chain c = chain();
  const std::vector<Mode> modes = c.modes();
  ASSERT_EQ(modes.size(), 2u);
  EXPECT_LT(modes[0].omega, modes[1].omega);
  std::array<std::complex<double>, 2> pair{};  // the eigenvalue with Im > 0 of each pair, slowest first
  for (int k = 0; k < 4; ++k)
    if (c.lambda[k].imag() > 0) pair[std::abs(c.lambda[k]) > 100 ? 1 : 0] = c.lambda[k];
  for (int k = 0; k < 2; ++k) {
    const double omega = modes[k].omega, zeta_omega = modes[k].two_zeta * omega / 2;
    EXPECT_NEAR(omega * omega, std::norm(pair[k]), 1e-6 * std::norm(pair[k])) << k;
    EXPECT_NEAR(zeta_omega, -pair[k].real(), 1e-6 * -pair[k].real()) << k;
  }
}

}  // namespace
}  // namespace steplab
