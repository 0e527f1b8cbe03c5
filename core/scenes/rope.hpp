// A hanging rope: N equal masses on a vertical line below an anchor at height 0, spring i joining
// mass i-1 (the anchor for i = 1) and mass i. A refinement of one rope, not a longer one: the
// totals stay as N grows (total mass M, stiffness K, rest length L, damping gamma, dashpot C_s):
//   m = M/N,  k = K N,  l = L/N,  c = gamma/N (each mass),  d = C_s N (along each spring)
// so that N = 1 is the sheet's spring. With heights y_i (y_0 = v_0 = 0 the anchor):
//   tension of spring i   T_i = k ((y_{i-1} - y_i) - l) + d (v_{i-1} - v_i),   T_{N+1} = 0
//   m y_i'' = T_i - T_{i+1} - c v_i - m g
// It is linear: with u = y - y_eq,  m u'' + (c I + d T) u' + k T u = 0, T the fixed-free
// Laplacian (2 on the diagonal but 1 in the last row, -1 beside it). Its modes, in closed form:
//   T phi_j = lambda_j phi_j,  phi_j(n) = sin(n theta_j),  theta_j = (2j - 1) pi / (2N + 1),
//   lambda_j = 4 sin^2(theta_j / 2),  omega_j = 2 sqrt(k/m) sin(theta_j / 2),  |phi_j|^2 = (2N + 1)/4.
// Both dampings are diagonal in the modes (mass- and stiffness-proportional), so mode j is one
// damped oscillator (core/scenes/oscillator.hpp): alpha_j = -(c + d lambda_j) / (2m),
// beta_j^2 = omega_j^2 - alpha_j^2. The exact flow projects u and v on the modes, moves each,
// and sums them back: two sine transforms each way, O(N log N) (SineTransform below, FFTW).
#pragma once

#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <span>
#include <vector>

#include "core/scene.hpp"
#include "core/springs.hpp"
#include "core/scenes/oscillator.hpp"

namespace steplab {

// u_n = sum_{j=1}^N q_j sin(n theta_j) (synthesis) and q_j = 4/M sum_{n=1}^N u_n sin(n theta_j)
// (analysis), n, j = 1 .. N, theta_j = (2j - 1) pi / M, M = 2N + 1 (a DST-VII). Each is one real
// FFT of the odd length M (FFTW r2hc, X_p = sum_{n=0}^{M-1} z_n e^{-2 pi i n p / M}), by
//   sin(n (M - 2p) pi / M) = -(-1)^n sin(2 pi n p / M),   2j - 1 = M - 2p,  p = N + 1 - j:
// analysis: z_n = (-1)^{n+1} u_n (n = 1 .. N, the rest zero), q_j = -(4/M) Im X_{N+1-j};
// synthesis: z_p = q_{N+1-p} (p = 1 .. N, the rest zero), u_n = (-1)^n Im X_n. FFTW's
// real-to-halfcomplex transform gives Im X_k at position M - k.
// (The DST-I of size 2N that holds the same sums has a DFT of length 2M behind it: twice the
// work.) The plan is made once per rope (FFTW's planner is not thread-safe: serialised) and
// executed on each call's own arrays (which is).
class SineTransform {
 public:
  explicit SineTransform(int n);
  ~SineTransform();
  SineTransform(const SineTransform&) = delete;
  SineTransform& operator=(const SineTransform&) = delete;
  Eigen::VectorXd synthesis(const Eigen::VectorXd& q) const;
  Eigen::VectorXd analysis(const Eigen::VectorXd& u) const;
  // The synthesis into u, its work arrays borrowed from the scratch pool (core/scratch.hpp): no
  // allocation after the first call on a thread.
  void synthesis(Eigen::Ref<const Eigen::VectorXd> q, Eigen::Ref<Eigen::VectorXd> u) const;
  void analysis(Eigen::Ref<const Eigen::VectorXd> u, Eigen::Ref<Eigen::VectorXd> q) const;

