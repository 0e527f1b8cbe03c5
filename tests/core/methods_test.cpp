// Unit tests for core/methods/*.hpp and core/method.hpp: each method's step against the same step
// written out by hand on the linear spring (y < 0, so F = -k (y + L) - gamma v - m g).
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "analysis/kernel/kernel.hpp"
#include "core/methods/adams_bashforth2.hpp"
#include "core/methods/adams_bashforth3.hpp"
#include "core/methods/analytic.hpp"
#include "core/methods/bdf2.hpp"
#include "core/methods/bdf3.hpp"
#include "core/methods/explicit_euler.hpp"
#include "core/methods/explicit_midpoint.hpp"
#include "core/methods/gauss_legendre4.hpp"
#include "core/methods/implicit_euler.hpp"
#include "core/methods/implicit_midpoint.hpp"
#include "core/methods/rk3.hpp"
#include "core/methods/rk4.hpp"
#include "core/methods/symplectic_euler.hpp"
#include "core/methods/velocity_verlet.hpp"
#include "core/methods/yoshida4.hpp"
#include "core/scenes/cannonball.hpp"
#include "core/scenes/spring.hpp"
#include "core/stepper.hpp"

namespace steplab {
namespace {

// The hand-written steps below evaluate the same formulas in a different order; a few ulps of
// the state's magnitude (|y| ~ 5) apart. 1e-13 relative leaves room for that and nothing more.
constexpr double kRoundoff = 1e-13;

struct Hand {
  double m = 1.3, k = 7.0, gamma = 0.4, L = 2.0, g = 9.81;
  double a(double y, double v) const { return (-k * (y + L) - gamma * v - m * g) / m; }
};

Spring make_spring(const Hand& p) {
  const std::array<double, 5> v{p.m, p.k, p.gamma, p.L, p.g};
  return Spring(v);
}

template <class M> State<1> one_step(const Spring& s, double y, double v, double h) {
  State<1> st{Vec<1>::Constant(y), Vec<1>::Constant(v)};
  EXPECT_EQ(M::step(s, st, 0.0, h), StepStatus::Ok);
  return st;
}

void expect_state(const State<1>& got, double y, double v) {
  EXPECT_NEAR(got.x[0], y, kRoundoff * std::max(1.0, std::abs(y)));
  EXPECT_NEAR(got.v[0], v, kRoundoff * std::max(1.0, std::abs(v)));
}

class MethodStep : public ::testing::TestWithParam<double> {
 protected:
  Hand p;
  Spring s = make_spring(p);
  double y = -6.3, v = 1.7;
  double h = GetParam();
};

TEST_P(MethodStep, ExplicitEuler) {
  expect_state(one_step<ExplicitEuler>(s, y, v, h), y + h * v, v + h * p.a(y, v));
}

TEST_P(MethodStep, SymplecticEuler) {
  const double v1 = v + h * p.a(y, v);
  expect_state(one_step<SymplecticEuler>(s, y, v, h), y + h * v1, v1);
}

TEST_P(MethodStep, ExplicitMidpoint) {
  const double ym = y + h / 2 * v, vm = v + h / 2 * p.a(y, v);
  expect_state(one_step<ExplicitMidpoint>(s, y, v, h), y + h * vm, v + h * p.a(ym, vm));
}

TEST_P(MethodStep, ImplicitEuler) {
  // v1 = v + h a(y + h v1, v1), linear in v1:
  //   v1 (1 + h gamma/m + h^2 k/m) = v + h (-k (y + L) - m g) / m
  const double v1 = (v + h * (-p.k * (y + p.L) - p.m * p.g) / p.m) / (1 + h * p.gamma / p.m + h * h * p.k / p.m);
  expect_state(one_step<ImplicitEuler>(s, y, v, h), y + h * v1, v1);
}

TEST_P(MethodStep, ImplicitMidpoint) {
  // vm = v + h/2 a(y + h/2 vm, vm); then x1 = y + h vm, v1 = 2 vm - v.
  const double vm = (v + h / 2 * (-p.k * (y + p.L) - p.m * p.g) / p.m) /
                    (1 + h / 2 * p.gamma / p.m + h * h / 4 * p.k / p.m);
  expect_state(one_step<ImplicitMidpoint>(s, y, v, h), y + h * vm, 2 * vm - v);
  // and it is the midpoint rule: v1 - v = h a((y + y1)/2, (v + v1)/2)
  const State<1> r = one_step<ImplicitMidpoint>(s, y, v, h);
  EXPECT_NEAR(r.v[0] - v, h * p.a((y + r.x[0]) / 2, (v + r.v[0]) / 2), kRoundoff * 10);
}

TEST_P(MethodStep, VelocityVerletDamped) {
  // x1 = y + h v + h^2/2 a0;  v1 = v + h/2 (a0 + a(x1, v1)), linear in v1:
  //   v1 (1 + h/2 gamma/m) = v + h/2 a0 + h/2 (-k (x1 + L) - m g) / m
  const double a0 = p.a(y, v), x1 = y + h * v + h * h / 2 * a0;
  const double v1 = (v + h / 2 * a0 + h / 2 * (-p.k * (x1 + p.L) - p.m * p.g) / p.m) / (1 + h / 2 * p.gamma / p.m);
  expect_state(one_step<VelocityVerlet>(s, y, v, h), x1, v1);
}

TEST_P(MethodStep, VelocityVerletUndamped) {
  p.gamma = 0;
  s = make_spring(p);
  const double a0 = p.a(y, v), x1 = y + h * v + h * h / 2 * a0;
  expect_state(one_step<VelocityVerlet>(s, y, v, h), x1, v + h / 2 * (a0 + p.a(x1, v)));
}

TEST_P(MethodStep, Rk4) {
  const double k1x = v, k1v = p.a(y, v);
  const double k2x = v + h / 2 * k1v, k2v = p.a(y + h / 2 * k1x, k2x);
  const double k3x = v + h / 2 * k2v, k3v = p.a(y + h / 2 * k2x, k3x);
  const double k4x = v + h * k3v, k4v = p.a(y + h * k3x, k4x);
  expect_state(one_step<Rk4>(s, y, v, h), y + h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x),
               v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v));
}

