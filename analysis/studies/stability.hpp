// Stability on the linear spring (y below the anchor): prediction from each method's own step
// matrix, measurement from long runs, and the two side by side.
//
// Prediction. On the linear spring a step is affine, (y, v) -> M(h) (y, v) + c, with the
// equilibrium as its fixed point. M is read off the implementation: step the equilibrium
// perturbed along each unit vector and subtract (so it stays true for every method in the
// table). From it:
//   rho(h)       spectral radius of M
//   rate(h)      2 ln(rho) / h, the energy's predicted growth rate per unit time
//                (the energy is quadratic in the state, which grows like rho^n)
//   dt*          the largest h with rho <= 1 on all of (0, h]: infinite for a method stable at
//                every step, 0 where no step is stable (explicit Euler and explicit midpoint
//                without damping: |R(i w h)| > 1 for every h > 0).
// Measurement. The least-squares slope of ln E against t over a run of kRateSteps steps from the
// rest start (E the oscillation energy about equilibrium). Where E oscillates (the partitioned
// methods, or any method with damping) the slope is biased by about 12 A / (Omega T^2) for an
// oscillation of amplitude A in ln E at frequency Omega over a time T; with 60 000 steps that is
// below 1e-7 for every h >= 0.01 on the default spring, under the tolerance kStableRate.
// A run is measured stable if its rate is <= kStableRate. A run stops early when E/E0 passes
// 1e4 (unstable) or falls below 1e-20 (decayed, before round-off flattens ln E). Runs use the
// spring with its anchor moved far away (linear_spring below), so that the motion about
// equilibrium stays linear: the prediction is about the linear oscillator, and so is the measurement.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "analysis/kernel/parallel.hpp"
#include "core/simulate.hpp"

