/* The stiff chain (core/scenes/chain.hpp, its defaults) by Hairer's RADAU5 called from plain C, no
 * steplab code: the reference the tests and `make bench` hold steplab's RADAU5 peer against
 * (bench/radau5_chain.c). */
#ifndef STEPLAB_BENCH_RADAU5_CHAIN_H
#define STEPLAB_BENCH_RADAU5_CHAIN_H
#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
  long steps, accepted, rejected, rhs, jacobians, decompositions, solves;
  int idid;
} radau5_chain_counts;

/* From the chain's start (both masses displaced by 1, at rest) to t_end at rtol = atol = tol, as
 * steplab's peer sets RADAU5 up (M1 = M2 = 2, analytic full Jacobian, its defaults otherwise);
 * z at t_end (x1, x2, v1, v2) into z_end when given. */
void radau5_chain_run(double tol, double t_end, radau5_chain_counts* out, double* z_end);

#ifdef __cplusplus
}
#endif
#endif
