// The peers (analysis/peers/peers.hpp) on a scene of fixed size S, over its first-order system of 2
// S::dim entries: Boost.Odeint's controlled dopri5 on a std::array; CVODE and ARKODE with a dense
// matrix (SundialsDense); RADAU5 with its full Jacobian of the second-order structure.
// Instantiated in analysis/peers/peers.cpp (and by the tests that check a peer's Jacobian).
#pragma once

#include <algorithm>
#include <array>
#include <limits>

#include <boost/numeric/odeint.hpp>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include "analysis/peers/arkode.hpp"
#include "analysis/peers/cvode.hpp"
#include "analysis/peers/radau5.hpp"
#include "core/scene.hpp"

namespace steplab {

// odeint's integrate_adaptive for a controlled stepper (integrate/detail/integrate_adaptive.hpp),
// written out so that the rejected tries are counted: the same steps (on while t_end - t exceeds
// the machine epsilon, t + dt clipped to t_end, try_step until it succeeds, at most 500 failed
// tries in a row as its failed_step_checker allows).
template <class Stepper, class System, class Z, class AfterStep>
void odeint_adaptive(Stepper&& stepper, System&& system, Z& z, double t_end, double dt, PeerCounts& n, AfterStep&& after_step) {
  namespace odeint = boost::numeric::odeint;
  constexpr double eps = std::numeric_limits<double>::epsilon();
  double t = 0;
  while (t_end - t > eps) {
    if ((t + dt) - t_end > eps) dt = t_end - t;
    int fails = 0;
    while (stepper.try_step(system, z, t, dt) == odeint::fail)
      if (++n.rejected, ++fails == 500) {
        n.failed = true;
        return;
      }
    ++n.steps;
    after_step(z, t);
  }
}

// odeint's integrate_times for a controlled stepper (integrate/detail/integrate_times.hpp),
// written out for the same reason: to each t_k = k t_end / frames in turn, k = 1 .. frames, the
// step clipped to end there and the unclipped step kept for the next one (dt = max(dt, the
// clipped step) after a success, the failed try's step after a failure); `at_frame(z, k)` at each.
template <class Stepper, class System, class Z, class AtFrame>
void odeint_times(Stepper&& stepper, System&& system, Z& z, double t_end, int frames, double dt, PeerCounts& n,
                  AtFrame&& at_frame) {
  namespace odeint = boost::numeric::odeint;
  constexpr double eps = std::numeric_limits<double>::epsilon();
  double t = 0;
  for (int k = 1; k <= frames; ++k) {
    const double tk = frame_time(k, frames, t_end);
    int fails = 0;
    while (tk - t > eps) {
      double step = std::min(dt, tk - t);
      if (stepper.try_step(system, z, t, step) == odeint::success) {
        ++n.steps, fails = 0;
        dt = std::max(dt, step);
      } else {
        ++n.rejected, dt = step;
        if (++fails == 500) {
          n.failed = true;
          return;
        }
      }
    }
    at_frame(z, k);
  }
}

template <Scene S> struct OdeintDopri5 {
  static constexpr int D = S::dim;
  using Z = std::array<double, 2 * D>;
  static State<D> run(const S& s, double tol, double t_end, PeerCounts& n, double* error_max = nullptr) {
    const State<D> y0 = s.initial();
    Z z{};
    for (int i = 0; i < D; ++i) z[i] = y0.x[i], z[D + i] = y0.v[i];
    n = {};
    const auto rhs = [&](const Z& a, Z& da, double t) {
      ++n.forces;
      const Vec<D> x = Eigen::Map<const Vec<D>>(a.data()), v = Eigen::Map<const Vec<D>>(a.data() + D);
      const Vec<D> acc = acceleration(s, t, x, v);
      for (int i = 0; i < D; ++i) da[i] = v[i], da[D + i] = acc[i];
    };
    namespace odeint = boost::numeric::odeint;
    odeint_adaptive(odeint::make_controlled(tol, tol, odeint::runge_kutta_dopri5<Z>()), rhs, z, t_end, 1e-6 * t_end, n,
                    [&](const Z& a, double t) {
                      if (error_max)
                        *error_max = std::max(*error_max, (Eigen::Map<const Vec<D>>(a.data()) - exact(s, t).x).norm());
                    });
    return {Eigen::Map<const Vec<D>>(z.data()), Eigen::Map<const Vec<D>>(z.data() + D)};
  }
};

// A scene of fixed size S as a first-order system z = (x, v) of 2 S::dim entries, for every
// peer's callbacks (CVODE's and ARKODE's, RADAU5's).
template <Scene S> struct FirstOrder {
  static constexpr int D = S::dim;
  // z' = f(z): the velocities, then the accelerations.
  static void derivative(const S& s, double t, const double* z, double* dz) {
    const Vec<D> x = Eigen::Map<const Vec<D>>(z), v = Eigen::Map<const Vec<D>>(z + D);
    const Vec<D> acc = acceleration(s, t, x, v);
    for (int i = 0; i < D; ++i) dz[i] = v[i], dz[D + i] = acc[i];
  }
  // The Jacobian's non-trivial rows, [M^-1 dF/dx, M^-1 dF/dv] (D x 2D), column-major with leading
  // dimension ld (x' = v's rows, [0, I], are the caller's).
  static void acceleration_rows(const S& s, double t, const double* z, double* rows, int ld) {
    const Vec<D> x = Eigen::Map<const Vec<D>>(z), v = Eigen::Map<const Vec<D>>(z + D);
    const Jacobians<D> j = jacobians_at(s, t, x, v);
    const Vec<D> w = s.inverse_mass();
    // entry by entry: an Eigen map with an outer stride would take a 1 x 2 block (D = 1) for a
    // vector and ignore the stride
    for (int c = 0; c < D; ++c)
      for (int r = 0; r < D; ++r) rows[r + c * ld] = w[r] * j.dx(r, c), rows[r + (c + D) * ld] = w[r] * j.dv(r, c);
  }
};

template <Scene S> struct SundialsDense {
  static constexpr int D = S::dim;

  static int rhs(sunrealtype t, N_Vector z, N_Vector dz, void* scene) {
    FirstOrder<S>::derivative(*static_cast<const S*>(scene), t, N_VGetArrayPointer(z), N_VGetArrayPointer(dz));
    return 0;
  }

  // df/dz = [[0, I], [M^-1 dF/dx, M^-1 dF/dv]] (column-major dense matrix).
  static int jacobian(sunrealtype t, N_Vector z, N_Vector, SUNMatrix J, void* scene, N_Vector, N_Vector, N_Vector) {
    Eigen::Map<Eigen::Matrix<double, 2 * D, 2 * D>> m(SUNDenseMatrix_Data(J));
    m.setZero();
    m.template topRightCorner<D, D>().setIdentity();
    FirstOrder<S>::acceleration_rows(*static_cast<const S*>(scene), t, N_VGetArrayPointer(z), SUNDenseMatrix_Data(J) + D, 2 * D);
    return 0;
  }

  // CVODE or ARKODE, as the peer is (their callbacks have one signature); ARKODE told the scene is
  // linear where it is (HasAffineFlow).
  static State<D> run(const S& s, const PeerInfo& peer, double tol, double t_end, PeerCounts& n, double* error_max = nullptr) {
    CvodeRun c(2 * D);
    const State<D> y0 = s.initial();
    double* a = c.data();
    for (int i = 0; i < D; ++i) a[i] = y0.x[i], a[D + i] = y0.v[i];
    if (peer.implicit) {
      c.J = SUNDenseMatrix(2 * D, 2 * D, c.ctx);
      c.ls = SUNLinSol_Dense(c.z, c.J, c.ctx);
    }
    const auto after_step = [&](double t) {
      if (error_max) *error_max = std::max(*error_max, (Eigen::Map<const Vec<D>>(a) - exact(s, t).x).norm());
    };
    if (peer.is_arkode()) arkode_solve(c, rhs, jacobian, &s, peer.arkode, HasAffineFlow<S>, tol, t_end, n, after_step);
    else cvode_solve(c, rhs, jacobian, &s, peer.cvode, tol, t_end, n, after_step);
    return {Eigen::Map<const Vec<D>>(a), Eigen::Map<const Vec<D>>(a + D)};
  }
};

// RADAU5 with M1 = M2 = D (x' = v eliminated) and its D x 2D Jacobian [M^-1 dF/dx, M^-1 dF/dv].
template <Scene S> struct Radau5Fixed {
  static constexpr int D = S::dim;
  static void rhs(const void* scene, double t, const double* z, double* dz) {
    FirstOrder<S>::derivative(*static_cast<const S*>(scene), t, z, dz);
  }
  static void jacobian(const void* scene, double t, const double* z, double* dfy, int ld) {
    FirstOrder<S>::acceleration_rows(*static_cast<const S*>(scene), t, z, dfy, ld);
  }
  static State<D> run(const S& s, double tol, double t_end, PeerCounts& n, double* error_max = nullptr) {
    const State<D> y0 = s.initial();
    std::array<double, 2 * D> z{};
    for (int i = 0; i < D; ++i) z[i] = y0.x[i], z[D + i] = y0.v[i];
    const Radau5Problem p{2 * D, -1, &s, rhs, jacobian};
    std::function<void(const Radau5Step&)> after;
    if (error_max)
      after = [&](const Radau5Step& step) {
        *error_max = std::max(*error_max, (Eigen::Map<const Vec<D>>(step.z.data()) - exact(s, step.t).x).norm());
      };
    radau5_solve(p, z.data(), tol, t_end, n, after);
    return {Eigen::Map<const Vec<D>>(z.data()), Eigen::Map<const Vec<D>>(z.data() + D)};
  }
};

}  // namespace steplab
