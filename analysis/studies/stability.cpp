#include "analysis/studies/stability.hpp"

#include <array>
#include <cmath>
#include <complex>

#include <Eigen/Eigenvalues>

#include "analysis/kernel/kernel.hpp"
#include "analysis/kernel/shard.hpp"
#include "core/scenes/spring.hpp"

namespace steplab {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The anchor moved kAnchorShift amplitudes further away (linear_spring, stability.hpp). The
// stability question is about m u'' + gamma u' + k u = 0 (u = y - y_eq): M(h) depends on m, k
// and gamma only, not on L. With the anchor that far the oscillation stays on the linear side
// (y < 0) up to E/E0 = kAnchorShift^2, so a growing run measures the linear growth rate and not
// the spring's kink at the anchor; the motion in u is the same as with the user's L.
constexpr double kAnchorShift = 1000;

// Scan factors: the prediction is cheap and scans by 1.05; runs scan by 2 up to dt* (the first
// unstable step: bisection finds the edge). Beyond dt* stable windows can be narrow (yoshida4
// undamped has some), so both scan by 1.05 there.
constexpr double kPredictFactor = 1.05, kMeasureFactor = 2;

// A map row's task: the predicted dt* at its damping, and each cell measured and predicted.
struct MapRow {
  double boundary = 0;
  std::vector<char> stable, predicted;
};
template <class F> void encode_fields(MapRow& r, F&& f) {
  f(r.boundary);
  f(r.stable);
  f(r.predicted);
}

}  // namespace

const PairKernel& spring_kernel(std::size_t method) { return pair_kernel(method, scene_index(Spring::name)); }

bool runs_spring_study(const SceneKernel& scene) { return scene.name == Spring::name; }

Spring linear_spring(const std::vector<double>& params, double gamma) {
  std::vector<double> p = params;
  p[damping_param_index<Spring>()] = gamma;
  const Spring user(p);
  p[param_index(Spring::params, "rest-length")] = user.L + kAnchorShift * std::max(user.m * user.g / user.k, 1.0);
  return Spring(p);
}

namespace {

// The spring's step map (analysis/kernel/step_map.hpp) through the kernel table, differenced.
Eigen::MatrixXd differenced_matrix(std::size_t method, const Spring& s, double h, double delta_x) {
  // An implicit method's Newton starts from x0 + h v0: the velocity perturbation must not carry
  // that guess past the anchor either, or Newton may settle on the other linear branch.
  const double delta_v = std::min(delta_x, 0.1 * std::abs(s.equilibrium()) / std::max(1.0, h));
  const PairKernel& k = spring_kernel(method);
  const std::array<double, 5> p = s.values();
  const int n = method_kernel(method).map_size;
  const Eigen::VectorXd rest = k.at_rest_flat(p, s.equilibrium(), 0.0);
  const Eigen::VectorXd base = k.step_flat(p, rest, h);
  Eigen::MatrixXd m(n, n);
  for (int j = 0; j < n; ++j) {
    Eigen::VectorXd z = rest;
    const double delta = j % 2 == 0 ? delta_x : delta_v;
    z[j] += delta;
    m.col(j) = (k.step_flat(p, z, h) - base) / delta;
  }
  return m;
}

}  // namespace

// A differenced matrix with entries of size |M| carries errors of about eps |M|^2 (the step from
// equilibrium is off by eps |M| |y_eq|, divided by a perturbation of |y_eq| / |M|): past
// kTrustedEntry its eigenvalues are noise. Such a matrix is not that of a stable step anyway: on the
// spring M = V R(h Lambda) V^-1 with V fixed by (m, k, gamma), so rho <= 1 bounds |M| by cond(V)
// (at most ~1e3 here, at critical damping). yoshida4 undamped at omega h = 553 (|M| ~ 1e8) came
// out "stable" from such noise; exact arithmetic on its trace finds no stable window there.
constexpr double kTrustedEntry = 1e6;

bool trusted(const Eigen::MatrixXd& m) { return m.cwiseAbs().maxCoeff() <= kTrustedEntry; }  // false for NaN too

// Two passes: a tiny perturbation estimates |M|; then one a tenth of the distance to the anchor,
// divided by max(1, |M|), which keeps every state below the anchor (where the force is linear)
// and resolves M to ~eps |y_eq| / delta ~ 1e-14.
Eigen::MatrixXd step_matrix(std::size_t method, const Spring& s, double h) {
  const double room = 0.1 * std::max(std::abs(s.equilibrium()), 1e-6);
  const Eigen::MatrixXd rough = differenced_matrix(method, s, h, 1e-6 * room);
  // so large that the second pass's perturbation would vanish in y_eq's rounding: past any
  // trust (predicted_stable), and the rough matrix already says so
  if (!trusted(rough)) return rough;
  return differenced_matrix(method, s, h, room / std::max(1.0, rough.cwiseAbs().maxCoeff()));
}