 private:
  // z_0 = 0, z_k = fill(k) for k = 1 .. N, the rest zero, through the real FFT of length M;
  // read(k, Im X_k) for k = 1 .. N. Its arrays borrowed from the scratch pool.
  template <class Fill, class Read> void odd_fft(Fill fill, Read read) const;
  int n_;
  void* plan_;
};

struct Rope {
  static constexpr int dim = Eigen::Dynamic;
  static constexpr std::string_view name = "rope";
  static constexpr bool symmetric_jacobians = true;  // dF/dx = -k T, dF/dv = -c I - d T (below)
  // What it offers the studies (core/scene.hpp): refined by its number of masses; its modes in
  // closed form (modes() below); tridiagonal Jacobians.
  static constexpr std::string_view title = "Rope of N masses";
  // The equation of motion, for the report (the math above is its derivation).
  static constexpr std::string_view equation = "m y_i'' = T_i - T_(i+1) - c y_i' - m g,  T_i = k ((y_(i-1) - y_i) - l) + d (y_(i-1)' - y_i'),  T_(N+1) = 0";
  static constexpr std::string_view size_param = "masses";
  static constexpr std::string_view stiffness_param = "stiffness";
  static constexpr std::string_view damping_param = "damping";
  static constexpr int jacobian_bandwidth = 1;
  // Defaults: the sheet's spring cut into 8 (M, K, L, gamma, g as the spring's).
  static constexpr std::array<ParamSpec, 7> params{{
      {"masses", 8, Bound::Positive, "number of masses N (a whole number, 1 to 100000)", true, 1e5},
      {"mass", 1.0, Bound::Positive, "total mass M (each mass M/N)"},
      {"stiffness", 5.0, Bound::Positive, "total stiffness K (each spring K N)"},
      {"rest-length", 5.0, Bound::NonNegative, "total rest length L (each spring L/N)"},
      {"damping", 0.1, Bound::NonNegative, "absolute damping gamma shared by the masses (gamma/N each)"},
      {"spring-damping", 0.0, Bound::NonNegative, "dashpot along the springs, total C_s (C_s N each)"},
      {"gravity", 9.81, Bound::NonNegative, "gravitational acceleration g (pointing down)"},
  }};

  int n;
  double M, K, L, gamma, Cs, g;
  double m = M / n, k = K * n, l = L / n, c = gamma / n, d = Cs * n;
  double inv_m = 1 / m, weight = m * g;
  Eigen::VectorXd eq;      // y_eq: spring i carries the N - i + 1 masses below it
  Eigen::VectorXd lambda;  // lambda_j, j = 1 .. N
  Eigen::VectorXd q0;      // the start's modal displacements (it starts at rest)
  Eigen::VectorXd m_all = Eigen::VectorXd::Constant(n, m), inv_m_all = Eigen::VectorXd::Constant(n, inv_m);
  Jacobians<Eigen::Dynamic> jac;  // constant: the rope is linear (made once, below)
  std::shared_ptr<const SineTransform> sine;

  explicit Rope(std::span<const double> p)
      : n(static_cast<int>(p[0])), M(p[1]), K(p[2]), L(p[3]), gamma(p[4]), Cs(p[5]), g(p[6]),
        eq(n), lambda(n), jac{SparseMat(n, n), SparseMat(n, n)}, sine(std::make_shared<const SineTransform>(n)) {
    double y = 0;
    for (int i = 0; i < n; ++i) {
      y -= l + (n - i) * weight / k;
      eq[i] = y;
      const double s = std::sin((2 * i + 1) * std::numbers::pi / (2 * (2 * n + 1)));
      lambda[i] = 4 * s * s;
    }
    q0 = sine->analysis(initial().x - eq);
    // dF/dx = -k T, dF/dv = -c I - d T (T above; the pattern tridiagonal also where d = 0)
    std::vector<Eigen::Triplet<double>> tx, tv;
    tx.reserve(3 * n), tv.reserve(3 * n);
    for (int i = 0; i < n; ++i) {
      const double diag = i + 1 < n ? 2 : 1;
      tx.emplace_back(i, i, -k * diag), tv.emplace_back(i, i, -c - d * diag);
      if (i + 1 < n) {
        tx.emplace_back(i, i + 1, k), tx.emplace_back(i + 1, i, k);
        tv.emplace_back(i, i + 1, d), tv.emplace_back(i + 1, i, d);
      }
    }
    jac.dx.setFromTriplets(tx.begin(), tx.end());
    jac.dv.setFromTriplets(tv.begin(), tv.end());
  }

