#include "analysis/studies/work_precision.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "analysis/studies/convergence.hpp"
#include "analysis/fits/fit.hpp"
#include "analysis/kernel/kernel.hpp"
#include "analysis/kernel/shard.hpp"
#include "analysis/peers/peers.hpp"
#include "analysis/kernel/noise.hpp"
#include "analysis/kernel/timing.hpp"

namespace steplab {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A scene of the study: its index in the kernel table and its parameter values.
struct Where {
  std::size_t scene;
  std::vector<double> params;
};

// The minimum of repeated timings (analysis/kernel/timing.hpp): of `run` (kMinRepeats, and kMinSeconds
// in all), or as a kernel took them.
double fastest(const std::vector<double>& times) { return *std::min_element(times.begin(), times.end()); }
template <class F> double min_time(F&& run) { return fastest(repeated_timings(run, kMinRepeats, kMinSeconds)); }

RunSpec fixed_spec(double dt, double t_end) {
  RunSpec spec;
  spec.dt = dt;
  spec.steps = steps_for(t_end, dt);
  return spec;
}

// The size of the solution to t_end, max(|x(0)|, |x(t_end)|): the scale of the blow-up test.
double solution_scale(const Where& w, double t_end) {
  const SceneKernel& s = scene_kernel(w.scene);
  return std::max(s.norm(s.initial(w.params).x), s.norm(s.exact(w.params, t_end).x));
}

// The point of a run of method m at dt, counting what it asked of the scene (scale:
// solution_scale(w, t_end)).
// A point's counts (analysis/kernel/counts.hpp).
void set_counts(WorkPoint& p, const Counts& n) {
  p.steps = n.steps, p.rejected = n.rejected, p.force_evaluations = n.forces, p.jacobian_evaluations = n.jacobians;
  p.factorisations = n.factorisations, p.solves = n.solves, p.newton = n.newton;
}

WorkPoint fixed_point(const Where& w, std::size_t m, double dt, double t_end, double scale) {
  Counts n;
  const AnyResult r = pair_kernel(m, w.scene).run_counted(w.params, fixed_spec(dt, t_end), n);
  WorkPoint p{std::string(method_info(m).name), false, dt};
  p.error = r.error_max;
  p.status = r.status;
  if (p.status == RunStatus::Ok && blown_up(p.error, scale)) p.status = RunStatus::Diverged;
  if (p.status != RunStatus::Ok) p.error = kInf;
  set_counts(p, n);
  return p;
}

// Method m's points at each of dts (default points where m does not apply to the scene).
std::vector<WorkPoint> fixed_points(const Where& w, std::size_t m, const std::vector<double>& dts, double t_end) {
  std::vector<WorkPoint> out(dts.size());
  if (!applies(m, w.scene)) return out;
  const double scale = solution_scale(w, t_end);
  for (std::size_t i = dts.size(); i-- > 0;) out[i] = fixed_point(w, m, dts[i], t_end, scale);  // the longest run first
  return out;
}

WorkPoint dopri5_point(const Where& w, double tol, double t_end) {
  WorkPoint p{"dopri5", true, tol};
  AdaptiveSpec spec;
  spec.tol = {tol, tol};
  spec.t_end = t_end;
  const AnyAdaptiveResult r = scene_kernel(w.scene).dopri5(w.params, spec);
  p.status = r.run.status;
  p.error = p.status == RunStatus::Ok ? r.run.error_max : kInf;
  set_counts(p, counts_of(r.stats));
  return p;
}

// A peer's point (analysis/peers/peers.hpp).
WorkPoint peer_point(const PeerInfo& peer, const Where& w, double tol, double t_end) {
  WorkPoint p{std::string(peer.name), true, tol};
  p.error = 0;
  PeerCounts n;
  run_fixed_peer(peer, scene_name(w.scene), w.params, tol, t_end, n, &p.error);
  set_counts(p, n);
  if (n.failed || !std::isfinite(p.error)) p.status = RunStatus::Diverged, p.error = kInf;
  return p;
}

// An adaptive solver's point: steplab's dopri5 or a peer.
WorkPoint adaptive_point(const std::string& solver, const Where& w, double tol, double t_end) {
  return solver == "dopri5" ? dopri5_point(w, tol, t_end) : peer_point(*find_peer(solver), w, tol, t_end);
}

// Times a point's run again, without counting or errors, one run at a time.
double time_point(const Where& w, const WorkPoint& p, double t_end) {
  if (p.method == "dopri5") {
    AdaptiveSpec spec;
    spec.tol = {p.setting, p.setting};
    spec.t_end = t_end;
    spec.errors = false;
    return fastest(scene_kernel(w.scene).dopri5_timings(w.params, spec, kMinRepeats, kMinSeconds));
  }
  if (const PeerInfo* peer = find_peer(p.method)) {
    PeerCounts n;
    return min_time([&] { run_fixed_peer(*peer, scene_name(w.scene), w.params, p.setting, t_end, n); });
  }
  RunSpec spec;
  spec.dt = p.setting;
  spec.steps = steps_for(t_end, p.setting);
  spec.errors = false;
  return fastest(pair_kernel(*find_method(p.method), w.scene).timings(w.params, spec, kMinRepeats, kMinSeconds));
}

// Every point of one scene: the dt sweep of each fixed-step method, the tolerance sweeps.
std::vector<WorkPoint> scene_points(const Where& w, const WorkPrecisionConfig& c, const std::vector<double>& dts,
                                    double t_end, const std::vector<std::size_t>& methods) {
  const std::size_t nm = methods.size(), nt = c.tolerances.size(), na = c.adaptive.size();
  // tasks: a method's dt sweep, then one per adaptive solver and tolerance; the implicit
  // methods' sweeps start first
  std::vector<std::size_t> order = implicit_first(methods);
  for (std::size_t job = nm; job < nm + na * nt; ++job) order.push_back(job);
  const auto parts = study_map<std::vector<WorkPoint>>(nm + na * nt, c.workers, [&](std::size_t job) {
    if (job < nm) return fixed_points(w, methods[job], dts, t_end);
    const std::size_t task = job - nm;
    return std::vector{adaptive_point(c.adaptive[task / nt], w, c.tolerances[task % nt], t_end)};
  }, order);
  std::vector<WorkPoint> points;
  for (const auto& part : parts) points.insert(points.end(), part.begin(), part.end());
  if (c.timing) {  // two passes: each point's spread (noise.hpp)
    std::vector<WorkPoint*> ok;
    for (WorkPoint& p : points)
      if (p.status == RunStatus::Ok) ok.push_back(&p);
    time_in_two_passes(ok, [&](const WorkPoint& p) { return time_point(w, p, t_end); });
  }
  return points;
}

// Whether a run of (seconds, force evaluations) is cheaper than one of (than_seconds, than_evaluations):
// by time where the study times its runs, else by force evaluations.
bool cheaper(bool timing, double seconds, long long evals, double than_seconds, long long than_evals) {
  return timing ? seconds < than_seconds : evals < than_evals;
}

// The cheapest run of `points` whose error is at most `level`, by time and by force evaluations.
Cheapest cheapest_at(const std::vector<WorkPoint>& points, double level) {
  Cheapest c{level, "", ""};
  for (std::size_t i = 0; i < points.size(); ++i) {
    const WorkPoint& p = points[i];
    if (p.status != RunStatus::Ok || !(p.error <= level)) continue;
    if (p.seconds >= 0 && (c.seconds < 0 || p.seconds < c.seconds))
      c.seconds = p.seconds, c.by_time = p.method, c.time_point = static_cast<std::ptrdiff_t>(i);
    if (c.by_forces.empty() || p.force_evaluations < c.forces)
      c.forces = p.force_evaluations, c.by_forces = p.method, c.forces_point = static_cast<std::ptrdiff_t>(i);
  }
  return c;
}

bool is_implicit(const std::string& method) {
  const auto m = find_method(method);
  return m && method_info(*m).implicit;
}

// Where the error of a dt sweep (points sorted by falling dt) first reaches `level`: the dt
// interpolated linearly in (ln dt, ln error) between the last run above it and the first at or
// below it; the largest dt if every run reaches it; -1 if none does.
double dt_reaching(const std::vector<WorkPoint>& points, double level) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!(points[i].error <= level)) continue;
    if (i == 0 || !std::isfinite(points[i - 1].error)) return points[i].setting;
    const WorkPoint &hi = points[i - 1], &lo = points[i];
    const double w = std::log(level / lo.error) / std::log(hi.error / lo.error);
    return std::exp(std::log(lo.setting) + w * std::log(hi.setting / lo.setting));
  }
  return -1;
}

