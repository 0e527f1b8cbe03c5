// The solvers users would pick instead of steplab's, run on steplab's scenes for the
// work-precision study (analysis/work_precision.cpp), each on the scene's first-order system
// z = (x, v), z' = (v, M^-1 F(x, v)):
//   Boost.Odeint's controlled runge_kutta_dopri5 (explicit, order 5(4), odeint's own controller
//     and its max norm of the error over rtol |z| + atol);
//   SUNDIALS CVODE (Debian's libsundials-dev, 6.4): variable-order (1..5) variable-step BDF, Newton
//     with a dense LU and the scene's analytic Jacobian, weighted RMS norm of rtol |z| + atol; its
//     other settings left at their defaults, as a user would (stability limit detection off: on,
//     it cut the chain's steps at loose tolerances but not at 1e-6 and below; a maximum order of 2
//     made every tolerance dearer).
// Both at rtol = atol = tol. A run returns its end state and counts its accepted steps and right
// side evaluations (CVODE also its Jacobian evaluations); `error_max`, when given, receives the
// largest position error against the exact solution at the accepted steps (the measure steplab's
// own runs use), and is left out of a timed run.
#pragma once

#include <array>
#include <stdexcept>

#include <boost/numeric/odeint.hpp>
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include "core/scene.hpp"

namespace steplab {

struct PeerCounts {
  long long steps = 0, evaluations = 0, jacobian_evaluations = 0;
  bool failed = false;
};

template <HasExact S> struct OdeintDopri5 {
  using Z = std::array<double, 2 * S::dim>;
  static State<S::dim> run(const S& s, double tol, double t_end, PeerCounts& n, double* error_max = nullptr) {
    constexpr int D = S::dim;
    const State<D> y0 = s.initial();
    Z z{};
    for (int i = 0; i < D; ++i) z[i] = y0.x[i], z[D + i] = y0.v[i];
    n = {};
    const auto rhs = [&](const Z& a, Z& da, double) {
      ++n.evaluations;
      const Vec<D> x = Eigen::Map<const Vec<D>>(a.data()), v = Eigen::Map<const Vec<D>>(a.data() + D);
      const Vec<D> acc = acceleration(s, x, v);
      for (int i = 0; i < D; ++i) da[i] = v[i], da[D + i] = acc[i];
    };
    namespace odeint = boost::numeric::odeint;
    odeint::integrate_adaptive(odeint::make_controlled(tol, tol, odeint::runge_kutta_dopri5<Z>()), rhs, z, 0.0, t_end,
                               1e-6 * t_end, [&](const Z& a, double t) {
                                 n.steps += t > 0;
                                 if (error_max) {
                                   const double e = (Eigen::Map<const Vec<D>>(a.data()) - exact(s, t).x).norm();
                                   *error_max = std::max(*error_max, e);
                                 }
                               });
    return {Eigen::Map<const Vec<D>>(z.data()), Eigen::Map<const Vec<D>>(z.data() + D)};
  }
};

// What one CVODE run owns: its context, the state z of `size` entries and, set by the caller
// (dense, banded or sparse), the Jacobian's matrix J and the linear solver on it; freed in reverse
// order however the run ends.
struct CvodeRun {
  SUNContext ctx = nullptr;
  N_Vector z = nullptr;
  SUNMatrix J = nullptr;
  SUNLinearSolver ls = nullptr;

