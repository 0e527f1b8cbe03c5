// The hanging rope of N masses (core/scenes/rope.hpp): its exact solution from the closed-form
// modes against an independent matrix exponential of the first-order system, its modes against a
// dense symmetric eigensolver, N = 1 against the sheet's spring, and its sparse Jacobians.
#include <gtest/gtest.h>

#include <array>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <Eigen/Eigenvalues>
#include <unsupported/Eigen/MatrixFunctions>

#include "analysis/kernel/kernel.hpp"
#include "core/scenes/rope.hpp"
#include "core/scenes/spring.hpp"
#include "core/simulate.hpp"
#include "core/methods/rk4.hpp"

namespace steplab {
namespace {

using LMat = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;

// masses, M, K, L, gamma, C_s, g
Rope rope(int n, double gamma = 0.1, double cs = 0.0) {
  const std::array<double, 7> p{double(n), 1.0, 5.0, 5.0, gamma, cs, 9.81};
  return Rope(p);
}

// z = (x, v, 1), z' = A z, written from the physics (not from the scene's code): per element
// m = M/N, k = K N, l = L/N, c = gamma/N, d = C_s N;  m x_i'' = k (x_{i-1} - 2 x_i + x_{i+1})
// (anchor x_0 = 0; the last mass has one spring: -k (x_N - x_{N-1})) + the same with d and v,
// - c v_i - m g, and -k l on the last mass (the rest lengths cancel between neighbours).
LMat system_matrix(int n, double gamma, double cs) {
  const long double m = 1.0L / n, k = 5.0L * n, l = 5.0L / n, c = (long double)gamma / n, d = (long double)cs * n;
  LMat A = LMat::Zero(2 * n + 1, 2 * n + 1);
  for (int i = 0; i < n; ++i) {
    A(i, n + i) = 1;
    const long double diag = i + 1 < n ? 2 : 1;
    A(n + i, i) = -k * diag / m;
    A(n + i, n + i) = -(c + d * diag) / m;
    if (i > 0) A(n + i, i - 1) = k / m, A(n + i, n + i - 1) = d / m;
    if (i + 1 < n) A(n + i, i + 1) = k / m, A(n + i, n + i + 1) = d / m;
    A(n + i, 2 * n) = -9.81L - (i + 1 == n ? k * l / m : 0);
  }
  return A;
}

// Agreement with expm(A t) z0 in long double (Eigen's Pade scaling and squaring): the issue asks
// 1e-12 of the largest |x|; measured 1.6e-15 at worst over these 60 cases.
TEST(Rope, ExactMatchesAMatrixExponential) {
  double worst = 0;
  for (const auto& [gamma, cs] : {std::pair{0.1, 0.0}, std::pair{0.0, 0.0}, std::pair{0.3, 0.02}, std::pair{5.0, 0.5}})
    for (int n : {1, 2, 3, 5, 8}) {
      const Rope r = rope(n, gamma, cs);
      const LMat A = system_matrix(n, gamma, cs);
      Eigen::Matrix<long double, Eigen::Dynamic, 1> z0(2 * n + 1);
      const State<Eigen::Dynamic> y0 = r.initial();
      for (int i = 0; i < n; ++i) z0[i] = y0.x[i], z0[n + i] = 0;
      z0[2 * n] = 1;
      for (double t : {0.5, 3.0, 10.0}) {
        const LMat At = A * (long double)t;
        const Eigen::Matrix<long double, Eigen::Dynamic, 1> z = At.exp() * z0;
        const State<Eigen::Dynamic> y = r.exact_at(t);
        const double scale = y.x.cwiseAbs().maxCoeff();
        for (int i = 0; i < n; ++i) {
          worst = std::max({worst, std::abs(y.x[i] - (double)z[i]) / scale, std::abs(y.v[i] - (double)z[n + i]) / scale});
          EXPECT_NEAR(y.x[i], (double)z[i], 1e-12 * scale) << "N " << n << " t " << t << " gamma " << gamma << " cs " << cs;
          EXPECT_NEAR(y.v[i], (double)z[n + i], 1e-12 * scale) << "N " << n << " t " << t;
        }
        // the flow from any state: from the exact state at t/2 to t
        const State<Eigen::Dynamic> half = r.flow(r.exact_at(t / 2), t / 2);
        EXPECT_LE((half.x - y.x).cwiseAbs().maxCoeff(), 1e-12 * scale) << "N " << n << " t " << t;
      }
    }
  std::printf("largest difference from expm: %.2g of max |x|\n", worst);
}

// omega_j = 2 sqrt(k/m) sin((2j - 1) pi / (2 (2N + 1))) against the eigenvalues of k T / m by a
// dense symmetric eigensolver (LAPACK-style QR iteration in Eigen), N = 64.
TEST(Rope, ModesMatchADenseEigensolver) {
  const int n = 64;
  const Rope r = rope(n);
  const Eigen::MatrixXd T = -Eigen::MatrixXd(r.jacobians(r.initial().x, r.initial().v).dx) / r.k;
  const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(T).eigenvalues();  // ascending
  for (int j = 1; j <= n; ++j) {
    const double omega = 2 * std::sqrt(r.k / r.m) * std::sin((2 * j - 1) * M_PI / (2 * (2 * n + 1)));
    EXPECT_NEAR(r.omega(j), omega, 1e-12 * omega) << j;
    EXPECT_NEAR(r.omega(j), std::sqrt(r.k * ev[j - 1] / r.m), 1e-10 * r.omega(n)) << j;
  }
}

// --masses 1 is the sheet's spring: the same force to the bit (so an explicit method's steps are
// the same to the bit), the exact solution to round-off (two formulas for beta^2).
TEST(Rope, OneMassIsTheSpring) {
  const std::size_t rope_s = *find_scene("rope"), spring_s = *find_scene("spring");
  const std::vector<double> pr{1, 1, 5, 5, 0.1, 0, 9.81}, ps{1, 5, 0.1, 5, 9.81};  // spring: m, k, gamma, L, g
  // The spring's gamma is the dashpot of its one spring (core/scenes/spring.hpp), which the methods
  // on springs take in their constraint; the rope's as that: its spring-damping.
  const std::vector<double> pr_dashpot{1, 1, 5, 5, 0, 0.1, 9.81};
  RunSpec spec;
  spec.dt = 0.01;
  spec.steps = 1000;
  for (std::size_t m = 0; m < method_count(); ++m) {
    const AnyResult a = pair_kernel(m, rope_s).run(method_info(m).on_springs ? pr_dashpot : pr, spec),
                    b = pair_kernel(m, spring_s).run(ps, spec);
    ASSERT_EQ(a.steps, b.steps) << method_info(m).name;
    const Family f = method_info(m).family;
    if (f == Family::ExplicitRungeKutta || f == Family::AdamsBashforth) {  // the same operations
      EXPECT_EQ(a.final.x[0], b.final.x[0]) << method_info(m).name;
      EXPECT_EQ(a.final.v[0], b.final.v[0]) << method_info(m).name;
    } else {  // exact flow (two formulas); Newton's solve (an LDL^T divides otherwise than r / J)
      EXPECT_NEAR(a.final.x[0], b.final.x[0], 1e-13 * std::abs(b.final.x[0])) << method_info(m).name;
      EXPECT_NEAR(a.final.v[0], b.final.v[0], 1e-13 * std::abs(b.final.x[0])) << method_info(m).name;
    }
    EXPECT_NEAR(a.error_final, b.error_final, 1e-13 * std::abs(b.final.x[0])) << method_info(m).name;
    EXPECT_NEAR(a.energy_ratio_final, b.energy_ratio_final, 1e-12) << method_info(m).name;
  }
  const Spring sp(ps);
  const Rope r = rope(1);
  for (double t : {0.1, 1.0, 10.0}) EXPECT_NEAR(r.exact_at(t).x[0], sp.exact_at(t).x[0], 1e-13 * std::abs(sp.exact_at(t).x[0]));
}

// The rope is linear: F(x + dx, v + dv) - F(x, v) = J_x dx + J_v dv to round-off.
TEST(Rope, JacobiansAreTheLinearForce) {
  const Rope r = rope(7, 0.1, 0.05);
  const State<Eigen::Dynamic> y = r.exact_at(0.7);
  const Eigen::VectorXd dx = Eigen::VectorXd::LinSpaced(7, -0.3, 0.2), dv = Eigen::VectorXd::LinSpaced(7, 0.5, -0.1);
  const Jacobians<Eigen::Dynamic> j = r.jacobians(y.x, y.v);
  const Eigen::VectorXd lhs = force_value(r, 0.0, y.x + dx, y.v + dv) - force_value(r, 0.0, y.x, y.v), rhs = j.dx * dx + j.dv * dv;
  EXPECT_LE((lhs - rhs).cwiseAbs().maxCoeff(), 1e-12 * force_value(r, 0.0, y.x, y.v).cwiseAbs().maxCoeff());
}

// The exact motion along a run (Rope::ExactAlong: each mode stepped by its 2 x 2 map, the closed
// form every kResync steps) against the closed form at every step: the recurrence's round-off
// over at most kResync steps, a few ulps of |q| each, summed over the modes by the transform, is
// far below 1e-12 of the rope's size; over 1000 steps it resyncs three times. Underdamped modes
// (the default), and with dashpots strong enough that the fastest modes are overdamped.
TEST(Rope, ExactAlongARunIsTheClosedForm) {
  for (const double cs : {0.0, 0.5})
    for (const int n : {16, 300}) {
      const Rope r = rope(n, 0.1, cs);
      const double h = 0.05 / n;
      Rope::ExactAlong along = r.exact_along(h);
      double worst_x = 0, worst_v = 0;
      for (int i = 1; i <= 1000; ++i) {
        const State<Eigen::Dynamic> closed = r.exact_at(i * h);
        worst_x = std::max(worst_x, (along.at(i * h) - closed.x).cwiseAbs().maxCoeff());
        if (i % 97 == 0) worst_v = std::max(worst_v, (along.velocities() - closed.v).cwiseAbs().maxCoeff());
      }
      EXPECT_LE(worst_x, 1e-12 * 5.0) << n << " masses, dashpots " << cs;  // the rope hangs 5 long
      EXPECT_LE(worst_v, 1e-12 * 5.0) << n << " masses, dashpots " << cs;
      if (cs > 0) {
        EXPECT_LT(r.beta2(n), 0) << "the fastest mode overdamped";
      }
    }
}

// A run that reads the error every few steps (RunSpec::error_stride; run --error-every) reads it
// at the multiples of the stride and at the last step, against the closed form there: its max,
// RMS and final errors are those of the same run's positions at those steps, taken here from an
// observer and Rope::exact_at (to 1e-12 of the rope's length, 5: the tracker's recurrence against
// the closed form, as above). A stride of 1 reads every step, as every other scene does.
TEST(Rope, ErrorsReadEveryFewStepsAreThoseSteps) {
  const Rope r = rope(64);
  for (const long long stride : {1LL, 100LL, 7LL}) {
    RunSpec spec;
    spec.dt = 1e-3, spec.steps = 1000, spec.error_stride = stride;
    double max = 0, sq = 0, last = 0;
    long long reads = 0;
    const RunResult<Eigen::Dynamic> run = simulate<Rk4>(r, spec, [&](long long i, double t, const State<Eigen::Dynamic>& y) {
      if (i % stride != 0 && i != spec.steps) return;
      const double e = (y.x - r.exact_at(t).x).norm();
      max = std::max(max, e), sq += e * e, last = e, ++reads;
    });
    EXPECT_EQ(run.error_reads, stride == 7 ? 143 : 1000 / stride) << stride;
    EXPECT_EQ(run.error_reads, reads) << stride;
    const double tol = 1e-12 * 5.0;
    EXPECT_NEAR(run.error_max, max, tol) << stride;
    EXPECT_NEAR(run.error_rms, std::sqrt(sq / reads), tol) << stride;
    EXPECT_NEAR(run.error_final, last, tol) << stride;
    EXPECT_NEAR(run.error_v_final, (run.final.v - r.exact_at(1.0).v).norm(), tol) << stride;
    EXPECT_GT(max, 1e3 * tol) << "the errors compared are far above the tolerance";
  }
}

}  // namespace
}  // namespace steplab