// The stiff scene's explicit methods: the largest stable dt of its sweep, against the dt at which
// the same method reaches kLimitErrorLevel on its stiff limit (core/scene.hpp: the chain's slow
// mode alone), what accuracy would allow if the stiff part did not have to be kept stable.
std::vector<StableStep> stable_steps(const WorkPrecisionConfig& c, const Where& stiff, const std::vector<double>& dts,
                                     const std::vector<WorkPoint>& points) {
  std::vector<StableStep> out;
  for (const std::size_t m : c.methods)
    if (!method_info(m).implicit) out.push_back({std::string(method_info(m).name), 0, -1, kInf});
  const SceneKernel& k = scene_kernel(stiff.scene);
  const Where slow{scene_index(k.stiff_limit_scene), k.stiff_limit(stiff.params)};
  const std::vector<double> accuracy = study_map<double>(out.size(), c.workers, [&](std::size_t task) {
    return dt_reaching(fixed_points(slow, *find_method(out[task].method), dts, c.t_end), kLimitErrorLevel);
  });
  for (std::size_t task = 0; task < out.size(); ++task) {
    StableStep& s = out[task];
    for (const WorkPoint& p : points)
      if (p.method == s.method && p.status == RunStatus::Ok) s.largest_stable_dt = std::max(s.largest_stable_dt, p.setting);
    for (const WorkPoint& p : points)
      if (p.method == s.method && p.setting > s.largest_stable_dt) s.next_tried_dt = std::min(s.next_tried_dt, p.setting);
    s.accuracy_dt = accuracy[task];
  }
  return out;
}