TEST_P(MethodStep, Rk3) {
  const double k1x = v, k1v = p.a(y, v);
  const double k2x = v + h / 2 * k1v, k2v = p.a(y + h / 2 * k1x, k2x);
  const double k3x = v - h * k1v + 2 * h * k2v, k3v = p.a(y - h * k1x + 2 * h * k2x, k3x);
  expect_state(one_step<Rk3>(s, y, v, h), y + h / 6 * (k1x + 4 * k2x + k3x), v + h / 6 * (k1v + 4 * k2v + k3v));
}

// Yoshida: three hand-written damped Verlet steps of w1 h, w0 h, w1 h.
TEST_P(MethodStep, Yoshida4IsATripleJumpOfVerlet) {
  const double c = std::cbrt(2.0), w1 = 1 / (2 - c), w0 = -c / (2 - c);
  double x = y, u = v;
  for (double w : {w1, w0, w1}) {
    const double t = w * h, a0 = p.a(x, u), x1 = x + t * u + t * t / 2 * a0;
    u = (u + t / 2 * a0 + t / 2 * (-p.k * (x1 + p.L) - p.m * p.g) / p.m) / (1 + t / 2 * p.gamma / p.m);
    x = x1;
  }
  expect_state(one_step<Yoshida4>(s, y, v, h), x, u);
}

// On the linear spring a Gauss-Legendre step is R(h A) applied to (y - y_eq, v), with R the (2,2)
// Pade approximant of exp: R(Z) = (I - Z/2 + Z^2/12)^-1 (I + Z/2 + Z^2/12).
TEST_P(MethodStep, GaussLegendre4IsThePadeApproximant) {
  Mat<2> A;
  A << 0, 1, -p.k / p.m, -p.gamma / p.m;
  const Mat<2> Z = h * A, I = Mat<2>::Identity();
  const Mat<2> R = (I - Z / 2 + Z * Z / 12).inverse() * (I + Z / 2 + Z * Z / 12);
  const double yeq = -p.L - p.m * p.g / p.k;
  const Eigen::Vector2d u = R * Eigen::Vector2d(y - yeq, v);
  expect_state(one_step<GaussLegendre4>(s, y, v, h), u[0] + yeq, u[1]);
}

// Multistep methods from a given past (their memory filled by `remember`), against the formulas.
template <class M> State<1> multistep(const Spring& s, const std::vector<std::pair<double, double>>& past, double y, double v,
                                      double h) {
  Stepper<M, Spring> st;
  st.memory = M::remember(s, [&](int k) { return State<1>{Vec<1>::Constant(past[k - 1].first), Vec<1>::Constant(past[k - 1].second)}; });
  State<1> out{Vec<1>::Constant(y), Vec<1>::Constant(v)};
  EXPECT_EQ(st.step(s, out, 0.0, h), StepStatus::Ok);
  return out;
}

TEST_P(MethodStep, AdamsBashforth) {
  const std::vector<std::pair<double, double>> past{{-6.2, 1.6}, {-6.05, 1.45}};  // y_{n-1}, y_{n-2}
  const double f0v = p.a(y, v), f1v = p.a(past[0].first, past[0].second), f2v = p.a(past[1].first, past[1].second);
  expect_state(multistep<AdamsBashforth2>(s, past, y, v, h), y + h * (1.5 * v - 0.5 * past[0].second),
               v + h * (1.5 * f0v - 0.5 * f1v));
  expect_state(multistep<AdamsBashforth3>(s, past, y, v, h),
               y + h / 12 * (23 * v - 16 * past[0].second + 5 * past[1].second), v + h / 12 * (23 * f0v - 16 * f1v + 5 * f2v));
}

