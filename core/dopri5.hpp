// Dormand-Prince 5(4), adaptive: the solver behind SciPy's RK45, MATLAB's ode45 and Boost.Odeint's
// runge_kutta_dopri5. It is not a row of the fixed-step table (core/registry.cmake): it takes a
// tolerance instead of a step, and chooses its steps itself.
//
// One step from (t, y) with k1 = f(y) (first same as last: k1 is the previous step's k7):
//   k_i = f(y + h sum_j a_ij k_j),  i = 2 .. 7
//   y1  = y + h sum_i b_i k_i                 (order 5; b = the last row of a, so k7 = f(y1))
//   err = h sum_i e_i k_i,  e = b - b*        (b*: the embedded order-4 weights)
// The error is measured in the mixed norm
//   |err| = sqrt(1/n sum_j (err_j / (atol + rtol max(|y_j|, |y1_j|)))^2)
// and the step accepted when |err| <= 1. The next step is h * clamp(0.9 |err|^(-1/5), 0.2, 10)
// (no growth right after a rejection), as in SciPy's RK45 (scipy/integrate/_ivp/rk.py); the first
// step by Hairer's rule (Hairer, Norsett, Wanner, Solving ODEs I, II.4; SciPy select_initial_step).
// Coefficients: Dormand & Prince (1980), as printed in Hairer's dopri5.f (the nodes c_i are left
// out: every scene here is autonomous).
//
// Output at chosen times comes from the method's own continuous extension (dopri5.f CONTD5),
// fourth order between the steps, so sampling never changes the steps taken.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/simulate.hpp"
#include "core/stepper.hpp"

