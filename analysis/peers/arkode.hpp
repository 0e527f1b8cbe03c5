// SUNDIALS ARKODE as the studies call it (analysis/peers/peers.hpp), beside CVODE (cvode.hpp), on the
// same SUNDIALS objects (CvodeRun: context, state, Jacobian's matrix, linear solver):
//   ARKStep with a diagonally implicit table alone (z' = f_I(z), no explicit part): Newton on the
//     caller's analytic Jacobian and linear solver, as ARKODE's guide advises for stiff problems;
//     on a scene that is linear in its state (HasAffineFlow) it is told so (ARKStepSetLinear with
//     a Jacobian constant in time: one Newton iteration per stage, the matrix kept until gamma
//     changes), as the guide advises for linearly implicit problems;
//   ERKStep with an explicit table, no linear algebra.
// Everything else at ARKODE's defaults (its I controller family's default PID, the predictor of
// the stages' starts, the iteration matrix refreshed every 20 steps or when gamma changes by 20 %).
// Included by the peers' source files only.
#pragma once

#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_erkstep.h>

#include "analysis/peers/cvode.hpp"

namespace steplab {

// `advance(mem, t, step)` drives the stepper from t = 0 to t_end with `step(mem, tout, t, task)`
// (ARKStepEvolve or ERKStepEvolve); counts into n from ARKODE's counters.
template <class Advance>
void arkode_run(CvodeRun& run, ARKRhsFn rhs, ARKLsJacFn jac, const void* scene, const ArkodeSettings& settings, bool linear,
                double tol, double t_end, PeerCounts& n, Advance&& advance) {
  N_Vector z = run.z;
  void* user = const_cast<void*>(scene);
  double t = 0;
  n = {};
  long int steps = 0, attempts = 0, fe = 0, fi = 0, jac_evals = 0, setups = 0, newton = 0, fd_rhs = 0;
  if (settings.explicit_table) {
    void* mem = ERKStepCreate(rhs, 0.0, z, run.ctx);
    bool ok = ERKStepSStolerances(mem, tol, tol) == ARK_SUCCESS && ERKStepSetUserData(mem, user) == ARK_SUCCESS &&
              ERKStepSetTableNum(mem, static_cast<ARKODE_ERKTableID>(settings.table)) == ARK_SUCCESS &&
              ERKStepSetMaxNumSteps(mem, 10'000'000) == ARK_SUCCESS && ERKStepSetStopTime(mem, t_end) == ARK_SUCCESS;
    ok = ok && advance(mem, t, [](void* m, double tout, N_Vector y, double* tr, int task) {
           return ERKStepEvolve(m, tout, y, tr, task);
         });
    ERKStepGetNumSteps(mem, &steps);
    ERKStepGetNumStepAttempts(mem, &attempts);
    ERKStepGetNumRhsEvals(mem, &fe);
    n.failed = !ok;
    ERKStepFree(&mem);
  } else {
    void* mem = ARKStepCreate(nullptr, rhs, 0.0, z, run.ctx);
    bool ok = ARKStepSStolerances(mem, tol, tol) == ARK_SUCCESS && ARKStepSetUserData(mem, user) == ARK_SUCCESS &&
              ARKStepSetTableNum(mem, static_cast<ARKODE_DIRKTableID>(settings.table), ARKODE_ERK_NONE) == ARK_SUCCESS &&
              ARKStepSetLinearSolver(mem, run.ls, run.J) == ARK_SUCCESS && ARKStepSetJacFn(mem, jac) == ARK_SUCCESS &&
              ARKStepSetMaxNumSteps(mem, 10'000'000) == ARK_SUCCESS && ARKStepSetStopTime(mem, t_end) == ARK_SUCCESS;
    if (ok && linear) ok = ARKStepSetLinear(mem, 0) == ARK_SUCCESS;
    ok = ok && advance(mem, t, [](void* m, double tout, N_Vector y, double* tr, int task) {
           return ARKStepEvolve(m, tout, y, tr, task);
         });
    ARKStepGetNumSteps(mem, &steps);
    ARKStepGetNumStepAttempts(mem, &attempts);
    ARKStepGetNumRhsEvals(mem, &fe, &fi);
    ARKStepGetNumLinRhsEvals(mem, &fd_rhs);  // 0 with the analytic Jacobian
    ARKStepGetNumJacEvals(mem, &jac_evals);
    ARKStepGetNumLinSolvSetups(mem, &setups);
    ARKStepGetNumNonlinSolvIters(mem, &newton);
    n.failed = !ok;
    ARKStepFree(&mem);
  }
  n.steps = steps, n.rejected = attempts - steps, n.forces = fe + fi + fd_rhs, n.jacobians = jac_evals;
  n.factorisations = setups, n.solves = newton, n.newton = newton;  // a direct solver: one solve per Newton iteration
}

// One step at a time to t_end (ARK_ONE_STEP), `after_step(t)` after each.
template <class AfterStep>
void arkode_solve(CvodeRun& run, ARKRhsFn rhs, ARKLsJacFn jac, const void* scene, const ArkodeSettings& settings,
                  bool linear, double tol, double t_end, PeerCounts& n, AfterStep&& after_step) {
  arkode_run(run, rhs, jac, scene, settings, linear, tol, t_end, n, [&](void* mem, double& t, auto step) {
    while (t < t_end) {
      if (step(mem, t_end, run.z, &t, ARK_ONE_STEP) < 0) return false;
      after_step(t);
    }
    return true;
  });
}

// Output at frames t_k = k t_end / frames (ARK_NORMAL: ARKODE steps past t_k and gives z(t_k) by
// its Hermite interpolation, as its guide has it for output times); `at_frame(k)` with z at t_k.
template <class AtFrame>
void arkode_solve_frames(CvodeRun& run, ARKRhsFn rhs, ARKLsJacFn jac, const void* scene, const ArkodeSettings& settings,
                         bool linear, double tol, double t_end, int frames, PeerCounts& n, AtFrame&& at_frame) {
  arkode_run(run, rhs, jac, scene, settings, linear, tol, t_end, n, [&](void* mem, double& t, auto step) {
    for (int k = 1; k <= frames; ++k) {
      const double tout = frame_time(k, frames, t_end);
      if (step(mem, tout, run.z, &t, ARK_NORMAL) < 0) return false;
      at_frame(k);
    }
    return true;
  });
}

}  // namespace steplab