TEST_P(MethodStep, Bdf) {
  const std::vector<std::pair<double, double>> past{{-6.2, 1.6}, {-6.05, 1.45}};
  // y1 = w + beta h f(y1), linear: v1 (1 + b gamma/m + b^2 k/m) = wv + b (-k (wx + L) - m g)/m, b = beta h
  const auto bdf = [&](double wx, double wv, double beta) {
    const double b = beta * h;
    const double v1 = (wv + b * (-p.k * (wx + p.L) - p.m * p.g) / p.m) / (1 + b * p.gamma / p.m + b * b * p.k / p.m);
    return std::pair{wx + b * v1, v1};
  };
  const auto [x2, v2] = bdf(4.0 / 3 * y - 1.0 / 3 * past[0].first, 4.0 / 3 * v - 1.0 / 3 * past[0].second, 2.0 / 3);
  expect_state(multistep<Bdf2>(s, past, y, v, h), x2, v2);
  const auto [x3, v3] = bdf(18.0 / 11 * y - 9.0 / 11 * past[0].first + 2.0 / 11 * past[1].first,
                            18.0 / 11 * v - 9.0 / 11 * past[0].second + 2.0 / 11 * past[1].second, 6.0 / 11);
  expect_state(multistep<Bdf3>(s, past, y, v, h), x3, v3);
}

// The start: an explicit multistep method's first steps are RK4 steps, an implicit one's
// Gauss-Legendre steps (A-stable, so a large step does not blow up what BDF damps).
TEST_P(MethodStep, MultistepMethodsStartWithOneStepMethods) {
  const auto first = [&]<class M>() {
    Stepper<M, Spring> st;
    State<1> out{Vec<1>::Constant(y), Vec<1>::Constant(v)};
    st.step(s, out, 0.0, h);
    return out;
  };
  const State<1> rk4 = one_step<Rk4>(s, y, v, h), gl = one_step<GaussLegendre4>(s, y, v, h);
  expect_state(first.operator()<AdamsBashforth2>(), rk4.x[0], rk4.v[0]);
  expect_state(first.operator()<AdamsBashforth3>(), rk4.x[0], rk4.v[0]);
  expect_state(first.operator()<Bdf2>(), gl.x[0], gl.v[0]);
  expect_state(first.operator()<Bdf3>(), gl.x[0], gl.v[0]);
}

TEST_P(MethodStep, AnalyticIsTheExactFlow) {
  const State<1> start{Vec<1>::Constant(y), Vec<1>::Constant(v)};
  const State<1> want = s.flow(start, h);
  expect_state(one_step<Analytic>(s, y, v, h), want.x[0], want.v[0]);
}

INSTANTIATE_TEST_SUITE_P(Steps, MethodStep, ::testing::Values(0.001, 0.01, 0.05, 0.3));

TEST(Cannonball, ExplicitAndSymplecticEulerByHand) {
  const Cannonball c = make_default_scene<Cannonball>();
  const double h = 0.01;
  State<2> e = c.initial(), se = c.initial();
  const Vec<2> x0 = e.x, v0 = e.v, g(0, -9.81);
  ExplicitEuler::step(c, e, 0, h);
  SymplecticEuler::step(c, se, 0, h);
  EXPECT_TRUE(e.x.isApprox(x0 + h * v0, kRoundoff));
  EXPECT_TRUE(e.v.isApprox(v0 + h * g, kRoundoff));
  EXPECT_TRUE(se.x.isApprox(x0 + h * (v0 + h * g), kRoundoff));
  // the sheet's launch: 100 (cos 1.047, sin 1.047) = (50.0171, 86.5927)
  EXPECT_NEAR(v0[0], 50.0171, 1e-4);
  EXPECT_NEAR(v0[1], 86.5927, 1e-4);
}

// A linear force: Newton's first step is already the solution, the second pass only confirms it.
struct CountingSpring : Spring {
  using Spring::Spring;
  mutable int jacobian_calls = 0;
  Jacobians<1> jacobians(const Vec<1>& x, const Vec<1>& v) const {
    ++jacobian_calls;
    return Spring::jacobians(x, v);
  }
};

