// What every integrator declares, and the one solver the implicit ones share.
//
// A method is a struct with
//   static constexpr MethodInfo info;                       name, order, flags
//   template <Scene S> static StepStatus step(const S&, State<S::dim>& y, double t, double h);
// that advances y from time t to t + h in place. It allocates nothing. It evaluates the force at
// each stage's own time, acceleration(s, t + c_i h, x, v) (core/scene.hpp): a driven scene's
// force depends on it, and a method that passed another time would lose its order there
// (`steplab check` measures it on the target). Written over the scalar,
//   template <class S, class T> static Status<T> step(const S&, State<S::dim, T>& y, Time<T> t, Time<T> h);
// the same step also advances a pack of runs (T = Pack<W>, core/pack.hpp; core/batch.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string_view>
#include <type_traits>

#include "core/scene.hpp"
#include "core/small_lu.hpp"
#include "core/sparse.hpp"

namespace steplab {

// A method file ends with STEPLAB_METHOD(<its type>), outside any namespace: the line CMake reads
// to name the type in the method's generated translation unit (tools/kernels.cmake), and a
// check that the type declares its MethodInfo.
template <class M>
concept MethodType = requires { M::info; };
#define STEPLAB_METHOD(...) static_assert(::steplab::MethodType<__VA_ARGS__>, "STEPLAB_METHOD: a method declares info")

// The families the report answers "is stability correlated with order?" for, one by one.
// Explicit Euler and implicit Euler are also the first Adams-Bashforth and BDF methods (`also`).
enum class Family { ExplicitRungeKutta, Splitting, ImplicitRungeKutta, AdamsBashforth, Bdf, PositionBased, Exact, None };

inline constexpr std::string_view to_string(Family f) {
  switch (f) {
    case Family::ExplicitRungeKutta: return "explicit Runge-Kutta";
    case Family::Splitting: return "symplectic splitting";
    case Family::ImplicitRungeKutta: return "implicit Runge-Kutta";
    case Family::AdamsBashforth: return "Adams-Bashforth";
    case Family::Bdf: return "BDF";
    case Family::PositionBased: return "position-based";
    case Family::Exact: return "exact flow";
    case Family::None: return "none";
  }
  return "?";
}

// What a method claims; `steplab check --method NAME` measures each claim (analysis/studies/check.hpp).
// A row names the flags that hold: {.name = "rk4", .order = 4, .family = ..., .summary = "..."}.
struct MethodInfo {
  std::string_view name;
  int order = 0;              // global order of accuracy; 0 for the exact flow
  Family family = Family::None;
  bool symplectic = false;    // preserves the flow's symplectic form: energy bounded, no drift
  bool implicit = false;      // solves a nonlinear system each step
  bool a_stable = false;      // stable for every h lambda with Re <= 0: every step on a damped spring
  bool exact_flow = false;    // the analytic solution: needs a scene with an exact flow
  bool on_springs = false;    // works on the scene's springs (core/springs.hpp): needs a mass-spring scene
  bool converges = true;      // to the scene's motion as h -> 0 (PBD does not: its stiffness is set per step)
  std::string_view summary;   // its update in one line (y = (x, v), f = (v, a)), for the report's appendix
  Family first_of = Family::None;  // a second family whose first member the method is (explicit Euler: AB1)
};

// What a run may set of a method that has settings (its step then step(s, y, t, h, settings)): the Gauss-Seidel sweeps a step of a position-based
// method (core/methods/xpbd.hpp, pbd.hpp), the conjugate-gradient iterations of Baraff and
// Witkin's step (core/methods/baraff_witkin.hpp): at most cg_iterations, stopping once the
// residual is below cg_tolerance times the right-hand side.
struct MethodSettings {
  int sweeps = 1;
  int cg_iterations = 100;
  double cg_tolerance = 1e-8;
};
// Which of them a method reads, from its row: the position-based methods their sweeps, a method
// on springs that is not position-based (Baraff-Witkin) its CG's; no other method has settings.
constexpr bool takes_sweeps(const MethodInfo& m) { return m.family == Family::PositionBased; }
constexpr bool takes_cg(const MethodInfo& m) { return m.on_springs && !takes_sweeps(m); }
template <class M> concept TakesSettings = takes_sweeps(M::info) || takes_cg(M::info);

// An implicit Runge-Kutta method declares its Butcher tableau, `static constexpr
// ButcherTableau<s> tableau`, whether its step is written from it (core/implicit_rk.hpp) or by
// hand (implicit Euler, implicit midpoint): the order-reduction study reads its stage order and
// R(infinity) from it (analysis/studies/order_reduction.hpp).
template <int Stages> struct ButcherTableau {
  std::array<std::array<double, Stages>, Stages> a;
  std::array<double, Stages> b;
  // Stage i's time within the step, c_i = sum_j a_ij: where a driven scene's force is evaluated.
  constexpr double c(int i) const {
    double sum = 0;
    for (double x : a[static_cast<std::size_t>(i)]) sum += x;
    return sum;
  }
  // |A|_F, A's Frobenius norm: how far the stages' coupling can scale the Jacobians (Newton's
  // round-off size on a run-time size, core/implicit_rk.hpp).
  double a_norm() const {
    double sq = 0;
    for (const auto& row : a)
      for (double x : row) sq += x * x;
    return std::sqrt(sq);
  }
};

// A method whose step solves for its stages by Newton (solve_implicit, core/implicit_rk.hpp)
// says how many it solves together: `static constexpr int solve_stages = K;`, K times the
// scene's coordinates unknowns in one dense system (Gauss-Legendre 4: 2, Radau IIA 5: 3; 1 for
// the one-stage solves). A pack solves up to kPackLuSize of them lane-wise in SIMD (core/
// small_lu.hpp); a larger one would be solved lane by lane, scalar, which makes packs slower than
// one run at a time (docs/design.md, Why a step is fast), so such a pair is stepped one run at a
// time (core/batch.hpp). A method that solves and does not say so is still packed: the same
// bits, only slower.
template <class M> constexpr int solve_stages() {
  if constexpr (requires { M::solve_stages; }) return M::solve_stages;
  else return 0;
}

// A partitioned method (x and v updated by different rules) has no scalar stability function
// R(z): its step matrix on the oscillator is not a function of h A alone.
constexpr bool has_stability_function(const MethodInfo& m) { return m.family != Family::Splitting && !m.exact_flow; }

// Eigen's ComputationInfo in spirit: a step reports, it never throws or exits.
enum class StepStatus { Ok, NoConvergence };

// What a step of T reports: one run's StepStatus, or for a pack of runs (core/batch.hpp) the
// lanes whose Newton iteration failed, a Mask. status_of(lanes) makes either from the lanes that
// failed; failed(status) gives those lanes back (a bool for one run).
template <class T> struct StatusOf { using type = StepStatus; };
template <int W> struct StatusOf<Pack<W>> { using type = Mask<W>; };
template <class T> using Status = typename StatusOf<T>::type;
inline StepStatus status_of(bool failed) { return failed ? StepStatus::NoConvergence : StepStatus::Ok; }
template <int W> Mask<W> status_of(const Mask<W>& failed) { return failed; }
inline bool failed(StepStatus s) { return s != StepStatus::Ok; }
template <int W> Mask<W> failed(const Mask<W>& s) { return s; }

// Newton's method for the implicit stages. Solves for the velocity u in
//
//     M (u - w) = c F(t, x0 + cx u, u)
//
// (backward Euler: w = v0, c = cx = h, t = t0 + h; a half step of it is the implicit midpoint
// rule, t = t0 + h/2; velocity Verlet's closing kick: w = v0 + h/2 a0, c = h/2, cx = 0 at fixed
// x1, t = t0 + h). t matters to a driven scene only. The Jacobian of the
// residual G(u) = M (u - w) - c F is  J = M - c dF/dv - c cx dF/dx.
// Starts from u = w and iterates until round-off, not a tolerance, decides (Hairer, Lubich and
// Wanner, Geometric Numerical Integration, VIII.6: iterate until the increment no longer shrinks).
// The scale is the size of the terms G balances: |M u| + |M w| + c (|F| + |dF/dx| |x| + |dF/dv| |u|),
// the last two from the first Jacobian (|c|: a composition such as Yoshida's runs substeps
// backwards; near equilibrium F itself is ~0 while its terms, k|y| or m g, are not, and round-off
// in F is relative to those). A correction below round-off's size (RoundOff below) would change
// u's last bits only, or G's: it is round-off's; and so, once |G(u)| is within tolerance * scale,
// is a correction no smaller than the last. At either the iteration stops without it: u is then
// the solution to round-off, and the force last evaluated is u's own (an implicit Runge-Kutta
// step builds v from its stages' forces: a correction applied after them would leave them a
// correction behind, which a stiff step multiplies by h^2 k / m). The size is bounded through
// |J|, not through M^-1: where the step is stiff, J is far larger than M, and M^-1 times the
// residual's scale would take the first correction for round-off.
// Stopping at the tolerance alone left each step's solution wrong by up to 1e-12 of that scale, a
// bias a long run adds up (Gauss-Legendre 4 on Kepler's orbit drifted in angular momentum by
// 8.5e-8 over 10^5 periods). A force linear in (x, v) converges in one Newton step, the second's
// correction is round-off. At most max_iterations, then NoConvergence.
struct NewtonSettings {
  static constexpr int max_iterations = 50;
  static constexpr double tolerance = 1e-12;
  static constexpr double round_off = 4 * 0x1p-52;  // 4 epsilon: a correction of about an ulp a coordinate
};

// Newton's round-off rule above, one iteration after another. A correction is round-off's below
// the size: an ulp or so of |u| + |w| (u_size), and at least the size whose effect on G is within
// round-off of G's own terms: |J du| <= j_bound |du| <= round_off scale, j_bound an upper bound on
// |J| (its Frobenius norm, or a sum of norms). Near rest u is ~0 while G's terms are not: x0 + cx u
// cannot see a change in u below ulp(x0) / cx, the residual then answers to only part of J, and
// each correction shrinks by 1 - (that part) / |J| (the damped spring at h = 1, implicit Euler:
// 0.82 an iteration, 50 iterations of corrections 1e-18 on a u of 4e-7); the second term ends
// that. stop() takes the correction just computed, of size `step`, with `small` whether the
// residual is within tolerance, and says where the iteration ends there, without it (where it
// does not, the correction is taken).
template <class T> struct RoundOff {
  T last = std::numeric_limits<double>::infinity();  // the last correction's size
  [[gnu::always_inline]] MaskOf<T> stop(const T& step, const T& u_size, const T& scale, const T& j_bound, const MaskOf<T>& small) {
    const T size = u_size + scale / j_bound;
    const MaskOf<T> at_round_off = (small && step >= last) || step <= NewtonSettings::round_off * size;
    last = step;
    return at_round_off;
  }
};

// Which lanes of a Newton iteration have stopped: solved, or given up (failed). Each call says
// whether every lane has now stopped; the loop then returns status().
template <class T> struct NewtonLanes {
  MaskOf<T> done{false}, failed{false};
  bool solved(const MaskOf<T>& now) {
    done = done || now;
    return all(done);
  }
  // A lane still iterating gives up at the last iteration or on a residual that is not finite.
  template <class R> bool give_up(int it, const R& r) {
    const MaskOf<T> now = !done && (MaskOf<T>(it == NewtonSettings::max_iterations) || !all_finite(r));
    failed = failed || now;
    return solved(now);
  }
  Status<T> status() const { return status_of(failed); }
};

// A scene that counts (analysis/kernel/kernel_impl.hpp, Counted) is told of each Newton iteration, with
// the factorisations and linear solves it made; for any other scene this is nothing at all. Full
// Newton on a fixed size (count_newton_update): one factorisation and one solve each.
template <class S> [[gnu::always_inline]] inline void count_iteration(const S& s, const SolveCounts& n) {
  if constexpr (requires { s.counted_iteration(n); }) s.counted_iteration(n);
}
template <class S> [[gnu::always_inline]] inline void count_newton_update(const S& s) { count_iteration(s, SolveCounts{1, 1}); }

// A scene of run-time size whose dF/dx and dF/dv are symmetric (the rope) says so with
// `static constexpr bool symmetric_jacobians = true`: its iteration matrices are then factorised
// by LDL^T, otherwise (the soft body's dashpots) by LU (core/sparse.hpp).
template <class S> constexpr bool kSymmetricJacobians = requires { requires S::symmetric_jacobians; };

// Simplified Newton's refresh (core/sparse.hpp): the Jacobians at (t, x, v) kept for the run's
// iteration matrices where none are yet, or where iteration `it` reduced the residual by less
// than kRefreshRate (r_norm against the last iteration's r_last). True where they were refreshed.
template <Scene S>
bool refresh_if_slow(IterationMatrices& kept, Jacobians<Eigen::Dynamic>& evaluated, const S& s, double t, Eigen::Ref<const Eigen::VectorXd> x,
                     Eigen::Ref<const Eigen::VectorXd> v, int it, double r_norm, double r_last) {
  if (kept.has_jacobians() && !(it > 0 && r_norm > kRefreshRate * r_last)) return false;
  const Jacobians<Eigen::Dynamic>& jac = jacobians_for_run(s, t, x, v, evaluated);  // the rope's own; the soft body's into `evaluated`
  kept.keep(jac.dx, jac.dv, s.mass(), kSymmetricJacobians<S>);
  return true;
}

// On a scene of run-time size: simplified Newton, as RADAU5 and CVODE solve (core/sparse.hpp).
// The iteration matrix J = E(c, c cx) is made from the Jacobians the run's workspace keeps, and
// factorised once for as long as they are kept; they are evaluated afresh, at the current
// iterate, on the first solve of a run and whenever an iteration reduces the residual by less
// than kRefreshRate (refresh_if_slow). The stopping test and its scale are full Newton's (below),
// the Jacobians' norms in it the kept ones'. A linear scene's kept J is exact: one update, as
// full Newton.
template <Scene S>
StepStatus solve_implicit_sparse(const S& s, double t, Eigen::Ref<const Eigen::VectorXd> x0, double cx, Eigen::Ref<const Eigen::VectorXd> w,
                                 double c, Eigen::Ref<Eigen::VectorXd> u) {
  NewtonWorkspace& ws = newton_workspace();
  IterationMatrices& kept = ws.matrices;
  const Eigen::VectorXd& m = s.mass();
  Eigen::VectorXd &x = ws.x, &r = ws.r, &f = ws.f;
  u = w;
  double force_terms = 0, r_last = 0;
  RoundOff<double> round_off;
  const double mw_norm = m.cwiseProduct(w).norm(), w_norm = w.norm(), m_norm = m.norm();
  for (int it = 0;; ++it) {
    x = x0 + cx * u;
    force_into(s, t, x, u, f);
    r = m.cwiseProduct(u - w) - c * f;
    const double r_norm = r.norm();
    const double f_norm = f.norm(), mu_norm = m.cwiseProduct(u).norm();
    const double scale = mu_norm + mw_norm + std::abs(c) * (f_norm + force_terms);
    const bool small = it > 0 && r_norm <= NewtonSettings::tolerance * scale;
    if (it == NewtonSettings::max_iterations || !all_finite(r)) return StepStatus::NoConvergence;
    if (!small) refresh_if_slow(kept, ws.jacobians, s, t, x, u, it, r_norm, r_last);  // not for round-off's corrections
    if (it == 0) force_terms = kept.force_terms(x, u);
    if (all_zero(r)) return StepStatus::Ok;  // already solved (e.g. at rest in equilibrium)
    const SolveCounts n = kept.solve(c, c * cx, r, ws.du);
    count_iteration(s, n);
    if (!n.ok) return StepStatus::NoConvergence;
    if (round_off.stop(ws.du.norm(), u.norm() + w_norm, scale, kept.norm_bound(m_norm, c, c * cx), small)) return StepStatus::Ok;
    u -= ws.du;
    r_last = r_norm;
  }
}

// On a fixed size: full Newton, J = M - c dF/dv - c cx dF/dx factorised by dense LU at every
// iteration (lu_solve, core/small_lu.hpp: a division for D = 1). One run (T = double), or a pack
// of runs (S the pack's scene): each lane iterates as its run would alone and stops where that
// run stops (solved, or given up: failed); the pack's loop ends when every lane has stopped. A
// stopped lane's u is not touched again. Always inlined: a call left out of line would be
// compiled for the default instruction set, not the batch's (core/batch.hpp).
template <class S, class T>
[[gnu::always_inline]] inline Status<T> solve_implicit_dense(const S& s, Time<T> t, const Vec<S::dim, T>& x0, Time<T> cx,
                                                             const Vec<S::dim, T>& w, Time<T> c, Vec<S::dim, T>& u) {
  using std::abs;
  constexpr int D = S::dim;
  const Vec<D, T>& m = s.mass();
  u = w;
  T force_terms = 0;
  RoundOff<T> round_off;
  const T mw_norm = m.cwiseProduct(w).norm(), w_norm = w.norm();
  NewtonLanes<T> lanes;
  for (int it = 0;; ++it) {
    const Vec<D, T> x = x0 + cx * u;
    const Vec<D, T> f = force_at(s, t, x, u);
    const Vec<D, T> r = m.cwiseProduct(u - w) - c * f;
    const T f_norm = f.norm(), mu_norm = m.cwiseProduct(u).norm();
    const T scale = mu_norm + mw_norm + abs(c) * (f_norm + force_terms);
    const MaskOf<T> small = MaskOf<T>(it > 0) && r.norm() <= NewtonSettings::tolerance * scale;
    if (lanes.give_up(it, r)) return lanes.status();
    const Jacobians<D, T>& jac = jacobians_at(s, t, x, u);
    if (it == 0) force_terms = jac.dx.norm() * x.norm() + jac.dv.norm() * u.norm();
    if (lanes.solved(all_zero(r))) return lanes.status();  // already solved (e.g. at rest in equilibrium)
    count_newton_update(s);
    Mat<D, T> J = -c * jac.dv - (c * cx) * jac.dx;
    J.diagonal() += m;
    const Vec<D, T> du = lu_solve(J, r);
    const MaskOf<T> stop = round_off.stop(du.norm(), u.norm() + w_norm, scale, J.norm(), small);
    u = select(!lanes.done && !stop, Vec<D, T>(u - du), u);
    if (lanes.solved(stop)) return lanes.status();
  }
}

// T is the scalar of u (a pack's, or double): the times and coefficients are of that type, a
// whole 0.0 included. On a run-time size x0, w and u may be any vectors (the run's, or a step's
// borrowed ones: core/scratch.hpp), taken by reference.
template <class S, class X0, class W, class U, class T = typename U::Scalar>
[[gnu::always_inline]] inline Status<T> solve_implicit(const S& s, std::type_identity_t<T> t, const X0& x0, std::type_identity_t<T> cx,
                                                       const W& w, std::type_identity_t<T> c, U& u) {
  if constexpr (S::dim == Eigen::Dynamic) return solve_implicit_sparse(s, t, x0, cx, w, c, u);
  else return solve_implicit_dense<S, T>(s, t, x0, cx, w, c, u);
}

}  // namespace steplab
