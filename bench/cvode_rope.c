/* The rope of N masses (core/scenes/rope.hpp) integrated by SUNDIALS CVODE in plain C, as a user of
 * CVODE would write it from its documentation: no steplab code, no C++. `make bench` times it
 * beside steplab's own CVODE peer on the same rope with the same settings (bench/peers_bench.cpp):
 * the two must take the same steps and evaluations, and their times show what steplab's wrapper
 * costs. Built also as the program `cvode_rope` (CVODE_ROPE_MAIN) to try CVODE's settings:
 *
 *   cvode_rope N TOL adams|bdf|adams_fixed_point [MAXORD [STLDET [MSBP]]]
 *
 * (adams_fixed_point: Adams with fixed-point iteration, SUNDIALS' advice for non-stiff problems,
 * in place of Newton on the banded Jacobian)
 * prints the counts and the run time (the minimum of repeats, at least 0.1 s in all).
 *
 * The rope (totals M, K, L, gamma; the defaults of steplab's rope, no dashpot): m = M/N, k = K N,
 * l = L/N, c = gamma/N; heights y_i, y_0 = v_0 = 0 the anchor,
 *   T_i = k ((y_{i-1} - y_i) - l),  T_{N+1} = 0,   m y_i'' = T_i - T_{i+1} - c v_i - m g.
 * The state interleaved, z = (y_1, v_1, y_2, v_2, ...): the Jacobian is banded, upper bandwidth 2
 * (row 2i: y_i' = v_i), lower 3 (row 2i+1: v_i' reaches y_{i-1} .. v_{i+1}). */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include "cvode_rope.h"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_band.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>
#include <sunmatrix/sunmatrix_band.h>

typedef struct {
  int n;
  double m, k, l, c, weight, inv_m;
} rope;

static int rhs(sunrealtype t, N_Vector z, N_Vector dz, void* data) {
  const rope* r = (const rope*)data;
  const double* y = N_VGetArrayPointer(z);
  double* d = N_VGetArrayPointer(dz);
  double above = r->k * ((0 - y[0]) - r->l);
  (void)t;
  for (int i = 0; i < r->n; ++i) {
    const double below = i + 1 < r->n ? r->k * ((y[2 * i] - y[2 * i + 2]) - r->l) : 0;
    d[2 * i] = y[2 * i + 1];
    d[2 * i + 1] = ((above - below) - r->c * y[2 * i + 1] - r->weight) * r->inv_m;
    above = below;
  }
  return 0;
}

static int jacobian(sunrealtype t, N_Vector z, N_Vector fz, SUNMatrix J, void* data, N_Vector t1, N_Vector t2, N_Vector t3) {
  const rope* r = (const rope*)data;
  (void)t, (void)z, (void)fz, (void)t1, (void)t2, (void)t3;
  SUNMatZero(J);
  for (int i = 0; i < r->n; ++i) {
    SM_ELEMENT_B(J, 2 * i, 2 * i + 1) = 1;
    SM_ELEMENT_B(J, 2 * i + 1, 2 * i) = r->inv_m * (-r->k * (i + 1 < r->n ? 2 : 1));
    SM_ELEMENT_B(J, 2 * i + 1, 2 * i + 1) = r->inv_m * -r->c;
    if (i > 0) SM_ELEMENT_B(J, 2 * i + 1, 2 * i - 2) = r->inv_m * r->k;
    if (i + 1 < r->n) SM_ELEMENT_B(J, 2 * i + 1, 2 * i + 2) = r->inv_m * r->k;
  }
  return 0;
}

