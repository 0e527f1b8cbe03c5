// The report's studies and its findings (reports/document/report.hpp).
#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include <fmt/format.h>

#include "analysis/kernel/parallel.hpp"
#include "analysis/kernel/kernel.hpp"
#include "analysis/peers/peers.hpp"
#include "core/scenes/spring.hpp"
#include "reports/document/report.hpp"

namespace steplab {
namespace {

std::vector<double> with_values(std::vector<double> v, std::initializer_list<double> extra) {
  v.insert(v.end(), extra);
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

// On a scene the report's own roles do not name (a user's), its default parameters; the methods
// that run on it (not the exact flow on a scene without an exact solution).
ConvergenceConfig convergence_config(const ReportData& d, std::size_t scene) {
  ConvergenceConfig cc = d.config.convergence;  // its step sweep
  cc.scene = scene;
  cc.params = default_param_values(scene);
  for (const ReportScene* s : d.config.scenes())
    if (s->scene == scene) cc.params = s->params;
  for (std::size_t m : d.methods)
    if (applies(m, scene)) cc.methods.push_back(m);
  cc.workers = d.workers;
  return cc;
}

// A run of `method` on the scene `scene` with its parameter values, as a result of the scene's size D.
template <int D> RunResult<D> figure_run(std::size_t method, std::size_t scene, const std::vector<double>& params,
                                         double dt, double t_end, long long samples) {
  RunSpec spec;
  spec.dt = dt;
  spec.steps = steps_for(t_end, dt);
  spec.max_samples = samples;
  spec.errors = false;
  return to_fixed<D>(pair_kernel(method, scene).run(params, spec));
}

// The scaling study of a scene of the report's sizes (analysis/studies/scaling.hpp): the scene's defaults,
// as `study scaling --scene ...` has them, at the report's error, on the methods that run on it.
ScalingConfig scaling_config_for(const ReportData& d, const ReportSizes& s) {
  ScalingConfig c = scaling_config(scene_name(s.scene));
  c.sizes = s.sizes;
  c.targets = {{d.config.scaling_error, false}};
  c.timing_seconds = kTimingSeconds;  // the report's timing budget per run (analysis/studies/convergence.hpp)
  c.t_end = d.config.scaling_t_end;
  for (std::size_t m : d.numerical_methods())
    if (applies(m, s.scene)) c.methods.push_back(m);  // a scene without Jacobians: the explicit methods
  c.timing = d.config.timing;
  c.workers = d.workers;
  return c;
}

// The peers on the map: CVODE as its guide would set it up for stiff oscillations, Adams or BDF of
// orders 1-2 (A-stable); its BDF of orders up to 5, unstable near the imaginary axis, crawls over
// the stiff scenes' lightly damped fast modes (up to 200 000 steps a run at K 5000, N 128), which
// the scaling study above already shows; and the explicit adaptive solvers.
bool map_peer(const PeerInfo& p) {
  return !p.is_cvode() || p.cvode.adams || (p.cvode.max_order >= 1 && p.cvode.max_order <= 2);
}

// The map's study: the scene at the map's sizes, stiffened, at the report's error and the visual one.
ScalingConfig scaling_map_config(const ReportData& d, const ReportSizes& s) {
  ScalingConfig c = scaling_config_for(d, s);
  const SceneKernel& k = scene_kernel(s.scene);
  c.sizes = d.config.scaling_map_sizes;
  for (double f : d.config.scaling_stiffening) c.stiffnesses.push_back(f * c.params[static_cast<std::size_t>(k.stiffness_param)]);
  c.targets.push_back({d.config.scaling_visual, true});
  c.max_steps = kReportMapSteps;
  std::erase_if(c.adaptive, [](const std::string& a) { return !map_peer(*find_peer(a)); });
  return c;
}

}  // namespace

const ConvergenceResult& ReportData::convergence_on(std::size_t scene) const {
  for (const ConvergenceResult& r : convergence)
    if (r.config.scene == scene) return r;
  throw std::out_of_range(fmt::format("the report ran no convergence study on {}", scene_name(scene)));
}

std::vector<std::size_t> ReportData::numerical_methods() const {
  std::vector<std::size_t> out;
  for (std::size_t m : methods)
    if (!method_info(m).exact_flow) out.push_back(m);
  return out;
}

ReportData run_report_studies(const ReportConfig& c, unsigned studies, ProgressHook progress) {
  ReportData d;
  d.config = c;
  d.workers = {c.threads, progress, nullptr};
  d.studies = studies;
  d.methods = c.methods;
  const double gamma = c.damping();
  const std::size_t damping = static_cast<std::size_t>(scene_kernel(c.oscillator.scene).damping_param);

  if (studies & kConvergenceStudy)
    for (std::size_t s : c.convergence_scenes()) d.convergence.push_back(convergence_study(convergence_config(d, s)));

  // The stability study is the damped spring's (analysis/studies/stability.hpp): the oscillator is one.
  const Spring spring(c.oscillator.params);
  StabilityConfig sc = c.stability;  // its dampings and steps with the sheet's, and the map
  sc.params = c.oscillator.params;
  sc.methods = d.methods;
  sc.threshold_dampings = with_values(c.stability.threshold_dampings, {0.0, gamma});
  sc.sweep_dts = with_values(c.stability.sweep_dts, {c.large_dt, c.small_dt});
  sc.sweep_dampings = with_values(default_dampings(spring), {0.0, gamma});
  sc.workers = d.workers;
  if (studies & kStabilityStudy) {
    d.thresholds = threshold_study(sc);
    d.sweep = damping_sweep(sc);
    d.map = stability_map(sc);
  }

  CollisionConfig cc = c.collision;  // its steps and time
  cc.rebound_scene = c.rebound.scene;
  cc.rebound_params = c.rebound.params;
  cc.body_scene = c.body.scene;
  cc.body_params = c.body.params;
  cc.methods = d.numerical_methods();
  cc.workers = d.workers;
  if (studies & kCollisionStudy) d.collision = collision_study(cc);

  WorkPrecisionConfig wc = c.work_precision;  // its sweeps
  wc.methods = d.numerical_methods();
  wc.timing = c.timing;
  wc.workers = d.workers;
  if (studies & kWorkPrecisionStudy) d.work = work_precision_study(wc);

  if ((studies & kStiffOrderStudy) && c.covers(c.stiffened.scene)) {
    ConvergenceConfig so = stiff_order_config(c.stiffened.scene, c.stiffened.params, c.stiff_order, d.numerical_methods());
    so.workers = d.workers;
    d.stiff_order = order_reduction(so, c.stiff_order.stiffnesses);
  }
  if (studies & kScalingStudy)
    for (const ReportSizes& s : c.scaling)
      if (c.covers(s.scene)) {
        if (d.scaling.empty() && scene_kernel(s.scene).stiffness_param >= 0 && !c.scaling_map_sizes.empty())
          d.scaling_map = scaling_study(scaling_map_config(d, s));
        d.scaling.push_back(scaling_study(scaling_config_for(d, s)));
      }

  if (studies & kLongTimeStudy)
    for (const auto& [result, name] : {std::pair{&d.long_time_orbit, kLongTimeScene}, {&d.long_time_swing, kLongTimeSheetScene}})
      if (const auto s = find_scene(name); s && c.covers(*s)) {
        LongTimeConfig lc = default_long_time_config(*s);
        std::erase_if(lc.methods, [&](std::size_t m) { return std::find(d.methods.begin(), d.methods.end(), m) == d.methods.end(); });
        lc.periods = c.long_time_periods;
        lc.workers = d.workers;
        *result = long_time_study(lc);
      }

  // Figures: the cannon ball's path and the spring's y(t) (kSceneFigures); the energy at the large
  // step, undamped and damped, and the predicted growth rate against damping on a fine grid (kStabilityStudy).
  if (!(studies & (kSceneFigures | kStabilityStudy))) return d;
  std::vector<double> undamped = c.oscillator.params;
  undamped[damping] = 0;
  const std::size_t nm = d.methods.size(), nf = c.spring_figure_dts.size();
  d.cannon.resize(nm);
  d.spring.assign(nf, std::vector<RunResult<1>>(nm));
  d.energy.resize(nm);
  d.energy_damped.resize(nm);
  for (int i = 0; i <= 200; ++i) d.curve_damping.push_back(2 * spring.critical_damping() * i / 200.0);
  d.curve_rate.assign(nm, std::vector<double>(d.curve_damping.size()));
  parallel_for(nm * (2 + nf + 1), d.workers, [&](std::size_t task) {
    const std::size_t m = task % nm, kind = task / nm;
    const std::size_t osc = c.oscillator.scene;
    const std::size_t method = d.methods[m];
    const bool stability = studies & kStabilityStudy;
    const bool figures = studies & kSceneFigures, cannon = figures && c.covers(c.projectile.scene),
               springs = figures && c.covers(osc);
    if (kind == 0) {
      if (cannon) d.cannon[m] = figure_run<2>(method, c.projectile.scene, c.projectile.params, c.cannonball_dt, c.cannonball_t_end, 2001);
    } else if (kind == 1) {
      if (stability) {
        d.energy[m] = figure_run<1>(method, osc, undamped, c.large_dt, c.energy_t_end, 2001);
        d.energy_damped[m] = figure_run<1>(method, osc, c.oscillator.params, c.large_dt, c.energy_t_end, 2001);
      }
    } else if (kind < 2 + nf) {
      if (springs)
        d.spring[kind - 2][m] =
            figure_run<1>(method, osc, c.oscillator.params, c.spring_figure_dts[kind - 2], c.spring_figure_t_end, 2001);
    } else if (stability) {
      for (std::size_t g = 0; g < d.curve_damping.size(); ++g) {
        std::vector<double> p = c.oscillator.params;
        p[damping] = d.curve_damping[g];
        d.curve_rate[m][g] = predicted_rate(method, Spring(p), c.large_dt);
      }
    }
  });
  return d;
}

std::vector<double> average_ranks(const std::vector<double>& x) {
  std::vector<std::size_t> idx(x.size());
  std::iota(idx.begin(), idx.end(), 0);
  std::sort(idx.begin(), idx.end(), [&](std::size_t i, std::size_t j) { return x[i] < x[j]; });
  std::vector<double> r(x.size());
  for (std::size_t i = 0; i < idx.size();) {
    std::size_t j = i;
    while (j + 1 < idx.size() && x[idx[j + 1]] == x[idx[i]]) ++j;
    for (std::size_t k = i; k <= j; ++k) r[idx[k]] = 0.5 * static_cast<double>(i + j) + 1;
    i = j + 1;
  }
  return r;
}

double spearman(const std::vector<double>& a, const std::vector<double>& b) {
  const std::vector<double> ra = average_ranks(a), rb = average_ranks(b);
  const double n = static_cast<double>(a.size());
  const double ma = std::accumulate(ra.begin(), ra.end(), 0.0) / n, mb = std::accumulate(rb.begin(), rb.end(), 0.0) / n;
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < ra.size(); ++i) {
    sab += (ra[i] - ma) * (rb[i] - mb);
    saa += (ra[i] - ma) * (ra[i] - ma);
    sbb += (rb[i] - mb) * (rb[i] - mb);
  }
  return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 0.0;
}

const ThresholdRow* find_threshold(const ReportData& d, std::size_t method, double damping) {
  for (const ThresholdRow& r : d.thresholds)
    if (r.method == method && r.damping == damping) return &r;
  return nullptr;
}

const SweepRow* find_sweep(const ReportData& d, std::size_t method, double dt, double damping) {
  for (const SweepRow& r : d.sweep)
    if (r.method == method && r.dt == dt && r.damping == damping) return &r;
  return nullptr;
}

Findings compute_findings(const ReportData& d) {
  const ReportConfig& c = d.config;
  const double gamma = c.damping();
  const ConvergenceResult& conv = d.convergence_on(c.oscillator.scene);
  Findings f;
  // the stability map's undamped row, if it has one
  const auto undamped_row = std::find(d.map.damping.begin(), d.map.damping.end(), 0.0);
  for (std::size_t i = 0; i < d.methods.size(); ++i) {
    const std::size_t m = d.methods[i];
    MethodFinding row{m, &conv.fits[i], false, false, 0, 0, 0, 0, 0, 0, 0, INFINITY, INFINITY, false};
    const SweepRow* large = find_sweep(d, m, c.large_dt, gamma);
    const SweepRow* undamped = find_sweep(d, m, c.small_dt, 0.0);
    const ThresholdRow* th = find_threshold(d, m, gamma);
    row.stable_large_dt = large && large->run.stable();
    row.energy_rate_large_dt = large ? large->run.rate : NAN;
    row.stable_undamped = undamped && undamped->run.stable();
    row.energy_rate_undamped = undamped ? undamped->run.rate : NAN;
    row.energy_max_large_dt = large ? large->run.energy_ratio_max : NAN;
    row.energy_max_undamped = undamped ? undamped->run.energy_ratio_max : NAN;
    row.dt_theory = th ? th->dt_theory : NAN;
    row.dt_measured = th ? th->dt_measured : NAN;
    row.again_measured = th ? th->again_measured : NAN;
    const ThresholdRow* th0 = find_threshold(d, m, 0.0);
    row.dt_undamped_theory = th0 ? th0->dt_theory : NAN;
    row.dt_undamped_measured = th0 ? th0->dt_measured : NAN;
    if (th0) row.again_undamped_theory = th0->again_theory, row.again_undamped_measured = th0->again_measured;
    const auto in_map = std::find(d.map.methods.begin(), d.map.methods.end(), m);
    if (in_map != d.map.methods.end() && undamped_row != d.map.damping.end()) {
      const auto& cells = d.map.stable[static_cast<std::size_t>(in_map - d.map.methods.begin())]
                                      [static_cast<std::size_t>(undamped_row - d.map.damping.begin())];
      row.map_stable_undamped = std::find(cells.begin(), cells.end(), true) != cells.end();
    }
    f.rows.push_back(row);
    if (method_info(m).exact_flow) continue;  // the reference, in no list and no statistic
    f.numerical.push_back(i);
    (row.stable_large_dt ? f.stable_large : f.unstable_large).push_back(i);
    (row.stable_undamped ? f.stable_undamped : f.unstable_undamped).push_back(i);
    if (row.dt_undamped_theory == 0) {
      f.unstable_small_undamped.push_back(i);
      if (std::isinf(row.again_undamped_theory) && std::isinf(row.again_undamped_measured) && !row.map_stable_undamped)
        f.never_stable_undamped.push_back(i);
    }
    if (std::isinf(row.dt_theory)) f.always_stable.push_back(i);
  }
  // Declared order against measured dt*, over the numerical methods.
  std::vector<double> order, dt;
  for (std::size_t i : f.numerical) {
    order.push_back(method_info(f.rows[i].method).order);
    dt.push_back(f.rows[i].dt_measured);
  }
  f.spearman_n = order.size();
  f.spearman = order.size() >= 2 ? spearman(order, dt) : NAN;
  return f;
}

}  // namespace steplab
