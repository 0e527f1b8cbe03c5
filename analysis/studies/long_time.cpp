#include "analysis/studies/long_time.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "analysis/fits/fit.hpp"
#include "analysis/kernel/shard.hpp"
#include "analysis/studies/defaults.hpp"

namespace steplab {
namespace {

// The step counts of the samples: 10^(j / per_decade) periods for j = 0, 1, ... up to `periods`
// (and `periods` itself last), rounded to whole periods (the exact motion is then at the same
// point of its orbit at every sample: the position error's growth is read without the orbit's
// own oscillation in it), each once.
std::vector<long long> sample_steps(double periods, int per_decade, int steps_per_period) {
  std::vector<long long> at;
  const auto add = [&](double p) {
    const long long n = std::max(1LL, std::llround(p)) * steps_per_period;
    if (at.empty() || n > at.back()) at.push_back(n);
  };
  for (int j = 0;; ++j) {
    const double p = std::pow(10.0, static_cast<double>(j) / per_decade);
    if (p >= periods * (1 - 1e-12)) break;
    add(p);
  }
  add(periods);
  return at;
}

// log10 y against log10 t over the samples from `from` periods on with y > 0 (and below `cap`).
GrowthFit fit_growth(const std::vector<double>& t, const std::vector<double>& y, double from, double cap) {
  std::vector<double> lx, ly;
  for (std::size_t k = 0; k < y.size(); ++k)
    if (t[k] >= from * (1 - 1e-12) && y[k] > 0 && y[k] < cap) lx.push_back(std::log10(t[k])), ly.push_back(std::log10(y[k]));
  GrowthFit g;
  if (lx.size() < 3) return g;
  const LineFit f = fit_line(lx, ly);
  g.fitted = true, g.exponent = f.slope, g.lo = f.ci95_lo, g.hi = f.ci95_hi;
  return g;
}

// When the position error first reaches `extent`: between the two samples that bracket it, the
// error taken as a power of t there; else from the fitted growth past the last sample.
void out_of_phase(LongTimeRow& r, double extent) {
  const std::vector<double>& e = r.position_error;
  for (std::size_t k = 0; k < e.size(); ++k) {
    if (e[k] < extent) continue;
    if (k == 0 || !(e[k - 1] > 0)) {
      r.out_of_phase = r.times[k];
    } else {
      const double s = std::log(e[k] / e[k - 1]) / std::log(r.times[k] / r.times[k - 1]);
      r.out_of_phase = r.times[k - 1] * std::pow(extent / e[k - 1], 1 / s);
    }
    return;
  }
  if (!e.empty() && r.status == RunStatus::Ok && r.position_growth.fitted && r.position_growth.exponent > 0.1 && e.back() > 0) {
    r.out_of_phase = r.times.back() * std::pow(extent / e.back(), 1 / r.position_growth.exponent);
    r.out_of_phase_extrapolated = true;
  }
}

}  // namespace

LongTimeConfig default_long_time_config(std::size_t scene) {
  LongTimeConfig c;
  c.scene = scene;
  c.params = default_param_values(scene);
  for (std::size_t m : ode_methods())
    if (applies(m, scene)) c.methods.push_back(m);
  c.steps_per_period = {kLongTimeDefaultStepsPerPeriod};
  for (const auto& [n, steps] : kLongTimeStepsPerPeriod)
    if (scene_name(scene) == n) c.steps_per_period = {steps};
  return c;
}

LongTimeResult long_time_study(const LongTimeConfig& c) {
  const SceneKernel& sk = scene_kernel(c.scene);
  if (!sk.period) throw std::invalid_argument("long-time study: the scene declares no invariants");
  LongTimeResult out;
  out.config = c;
  out.invariants.assign(sk.invariant_names.begin(), sk.invariant_names.end());
  out.period = sk.period(c.params);
  out.extent = sk.extent(c.params);
  out.has_exact = sk.exact != nullptr;
  for (std::size_t m : c.methods)
    for (int n : c.steps_per_period) {
      LongTimeRow r;
      r.method = m, r.steps_per_period = n, r.dt = out.period / n;
      out.rows.push_back(r);
    }
  // The dearest runs first (the implicit methods'), so that none starts last alone.
  std::vector<std::size_t> order(out.rows.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return method_info(out.rows[a].method).implicit > method_info(out.rows[b].method).implicit;
  });
  constexpr double u = 0x1p-53;
  // One task a row, through study_map: a shard (analysis/kernel/shard.hpp) runs its part of them.
  out.rows = study_map<LongTimeRow>(out.rows.size(), c.workers, [&](std::size_t i) {
    LongTimeRow r = out.rows[i];
    InvariantsRunSpec spec;
    spec.dt = r.dt;
    spec.at = sample_steps(c.periods, c.samples_per_decade, r.steps_per_period);
    spec.settings = c.settings;
    const InvariantsRun run = pair_kernel(r.method, c.scene).invariants_run(c.params, spec);
    r.status = run.status;
    r.ended = static_cast<double>(run.steps) / r.steps_per_period;
    const std::size_t reached = run.largest.empty() ? 0 : run.largest[0].size();
    for (std::size_t k = 0; k < reached; ++k) r.times.push_back(static_cast<double>(spec.at[k]) / r.steps_per_period);
    for (std::size_t q = 0; q < run.largest.size(); ++q) {
      const double scale = run.invariant0[q] != 0 ? std::abs(run.invariant0[q]) : 1;
      std::vector<double> rel;
      for (double e : run.largest[q]) rel.push_back(e / scale);
      r.growth.push_back(fit_growth(r.times, rel, c.fit_from, std::numeric_limits<double>::infinity()));
      r.round_off.push_back(!rel.empty() && run.status == RunStatus::Ok &&
                            rel.back() <= kRoundOff * u * std::sqrt(static_cast<double>(spec.at.back())));
      r.error.push_back(std::move(rel));
      r.change.push_back((run.last[q] - run.invariant0[q]) / scale);
    }
    r.position_error = run.position_error;
    if (!r.position_error.empty()) {
      r.position_growth = fit_growth(r.times, r.position_error, c.fit_from, out.extent / 10);
      out_of_phase(r, out.extent);
    }
    return r;
  }, order);
  return out;
}

}  // namespace steplab