int cvode_rope_run(int n, double tol, double t_end, cvode_rope_settings s, cvode_rope_counts* out, double* y_end) {
  rope r = {n, 1.0 / n, 5.0 * n, 5.0 / n, 0.1 / n, 0, 0};
  r.weight = r.m * 9.81, r.inv_m = 1 / r.m;
  SUNContext ctx;
  if (SUNContext_Create(NULL, &ctx) != 0) return -1;
  N_Vector z = N_VNew_Serial(2 * n, ctx);
  double* y = N_VGetArrayPointer(z);
  for (int i = 0; i < n; ++i) y[2 * i] = -(i + 1) * r.l, y[2 * i + 1] = 0;  /* at rest, springs at rest length */
  SUNMatrix J = s.fixed_point ? NULL : SUNBandMatrix(2 * n, 2, 3, ctx);
  SUNLinearSolver ls = s.fixed_point ? NULL : SUNLinSol_Band(z, J, ctx);
  SUNNonlinearSolver fp = s.fixed_point ? SUNNonlinSol_FixedPoint(z, 0, ctx) : NULL;
  void* mem = CVodeCreate(s.adams ? CV_ADAMS : CV_BDF, ctx);
  int ok = CVodeInit(mem, rhs, 0.0, z) == CV_SUCCESS && CVodeSStolerances(mem, tol, tol) == CV_SUCCESS &&
           CVodeSetUserData(mem, &r) == CV_SUCCESS && CVodeSetMaxNumSteps(mem, 10000000) == CV_SUCCESS &&
           CVodeSetStopTime(mem, t_end) == CV_SUCCESS;
  if (ok && s.fixed_point) ok = CVodeSetNonlinearSolver(mem, fp) == CV_SUCCESS;
  else if (ok) ok = CVodeSetLinearSolver(mem, ls, J) == CV_SUCCESS && CVodeSetJacFn(mem, jacobian) == CV_SUCCESS;
  if (ok && s.max_order > 0) ok = CVodeSetMaxOrd(mem, s.max_order) == CV_SUCCESS;
  if (ok && s.stab_lim_det) ok = CVodeSetStabLimDet(mem, SUNTRUE) == CV_SUCCESS;
  if (ok && s.setup_frequency > 0) ok = CVodeSetLSetupFrequency(mem, s.setup_frequency) == CV_SUCCESS;
  double t = 0;
  while (ok && t < t_end) ok = CVode(mem, t_end, z, &t, CV_ONE_STEP) >= 0;
  long v[8] = {0};
  CVodeGetNumSteps(mem, &v[0]);
  CVodeGetNumErrTestFails(mem, &v[1]);
  CVodeGetNumStepSolveFails(mem, &v[2]);
  CVodeGetNumRhsEvals(mem, &v[3]);
  if (!s.fixed_point) CVodeGetNumJacEvals(mem, &v[4]), CVodeGetNumLinSolvSetups(mem, &v[5]);
  CVodeGetNumNonlinSolvIters(mem, &v[6]);
  if (out) {
    out->steps = v[0], out->error_test_fails = v[1], out->solve_fails = v[2], out->rhs = v[3];
    out->jacobians = v[4], out->setups = v[5], out->newton = v[6], out->ok = ok;
  }
  if (y_end)
    for (int i = 0; i < n; ++i) y_end[i] = y[2 * i];
  CVodeFree(&mem);
  if (fp) SUNNonlinSolFree(fp);
  if (ls) SUNLinSolFree(ls);
  if (J) SUNMatDestroy(J);
  N_VDestroy(z);
  SUNContext_Free(&ctx);
  return ok ? 0 : -1;
}

#ifdef CVODE_ROPE_MAIN
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

int main(int argc, char** argv) {
  const int fixed_point = argc >= 4 && strcmp(argv[3], "adams_fixed_point") == 0;
  if (argc < 4 || (strcmp(argv[3], "adams") != 0 && strcmp(argv[3], "bdf") != 0 && !fixed_point)) {
    fprintf(stderr, "usage: cvode_rope N TOL adams|bdf|adams_fixed_point [MAXORD [STLDET [MSBP]]]\n");
    return 2;
  }
  const int n = atoi(argv[1]);
  const double tol = atof(argv[2]);
  cvode_rope_settings s = {strcmp(argv[3], "bdf") != 0, argc > 4 ? atoi(argv[4]) : 0, argc > 5 ? atoi(argv[5]) : 0,
                           argc > 6 ? atol(argv[6]) : 0, fixed_point};
  cvode_rope_counts c;
  double best = 1e300, total = 0;
  int runs = 0;
  while (runs < 1 || total < 0.1) {
    const double t0 = now();
    cvode_rope_run(n, tol, 2.0, s, &c, NULL);
    const double dt = now() - t0;
    best = dt < best ? dt : best, total += dt, ++runs;
  }
  printf("steps %ld rejected %ld rhs %ld jacobians %ld setups %ld newton %ld ok %d seconds %.6g runs %d\n", c.steps,
         c.error_test_fails + c.solve_fails, c.rhs, c.jacobians, c.setups, c.newton, c.ok, best, runs);
  return c.ok ? 0 : 1;
}
#endif