TEST(Newton, OneStepIsExactForALinearForce) {
  const std::array<double, 5> p{1.0, 5.0, 0.1, 5.0, 9.81};
  const CountingSpring s(p);
  Vec<1> u;
  EXPECT_EQ(solve_implicit(s, 0.05, Vec<1>::Constant(-6.0), 0.05, Vec<1>::Constant(0.5), 0.05, u), StepStatus::Ok);
  // the first update solves it; the second's correction is round-off's and ends the iteration
  // (Newton's round-off rule, core/method.hpp): two Jacobians, unless the first left no residual
  EXPECT_LE(s.jacobian_calls, 2);
  const Vec<1> x = Vec<1>::Constant(-6.0) + 0.05 * u;  // the solution to round-off: M (u - w) = c F(x, u)
  EXPECT_NEAR(u[0] - 0.5, 0.05 * s.force(x, u)[0], 1e-15 * (std::abs(u[0]) + 0.5 + 0.05 * 9.81 * 3));
}

// A force whose Jacobian lies (says 0 while the force is steep) makes Newton stall: it must stop
// at its cap and say so, not loop or exit.
struct LyingSpring : Spring {
  using Spring::Spring;
  Jacobians<1> jacobians(const Vec<1>&, const Vec<1>&) const { return {Mat<1>::Constant(1e6), Mat<1>::Zero()}; }
};

TEST(Newton, ReportsNoConvergence) {
  const std::array<double, 5> p{1.0, 5.0, 0.1, 5.0, 9.81};
  const LyingSpring s(p);
  State<1> y = s.initial();
  EXPECT_EQ(ImplicitEuler::step(s, y, 0.0, 0.5), StepStatus::NoConvergence);
}

TEST(MethodTable, NamesAliasesAndFlags) {
  EXPECT_EQ(method_count(), 19u);
  EXPECT_EQ(find_method("euler"), find_method("explicit_euler"));
  EXPECT_EQ(find_method("midpoint"), find_method("explicit_midpoint"));
  EXPECT_EQ(find_method("backwards_euler"), find_method("implicit_euler"));
  EXPECT_FALSE(find_method("backward_euler").has_value());
  for (std::size_t m = 0; m < method_count(); ++m) {
    const MethodInfo& info = method_info(m);
    const bool implicit = info.name == "implicit_euler" || info.name == "implicit_midpoint" ||
                          info.name == "gauss_legendre4" || info.name == "radau_iia5" || info.name == "bdf2" || info.name == "bdf3";
    const bool symplectic = info.name == "symplectic_euler" || info.name == "velocity_verlet" || info.name == "yoshida4" ||
                            info.name == "implicit_midpoint" || info.name == "gauss_legendre4" || info.name == "analytic";
    // A-stable: |R(z)| <= 1 on the left half-plane (implicit Euler, implicit midpoint, Gauss-Legendre,
    // the exact flow) or the root condition there (BDF2); BDF3 is A(86 degrees)-stable only
    const bool a_stable = info.name == "implicit_euler" || info.name == "implicit_midpoint" ||
                          info.name == "gauss_legendre4" || info.name == "radau_iia5" || info.name == "bdf2" ||
                          info.name == "analytic" ||
                          // on one spring a sweep solves the constraint, CG the 1 x 1 system: implicit Euler
                          info.name == "xpbd" || info.name == "baraff_witkin";
    EXPECT_EQ(info.implicit, implicit) << info.name;
    EXPECT_EQ(info.symplectic, symplectic) << info.name;
    EXPECT_EQ(info.a_stable, a_stable) << info.name;
  }
  EXPECT_EQ(method_info(*find_method("rk4")).order, 4);
  // the methods on springs: XPBD and Baraff-Witkin first order, PBD no order (it does not converge)
  for (const char* n : {"xpbd", "pbd", "baraff_witkin"}) EXPECT_TRUE(method_info(*find_method(n)).on_springs) << n;
  EXPECT_EQ(method_info(*find_method("xpbd")).order, 1);
  EXPECT_EQ(method_info(*find_method("baraff_witkin")).order, 1);
  EXPECT_FALSE(method_info(*find_method("pbd")).converges);
  EXPECT_EQ(method_info(*find_method("pbd")).family, Family::PositionBased);
  // every family spans several orders; explicit and implicit Euler open Adams-Bashforth and BDF
  EXPECT_EQ(method_info(*find_method("explicit_euler")).first_of, Family::AdamsBashforth);
  EXPECT_EQ(method_info(*find_method("implicit_euler")).first_of, Family::Bdf);
  for (Family f : {Family::ExplicitRungeKutta, Family::Splitting, Family::ImplicitRungeKutta}) {
    std::set<int> orders;
    for (std::size_t m = 0; m < method_count(); ++m)
      if (method_info(m).family == f) orders.insert(method_info(m).order);
    EXPECT_EQ(orders.size(), f == Family::Splitting ? 3u : 4u) << to_string(f);
  }
}

}  // namespace
}  // namespace steplab