// The stiffness sweep's scenes: the stiff scene's defaults with its stiffness parameter (the
// chain's k2) at each of c.stiffnesses.
std::vector<Where> stiffness_chains(const WorkPrecisionConfig& c, std::size_t stiff) {
  std::vector<Where> chains;
  for (const double k2 : c.stiffnesses) {
    std::vector<double> p = default_param_values(stiff);
    p[static_cast<std::size_t>(scene_kernel(stiff).stiffness_param)] = k2;
    chains.push_back({stiff, p});
  }
  return chains;
}

bool reaches_crossover(const WorkPrecisionConfig& c, const WorkPoint& w) {
  return w.status == RunStatus::Ok && w.error <= c.crossover_error;
}

// Method m's search on every chain: for each, the first run of the falling dt sweep `dts` whose
// error is at most crossover_error (a default WorkPoint if none, or if m does not apply).
std::vector<WorkPoint> first_reaching(const WorkPrecisionConfig& c, const std::vector<Where>& chains, std::size_t m,
                                      const std::vector<double>& dts) {
  std::vector<WorkPoint> found(chains.size());
  for (std::size_t s = 0; s < chains.size(); ++s) {
    if (!applies(m, chains[s].scene)) continue;
    const double scale = solution_scale(chains[s], c.sweep_t_end);
    for (const double dt : dts)
      if (const WorkPoint w = fixed_point(chains[s], m, dt, c.sweep_t_end, scale); reaches_crossover(c, w)) {
        found[s] = w;
        break;
      }
  }
  return found;
}

