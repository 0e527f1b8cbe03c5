// The report's studies and its findings (reports/document/report.hpp).
#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include <fmt/format.h>

#include "analysis/parallel.hpp"
#include "analysis/kernel.hpp"
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
  ConvergenceConfig cc;
  cc.scene = scene;
  cc.params = default_param_values(scene);
  for (const ReportScene* s : d.config.scenes())
    if (s->scene == scene) cc.params = s->params;
  for (std::size_t m : d.methods)
    if (applies(m, scene)) cc.methods.push_back(m);
  const ReportConfig& c = d.config;
  cc.t_end = c.conv_t_end;
  cc.dt_max = c.conv_dt_max;
  cc.dt_min = c.conv_dt_min;
  cc.points = c.conv_points;
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

  // The stability study is the damped spring's (analysis/stability.hpp): the oscillator is one.
  const Spring spring(c.oscillator.params);
  StabilityConfig sc;
  sc.params = c.oscillator.params;
  sc.methods = d.methods;
  sc.threshold_dampings = with_values(c.threshold_dampings, {0.0, gamma});
  sc.sweep_dts = with_values(c.sweep_dts, {c.large_dt, c.small_dt});
  sc.sweep_dampings = with_values(default_dampings(spring), {0.0, gamma});
  sc.map_dt_points = c.map_dt_points;
  sc.map_damping_points = c.map_damping_points;
  sc.map_dt_min = c.map_dt_min;
  sc.map_dt_max = c.map_dt_max;
  sc.workers = d.workers;
  if (studies & kStabilityStudy) {
    d.thresholds = threshold_study(sc);
    d.sweep = damping_sweep(sc);
    d.map = stability_map(sc);
  }

  CollisionConfig cc;
  cc.rebound_scene = c.rebound.scene;
  cc.rebound_params = c.rebound.params;
  cc.body_scene = c.body.scene;
  cc.body_params = c.body.params;
  cc.methods = d.numerical_methods();
  cc.dts = c.collision_dts;
  cc.t_end = c.collision_t_end;
  cc.triangle_dt = c.triangle_dt;
  cc.workers = d.workers;
  if (studies & kCollisionStudy) d.collision = collision_study(cc);

  WorkPrecisionConfig wc;
  wc.methods = d.numerical_methods();
  wc.points = c.wp_points;
  wc.stiffnesses = c.wp_stiffnesses;
  wc.timing = c.timing;
  wc.workers = d.workers;
  if (studies & kWorkPrecisionStudy) d.work = work_precision_study(wc);

  // Figures: the cannon ball's path and the spring's y(t) (kSceneFigures); the undamped energy at
  // the large step and the predicted growth rate against damping on a fine grid (kStabilityStudy).
  if (!(studies & (kSceneFigures | kStabilityStudy))) return d;
  std::vector<double> undamped = c.oscillator.params;
  undamped[damping] = 0;
  const std::size_t nm = d.methods.size(), nf = c.spring_figure_dts.size();
  d.cannon.resize(nm);
  d.spring.assign(nf, std::vector<RunResult<1>>(nm));
  d.energy.resize(nm);
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
      if (stability) d.energy[m] = figure_run<1>(method, osc, undamped, c.large_dt, c.energy_t_end, 2001);
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

Findings compute_findings(const ReportData& d) {
  const ReportConfig& c = d.config;
  const double gamma = c.damping();
  const ConvergenceResult& conv = d.convergence_on(c.oscillator.scene);
  Findings f;
  const auto sweep_row = [&](std::size_t m, double dt, double damping) -> const SweepRow* {
    for (const SweepRow& r : d.sweep)
      if (r.method == m && r.dt == dt && r.damping == damping) return &r;
    return nullptr;
  };
  for (std::size_t i = 0; i < d.methods.size(); ++i) {
    const std::size_t m = d.methods[i];
    MethodFinding row{m, &conv.fits[i], false, false, 0, 0, 0, 0, 0, 0};
    const SweepRow* large = sweep_row(m, c.large_dt, gamma);
    const SweepRow* undamped = sweep_row(m, c.small_dt, 0.0);
    const ThresholdRow* th = find_threshold(d, m, gamma);
    row.stable_large_dt = large && large->run.stable();
    row.growth_large_dt = large ? large->run.rate : NAN;
    row.stable_undamped = undamped && undamped->run.stable();
    row.dt_theory = th ? th->dt_theory : NAN;
    row.dt_measured = th ? th->dt_measured : NAN;
    row.again_measured = th ? th->again_measured : NAN;
    const ThresholdRow* th0 = find_threshold(d, m, 0.0);
    row.dt_undamped_theory = th0 ? th0->dt_theory : NAN;
    row.dt_undamped_measured = th0 ? th0->dt_measured : NAN;
    (row.stable_large_dt ? f.stable_large : f.unstable_large).push_back(i);
    (row.stable_undamped ? f.stable_undamped : f.unstable_undamped).push_back(i);
    if (row.dt_undamped_theory == 0) f.never_stable_undamped.push_back(i);
    if (std::isinf(row.dt_theory)) f.always_stable.push_back(i);
    f.rows.push_back(row);
  }
  // Order (the exact flow: infinite) against measured dt* over every method.
  std::vector<double> order, dt;
  for (const MethodFinding& r : f.rows) {
    const MethodInfo& info = method_info(r.method);
    order.push_back(info.exact_flow ? INFINITY : info.order);
    dt.push_back(r.dt_measured);
  }
  f.spearman = spearman(order, dt);
  return f;
}

}  // namespace steplab
