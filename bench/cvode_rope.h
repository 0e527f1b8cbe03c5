/* The rope of N masses by SUNDIALS CVODE in plain C (bench/cvode_rope.c). */
#ifndef STEPLAB_BENCH_CVODE_ROPE_H
#define STEPLAB_BENCH_CVODE_ROPE_H
#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
  int adams;            /* CV_ADAMS if nonzero, else CV_BDF */
  int max_order;        /* CVodeSetMaxOrd; 0: CVODE's default (12 Adams, 5 BDF) */
  int stab_lim_det;     /* CVodeSetStabLimDet */
  long setup_frequency; /* CVodeSetLSetupFrequency; 0: CVODE's default (20) */
  int fixed_point;      /* the nonlinear solver: fixed-point (functional) iteration, no Jacobian, if nonzero; else Newton */
} cvode_rope_settings;

typedef struct {
  long steps, error_test_fails, solve_fails, rhs, jacobians, setups, newton;
  int ok;
} cvode_rope_counts;

/* From the rope at rest (springs at rest length) to t_end at rtol = atol = tol; the heights at
 * t_end into y_end (n entries) when given. 0 on success. */
int cvode_rope_run(int n, double tol, double t_end, cvode_rope_settings s, cvode_rope_counts* out, double* y_end);

#ifdef __cplusplus
}
#endif
#endif
