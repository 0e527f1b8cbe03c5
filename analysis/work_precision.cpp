#include "analysis/work_precision.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "analysis/convergence.hpp"
#include "analysis/fit.hpp"
#include "analysis/lanes.hpp"
#include "analysis/shard.hpp"
#include "analysis/peers.hpp"
#include "analysis/timing.hpp"
#include "core/dopri5.hpp"
#include "core/scenes.hpp"

namespace steplab {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A scene that counts what a method asks of it; otherwise the scene itself.
template <Scene S> struct Counted : S {
  explicit Counted(const S& s) : S(s) {}
  explicit Counted(std::span<const double> p) : S(p) {}
  mutable long long forces = 0, jacobian_calls = 0;
  Vec<S::dim> force(const Vec<S::dim>& x, const Vec<S::dim>& v) const {
    ++forces;
    return S::force(x, v);
  }
  Jacobians<S::dim> jacobians(const Vec<S::dim>& x, const Vec<S::dim>& v) const {
    ++jacobian_calls;
    return S::jacobians(x, v);
  }
};

// Minimum of repeated timings of `run` (kMinRepeats, and kMinSeconds in all).
template <class F> double min_time(F&& run) {
  const std::vector<double> times = repeated_timings(run, kMinRepeats, kMinSeconds);
  return *std::min_element(times.begin(), times.end());
}

RunSpec fixed_spec(double dt, double t_end) {
  RunSpec spec;
  spec.dt = dt;
  spec.steps = steps_for(t_end, dt);
  return spec;
}

// The point of a run of method m at dt on the counting scene.
template <HasExact S> WorkPoint fixed_point_of(const Counted<S>& counted, std::size_t m, double dt, double t_end,
                                               const RunResult<S::dim>& r) {
  const S& s = counted;
  WorkPoint p{std::string(method_infos[m].name), false, dt};
  const State<S::dim> ex = exact(s, t_end);
  p.error = r.error_max;
  p.status = r.status;
  if (p.status == RunStatus::Ok && blown_up(p.error, std::max(s.initial().x.norm(), ex.x.norm()))) p.status = RunStatus::Diverged;
  if (p.status != RunStatus::Ok) p.error = kInf;
  p.steps = r.steps;
  p.force_evaluations = counted.forces;
  p.jacobian_evaluations = counted.jacobian_calls;
  return p;
}

// Method m's points at each of dts, run in lanes (analysis/lanes.hpp).
template <HasExact S> std::vector<WorkPoint> fixed_points(const S& s, std::size_t m, const std::vector<double>& dts,
                                                          double t_end, int lanes) {
  std::vector<WorkPoint> out(dts.size());
  const std::size_t n = dts.size();  // the smallest dt (the longest run) first
  run_batch<Counted<S>>(
      m, n, lanes, [&](std::size_t k) { return std::pair(Counted<S>(s), fixed_spec(dts[n - 1 - k], t_end)); },
      [&](std::size_t k, const RunResult<S::dim>& r, const Counted<S>& counted) {
        out[n - 1 - k] = fixed_point_of(counted, m, dts[n - 1 - k], t_end, r);
      });
  return out;
}

template <HasExact S> WorkPoint dopri5_point(const S& s, double tol, double t_end) {
  WorkPoint p{"dopri5", true, tol};
  AdaptiveSpec spec;
  spec.tol = {tol, tol};
  spec.t_end = t_end;
  const AdaptiveResult<S::dim> r = simulate_dopri5(s, spec);
  p.status = r.run.status;
  p.error = p.status == RunStatus::Ok ? r.run.error_max : kInf;
  p.steps = r.stats.accepted;
  p.force_evaluations = r.stats.force_evaluations;
  return p;
}

// A peer's point (analysis/peers.hpp): "odeint_dopri5" or "cvode_bdf".
template <class Peer, HasExact S> WorkPoint peer_point(const char* name, const S& s, double tol, double t_end) {
  WorkPoint p{name, true, tol};
  p.error = 0;
  PeerCounts n;
  Peer::run(s, tol, t_end, n, &p.error);
  p.steps = n.steps;
  p.force_evaluations = n.evaluations;
  p.jacobian_evaluations = n.jacobian_evaluations;
  if (n.failed || !std::isfinite(p.error)) p.status = RunStatus::Diverged, p.error = kInf;
  return p;
}

// Times a point's run again, with the plain scene (no counting), one run at a time.
template <HasExact S> double time_point(const S& s, const WorkPoint& p, double t_end) {
  if (p.method == "dopri5") {
    AdaptiveSpec spec;
    spec.tol = {p.setting, p.setting};
    spec.t_end = t_end;
    spec.errors = false;
    return min_time([&] { simulate_dopri5(s, spec); });
  }
  PeerCounts n;
  if (p.method == "odeint_dopri5") return min_time([&] { OdeintDopri5<S>::run(s, p.setting, t_end, n); });
  if (p.method == "cvode_bdf") return min_time([&] { CvodeBdf<S>::run(s, p.setting, t_end, n); });
  return with_method(*find_method(p.method), [&]<class M>() {
    RunSpec spec;
    spec.dt = p.setting;
    spec.steps = steps_for(t_end, p.setting);
    spec.errors = false;
    return min_time([&] { simulate<M>(s, spec); });
  });
}

// Every point of one scene: the dt sweep of each fixed-step method, the tolerance sweeps.
template <HasExact S>
std::vector<WorkPoint> scene_points(const S& s, const WorkPrecisionConfig& c, const std::vector<double>& dts,
                                    double t_end, const std::vector<std::size_t>& methods) {
  const std::size_t nm = methods.size(), nf = nm * dts.size(), nt = c.tolerances.size();
  // tasks: a method's dt sweep (in lanes), then one per tolerance and adaptive solver; the
  // implicit methods' sweeps start first
  std::vector<std::size_t> order = implicit_first(methods);
  for (std::size_t job = nm; job < nm + 3 * nt; ++job) order.push_back(job);
  const auto parts = study_map<std::vector<WorkPoint>>(nm + 3 * nt, c.threads, [&](std::size_t job) {
    if (job < nm) return fixed_points(s, methods[job], dts, t_end, c.lanes);
    const std::size_t task = job - nm + nf;
    if (task < nf + nt) return std::vector{dopri5_point(s, c.tolerances[task - nf], t_end)};
    if (task < nf + 2 * nt) return std::vector{peer_point<OdeintDopri5<S>>("odeint_dopri5", s, c.tolerances[task - nf - nt], t_end)};
    return std::vector{peer_point<CvodeBdf<S>>("cvode_bdf", s, c.tolerances[task - nf - 2 * nt], t_end)};
  }, order);
  std::vector<WorkPoint> points;
  for (const auto& part : parts) points.insert(points.end(), part.begin(), part.end());
  if (c.timing)
    for (WorkPoint& p : points)
      if (p.status == RunStatus::Ok) p.seconds = time_point(s, p, t_end);
  return points;
}

long long evaluations(const WorkPoint& p) { return p.force_evaluations + p.jacobian_evaluations; }

// Whether a run of (seconds, evaluations) is cheaper than one of (than_seconds, than_evaluations):
// by time where the study times its runs, else by evaluations.
bool cheaper(bool timing, double seconds, long long evals, double than_seconds, long long than_evals) {
  return timing ? seconds < than_seconds : evals < than_evals;
}

// The cheapest run of `points` whose error is at most `level`, by time and by evaluations.
Cheapest cheapest_at(const std::vector<WorkPoint>& points, double level) {
  Cheapest c{level, "", ""};
  for (const WorkPoint& p : points) {
    if (p.status != RunStatus::Ok || !(p.error <= level)) continue;
    if (p.seconds >= 0 && (c.seconds < 0 || p.seconds < c.seconds)) c.seconds = p.seconds, c.by_time = p.method;
    if (c.by_evaluations.empty() || evaluations(p) < c.evaluations) c.evaluations = evaluations(p), c.by_evaluations = p.method;
  }
  return c;
}

bool is_implicit(const std::string& method) {
  const auto m = find_method(method);
  return m && method_infos[*m].implicit;
}

// The chain's slow mode alone: its limit k2 -> inf, where the two masses move as one,
// (m1 + m2) u'' = -k1 u - c1 u', as the spring scene (which starts at rest, m g / k above its
// equilibrium: g is chosen for the amplitude of the chain's mass-weighted mean displacement,
// times sqrt 2, the norm of (u, u), so that errors compare with the chain's two-coordinate ones).
Spring slow_mode_spring(const std::vector<double>& chain) {
  // Chain::params: mass1, mass2, stiffness1, stiffness2, damping1, damping2, u1, u2
  const double m = chain[0] + chain[1], u = (chain[0] * chain[6] + chain[1] * chain[7]) / m;
  std::vector<double> p = default_param_values<Spring>();  // mass, stiffness, damping, rest length, g
  p[0] = m, p[1] = chain[2], p[2] = chain[4], p[4] = chain[2] * std::sqrt(2.0) * std::abs(u) / m;
  return Spring(p);
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

// The chain's explicit methods: the largest stable dt of the chain's sweep, against the dt at
// which the same method reaches kLimitErrorLevel on the slow mode alone (what accuracy would
// allow if the stiff mode did not have to be kept stable).
std::vector<StableStep> stable_steps(const WorkPrecisionConfig& c, const std::vector<double>& chain,
                                     const std::vector<double>& dts, const std::vector<WorkPoint>& points) {
  std::vector<StableStep> out;
  for (const std::size_t m : c.methods)
    if (!method_infos[m].implicit) out.push_back({std::string(method_infos[m].name), 0, -1});
  const Spring slow = slow_mode_spring(chain);
  const std::vector<double> accuracy = study_map<double>(out.size(), c.threads, [&](std::size_t task) {
    return dt_reaching(fixed_points(slow, *find_method(out[task].method), dts, c.t_end, c.lanes), kLimitErrorLevel);
  });
  for (std::size_t task = 0; task < out.size(); ++task) {
    StableStep& s = out[task];
    for (const WorkPoint& p : points)
      if (p.method == s.method && p.status == RunStatus::Ok) s.largest_stable_dt = std::max(s.largest_stable_dt, p.setting);
    s.accuracy_dt = accuracy[task];
  }
  return out;
}

Chain stiffness_chain(double k2) {
  std::vector<double> p = default_param_values<Chain>();
  p[3] = k2;  // Chain::params: mass1, mass2, stiffness1, stiffness2, ...
  return Chain(p);
}

// Method m's search at every stiffness: for each, the first run of the falling dt sweep `dts`
// whose error is at most crossover_error (a default WorkPoint if none). The searches go in
// lockstep, a round being the next dt of every stiffness still searching, run in lanes: each
// search runs the same dts, in the same order, as alone.
std::vector<WorkPoint> first_reaching(const WorkPrecisionConfig& c, std::size_t m, const std::vector<double>& dts) {
  const std::size_t ns = c.stiffnesses.size();
  std::vector<WorkPoint> found(ns);
  std::vector<std::size_t> next(ns, 0), round;  // each stiffness's next dt; the stiffnesses of a round
  for (;;) {
    round.clear();
    for (std::size_t s = 0; s < ns; ++s)
      if (found[s].method.empty() && next[s] < dts.size()) round.push_back(s);
    if (round.empty()) return found;
    std::size_t ran = 0;
    run_batch<Counted<Chain>>(
        m, round.size(), c.lanes,
        [&](std::size_t k) {
          const std::size_t s = round[k];
          return std::pair(Counted<Chain>(stiffness_chain(c.stiffnesses[s])), fixed_spec(dts[next[s]], c.sweep_t_end));
        },
        [&](std::size_t k, const RunResult<Chain::dim>& r, const Counted<Chain>& counted) {
          const std::size_t s = round[k];
          const WorkPoint w = fixed_point_of(counted, m, dts[next[s]++], c.sweep_t_end, r);
          if (w.status == RunStatus::Ok && w.error <= c.crossover_error) found[s] = w;
          ++ran;
        });
    if (ran == 0) return found;  // m does not apply to the chain
  }
}

// The stiffness sweep: at each stiffness, for each method (and dopri5 over the tolerances), the
// first run of a falling dt (or tolerance) sweep whose error is at most crossover_error; then the
// cheapest explicit and implicit ones.
std::vector<StiffnessRow> stiffness_rows(const WorkPrecisionConfig& c) {
  const std::vector<double> dts = sweep_steps(c.sweep_t_end, 0.5, 1e-7, 57);  // 8 per decade
  const std::size_t nm = c.methods.size(), ns = c.stiffnesses.size();
  // tasks: a method's searches at every stiffness (the implicit methods' first), then dopri5's at each
  std::vector<std::size_t> order = implicit_first(c.methods);
  for (std::size_t task = nm; task < nm + ns; ++task) order.push_back(task);
  const auto found = study_map<std::vector<WorkPoint>>(nm + ns, c.threads, [&](std::size_t task) {
    if (task < nm) return first_reaching(c, c.methods[task], dts);
    const Chain s = stiffness_chain(c.stiffnesses[task - nm]);
    for (const double tol : c.tolerances)
      if (WorkPoint w = dopri5_point(s, tol, c.sweep_t_end); w.status == RunStatus::Ok && w.error <= c.crossover_error)
        return std::vector{w};
    return std::vector{WorkPoint{}};
  }, order);
  std::vector<StiffnessRow> rows;
  for (std::size_t i = 0; i < ns; ++i) {
    const Chain s = stiffness_chain(c.stiffnesses[i]);
    StiffnessRow row{c.stiffnesses[i], c.stiffnesses[i] / default_param_values<Chain>()[2], "", ""};
    // the methods', then dopri5's (a shard's run leaves the other shards' tasks empty)
    const auto at = [&](std::size_t task, std::size_t k) { return k < found[task].size() ? found[task][k] : WorkPoint{}; };
    std::vector<WorkPoint> points;
    for (std::size_t task = 0; task < nm; ++task) points.push_back(at(task, i));
    points.push_back(at(nm + i, 0));
    for (WorkPoint& w : points) {
      if (w.method.empty()) continue;
      if (c.timing) w.seconds = time_point(s, w, c.sweep_t_end);
      const bool implicit = is_implicit(w.method);
      std::string& best = implicit ? row.best_implicit : row.best_explicit;
      double& secs = implicit ? row.implicit_seconds : row.explicit_seconds;
      long long& evals = implicit ? row.implicit_evaluations : row.explicit_evaluations;
      if (best.empty() || cheaper(c.timing, w.seconds, evaluations(w), secs, evals))
        best = w.method, secs = w.seconds, evals = evaluations(w);
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace

WorkPrecisionResult work_precision_study(const WorkPrecisionConfig& config) {
  WorkPrecisionResult out;
  out.config = config;
  for (const std::string_view name : {"spring", "chain"}) {
    const std::size_t scene = *find_scene(name);
    SceneWork w{scene, {}, {}, {}};
    with_scene(scene, [&]<class S>() {
      if constexpr (HasExact<S>) {
        w.params = default_param_values<S>();
        const S s(w.params);
        const bool chain = name == "chain";
        const auto dts = sweep_steps(config.t_end, chain ? 0.5 : 0.1, chain ? 1e-5 : 1e-4, config.points);
        w.points = scene_points(s, config, dts, config.t_end, config.methods);
        if (chain) out.limits = stable_steps(config, w.params, dts, w.points);
      }
    });
    for (const double level : config.error_levels) w.cheapest.push_back(cheapest_at(w.points, level));
    out.scenes.push_back(std::move(w));
  }
  out.stiffness = stiffness_rows(config);
  // The crossover: the smallest ratio from which on, at every larger one, the best implicit run is
  // cheaper than the best explicit one.
  for (std::size_t i = out.stiffness.size(); i-- > 0;) {
    const StiffnessRow& r = out.stiffness[i];
    const bool implicit_wins =
        !r.best_implicit.empty() &&
        (r.best_explicit.empty() || cheaper(config.timing, r.implicit_seconds, r.implicit_evaluations,
                                            r.explicit_seconds, r.explicit_evaluations));
    if (!implicit_wins) break;
    out.crossover_ratio = r.ratio;
  }
  return out;
}

}  // namespace steplab
