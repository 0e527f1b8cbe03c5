#include "analysis/stability.hpp"

#include <cmath>
#include <complex>

#include "analysis/parallel.hpp"
#include "core/methods.hpp"

namespace steplab {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The spring with damping gamma and its anchor moved kAnchorShift amplitudes further away. The
// stability question is about m u'' + gamma u' + k u = 0 (u = y - y_eq): M(h) depends on m, k
// and gamma only, not on L. With the anchor that far the oscillation stays on the linear side
// (y < 0) up to E/E0 = kAnchorShift^2, so a growing run measures the linear growth rate and not
// the spring's kink at the anchor; the motion in u is the same as with the user's L.
constexpr double kAnchorShift = 1000;

Spring with_damping(const std::vector<double>& params, double gamma) {
  std::vector<double> p = params;
  p[2] = gamma;  // Spring::params: mass, stiffness, damping, rest-length, gravity
  const Spring user(p);
  p[3] = user.L + kAnchorShift * std::max(user.m * user.g / user.k, 1.0);
  return Spring(p);
}

State<1> step_once(std::size_t method, const Spring& s, State<1> y, double h) {
  with_method(method, [&]<class M>() { return M::step(s, y, 0.0, h); });
  return y;
}

// First h in (lo, hi] on a geometric scan by `factor` where `unstable(h)`; then bisection (in
// log h) down to relative `precision`. 0 if unstable at lo, inf if never.
template <class Unstable> double first_crossing(double lo, double hi, double factor, double precision, Unstable unstable) {
  if (unstable(lo)) return 0;
  double good = lo, bad = kInf;
  for (double h = lo * factor; h <= hi * (1 + 1e-12); h *= factor) {
    if (unstable(h)) {
      bad = h;
      break;
    }
    good = h;
  }
  if (!std::isfinite(bad)) return kInf;
  while (bad / good - 1 > precision) {
    const double mid = std::sqrt(good * bad);
    (unstable(mid) ? bad : good) = mid;
  }
  return good;
}

}  // namespace

namespace {

Mat<2> differenced_matrix(std::size_t method, const Spring& s, double h, double delta_x) {
  // An implicit method's Newton starts from x0 + h v0: the velocity perturbation must not carry
  // that guess past the anchor either, or Newton may settle on the other linear branch.
  const double delta_v = std::min(delta_x, 0.1 * std::abs(s.equilibrium()) / std::max(1.0, h));
  const State<1> eq{Vec<1>::Constant(s.equilibrium()), Vec<1>::Zero()};
  const State<1> base = step_once(method, s, eq, h);
  Mat<2> m;
  for (int j = 0; j < 2; ++j) {
    State<1> p = eq;
    const double delta = j == 0 ? delta_x : delta_v;
    (j == 0 ? p.x[0] : p.v[0]) += delta;
    const State<1> out = step_once(method, s, p, h);
    m(0, j) = (out.x[0] - base.x[0]) / delta;
    m(1, j) = (out.v[0] - base.v[0]) / delta;
  }
  return m;
}

}  // namespace

// Two passes: a tiny perturbation estimates |M|; then one a tenth of the distance to the anchor,
// divided by max(1, |M|), which keeps every state below the anchor (where the force is linear)
// and resolves M to ~eps |y_eq| / delta ~ 1e-14.
Mat<2> step_matrix(std::size_t method, const Spring& s, double h) {
  const double room = 0.1 * std::max(std::abs(s.equilibrium()), 1e-6);
  const Mat<2> rough = differenced_matrix(method, s, h, 1e-6 * room);
  return differenced_matrix(method, s, h, room / std::max(1.0, rough.cwiseAbs().maxCoeff()));
}

// Eigenvalues of [[a, b], [c, d]]: tr/2 +- sqrt(tr^2/4 - det); a complex pair has |lambda|^2 = det.
double spectral_radius(const Mat<2>& m) {
  const double half_tr = 0.5 * m.trace(), det = m.determinant();
  const double disc = half_tr * half_tr - det;
  if (disc < 0) return std::sqrt(det);
  const double root = std::sqrt(disc);
  return std::max(std::abs(half_tr + root), std::abs(half_tr - root));
}

double predicted_rate(std::size_t method, const Spring& s, double h) {
  return 2 * std::log(spectral_radius(step_matrix(method, s, h))) / h;
}

double predicted_threshold(std::size_t method, const Spring& s) {
  const double w = s.omega();
  return first_crossing(kPredictMinWh / w, kMaxWh / w, 1.05, 1e-10, [&](double h) {
    return spectral_radius(step_matrix(method, s, h)) > 1 + kRhoTolerance;
  });
}