// The stiffness sweep: at each stiffness, for each method (and dopri5 over the tolerances), the
// first run of a falling dt (or tolerance) sweep whose error is at most crossover_error; then the
// cheapest explicit and implicit ones.
std::vector<StiffnessRow> stiffness_rows(const WorkPrecisionConfig& c, std::size_t stiff) {
  const std::vector<double> dts = sweep_steps(c.sweep_t_end, 0.5, 1e-7, 57);  // 8 per decade
  const std::vector<Where> chains = stiffness_chains(c, stiff);
  const std::size_t nm = c.methods.size(), ns = chains.size();
  // tasks: a method's searches on every chain (the implicit methods' first), then dopri5's on each
  std::vector<std::size_t> order = implicit_first(c.methods);
  for (std::size_t task = nm; task < nm + ns; ++task) order.push_back(task);
  const auto found = study_map<std::vector<WorkPoint>>(nm + ns, c.workers, [&](std::size_t task) {
    if (task < nm) return first_reaching(c, chains, c.methods[task], dts);
    for (const double tol : c.tolerances)
      if (WorkPoint w = dopri5_point(chains[task - nm], tol, c.sweep_t_end); reaches_crossover(c, w)) return std::vector{w};
    return std::vector{WorkPoint{}};
  }, order);
  // The ratio to the stiffness that remains in the limit (the chain's k2 / k1).
  const SceneKernel& kernel = scene_kernel(stiff);
  const std::size_t limit = scene_index(kernel.stiff_limit_scene);
  const double k1 = kernel.stiff_limit(default_param_values(stiff))[static_cast<std::size_t>(scene_kernel(limit).stiffness_param)];
  std::vector<StiffnessRow> rows;
  for (std::size_t i = 0; i < ns; ++i) {
    StiffnessRow row{c.stiffnesses[i], c.stiffnesses[i] / k1, "", ""};
    // the methods', then dopri5's (a shard's run leaves the other shards' tasks empty)
    const auto at = [&](std::size_t task, std::size_t k) { return k < found[task].size() ? found[task][k] : WorkPoint{}; };
    std::vector<WorkPoint> points;
    for (std::size_t task = 0; task < nm; ++task) points.push_back(at(task, i));
    points.push_back(at(nm + i, 0));
    for (WorkPoint& w : points) {
      if (w.method.empty()) continue;
      if (c.timing) w.seconds = time_point(chains[i], w, c.sweep_t_end);
      const bool implicit = is_implicit(w.method);
      std::string& best = implicit ? row.best_implicit : row.best_explicit;
      double& secs = implicit ? row.implicit_seconds : row.explicit_seconds;
      long long& evals = implicit ? row.implicit_forces : row.explicit_forces;
      if (best.empty() || cheaper(c.timing, w.seconds, w.force_evaluations, secs, evals))
        best = w.method, secs = w.seconds, evals = w.force_evaluations;
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace

std::vector<std::string> adaptive_solvers() { return peer_names(PeerScenes::FixedSize); }

WorkPrecisionResult work_precision_study(const WorkPrecisionConfig& config) {
  WorkPrecisionResult out;
  out.config = config;
  std::optional<std::size_t> stiff;  // the first scene with a stiff limit: the stiffness sweep's
  for (const SweepScene& where : config.scenes) {
    const std::size_t scene = *find_scene(where.scene);
    SceneWork w{scene, {}, {}, {}};
    w.params = default_param_values(scene);
    const auto dts = sweep_steps(config.t_end, where.dt_max, where.dt_min, config.points);
    w.points = scene_points({scene, w.params}, config, dts, config.t_end, config.methods);
    if (scene_kernel(scene).stiff_limit && !stiff) {
      stiff = scene;
      out.stiff = static_cast<std::ptrdiff_t>(out.scenes.size());
      out.limits = stable_steps(config, {scene, w.params}, dts, w.points);
    }
    for (const double level : config.error_levels) w.cheapest.push_back(cheapest_at(w.points, level));
    out.scenes.push_back(std::move(w));
  }
  if (stiff) out.stiffness = stiffness_rows(config, *stiff);
  // The crossover: the smallest ratio from which on, at every larger one, the best implicit run is
  // cheaper than the best explicit one: timed, by more than the timing's noise (kTieMargin).
  for (std::size_t i = out.stiffness.size(); i-- > 0;) {
    const StiffnessRow& r = out.stiffness[i];
    const bool implicit_wins =
        !r.best_implicit.empty() &&
        (r.best_explicit.empty() || (config.timing ? kTieMargin * r.implicit_seconds < r.explicit_seconds
                                                   : r.implicit_forces < r.explicit_forces));
    if (!implicit_wins) break;
    out.crossover_ratio = r.ratio;
  }
  return out;
}

}  // namespace steplab