// 2 x 2: eigenvalues of [[a, b], [c, d]] are tr/2 +- sqrt(tr^2/4 - det), and a complex pair has
// |lambda|^2 = det. Larger (a multistep method's companion matrix): Eigen's real Schur form.
double spectral_radius(const Eigen::MatrixXd& m) {
  if (m.rows() != 2) return Eigen::EigenSolver<Eigen::MatrixXd>(m, false).eigenvalues().cwiseAbs().maxCoeff();
  const double half_tr = 0.5 * m.trace(), det = m.determinant();
  const double disc = half_tr * half_tr - det;
  if (disc < 0) return std::sqrt(det);
  const double root = std::sqrt(disc);
  return std::max(std::abs(half_tr + root), std::abs(half_tr - root));
}

double predicted_rate(std::size_t method, const Spring& s, double h) {
  return 2 * std::log(spectral_radius(step_matrix(method, s, h))) / h;
}

bool predicted_stable(std::size_t method, const Spring& s, double h) {
  const double wh = s.omega() * h;
  const Eigen::MatrixXd m = step_matrix(method, s, h);
  if (!trusted(m)) return false;
  return spectral_radius(m) <= 1 + std::min(kRhoToleranceMax, kRhoTolerance * std::max(1.0, wh * wh));
}

StableSet predicted_stable_set(std::size_t method, const Spring& s, bool find_again) {
  const double w = s.omega();
  return stable_set(kPredictMinWh / w, kMaxWh / w, kPredictFactor, 1e-10,
                    [&](double h) { return !predicted_stable(method, s, h); }, find_again);
}

namespace {

RunSpec rate_spec(double h, long long steps, bool errors) {
  RunSpec spec;
  spec.dt = h;
  spec.steps = steps;
  spec.energy_rate = true;
  spec.errors = errors;
  spec.stop_above = 0.01 * kAnchorShift * kAnchorShift;  // well before the anchor
  spec.stop_below = 1e-20;
  return spec;
}

RateRun rate_run(const AnyResult& r) {
  const bool ok = r.status == RunStatus::Ok;
  return RateRun{r.energy_rate, r.energy_ratio_final, r.energy_ratio_max, ok ? r.error_final : kInf,
                 r.status,      r.steps,             r.failed_step};
}

}  // namespace

RateRun measure_rate(std::size_t method, const Spring& s, double h, long long steps) {
  return rate_run(spring_kernel(method).run(s.values(), rate_spec(h, steps, true)));
}

std::vector<RateRun> measure_rates(std::size_t method, const std::vector<Spring>& s, const std::vector<double>& h,
                                   long long steps, bool errors, int width) {
  std::vector<std::array<double, 5>> params(h.size());
  std::vector<BatchRun> runs(h.size());
  for (std::size_t i = 0; i < h.size(); ++i) {
    params[i] = s[i].values();
    runs[i] = {params[i], rate_spec(h[i], steps, errors)};
  }
  const std::vector<AnyResult> results = run_all(spring_kernel(method), runs, width);
  std::vector<RateRun> out;
  for (const AnyResult& r : results) out.push_back(rate_run(r));
  return out;
}

StableSet measured_stable_set(std::size_t method, const Spring& s, int width) {
  const double w = s.omega();
  // as run_all steps them: width 0 is the CPU's best; one at a time, asking ahead gains nothing
  const int ahead = spring_kernel(method).run_batch ? (width == 0 ? best_width() : width) : 1;
  return stable_set_batched(kMeasureMinWh / w, kMaxWh / w, kMeasureFactor, 1e-4, ahead, [&](const std::vector<double>& hs) {
    std::vector<char> unstable;
    for (const RateRun& r : measure_rates(method, std::vector<Spring>(hs.size(), s), hs, kRateSteps, false, width))
      unstable.push_back(!r.stable());
    return unstable;
  });
}

std::vector<double> default_dampings(const Spring& s) {
  std::vector<double> g;
  const double crit = s.critical_damping();
  for (int i = 0; i <= 20; ++i) g.push_back(2 * crit * i / 20.0);
  g.push_back(0.1);
  std::sort(g.begin(), g.end());
  return g;
}

std::vector<ThresholdRow> threshold_study(const StabilityConfig& c) {
  const std::size_t nm = c.methods.size(), ng = c.threshold_dampings.size();
  return study_map<ThresholdRow>(nm * ng, c.workers, [&](std::size_t task) {
    const std::size_t m = c.methods[task / ng];
    const double gamma = c.threshold_dampings[task % ng];
    const Spring s = linear_spring(c.params, gamma);
    const StableSet predicted = predicted_stable_set(m, s), measured = measured_stable_set(m, s, c.pack_width);
    return ThresholdRow{m, gamma, predicted.dt_star, measured.dt_star, predicted.again, measured.again};
  });
}