RateRun measure_rate(std::size_t method, const Spring& s, double h, long long steps) {
  RunSpec spec;
  spec.dt = h;
  spec.steps = steps;
  spec.energy_rate = true;
  spec.stop_above = 0.01 * kAnchorShift * kAnchorShift;  // well before the anchor
  spec.stop_below = 1e-20;
  return with_method(method, [&]<class M>() {
    const RunResult<1> r = simulate<M>(s, spec);
    const bool ok = r.status == RunStatus::Ok;
    return RateRun{r.energy_rate, r.energy_ratio_final, r.energy_ratio_max, ok ? r.error_final : kInf,
                   r.status, r.steps, r.failed_step};
  });
}

double measured_threshold(std::size_t method, const Spring& s) {
  const double w = s.omega();
  return first_crossing(kMeasureMinWh / w, kMaxWh / w, 2.0, 1e-4,
                        [&](double h) { return !measure_rate(method, s, h).stable(); });
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
  std::vector<ThresholdRow> rows(nm * ng);
  parallel_for(nm * ng, c.threads, [&](std::size_t task) {
    const std::size_t m = c.methods[task / ng];
    const double gamma = c.threshold_dampings[task % ng];
    const Spring s = with_damping(c.params, gamma);
    rows[task] = {m, gamma, predicted_threshold(m, s), measured_threshold(m, s)};
  });
  return rows;
}

std::vector<SweepRow> damping_sweep(const StabilityConfig& c) {
  const std::vector<double> gammas =
      c.sweep_dampings.empty() ? default_dampings(with_damping(c.params, c.params[2])) : c.sweep_dampings;
  const std::size_t nm = c.methods.size(), nd = c.sweep_dts.size(), ng = gammas.size();
  std::vector<SweepRow> rows(nm * nd * ng);
  parallel_for(rows.size(), c.threads, [&](std::size_t task) {
    const std::size_t m = c.methods[task / (nd * ng)];
    const double dt = c.sweep_dts[(task / ng) % nd], gamma = gammas[task % ng];
    const Spring s = with_damping(c.params, gamma);
    rows[task] = {m, dt, gamma, measure_rate(m, s, dt), predicted_rate(m, s, dt)};
  });
  return rows;
}

StabilityMap stability_map(const StabilityConfig& c) {
  StabilityMap map;
  map.methods = c.methods;
  const Spring base = with_damping(c.params, c.params[2]);
  const double gmax = c.map_damping_max > 0 ? c.map_damping_max : 2 * base.critical_damping();
  for (int i = 0; i < c.map_dt_points; ++i)
    map.dt.push_back(c.map_dt_min * std::pow(c.map_dt_max / c.map_dt_min, i / double(std::max(1, c.map_dt_points - 1))));
  for (int j = 0; j < c.map_damping_points; ++j) map.damping.push_back(gmax * j / double(std::max(1, c.map_damping_points - 1)));
  const std::size_t nm = c.methods.size(), ng = map.damping.size(), nd = map.dt.size();
  std::vector<char> cells(nm * ng * nd);
  map.boundary.assign(nm, std::vector<double>(ng));
  // one task per (method, damping) row: its predicted dt* and every cell of the row
  parallel_for(nm * ng, c.threads, [&](std::size_t task) {
    const std::size_t mi = task / ng, gi = task % ng;
    const Spring s = with_damping(c.params, map.damping[gi]);
    map.boundary[mi][gi] = predicted_threshold(c.methods[mi], s);
    for (std::size_t di = 0; di < nd; ++di)
      cells[task * nd + di] = measure_rate(c.methods[mi], s, map.dt[di], c.map_steps).stable();
  });
  map.stable.assign(nm, std::vector<std::vector<bool>>(ng, std::vector<bool>(nd)));
  for (std::size_t i = 0; i < cells.size(); ++i) map.stable[i / (ng * nd)][(i / nd) % ng][i % nd] = cells[i];
  return map;
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
      double max_abs_y = s.L;
      const auto observe = [&](long long, double, const State<1>& y) { max_abs_y = std::max(max_abs_y, std::abs(y.x[0])); };
      const RunResult<1> r = with_method(m, [&]<class M>() { return simulate<M>(s, spec, observe); });
      row.push_back(r.status == RunStatus::Ok ? max_abs_y + s.L : kInf);
    }
    t.amplitude.push_back(std::move(row));
  }
  return t;
}

}  // namespace steplab