  std::array<double, 7> values() const { return {double(n), M, K, L, gamma, Cs, g}; }
  // As springs (core/springs.hpp): spring i from mass i - 1 above (the anchor for i = 0) to mass
  // i, C = (y_(i-1) - y_i) - l, its dashpot d; gravity and the absolute damping c outside them.
  int links() const { return n; }
  Link link(int i) const { return {i - 1, i, l, k, d}; }
  double external(int, double v) const { return -c * v - weight; }
  // Mode j's angular frequency (j = 1 .. N; omega(N) the fastest: an explicit method's stable step
  // is C / omega(N)).
  double omega(int j) const { return std::sqrt(k * lambda[j - 1] / m); }
  // Mode j's oscillator (core/scenes/oscillator.hpp): alpha_j and beta_j^2.
  double alpha(int j) const { return -(c + d * lambda[j - 1]) / (2 * m); }
  double beta2(int j) const { return k * lambda[j - 1] / m - alpha(j) * alpha(j); }
  // Mode j (j = 1 .. N, slowest first) as a unit oscillator: omega_j and
  // 2 zeta_j = (c + d lambda_j) / (m omega_j).
  std::vector<Mode> modes() const {
    std::vector<Mode> out(n);
    for (int j = 1; j <= n; ++j) {
      const double w = omega(j);
      out[j - 1] = {w, (c + d * lambda[j - 1]) / (m * w)};
    }
    return out;
  }

  const Eigen::VectorXd& mass() const { return m_all; }
  const Eigen::VectorXd& inverse_mass() const { return inv_m_all; }

  // F into the run's f: the tensions first, f_i = T_(i+1) (f_0 = T_1, from the anchor), then
  // f_i = (T_(i+1) - T_(i+2)) - c v_i - m g (T_(N+1) = 0). Two loops without a recurrence between
  // their iterations, so that both vectorise; the operations and their order are the same as
  // carrying each tension on to the next mass, so the values are the same to the bit.
  // The parameters are copied to locals: a store through f could otherwise alias them, and the
  // compiler would reload them every iteration instead of vectorising.
  void force(Eigen::Ref<const Eigen::VectorXd> x, Eigen::Ref<const Eigen::VectorXd> v, Eigen::Ref<Eigen::VectorXd> f) const {
    forces<false>(x.data(), v.data(), f.data());
  }
  // M^-1 F into a, 1/m applied in the second loop (core/scene.hpp, AccelerationInto): the values
  // of F times 1/m, one pass over the state fewer.
  void acceleration(Eigen::Ref<const Eigen::VectorXd> x, Eigen::Ref<const Eigen::VectorXd> v, Eigen::Ref<Eigen::VectorXd> a) const {
    forces<true>(x.data(), v.data(), a.data());
  }

  const Jacobians<Eigen::Dynamic>& jacobians(Eigen::Ref<const Eigen::VectorXd>, Eigen::Ref<const Eigen::VectorXd>) const { return jac; }

  bool velocity_dependent() const { return c != 0 || d != 0; }