std::vector<SweepRow> damping_sweep(const StabilityConfig& c) {
  const std::vector<double> gammas =
      c.sweep_dampings.empty() ? default_dampings(linear_spring(c.params, c.params[damping_param_index<Spring>()])) : c.sweep_dampings;
  const std::size_t nm = c.methods.size(), nd = c.sweep_dts.size(), ng = gammas.size();
  std::vector<Spring> springs;
  for (double gamma : gammas) springs.push_back(linear_spring(c.params, gamma));
  // a task per (method, dt): its dampings
  const auto parts = study_map<std::vector<SweepRow>>(nm * nd, c.workers, [&](std::size_t task) {
    const std::size_t m = c.methods[task / nd];
    const double dt = c.sweep_dts[task % nd];
    const std::vector<RateRun> runs = measure_rates(m, springs, std::vector<double>(ng, dt), kRateSteps, true, c.pack_width);
    std::vector<SweepRow> rows;
    for (std::size_t g = 0; g < ng; ++g) rows.push_back({m, dt, gammas[g], runs[g], predicted_rate(m, springs[g], dt)});
    return rows;
  });
  std::vector<SweepRow> rows;
  for (const auto& part : parts) rows.insert(rows.end(), part.begin(), part.end());
  return rows;
}

StabilityMap stability_map(const StabilityConfig& c) {
  StabilityMap map;
  map.methods = c.methods;
  const Spring base = linear_spring(c.params, c.params[damping_param_index<Spring>()]);
  const double gmax = c.map_damping_max > 0 ? c.map_damping_max : 2 * base.critical_damping();
  for (int i = 0; i < c.map_dt_points; ++i)
    map.dt.push_back(c.map_dt_min * std::pow(c.map_dt_max / c.map_dt_min, i / double(std::max(1, c.map_dt_points - 1))));
  for (int j = 0; j < c.map_damping_points; ++j) map.damping.push_back(gmax * j / double(std::max(1, c.map_damping_points - 1)));
  const std::size_t nm = c.methods.size(), ng = map.damping.size(), nd = map.dt.size();
  // one task per (method, damping) row: its predicted dt* and every cell of the row
  const std::vector<MapRow> rows = study_map<MapRow>(nm * ng, c.workers, [&](std::size_t task) {
    const std::size_t mi = task / ng, gi = task % ng;
    const Spring s = linear_spring(c.params, map.damping[gi]);
    MapRow row{predicted_stable_set(c.methods[mi], s).dt_star, {}, {}};
    const std::vector<RateRun> runs = measure_rates(c.methods[mi], std::vector<Spring>(nd, s), map.dt, c.map_steps, false, c.pack_width);
    for (std::size_t di = 0; di < nd; ++di) {
      row.stable.push_back(runs[di].stable());
      row.predicted.push_back(predicted_stable(c.methods[mi], s, map.dt[di]));
    }
    return row;
  });
  map.boundary.assign(nm, std::vector<double>(ng));
  map.stable.assign(nm, std::vector<std::vector<bool>>(ng, std::vector<bool>(nd)));
  map.predicted = map.stable;
  for (std::size_t task = 0; task < rows.size(); ++task) {
    const std::size_t mi = task / ng, gi = task % ng;
    map.boundary[mi][gi] = rows[task].boundary;
    for (std::size_t di = 0; di < rows[task].stable.size(); ++di) {  // none in another shard's row
      map.stable[mi][gi][di] = rows[task].stable[di];
      map.predicted[mi][gi][di] = rows[task].predicted[di];
    }
  }
  return map;
}

std::size_t disagreeing_cells(const StabilityMap& map, std::size_t i) {
  std::size_t n = 0;
  for (std::size_t g = 0; g < map.damping.size(); ++g)
    for (std::size_t d = 0; d < map.dt.size(); ++d) n += map.stable[i][g][d] != map.predicted[i][g][d];
  return n;
}

AmplitudeTable amplitude_table(const std::vector<double>& params, const std::vector<std::size_t>& methods,
                               double step, int count) {
  AmplitudeTable t;
  t.methods = methods;
  const Spring s(params);
  const long long n = static_cast<long long>(10 / step);
  for (int i = 0; i < count; ++i) {
    const double h = step * std::pow(2.0, i);
    t.steps.push_back(h);
    std::vector<double> row;
    for (std::size_t m : methods) {
      RunSpec spec;
      spec.dt = h;
      spec.steps = n;
      spec.errors = false;
      // |y - L| with y < 0 is |y| + L: the largest |y| reached (from the rest start, |y| = L), plus L
      Observed o;
      const AnyResult r = spring_kernel(m).run_observed(params, spec, o);
      row.push_back(r.status == RunStatus::Ok ? std::max(s.L, o.max_abs_x) + s.L : kInf);
    }
    t.amplitude.push_back(std::move(row));
  }
  return t;
}

}  // namespace steplab
