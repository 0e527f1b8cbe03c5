#include "analysis/work_precision.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <boost/numeric/odeint.hpp>

#include "analysis/convergence.hpp"
#include "analysis/fit.hpp"
#include "analysis/parallel.hpp"
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

// Boost.Odeint's controlled runge_kutta_dopri5 on the scene's own first-order system z = (x, v).
template <HasExact S> struct OdeintRun {
  using Z = std::array<double, 2 * S::dim>;
  // error_max: the largest position error at the accepted steps (null: not computed, for timing)
  static State<S::dim> run(const S& s, double tol, double t_end, long long& steps, long long& evaluations,
                           double* error_max = nullptr) {
    constexpr int D = S::dim;
    const State<D> y0 = s.initial();
    Z z{};
    for (int i = 0; i < D; ++i) z[i] = y0.x[i], z[D + i] = y0.v[i];
    steps = evaluations = 0;
    const auto rhs = [&](const Z& a, Z& da, double) {
      ++evaluations;
      const Vec<D> x = Eigen::Map<const Vec<D>>(a.data()), v = Eigen::Map<const Vec<D>>(a.data() + D);
      const Vec<D> acc = acceleration(s, x, v);
      for (int i = 0; i < D; ++i) da[i] = v[i], da[D + i] = acc[i];
    };
    namespace odeint = boost::numeric::odeint;
    odeint::integrate_adaptive(odeint::make_controlled(tol, tol, odeint::runge_kutta_dopri5<Z>()), rhs, z, 0.0, t_end,
                               1e-6 * t_end, [&](const Z& a, double t) {
                                 steps += t > 0;
                                 if (error_max) {
                                   const double e = (Eigen::Map<const Vec<D>>(a.data()) - exact(s, t).x).norm();
                                   *error_max = std::max(*error_max, e);
                                 }
                               });
    return {Eigen::Map<const Vec<D>>(z.data()), Eigen::Map<const Vec<D>>(z.data() + D)};
  }
};

template <HasExact S, class M> WorkPoint fixed_point(const S& s, std::size_t m, double dt, double t_end) {
  WorkPoint p{std::string(method_infos[m].name), false, dt};
  const Counted<S> counted(s);
  RunSpec spec;
  spec.dt = dt;
  spec.steps = steps_for(t_end, dt);
  const RunResult<S::dim> r = simulate<M>(counted, spec);
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

template <HasExact S> WorkPoint odeint_point(const S& s, double tol, double t_end) {
  WorkPoint p{"odeint_dopri5", true, tol};
  p.error = 0;
  OdeintRun<S>::run(s, tol, t_end, p.steps, p.force_evaluations, &p.error);
  if (!std::isfinite(p.error)) p.status = RunStatus::Diverged, p.error = kInf;
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
  if (p.method == "odeint_dopri5") {
    long long a = 0, b = 0;
    return min_time([&] { OdeintRun<S>::run(s, p.setting, t_end, a, b); });
  }
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
  const std::size_t nf = methods.size() * dts.size(), nt = c.tolerances.size();
  std::vector<WorkPoint> points(nf + 2 * nt);
  parallel_for(points.size(), c.threads, [&](std::size_t task) {
    if (task < nf) {
      const std::size_t m = methods[task / dts.size()];
      points[task] = with_method(m, [&]<class M>() { return fixed_point<S, M>(s, m, dts[task % dts.size()], t_end); });
    } else if (task < nf + nt) {
      points[task] = dopri5_point(s, c.tolerances[task - nf], t_end);
    } else {
      points[task] = odeint_point(s, c.tolerances[task - nf - nt], t_end);
    }
  });
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

// The chain's explicit methods: the largest stable dt of the sweep, and the dt their own error
// line (least squares of ln error on ln dt over the stable runs) puts at kLimitErrorLevel.
std::vector<StableStep> stable_steps(const std::vector<std::size_t>& methods, const std::vector<WorkPoint>& points) {
  std::vector<StableStep> out;
  for (const std::size_t m : methods) {
    if (method_infos[m].implicit) continue;
    StableStep s{std::string(method_infos[m].name), 0, -1};
    std::vector<double> ln_dt, ln_error;
    for (const WorkPoint& p : points) {
      if (p.method != s.method || p.status != RunStatus::Ok || !(p.error > 1e-13)) continue;
      s.largest_stable_dt = std::max(s.largest_stable_dt, p.setting);
      ln_dt.push_back(std::log(p.setting));
      ln_error.push_back(std::log(p.error));
    }
    if (ln_dt.size() >= 2) {
      const LineFit line = fit_line(ln_dt, ln_error);
      s.accuracy_dt = std::exp((std::log(kLimitErrorLevel) - line.intercept) / line.slope);
    }
    out.push_back(std::move(s));
  }
  return out;
}

// One stiffness: for each method, the first run of a falling dt (or tolerance) sweep whose error is
// at most crossover_error; then the cheapest explicit and implicit ones.
StiffnessRow stiffness_row(const WorkPrecisionConfig& c, double k2) {
  std::vector<double> p = default_param_values<Chain>();
  p[3] = k2;  // Chain::params: mass1, mass2, stiffness1, stiffness2, ...
  const Chain s(p);
  const std::vector<double> dts = sweep_steps(c.sweep_t_end, 0.5, 1e-7, 57);  // 8 per decade
  const auto reaches = [&](const WorkPoint& w) { return w.status == RunStatus::Ok && w.error <= c.crossover_error; };
  std::vector<WorkPoint> found(c.methods.size() + 1);  // the methods, then dopri5
  parallel_for(found.size(), c.threads, [&](std::size_t task) {
    const auto first_reaching = [&](const std::vector<double>& settings, auto&& run) {
      for (const double setting : settings)
        if (WorkPoint w = run(setting); reaches(w)) return w;
      return WorkPoint{};
    };
    if (task == c.methods.size()) {
      found[task] = first_reaching(c.tolerances, [&](double tol) { return dopri5_point(s, tol, c.sweep_t_end); });
    } else {
      const std::size_t m = c.methods[task];
      found[task] = with_method(m, [&]<class M>() {
        return first_reaching(dts, [&](double dt) { return fixed_point<Chain, M>(s, m, dt, c.sweep_t_end); });
      });
    }
  });
  StiffnessRow row{k2, k2 / p[2], "", ""};
  for (WorkPoint& w : found) {
    if (w.method.empty()) continue;
    if (c.timing) w.seconds = time_point(s, w, c.sweep_t_end);
    const bool implicit = is_implicit(w.method);
    std::string& best = implicit ? row.best_implicit : row.best_explicit;
    double& secs = implicit ? row.implicit_seconds : row.explicit_seconds;
    long long& evals = implicit ? row.implicit_evaluations : row.explicit_evaluations;
    if (best.empty() || cheaper(c.timing, w.seconds, evaluations(w), secs, evals))
      best = w.method, secs = w.seconds, evals = evaluations(w);
  }
  return row;
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
      }
    });
    for (const double level : config.error_levels) w.cheapest.push_back(cheapest_at(w.points, level));
    out.scenes.push_back(std::move(w));
  }
  out.limits = stable_steps(config.methods, out.scenes[1].points);
  for (const double k2 : config.stiffnesses) out.stiffness.push_back(stiffness_row(config, k2));
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