  // Oscillation energy about the equilibrium: 1/2 m |v|^2 + 1/2 k sum_i (u_{i-1} - u_i)^2, u_0 = 0.
  double energy(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const {
    double stretch = 0, above = 0;
    for (int i = 0; i < n; ++i) {
      const double u = x[i] - eq[i], e = above - u;
      stretch += e * e;
      above = u;
    }
    return 0.5 * m * v.squaredNorm() + 0.5 * k * stretch;
  }

  // At rest, every spring at its rest length.
  State<Eigen::Dynamic> initial() const {
    Eigen::VectorXd x(n);
    for (int i = 0; i < n; ++i) x[i] = -(i + 1) * l;
    return {x, Eigen::VectorXd::Zero(n)};
  }

  State<Eigen::Dynamic> exact_at(double t) const {
    Eigen::VectorXd q = q0, p = Eigen::VectorXd::Zero(n);
    State<Eigen::Dynamic> y{Eigen::VectorXd(n), Eigen::VectorXd(n)};
    move_modes(q, p, t);
    synthesise(q, p, y);
    return y;
  }

  // The exact motion along a run, read every h (core/exact_tracker.hpp, HasExactAlong): each
  // mode's oscillator stepped over h by its own 2 x 2 map,
  //   (q_j, p_j) <- (a_j q_j + b_j p_j,  c_j q_j + d_j p_j),
  // whose columns are the oscillator's motion over h from (1, 0) and from (0, 1)
  // (damped_oscillation): O(N) a step, where the closed form costs an exp, a sin and a cos a
  // mode. Every kResync reads the closed form again, so that the recurrence's round-off
  // accumulates over kResync steps at most (a few ulps of |q| each). The positions eq + S q by one
  // sine transform a read; the velocities S p only when asked (a run's end).
  class ExactAlong {
   public:
    static constexpr int kResync = 256;
    ExactAlong(const Rope& rope, double h);
    const Eigen::VectorXd& at(double t);  // t = h, 2h, 3h, ... in turn
    void jump() { until_closed_form_ = 1; }  // the next at(t) at any t, by the closed form
    const Eigen::VectorXd& velocities();  // at the last t
   private:
    const Rope* r_;
    Eigen::VectorXd q_, p_, a_, b_, c_, d_, x_, v_;
    int until_closed_form_ = 1;  // 1 + the steps left before the closed form again
  };
  ExactAlong exact_along(double h) const { return ExactAlong(*this, h); }
  State<Eigen::Dynamic> flow(const State<Eigen::Dynamic>& y, double t) const {
    State<Eigen::Dynamic> out = y;
    advance(out, t);
    return out;
  }
  // The same flow in place, in the scratch pool's vectors (the exact method's step: no allocation).
  void advance(State<Eigen::Dynamic>& y, double t) const {
    ScratchVec q(n), p(n);
    sine->analysis(ScratchVec(y.x - eq), q);
    sine->analysis(y.v, p);
    move_modes(q, p, t);
    synthesise(q, p, y);
  }

 private:
  template <bool TimesInverseMass>
  void forces(const double* __restrict xs, const double* __restrict vs, double* __restrict fs) const {
    const double ks = k, ls = l, ds = d, cs = c, w = weight, im = inv_m;
    const int ns = n;
    fs[0] = ks * ((0 - xs[0]) - ls) + ds * (0 - vs[0]);
    for (int i = 1; i < ns; ++i) fs[i] = ks * ((xs[i - 1] - xs[i]) - ls) + ds * (vs[i - 1] - vs[i]);
    for (int i = 0; i + 1 < ns; ++i) {
      const double f = (fs[i] - fs[i + 1]) - cs * vs[i] - w;
      fs[i] = TimesInverseMass ? f * im : f;
    }
    const double last = (fs[ns - 1] - 0) - cs * vs[ns - 1] - w;
    fs[ns - 1] = TimesInverseMass ? last * im : last;
  }

  // Each mode j moved over t from (q_j, p_j), in place (its oscillator's closed form).
  void move_modes(Eigen::Ref<Eigen::VectorXd> q, Eigen::Ref<Eigen::VectorXd> p, double t) const {
    for (int j = 1; j <= n; ++j) {
      const auto [u, du] = damped_oscillation(q[j - 1], p[j - 1], alpha(j), beta2(j), t);
      q[j - 1] = u, p[j - 1] = du;
    }
  }
  // The positions of modal coordinates q, x = eq + S q, into x (sized).
  void positions(Eigen::Ref<const Eigen::VectorXd> q, Eigen::Ref<Eigen::VectorXd> x) const {
    sine->synthesis(q, x);
    x += eq;
  }
  // The state of modal coordinates (q, p): x = eq + S q, v = S p, into y (sized).
  void synthesise(Eigen::Ref<const Eigen::VectorXd> q, Eigen::Ref<const Eigen::VectorXd> p, State<Eigen::Dynamic>& y) const {
    positions(q, y.x);
    sine->synthesis(p, y.v);
  }
};

inline Rope::ExactAlong::ExactAlong(const Rope& rope, double h) : r_(&rope), q_(rope.n), p_(rope.n), x_(rope.n), v_(rope.n) {
  if (!(h > 0)) return;
  a_.resize(rope.n), b_.resize(rope.n), c_.resize(rope.n), d_.resize(rope.n);
  for (int j = 1; j <= rope.n; ++j) {
    const Oscillation from_q = damped_oscillation(1, 0, rope.alpha(j), rope.beta2(j), h);
    const Oscillation from_p = damped_oscillation(0, 1, rope.alpha(j), rope.beta2(j), h);
    a_[j - 1] = from_q.u, c_[j - 1] = from_q.du, b_[j - 1] = from_p.u, d_[j - 1] = from_p.du;
  }
}

inline const Eigen::VectorXd& Rope::ExactAlong::at(double t) {
  const int n = r_->n;
  if (until_closed_form_ > 1) {
    --until_closed_form_;
    double *__restrict q = q_.data(), *__restrict p = p_.data();
    const double *__restrict a = a_.data(), *__restrict b = b_.data(), *__restrict c = c_.data(), *__restrict d = d_.data();
    for (int j = 0; j < n; ++j) {
      const double qj = q[j], pj = p[j];
      q[j] = a[j] * qj + b[j] * pj;
      p[j] = c[j] * qj + d[j] * pj;
    }
  } else {
    until_closed_form_ = kResync;
    q_ = r_->q0, p_.setZero();
    r_->move_modes(q_, p_, t);
  }
  r_->positions(q_, x_);
  return x_;
}

inline const Eigen::VectorXd& Rope::ExactAlong::velocities() {
  r_->sine->synthesis(p_, v_);
  return v_;
}

}  // namespace steplab

#ifdef STEPLAB_SCENE_SOURCE
#include <mutex>

#include <fftw3.h>

namespace steplab {

namespace {
std::mutex& fftw_planner() {
  static std::mutex m;
  return m;
}
}  // namespace

SineTransform::SineTransform(int n) : n_(n) {
  const int m = 2 * n + 1;
  std::vector<double> in(m), out(m);
  const std::lock_guard lock(fftw_planner());
  // Real-to-halfcomplex (out[k] = Re X_k, out[M - k] = Im X_k): where M's prime factors are small
  // its execution allocates nothing; the real-to-complex interface's (rdft2) allocated a buffer of
  // M each call. Where M has a large prime factor (M = 2049 = 3 x 683) FFTW's Rader algorithm
  // allocates a buffer each call whichever the interface (docs/scenes.md).
  plan_ = fftw_plan_r2r_1d(m, in.data(), out.data(), FFTW_R2HC, FFTW_ESTIMATE | FFTW_UNALIGNED);
}

SineTransform::~SineTransform() {
  const std::lock_guard lock(fftw_planner());
  fftw_destroy_plan(static_cast<fftw_plan>(plan_));
}

Eigen::VectorXd SineTransform::synthesis(const Eigen::VectorXd& q) const {
  Eigen::VectorXd u(n_);
  synthesis(q, u);
  return u;
}

template <class Fill, class Read> void SineTransform::odd_fft(Fill fill, Read read) const {
  const int n = n_;
  const int m = 2 * n + 1;
  ScratchVec z(m), x(m);
  z[0] = 0;
  for (int k = 1; k <= n; ++k) z[k] = fill(k);
  z.tail(n).setZero();
  fftw_execute_r2r(static_cast<fftw_plan>(plan_), z.data(), x.data());
  for (int k = 1; k <= n; ++k) read(k, x[m - k]);  // Im X_k
}

void SineTransform::synthesis(Eigen::Ref<const Eigen::VectorXd> q, Eigen::Ref<Eigen::VectorXd> u) const {
  odd_fft([&](int p) { return q[n_ - p]; },                                        // z_p = q_(N+1-p)
          [&](int k, double im) { u[k - 1] = (k % 2 == 0 ? 1.0 : -1.0) * im; });  // u_k = (-1)^k Im X_k
}

Eigen::VectorXd SineTransform::analysis(const Eigen::VectorXd& u) const {
  Eigen::VectorXd q(n_);
  analysis(u, q);
  return q;
}

void SineTransform::analysis(Eigen::Ref<const Eigen::VectorXd> u, Eigen::Ref<Eigen::VectorXd> q) const {
  const double scale = -4.0 / (2 * n_ + 1);
  odd_fft([&](int k) { return (k % 2 == 1 ? 1.0 : -1.0) * u[k - 1]; },  // z_k = (-1)^(k+1) u_k
          [&](int k, double im) { q[n_ - k] = scale * im; });          // q_(N+1-k) = -(4/M) Im X_k
}

}  // namespace steplab
#endif

STEPLAB_SCENE(steplab::Rope);
