// SUNDIALS CVODE as the studies call it (analysis/peers/peers.hpp): one run from z(0) to t_end with the
// caller's right side, analytic Jacobian and linear solver (dense, band or KLU), set up as
// CvodeSettings says, and every counter CVODE keeps read into Counts. Included by the peers'
// source files only: nothing else sees CVODE's headers.
#pragma once

#include <stdexcept>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

#include "analysis/peers/peers.hpp"

namespace steplab {

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

// CVODE on z' = rhs(z) from the run's z at t = 0, rtol = atol = tol, Newton on the run's linear
// solver with the analytic Jacobian `jac`, the family and options of `settings`; `scene` is the
// user data the callbacks read (CVODE takes a void*; they only read it). `advance(mem, t)` drives
// CVode from t = 0 to t_end (t its time, updated) and says whether every call succeeded. Counts
// into n (failed if CVODE stopped before t_end).
template <class Advance>
void cvode_run(CvodeRun& run, CVRhsFn rhs, CVLsJacFn jac, const void* scene, const CvodeSettings& settings, double tol,
               double t_end, PeerCounts& n, Advance&& advance) {
  N_Vector z = run.z;
  void* mem = CVodeCreate(settings.adams ? CV_ADAMS : CV_BDF, run.ctx);
  bool ok = CVodeInit(mem, rhs, 0.0, z) == CV_SUCCESS && CVodeSStolerances(mem, tol, tol) == CV_SUCCESS &&
            CVodeSetUserData(mem, const_cast<void*>(scene)) == CV_SUCCESS &&
            CVodeSetLinearSolver(mem, run.ls, run.J) == CV_SUCCESS && CVodeSetJacFn(mem, jac) == CV_SUCCESS &&
            CVodeSetMaxNumSteps(mem, 10'000'000) == CV_SUCCESS && CVodeSetStopTime(mem, t_end) == CV_SUCCESS;
  if (ok && settings.max_order > 0) ok = CVodeSetMaxOrd(mem, settings.max_order) == CV_SUCCESS;
  if (ok && settings.stability_limit_detection) ok = CVodeSetStabLimDet(mem, SUNTRUE) == CV_SUCCESS;
  double t = 0;
  ok = ok && advance(mem, t);
  long int steps = 0, error_fails = 0, solve_fails = 0, rhs_evals = 0, fd_rhs_evals = 0, jac_evals = 0, setups = 0, newton = 0;
  CVodeGetNumSteps(mem, &steps);
  CVodeGetNumErrTestFails(mem, &error_fails);
  CVodeGetNumStepSolveFails(mem, &solve_fails);
  CVodeGetNumRhsEvals(mem, &rhs_evals);
  CVodeGetNumLinRhsEvals(mem, &fd_rhs_evals);  // 0 with the analytic Jacobian
  CVodeGetNumJacEvals(mem, &jac_evals);
  CVodeGetNumLinSolvSetups(mem, &setups);
  CVodeGetNumNonlinSolvIters(mem, &newton);
  n = {};
  n.steps = steps, n.rejected = error_fails + solve_fails, n.forces = rhs_evals + fd_rhs_evals, n.jacobians = jac_evals;
  n.factorisations = setups, n.solves = newton, n.newton = newton;  // a direct solver: one solve per Newton iteration
  n.failed = !ok;
  CVodeFree(&mem);
}

// One step at a time to t_end (CV_ONE_STEP), `after_step(t)` after each; the run's z is left at
// t_end.
template <class AfterStep>
void cvode_solve(CvodeRun& run, CVRhsFn rhs, CVLsJacFn jac, const void* scene, const CvodeSettings& settings, double tol,
                 double t_end, PeerCounts& n, AfterStep&& after_step) {
  cvode_run(run, rhs, jac, scene, settings, tol, t_end, n, [&](void* mem, double& t) {
    while (t < t_end) {
      if (CVode(mem, t_end, run.z, &t, CV_ONE_STEP) < 0) return false;
      after_step(t);
    }
    return true;
  });
}

// Output at frames t_k = k t_end / frames, k = 1 .. frames, as CVODE's guide has it for output
// times (CV_NORMAL: it steps past t_k as its error control chooses and interpolates z(t_k) there;
// its steps nearly those of a run to t_end, its first step estimated from t_1); `at_frame(k)`
// with the run's z at t_k.
template <class AtFrame>
void cvode_solve_frames(CvodeRun& run, CVRhsFn rhs, CVLsJacFn jac, const void* scene, const CvodeSettings& settings,
                        double tol, double t_end, int frames, PeerCounts& n, AtFrame&& at_frame) {
  cvode_run(run, rhs, jac, scene, settings, tol, t_end, n, [&](void* mem, double& t) {
    for (int k = 1; k <= frames; ++k) {
      const double tout = frame_time(k, frames, t_end);
      if (CVode(mem, tout, run.z, &t, CV_NORMAL) < 0) return false;
      at_frame(k);
    }
    return true;
  });
}

}  // namespace steplab