  explicit CvodeRun(sunindextype size) {
    if (SUNContext_Create(nullptr, &ctx) != 0) throw std::runtime_error("CVODE: no context");
    z = N_VNew_Serial(size, ctx);
  }
  ~CvodeRun() {
    if (ls) SUNLinSolFree(ls);
    if (J) SUNMatDestroy(J);
    if (z) N_VDestroy(z);
    SUNContext_Free(&ctx);
  }
  CvodeRun(const CvodeRun&) = delete;
  CvodeRun& operator=(const CvodeRun&) = delete;
  double* data() const { return N_VGetArrayPointer(z); }
};

// CVODE's BDF on z' = rhs(z) from the run's z at t = 0 (overwritten with the state at t_end), rtol
// = atol = tol, Newton on its linear solver with the analytic Jacobian `jac`; `scene` is the user
// data the callbacks read (CVODE takes a void*; they only read it). `after_step(t)` after every
// internal step. Counts into n (failed if CVODE stopped before t_end).
template <class AfterStep>
void cvode_bdf(CvodeRun& run, CVRhsFn rhs, CVLsJacFn jac, const void* scene, double tol, double t_end, PeerCounts& n,
               AfterStep&& after_step) {
  N_Vector z = run.z;
  void* mem = CVodeCreate(CV_BDF, run.ctx);
  bool ok = CVodeInit(mem, rhs, 0.0, z) == CV_SUCCESS && CVodeSStolerances(mem, tol, tol) == CV_SUCCESS &&
            CVodeSetUserData(mem, const_cast<void*>(scene)) == CV_SUCCESS &&
            CVodeSetLinearSolver(mem, run.ls, run.J) == CV_SUCCESS &&
            CVodeSetJacFn(mem, jac) == CV_SUCCESS && CVodeSetMaxNumSteps(mem, 10'000'000) == CV_SUCCESS &&
            CVodeSetStopTime(mem, t_end) == CV_SUCCESS;
  double t = 0;
  while (ok && t < t_end) {
    ok = CVode(mem, t_end, z, &t, CV_ONE_STEP) >= 0;
    if (ok) after_step(t);
  }
  long int steps = 0, fevals = 0, jevals = 0;
  CVodeGetNumSteps(mem, &steps);
  CVodeGetNumRhsEvals(mem, &fevals);
  CVodeGetNumJacEvals(mem, &jevals);
  n = {steps, fevals, jevals, !ok};
  CVodeFree(&mem);
}

template <HasExact S> struct CvodeBdf {
  static constexpr int D = S::dim;

  // z' = f(z): the velocities, then the accelerations.
  static int rhs(sunrealtype, N_Vector z, N_Vector dz, void* scene) {
    const S& s = *static_cast<const S*>(scene);
    const double* a = N_VGetArrayPointer(z);
    double* da = N_VGetArrayPointer(dz);
    const Vec<D> x = Eigen::Map<const Vec<D>>(a), v = Eigen::Map<const Vec<D>>(a + D);
    const Vec<D> acc = acceleration(s, x, v);
    for (int i = 0; i < D; ++i) da[i] = v[i], da[D + i] = acc[i];
    return 0;
  }

  // df/dz = [[0, I], [M^-1 dF/dx, M^-1 dF/dv]] (column-major dense matrix).
  static int jacobian(sunrealtype, N_Vector z, N_Vector, SUNMatrix J, void* scene, N_Vector, N_Vector, N_Vector) {
    const S& s = *static_cast<const S*>(scene);
    const double* a = N_VGetArrayPointer(z);
    const Vec<D> x = Eigen::Map<const Vec<D>>(a), v = Eigen::Map<const Vec<D>>(a + D);
    const Jacobians<D> j = s.jacobians(x, v);
    const Vec<D> w = s.inverse_mass();
    Eigen::Map<Eigen::Matrix<double, 2 * D, 2 * D>> m(SUNDenseMatrix_Data(J));
    m.setZero();
    m.template topRightCorner<D, D>().setIdentity();
    m.template bottomLeftCorner<D, D>() = w.asDiagonal() * j.dx;
    m.template bottomRightCorner<D, D>() = w.asDiagonal() * j.dv;
    return 0;
  }

  static State<D> run(const S& s, double tol, double t_end, PeerCounts& n, double* error_max = nullptr) {
    CvodeRun c(2 * D);
    const State<D> y0 = s.initial();
    double* a = c.data();
    for (int i = 0; i < D; ++i) a[i] = y0.x[i], a[D + i] = y0.v[i];
    c.J = SUNDenseMatrix(2 * D, 2 * D, c.ctx);
    c.ls = SUNLinSol_Dense(c.z, c.J, c.ctx);
    cvode_bdf(c, rhs, jacobian, &s, tol, t_end, n, [&](double t) {
      if (error_max) *error_max = std::max(*error_max, (Eigen::Map<const Vec<D>>(a) - exact(s, t).x).norm());
    });
    return {Eigen::Map<const Vec<D>>(a), Eigen::Map<const Vec<D>>(a + D)};
  }
};

}  // namespace steplab