namespace steplab {

struct Tolerance {
  double rtol = 1e-3;  // SciPy's RK45 defaults
  double atol = 1e-6;
};

struct AdaptiveSpec {
  Tolerance tol;
  double t_end = 10;
  long long max_samples = 0;          // 0: none; else this many evenly spaced times, 0 .. t_end
  long long max_steps = 10'000'000;  // attempts; beyond it the run ends as NoConvergence
  bool errors = true;                 // compare with the exact solution at every accepted step
};

struct AdaptiveStats {
  long long accepted = 0, rejected = 0;
  long long force_evaluations = 0;
  double h_min = std::numeric_limits<double>::infinity(), h_max = 0;  // accepted steps
};

template <int D> struct AdaptiveResult {
  RunResult<D> run;  // steps = accepted steps; errors and energy at every accepted step
  AdaptiveStats stats;
};

namespace dp5 {
inline constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;  // stage times; c6 = c7 = 1
inline constexpr double a21 = 1.0 / 5;
inline constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
inline constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
inline constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561, a54 = -212.0 / 729;
inline constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                        a65 = -5103.0 / 18656;
inline constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784, b6 = 11.0 / 84;
inline constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                        e6 = 22.0 / 525, e7 = -1.0 / 40;
inline constexpr double d1 = -12715105075.0 / 11282082432.0, d3 = 87487479700.0 / 32700410799.0,
                        d4 = -10690763975.0 / 1880347072.0, d5 = 701980252875.0 / 199316789632.0,
                        d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;
inline constexpr double safety = 0.9, min_factor = 0.2, max_factor = 10;
}  // namespace dp5

// The mixed error norm above, over the 2D coordinates of (x, v).
template <int D> double error_norm(const State<D>& err, const State<D>& y0, const State<D>& y1, const Tolerance& tol) {
  const auto scaled = [&](const Vec<D>& e, const Vec<D>& a, const Vec<D>& b) {
    return (e.array() / (tol.atol + tol.rtol * a.cwiseAbs().cwiseMax(b.cwiseAbs()).array())).square().sum();
  };
  return std::sqrt((scaled(err.x, y0.x, y1.x) + scaled(err.v, y0.v, y1.v)) / static_cast<double>(2 * err.x.size()));
}

template <int D> State<D> axpy(const State<D>& y, double h, const State<D>& k) { return {y.x + h * k.x, y.v + h * k.v}; }

// Hairer's starting step: h0 = 0.01 |y0| / |f0| in the error norm, one explicit Euler step to
// estimate the second derivative d2, then h1 = (0.01 / max(|f0|, d2))^(1/5); take min(100 h0, h1).
template <Scene S> double initial_step(const S& s, const State<S::dim>& y0, const State<S::dim>& f0,
                                       const Tolerance& tol, double span, long long& evaluations) {
  constexpr int D = S::dim;
  const auto norm = [&](const State<D>& a) { return error_norm<D>(a, y0, y0, tol); };
  const double d0 = norm(y0), d1 = norm(f0);
  const double h0 = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
  const State<D> f1 = derivative(s, h0, axpy(y0, h0, f0));  // from t = 0
  ++evaluations;
  const double d2 = norm({f1.x - f0.x, f1.v - f0.v}) / h0;
  const double h1 = (d1 <= 1e-15 && d2 <= 1e-15) ? std::max(1e-6, h0 * 1e-3) : std::pow(0.01 / std::max(d1, d2), 0.2);
  return std::min({100 * h0, h1, span});
}

// f(t, y) = (v, a(t, x, v)) into k (sized): the stages' derivatives, in vectors the run keeps.
template <Scene S> void derivative_into(const S& s, double t, const State<S::dim>& y, State<S::dim>& k) {
  k.x = y.v;
  k.v = acceleration(s, t, y.x, y.v);
}

// Runs from 0 to spec.t_end; `observe(t, y)` after every accepted step (must not allocate).
// On a scene of run-time size the stages' vectors are made once, before the first step, and a
// step's temporaries come from the thread's scratch pool (core/scratch.hpp): after the first
// step a step allocates nothing (a sample's state does, at the samples).
template <Scene S, class Observer = NoObserver>
AdaptiveResult<S::dim> simulate_dopri5(const S& s, const AdaptiveSpec& spec, Observer&& observe = {}) {
  using namespace dp5;
  constexpr int D = S::dim;
  AdaptiveResult<D> out;
  RunResult<D>& r = out.run;
  AdaptiveStats& st = out.stats;
  State<D> y = s.initial();
  const double e0 = s.energy(y.x, y.v), blow_up = blow_up_energy(s, y, e0);
  r.energy0 = e0;
  RunTally<double> tally;  // no fit of ln E, no stop on E/E0
  ErrorSums<double> errors;
  const long long n_samples = spec.max_samples > 0 ? std::max(2LL, spec.max_samples) : 0;
  r.samples.reserve(static_cast<std::size_t>(n_samples));
  long long next_sample = 0;
  const auto sample_time = [&](long long k) { return spec.t_end * static_cast<double>(k) / static_cast<double>(n_samples - 1); };
  if (n_samples > 0) r.samples.push_back({0.0, y.x, y.v, e0}), next_sample = 1;
  // The exact state at an accepted step's end: where the scene's exact positions cost a transform
  // (HasExactAlong: the rope), its closed form at any t (jump) into the tracker's own vectors, the
  // velocities read once at the end, as a fixed-step run reads them (core/simulate.hpp).
  [[maybe_unused]] auto tracker = [&] {
    if constexpr (HasExactAlong<S>) return s.exact_along(0.0);
    else if constexpr (HasExact<S>) return ExactTracker<S>(s);
    else return 0;
  }();

  State<D> k1 = y, k2 = y, k3 = y, k4 = y, k5 = y, k6 = y, k7 = y, ys = y, y1 = y, err = y;
  derivative_into(s, 0.0, y, k1);
  st.force_evaluations = 1;
  double t = 0;
  double h = spec.t_end > 0 ? initial_step(s, y, k1, spec.tol, spec.t_end, st.force_evaluations) : 0;
  bool rejected_last = false;
  while (t < spec.t_end) {
    if (st.accepted + st.rejected >= spec.max_steps || h <= 10 * std::numeric_limits<double>::epsilon() * t) {
      r.status = RunStatus::NoConvergence;  // the step size collapsed: the tolerance cannot be met
      r.failed_step = st.accepted + 1;
      r.failed_t = t;
      break;
    }
    const bool last = t + h >= spec.t_end;
    if (last) h = spec.t_end - t;
    ys.x = y.x + (h * a21) * k1.x, ys.v = y.v + (h * a21) * k1.v;
    derivative_into(s, t + c2 * h, ys, k2);
    ys.x = y.x + h * (a31 * k1.x + a32 * k2.x), ys.v = y.v + h * (a31 * k1.v + a32 * k2.v);
    derivative_into(s, t + c3 * h, ys, k3);
    ys.x = y.x + h * (a41 * k1.x + a42 * k2.x + a43 * k3.x), ys.v = y.v + h * (a41 * k1.v + a42 * k2.v + a43 * k3.v);
    derivative_into(s, t + c4 * h, ys, k4);
    ys.x = y.x + h * (a51 * k1.x + a52 * k2.x + a53 * k3.x + a54 * k4.x);
    ys.v = y.v + h * (a51 * k1.v + a52 * k2.v + a53 * k3.v + a54 * k4.v);
    derivative_into(s, t + c5 * h, ys, k5);
    ys.x = y.x + h * (a61 * k1.x + a62 * k2.x + a63 * k3.x + a64 * k4.x + a65 * k5.x);
    ys.v = y.v + h * (a61 * k1.v + a62 * k2.v + a63 * k3.v + a64 * k4.v + a65 * k5.v);
    derivative_into(s, t + h, ys, k6);
    y1.x = y.x + h * (b1 * k1.x + b3 * k3.x + b4 * k4.x + b5 * k5.x + b6 * k6.x);
    y1.v = y.v + h * (b1 * k1.v + b3 * k3.v + b4 * k4.v + b5 * k5.v + b6 * k6.v);
    derivative_into(s, t + h, y1, k7);
    st.force_evaluations += 6;
    err.x = h * (e1 * k1.x + e3 * k3.x + e4 * k4.x + e5 * k5.x + e6 * k6.x + e7 * k7.x);
    err.v = h * (e1 * k1.v + e3 * k3.v + e4 * k4.v + e5 * k5.v + e6 * k6.v + e7 * k7.v);
    const double en = error_norm<D>(err, y, y1, spec.tol);
    if (!std::isfinite(en) || !all_finite(y1)) {  // a blow-up inside the step: shrink and retry
      ++st.rejected;
      rejected_last = true;
      h *= min_factor;
      continue;
    }
    if (en > 1) {
      ++st.rejected;
      rejected_last = true;
      h *= std::max(min_factor, safety * std::pow(en, -0.2));
      continue;
    }
    const double energy1 = s.energy(y1.x, y1.v);
    if (!within_blow_up(energy1, e0, blow_up)) {  // within its tolerance, yet blown up (core/simulate.hpp)
      r.status = RunStatus::Diverged;
      r.failed_step = st.accepted + 1;
      r.failed_t = t + h;
      break;
    }
    // Accepted. Dense output between t and t + h (CONTD5), for the sample times inside the step.
    const double t1 = last ? spec.t_end : t + h;
    while (next_sample < n_samples && sample_time(next_sample) <= t1) {
      const double ts = next_sample == n_samples - 1 ? spec.t_end : sample_time(next_sample);
      const double th = (ts - t) / h, th1 = 1 - th;
      const auto dense = [&](const Vec<D>& y0, const Vec<D>& yn, const Vec<D>& q1, const Vec<D>& q3, const Vec<D>& q4,
                             const Vec<D>& q5, const Vec<D>& q6, const Vec<D>& q7) -> Vec<D> {
        const Vec<D> dy = yn - y0, bspl = h * q1 - dy, r4 = dy - h * q7 - bspl;
        const Vec<D> r5 = h * (d1 * q1 + d3 * q3 + d4 * q4 + d5 * q5 + d6 * q6 + d7 * q7);
        return y0 + th * (dy + th1 * (bspl + th * (r4 + th1 * r5)));
      };
      const Vec<D> xs = dense(y.x, y1.x, k1.x, k3.x, k4.x, k5.x, k6.x, k7.x);
      const Vec<D> vs = dense(y.v, y1.v, k1.v, k3.v, k4.v, k5.v, k6.v, k7.v);
      r.samples.push_back({ts, xs, vs, s.energy(xs, vs)});
      ++next_sample;
    }
    st.h_min = std::min(st.h_min, h);
    st.h_max = std::max(st.h_max, h);
    ++st.accepted;
    t = t1;
    y = y1;
    std::swap(k1, k7);  // first same as last: k1 is k7, whose storage the next step overwrites
    tally.account(t, energy1, e0, true, e0 != 0, false, false);
    if constexpr (HasExactAlong<S>) {
      if (spec.errors) tracker.jump(), errors.add_positions(y.x, tracker.at(t));
    } else if constexpr (HasExact<S>) {
      if (spec.errors) errors.add(y, tracker.at(t), true);
    }
    observe(t, y);
    const double grow = en == 0 ? max_factor : std::min(max_factor, safety * std::pow(en, -0.2));
    h *= rejected_last ? std::min(1.0, grow) : grow;
    rejected_last = false;
  }
  if constexpr (HasExactAlong<S>) {
    if (spec.errors && st.accepted > 0) errors.error_v_final = (y.v - tracker.velocities()).norm();
  }
  r.steps = st.accepted;
  r.t_final = t;
  r.final = y;
  finish_run(r, HasExact<S> && spec.errors, errors, tally, false, r.steps);  // read every accepted step
  return out;
}

}  // namespace steplab
