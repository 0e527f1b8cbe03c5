#include "analysis/peers/radau5.hpp"

#include <algorithm>
#include <mutex>
#include <stdexcept>
#include <vector>

namespace steplab {

#if STEPLAB_HAVE_RADAU5
namespace {

// What the callbacks read, handed through RADAU5's RPAR (which it passes on untouched).
struct Call {
  const Radau5Problem* problem;
  const std::function<void(const Radau5Step&)>* after_step;
};
const Call& call_of(const double* rpar) { return *reinterpret_cast<const Call*>(rpar); }

extern "C" {
using Fcn = void (*)(const int*, const double*, const double*, double*, const double*, const int*);
using Jac = void (*)(const int*, const double*, const double*, const int*, const int*, double*, const int*, const double*,
                     const int*);
using Mas = void (*)(const int*, double*, const int*, const double*, const int*);
using Solout = void (*)(const int*, const double*, const double*, const double*, const double*, const int*, const int*,
                        const double*, const int*, int*);
void radau5_(const int* n, Fcn fcn, double* x, double* y, const double* xend, double* h, double* rtol, double* atol,
             const int* itol, Jac jac, const int* ijac, const int* mljac, const int* mujac, Mas mas, const int* imas,
             const int* mlmas, const int* mumas, Solout solout, const int* iout, double* work, const int* lwork, int* iwork,
             const int* liwork, double* rpar, int* ipar, int* idid);

void fcn(const int*, const double* t, const double* z, double* dz, const double* rpar, const int*) {
  const Radau5Problem& p = *call_of(rpar).problem;
  p.f(p.context, *t, z, dz);
}
// deSolve's RADAU5 passes the bandwidths too: JAC(N, X, Y, MLJAC, MUJAC, DFY, LDFY, RPAR, IPAR).
void jac(const int*, const double* t, const double* z, const int*, const int*, double* dfy, const int* ld,
         const double* rpar, const int*) {
  const Radau5Problem& p = *call_of(rpar).problem;
  p.jacobian(p.context, *t, z, dfy, *ld);
}
void mas(const int*, double*, const int*, const double*, const int*) {}  // M = I (IMAS = 0): never called
void solout(const int* nr, const double* t_old, const double* t, const double* z, const double* cont, const int* lrc,
            const int* n, const double* rpar, const int*, int* irtrn) {
  *irtrn = 0;
  const Call& c = call_of(rpar);
  if (*nr == 1 || !*c.after_step) return;  // the first call is at the start, before any step
  const auto size = static_cast<std::size_t>(*n);
  (*c.after_step)({*t_old, *t, {z, size}, {cont, static_cast<std::size_t>(*lrc)}});
}

// deSolve rewrote RADAU5's WRITE statements as calls to R's printing; outside R they are silent:
// a failure is read from IDID (the run is marked failed).
void rprintf_(const char*, int) {}
void rprintfd1_(const char*, const double*, int) {}
void rprintfd2_(const char*, const double*, const double*, int) {}
void rprintfi1_(const char*, const int*, int) {}
void rprintfi2_(const char*, const int*, const int*, int) {}
void rprintfi3_(const char*, const int*, const int*, const int*, int) {}
}

std::mutex radau5_lock;

}  // namespace

bool have_radau5() { return true; }

void radau5_solve(const Radau5Problem& p, double* z, double tol, double t_end, PeerCounts& n,
                  const std::function<void(const Radau5Step&)>& after_step) {
  const int size = p.n, half = p.n / 2, itol = 0, ijac = 1, imas = 0, zero = 0, iout = after_step ? 1 : 0;
  const bool band = p.bandwidth >= 0 && p.bandwidth < half;
  const int ml = band ? p.bandwidth : half, mu = ml;
  // work sizes (RADAU5's own comment): N (LJAC + 12) + (N - M1)(LMAS + 3 LE) + 20, LJAC and LE
  // the Jacobian's and the iteration matrices' column lengths; 3 N + 20 integers
  const int ljac = band ? ml + mu + 1 : half, le = band ? 2 * ml + mu + 1 : half;
  const int lwork = size * (ljac + 12) + half * 3 * le + 20, liwork = 3 * size + 20;
  std::vector<double> work(static_cast<std::size_t>(lwork), 0.0);
  std::vector<int> iwork(static_cast<std::size_t>(liwork), 0);
  iwork[1] = 10'000'000;  // IWORK(2): the steps allowed, as CVODE is given
  iwork[8] = half;        // IWORK(9) = M1: x' = v for the first half
  iwork[9] = half;        // IWORK(10) = M2
  double t = 0, h = 0, rtol = tol, atol = tol;  // h = 0: RADAU5's own first step (1e-6)
  int idid = 0, ipar = 0;
  Call c{&p, &after_step};
  {
    const std::lock_guard<std::mutex> lock(radau5_lock);
    radau5_(&size, fcn, &t, z, &t_end, &h, &rtol, &atol, &itol, jac, &ijac, &ml, &mu, mas, &imas, &zero, &zero, solout,
            &iout, work.data(), &lwork, iwork.data(), &liwork, reinterpret_cast<double*>(&c), &ipar, &idid);
  }
  n = {};
  const long long computed = iwork[15], accepted = iwork[16];
  n.steps = accepted, n.rejected = computed - accepted;  // error test (IWORK(18)) and Newton failures
  n.forces = iwork[13], n.jacobians = iwork[14], n.factorisations = iwork[18];
  n.solves = n.newton = iwork[19];  // IWORK(20): one substitution of both systems per Newton iteration
  n.failed = idid < 0;
}

#else

bool have_radau5() { return false; }

void radau5_solve(const Radau5Problem&, double*, double, double, PeerCounts&, const std::function<void(const Radau5Step&)>&) {
  throw std::logic_error("RADAU5 is not built into this steplab (tools/radau5.cmake)");
}

#endif

}  // namespace steplab
