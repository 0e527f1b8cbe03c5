/* The stiff chain by RADAU5 from plain C (radau5_chain.h): M u'' = -K u - C u', z = (u, u'),
 * m1 = m2 = 1, k1 = 5, k2 = 5e4, c1 = 0.1, c2 = 10, u(0) = (1, 1), u'(0) = 0. With
 * RADAU5_CHAIN_MAIN a program: radau5_chain [tol [t_end]] prints the counts, the end state and
 * the time of one run. */
#include "radau5_chain.h"

#include <string.h>

static const double k1 = 5, k2 = 5e4, c1 = 0.1, c2 = 10;

static void fcn(const int* n, const double* t, const double* z, double* dz, const double* rpar, const int* ipar) {
  (void)n, (void)t, (void)rpar, (void)ipar;
  dz[0] = z[2];
  dz[1] = z[3];
  /* grouped as -(K u) - (C u'), as the scene computes it: the same bits */
  dz[2] = -((k1 + k2) * z[0] + -k2 * z[1]) - ((c1 + c2) * z[2] + -c2 * z[3]);
  dz[3] = -(-k2 * z[0] + k2 * z[1]) - (-c2 * z[2] + c2 * z[3]);
}

/* The non-trivial rows (M1 = 2): dfy(i, j) = d(u''_i)/dz_j, column-major, leading dimension ld. */
static void jac(const int* n, const double* t, const double* z, const int* ml, const int* mu, double* dfy, const int* ld,
                const double* rpar, const int* ipar) {
  (void)n, (void)t, (void)z, (void)ml, (void)mu, (void)rpar, (void)ipar;
  const int l = *ld;
  dfy[0 + 0 * l] = -(k1 + k2), dfy[1 + 0 * l] = k2;
  dfy[0 + 1 * l] = k2, dfy[1 + 1 * l] = -k2;
  dfy[0 + 2 * l] = -(c1 + c2), dfy[1 + 2 * l] = c2;
  dfy[0 + 3 * l] = c2, dfy[1 + 3 * l] = -c2;
}

static void mas(const int* n, double* am, const int* lmas, const double* rpar, const int* ipar) {
  (void)n, (void)am, (void)lmas, (void)rpar, (void)ipar;
}
static void solout(const int* nr, const double* xold, const double* x, const double* y, const double* cont, const int* lrc,
                   const int* n, const double* rpar, const int* ipar, int* irtrn) {
  (void)nr, (void)xold, (void)x, (void)y, (void)cont, (void)lrc, (void)n, (void)rpar, (void)ipar;
  *irtrn = 0;
}

void radau5_(const int* n, void* fcn, double* x, double* y, const double* xend, double* h, double* rtol, double* atol,
             const int* itol, void* jac, const int* ijac, const int* mljac, const int* mujac, void* mas, const int* imas,
             const int* mlmas, const int* mumas, void* solout, const int* iout, double* work, const int* lwork, int* iwork,
             const int* liwork, double* rpar, int* ipar, int* idid);

/* deSolve's RADAU5 prints through R; outside R, silent (steplab's peer defines the same). */
__attribute__((weak)) void rprintf_(void) {}
__attribute__((weak)) void rprintfd1_(void) {}
__attribute__((weak)) void rprintfd2_(void) {}
__attribute__((weak)) void rprintfi1_(void) {}
__attribute__((weak)) void rprintfi2_(void) {}
__attribute__((weak)) void rprintfi3_(void) {}

void radau5_chain_run(double tol, double t_end, radau5_chain_counts* out, double* z_end) {
  enum { N = 4, M1 = 2, LWORK = N * (M1 + 12) + M1 * 3 * M1 + 20, LIWORK = 3 * N + 20 };
  double work[LWORK], z[N] = {1, 1, 0, 0}, t = 0, h = 0, rtol = tol, atol = tol, rpar = 0;
  int iwork[LIWORK], n = N, itol = 0, ijac = 1, ml = M1, mu = M1, imas = 0, zero = 0, iout = 0, lwork = LWORK,
      liwork = LIWORK, ipar = 0, idid = 0;
  memset(work, 0, sizeof work);
  memset(iwork, 0, sizeof iwork);
  iwork[1] = 10000000;
  iwork[8] = M1;
  iwork[9] = M1;
  radau5_(&n, (void*)fcn, &t, z, &t_end, &h, &rtol, &atol, &itol, (void*)jac, &ijac, &ml, &mu, (void*)mas, &imas, &zero,
          &zero, (void*)solout, &iout, work, &lwork, iwork, &liwork, &rpar, &ipar, &idid);
  out->steps = iwork[15], out->accepted = iwork[16], out->rejected = iwork[17], out->rhs = iwork[13];
  out->jacobians = iwork[14], out->decompositions = iwork[18], out->solves = iwork[19], out->idid = idid;
  if (z_end) memcpy(z_end, z, sizeof z);
}

#ifdef RADAU5_CHAIN_MAIN
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

int main(int argc, char** argv) {
  const double tol = argc > 1 ? atof(argv[1]) : 1e-6, t_end = argc > 2 ? atof(argv[2]) : 10;
  radau5_chain_counts c;
  double z[4];
  struct timespec a, b;
  clock_gettime(CLOCK_MONOTONIC, &a);
  radau5_chain_run(tol, t_end, &c, z);
  clock_gettime(CLOCK_MONOTONIC, &b);
  printf("RADAU5 on the chain, tol %g, t_end %g: idid %d, %ld steps (%ld accepted, %ld rejected), %ld evaluations, "
         "%ld Jacobians, %ld decompositions, %ld solves; u = (%.17g, %.17g); %.1f us\n",
         tol, t_end, c.idid, c.steps, c.accepted, c.rejected, c.rhs, c.jacobians, c.decompositions, c.solves, z[0], z[1],
         ((double)(b.tv_sec - a.tv_sec) * 1e9 + (double)(b.tv_nsec - a.tv_nsec)) / 1e3);
  return c.idid < 0;
}
#endif
