// steplab's explicit methods against Boost.Odeint's steppers on the same problem: the trajectories
// must agree to 1e-12 relative after 1000 steps (they perform the same arithmetic up to the order
// of additions, so they differ by accumulated round-off only: ~1000 steps x a few ulps).
#include <gtest/gtest.h>

#include <array>
#include <utility>

#include <boost/numeric/odeint.hpp>

#include "analysis/kernel/kernel.hpp"
#include "core/methods/adams_bashforth2.hpp"
#include "core/methods/adams_bashforth3.hpp"
#include "core/methods/explicit_euler.hpp"
#include "core/methods/explicit_midpoint.hpp"
#include "core/methods/rk3.hpp"
#include "core/methods/rk4.hpp"
#include "core/methods/velocity_verlet.hpp"
#include "core/scenes/cannonball.hpp"
#include "core/scenes/spring.hpp"
#include "core/simulate.hpp"

namespace steplab {
namespace {

namespace odeint = boost::numeric::odeint;
using Y = std::array<double, 2>;  // (y, v)

constexpr double kRelTol = 1e-12;
constexpr int kSteps = 1000;
constexpr double kDt = 0.01;

Spring spring(double gamma) {
  const std::array<double, 5> p{1.0, 5.0, gamma, 5.0, 9.81};
  return Spring(p);
}

// y' = v, v' = a(y, v) as a first-order system for odeint
struct SpringOde {
  Spring s;
  void operator()(const Y& y, Y& dy, double t) const {
    dy[0] = y[1];
    dy[1] = acceleration(s, t, Vec<1>::Constant(y[0]), Vec<1>::Constant(y[1]))[0];
  }
};

template <class M> State<1> ours(const Spring& s) {
  RunSpec spec;
  spec.dt = kDt;
  spec.steps = kSteps;
  spec.errors = false;
  return simulate<M>(s, spec).final;
}

template <class Stepper> Y theirs(Stepper stepper, const Spring& s) {
  Y y{s.initial().x[0], 0.0};
  for (int i = 0; i < kSteps; ++i) stepper.do_step(SpringOde{s}, y, i * kDt, kDt);
  return y;
}

void expect_same(const State<1>& a, const Y& b) {
  EXPECT_NEAR(a.x[0], b[0], kRelTol * std::abs(b[0]));
  EXPECT_NEAR(a.v[0], b[1], kRelTol * std::max(1.0, std::abs(b[1])));
}

TEST(Odeint, ExplicitEulerEqualsEuler) {
  const Spring s = spring(0.1);
  expect_same(ours<ExplicitEuler>(s), theirs(odeint::euler<Y>(), s));
}

TEST(Odeint, ExplicitMidpointEqualsGenericRk2) {
  using Rk2 = odeint::explicit_generic_rk<2, 2, Y, double>;
  const Rk2::coef_a_type a(boost::array<double, 1>{{0.5}});
  const Rk2::coef_b_type b{{0.0, 1.0}};
  const Rk2::coef_c_type c{{0.0, 0.5}};
  const Spring s = spring(0.1);
  expect_same(ours<ExplicitMidpoint>(s), theirs(Rk2(a, b, c), s));
}

TEST(Odeint, Rk4EqualsRungeKutta4) {
  const Spring s = spring(0.1);
  expect_same(ours<Rk4>(s), theirs(odeint::runge_kutta4<Y>(), s));
}

// Kutta's third-order method as a generic explicit Runge-Kutta tableau.
TEST(Odeint, Rk3EqualsGenericRk3) {
  using Kutta3 = odeint::explicit_generic_rk<3, 3, Y, double>;
  const Kutta3::coef_a_type a(boost::fusion::make_vector(boost::array<double, 1>{{0.5}}, boost::array<double, 2>{{-1.0, 2.0}}));
  const Kutta3::coef_b_type b{{1.0 / 6, 2.0 / 3, 1.0 / 6}};
  const Kutta3::coef_c_type c{{0.0, 0.5, 1.0}};
  const Spring s = spring(0.1);
  expect_same(ours<Rk3>(s), theirs(Kutta3(a, b, c), s));
}

// odeint's Adams-Bashforth with RK4 as its initialising stepper, which is how steplab starts them.
template <std::size_t N>
using OdeintAb = odeint::adams_bashforth<N, Y, double, Y, double, odeint::algebra_dispatcher<Y>::algebra_type,
                                         odeint::operations_dispatcher<Y>::operations_type, odeint::initially_resizer,
                                         odeint::runge_kutta4<Y>>;

TEST(Odeint, AdamsBashforthEqualsAdamsBashforth) {
  for (double gamma : {0.0, 0.1}) {
    const Spring s = spring(gamma);
    expect_same(ours<AdamsBashforth2>(s), theirs(OdeintAb<2>(), s));
    expect_same(ours<AdamsBashforth3>(s), theirs(OdeintAb<3>(), s));
  }
}

// odeint's velocity_verlet evaluates the new acceleration at the old velocity, so it is the same
// method only without damping (see core/methods/velocity_verlet.hpp).
TEST(Odeint, VelocityVerletEqualsVelocityVerletUndamped) {
  const Spring s = spring(0.0);
  using Q = std::array<double, 1>;
  odeint::velocity_verlet<Q> vv;
  std::pair<Q, Q> qp{Q{s.initial().x[0]}, Q{0.0}};
  const auto acc = [&](const Q& q, const Q& p, Q& a, double t) {
    a[0] = acceleration(s, t, Vec<1>::Constant(q[0]), Vec<1>::Constant(p[0]))[0];
  };
  for (int i = 0; i < kSteps; ++i) vv.do_step(acc, qp, i * kDt, kDt);
  expect_same(ours<VelocityVerlet>(s), Y{qp.first[0], qp.second[0]});
}

TEST(Odeint, CannonballRk4AndEuler) {
  using C = std::array<double, 4>;  // x0, x1, v0, v1
  const Cannonball c = make_default_scene<Cannonball>();
  const auto ode = [&](const C& y, C& dy, double) {
    dy[0] = y[2], dy[1] = y[3], dy[2] = c.g[0], dy[3] = c.g[1];
  };
  RunSpec spec;
  spec.dt = kDt;
  spec.steps = kSteps;
  for (int which = 0; which < 2; ++which) {
    C y{0, 0, c.v0[0], c.v0[1]};
    odeint::runge_kutta4<C> rk4;
    odeint::euler<C> eu;
    for (int i = 0; i < kSteps; ++i) which ? rk4.do_step(ode, y, i * kDt, kDt) : eu.do_step(ode, y, i * kDt, kDt);
    const State<2> o = which ? simulate<Rk4>(c, spec).final : simulate<ExplicitEuler>(c, spec).final;
    for (int d = 0; d < 2; ++d) {
      EXPECT_NEAR(o.x[d], y[d], kRelTol * std::max(1.0, std::abs(y[d])));
      EXPECT_NEAR(o.v[d], y[2 + d], kRelTol * std::max(1.0, std::abs(y[2 + d])));
    }
  }
}

}  // namespace
}  // namespace steplab