namespace steplab {

template <class T> struct SpringT;  // core/scenes/spring.hpp: included where a spring is made or asked
using Spring = SpringT<double>;
struct PairKernel;  // analysis/kernel/kernel.hpp

inline constexpr double kStableRate = 1e-6;        // per unit time: E changes < 0.1 % over 1000 time units
inline constexpr long long kRateSteps = 60'000;
// Round-off in rho from a differenced step matrix: 1e-12, times (omega h)^2 past omega h = 1, the
// growth of the condition number of an implicit method's stage system (measured on
// gauss_legendre4: rho - 1 = 3e-13 at omega h = 45, 1.5e-10 at 670), at most kRhoToleranceMax.
inline constexpr double kRhoTolerance = 1e-12, kRhoToleranceMax = 1e-9;

// Method m's compiled code on the spring scene (analysis/kernel/kernel.hpp): what every stability run,
// step map and check on the spring goes through.
const PairKernel& spring_kernel(std::size_t method);

// The spring of `params` (Spring's table order) with damping gamma and its anchor moved so far
// away that every run of the studies stays on its linear side: what every stability run uses.
Spring linear_spring(const std::vector<double>& params, double gamma);

// The matrix of the whole step map: 2 x 2 on (y, v) for a one-step method; for a multistep
// method the companion matrix on (y, v and its memory), 2 (1 + K) square.
Eigen::MatrixXd step_matrix(std::size_t method, const Spring& s, double h);
double spectral_radius(const Eigen::MatrixXd& m);
double predicted_rate(std::size_t method, const Spring& s, double h);   // 2 ln(rho) / h

// Smallest and largest steps the threshold searches consider, in units of 1/omega.
inline constexpr double kPredictMinWh = 1e-2, kMeasureMinWh = 2e-2, kMaxWh = 1e3;

// Where a method is stable. The stable set need not be an interval (BDF3 on the undamped spring
// grows at small steps and is stable again at large ones), so besides dt* ("the largest h stable
// on all of (0, h]": 0 if unstable at the smallest h tried, inf if never unstable) it says where
// stability comes back: the smallest h > dt* stable again (inf if none up to kMaxWh / omega).
struct StableSet {
  double dt_star, again;
};

// The stable set of h on a geometric scan from lo to hi (by `factor` up to the first unstable
// step, then by kAgainFactor), each edge then bisected (in log h) down to relative `precision`:
//   dt*    the largest h with every step in [lo, h] stable: 0 if unstable at lo, inf if never;
//   again  the smallest h > dt* from which the scan finds stable steps again (inf if none up to
//          hi; not looked for if !find_again). The scan beyond dt* goes by 1.05: stable windows
//          there can be narrow (yoshida4 undamped has some).
// unstable(hs) gives the verdicts at the steps hs (a vector<char>, true: unstable), which a study
// runs as one batch, several at a time in SIMD packs. With ahead > 1 the searches ask ahead of
// the verdicts they wait for: a scan the next `ahead` steps at once (those past the one it stops
// at are not used), a bisection with its midpoint the two midpoints the next round could take,
// so two rounds at a time. The steps tried and the result are those of asking one at a time
// (ahead = 1): each h is computed by the same operations, and a verdict only ever decides what
// it decides there.
template <class Unstable>
StableSet stable_set_batched(double lo, double hi, double factor, double precision, int ahead, Unstable unstable,
                             bool find_again = true) {
  constexpr double kInf = std::numeric_limits<double>::infinity(), kAgainFactor = 1.05;
  const double top = hi * (1 + 1e-12);
  const auto wide = [&](double a, double b) { return std::max(a, b) / std::min(a, b) - 1 > precision; };
  const auto bisect = [&](double good, double bad) {  // the edge between a stable and an unstable h
    while (wide(good, bad)) {
      const double mid = std::sqrt(good * bad);
      std::vector<double> hs{mid};
      const bool down = ahead > 1 && wide(good, mid), up = ahead > 1 && wide(mid, bad);  // the next round's, either way
      if (down) hs.push_back(std::sqrt(good * mid));
      if (up) hs.push_back(std::sqrt(mid * bad));
      const std::vector<char> v = unstable(hs);
      if (v[0]) {
        bad = mid;
        if (down) (v[1] ? bad : good) = hs[1];
      } else {
        good = mid;
        if (up) (v.back() ? bad : good) = hs.back();
      }
    }
    return good;
  };
  // The first h of h, h f, h f^2, ... (up to top) whose verdict is `want`; h > top if there is
  // none. `before` becomes the step tried last before it (left as given if it is the first).
  const auto first = [&](double h, double f, bool want, double& before) {
    while (h <= top) {
      std::vector<double> hs;
      for (double g = h; g <= top && std::ssize(hs) < ahead; g *= f) hs.push_back(g);
      const std::vector<char> v = unstable(hs);
      for (std::size_t i = 0; i < hs.size(); ++i) {
        if (static_cast<bool>(v[i]) == want) return hs[i];
        before = hs[i];
      }
      h = hs.back() * f;
    }
    return h;
  };
  StableSet out{kInf, kInf};
  double last_good = 0;
  const double h = first(lo, factor, true, last_good);
  if (h > top) return out;  // stable everywhere scanned
  out.dt_star = last_good == 0 ? 0 : bisect(last_good, h);
  if (!find_again) return out;
  double last_bad = h;
  const double again = first(h * kAgainFactor, kAgainFactor, false, last_bad);
  if (again <= top) out.again = bisect(again, last_bad);
  return out;
}
// The same, the verdict asked at one step at a time: unstable(h) is a bool.
template <class Unstable>
StableSet stable_set(double lo, double hi, double factor, double precision, Unstable unstable, bool find_again = true) {
  return stable_set_batched(lo, hi, factor, precision, 1, [&](const std::vector<double>& hs) {
    std::vector<char> v;
    for (double h : hs) v.push_back(unstable(h));
    return v;
  }, find_again);
}

// Predicted stable at step h: the step matrix's spectral radius <= 1 (within kRhoTolerance).
bool predicted_stable(std::size_t method, const Spring& s, double h);

// From the step matrix: h scanned geometrically by 1.05 from kPredictMinWh/omega, each edge
// bisected to 1e-10 relative. (The predicted and measured dt* are compared in the tests.)
StableSet predicted_stable_set(std::size_t method, const Spring& s, bool find_again = true);

struct RateRun {
  double rate;               // least-squares d ln E / dt
  double energy_ratio_final, energy_ratio_max;
  double error_final;        // position error against the exact solution (inf if it blew up)
  RunStatus status;
  long long steps, failed_step;
  // Not growing. A NaN rate (fewer than two energies to fit: the energy vanished within a step,
  // as the exact flow does at a huge step with strong damping) is not growth.
  bool stable() const { return !(rate > kStableRate) && status == RunStatus::Ok; }
};

RateRun measure_rate(std::size_t method, const Spring& s, double h, long long steps = kRateSteps);
// Runs (s[i], h[i]), with the position error against the exact solution along each run or
// (errors false) without it (error_final 0); `width` steps them in SIMD packs where the method
// has packed kernels, 1 one at a time (run_all in analysis/kernel/kernel.hpp): the same numbers.
std::vector<RateRun> measure_rates(std::size_t method, const std::vector<Spring>& s, const std::vector<double>& h,
                                   long long steps, bool errors, int width = 0);

// From runs (measure_rates): h scanned by factors of 2 from kMeasureMinWh/omega up to dt*, by
// 1.05 beyond it, each edge bisected to 1e-4 relative. `width` as measure_rates': where the
// method's runs are packed (width > 1), the searches ask ahead a pack's width of steps at once
// (stable_set_batched), with the result of asking one at a time.
StableSet measured_stable_set(std::size_t method, const Spring& s, int width = 1);

inline double predicted_threshold(std::size_t method, const Spring& s) { return predicted_stable_set(method, s).dt_star; }
inline double measured_threshold(std::size_t method, const Spring& s) { return measured_stable_set(method, s).dt_star; }

// ---- the studies ----

struct ThresholdRow {
  std::size_t method;
  double damping, dt_theory, dt_measured;
  double again_theory, again_measured;  // stable again from here on (StableSet::again)
};

struct SweepRow {
  std::size_t method;
  double dt, damping;
  RateRun run;
  double rate_theory;
};

struct StabilityMap {
  std::vector<double> dt, damping;
  std::vector<std::size_t> methods;
  std::vector<std::vector<std::vector<bool>>> stable;   // [method][damping][dt]
  std::vector<std::vector<std::vector<bool>>> predicted;  // [method][damping][dt]: rho <= 1
  std::vector<std::vector<double>> boundary;            // [method][damping]: predicted dt*
};

// The cells of method i's map whose measured verdict differs from the prediction at that cell.
std::size_t disagreeing_cells(const StabilityMap& map, std::size_t i);

// Whether a scene of the table is the one this study runs on: its thresholds, sweep and map are
// made on the spring itself (linear_spring), so they take the spring's parameters and no other
// scene's; a scene's stability otherwise comes from its modes (analysis/studies/mode_stability.hpp).
struct SceneKernel;
bool runs_spring_study(const SceneKernel& scene);

struct StabilityConfig {
  std::vector<double> params;                  // Spring parameters, table order (damping replaced per row)
  std::vector<std::size_t> methods;
  std::vector<double> threshold_dampings{0, 0.1, 1, 4};
  std::vector<double> sweep_dts{0.01, 0.05, 0.2};
  std::vector<double> sweep_dampings;          // empty: default_dampings()
  int map_dt_points = 64, map_damping_points = 64;
  double map_dt_min = 0.01, map_dt_max = 10;   // log-spaced
  double map_damping_max = 0;                  // 0: twice critical damping
  long long map_steps = kRateSteps;
  Workers workers;  // threads (0: all cores), progress, shard log
  int pack_width = 0;  // runs stepped together in SIMD lanes (run_all, analysis/kernel/kernel.hpp): 0 the CPU's best, 2, 4, 8, or 1 (one at a time); the same numbers
};

// 0 through critical damping 2 sqrt(k m) to twice that (21 values), plus 0.1.
std::vector<double> default_dampings(const Spring& s);

std::vector<ThresholdRow> threshold_study(const StabilityConfig& c);
std::vector<SweepRow> damping_sweep(const StabilityConfig& c);
StabilityMap stability_map(const StabilityConfig& c);

// The old framework's stability_measurement: each method from rest, N = (int)(10 / step) steps,
// the step doubled `count` times with N fixed; the max over the run of |y - L| (inf if it blew up).
struct AmplitudeTable {
  std::vector<double> steps;
  std::vector<std::size_t> methods;            // the analytic solution is column 0 if listed
  std::vector<std::vector<double>> amplitude;  // [step][method]
};
AmplitudeTable amplitude_table(const std::vector<double>& params, const std::vector<std::size_t>& methods,
                               double step, int count);

}  // namespace steplab
