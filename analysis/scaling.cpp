#include "analysis/scaling.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

#include "analysis/convergence.hpp"
#include "analysis/fit.hpp"
#include "analysis/kernel.hpp"
#include "analysis/defaults.hpp"
#include "analysis/mode_stability.hpp"
#include "analysis/shard.hpp"
#include "analysis/sized_peers.hpp"
#include "analysis/timing.hpp"

namespace steplab {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

// A row crosses a shard as bytes (analysis/shard.hpp).
template <class F> void encode_fields(ScalingRow& r, F&& f) {
  f(r.solver), f(r.implicit), f(r.adaptive), f(r.n), f(r.masses), f(r.dt_stable), f(r.dt), f(r.capped), f(r.error);
  f(r.steps), f(r.forces), f(r.jacobians), f(r.rejected), f(r.factorisations), f(r.solves), f(r.newton), f(r.seconds), f(r.runs);
}

namespace {

// Timed runs: at least one and 0.1 s in all, the minimum kept; so a run shorter than 0.1 s is
// timed at least twice, and a run of the largest sizes (seconds alone) once.
constexpr std::size_t kRepeats = 1;
constexpr double kSeconds = 0.1;

const SceneKernel& scene_of(const ScalingConfig& c) { return scene_kernel(scene_index(c.scene)); }

// The study's parameters with the scene's size parameter (core/scene.hpp, size_param) at n.
std::vector<double> sized(const ScalingConfig& c, int n) {
  std::vector<double> p = c.params;
  p[scene_of(c).size_param] = n;
  return p;
}

std::string fmt_reference_error(double estimated, double target, int n) {
  char text[200];
  std::snprintf(text, sizeof text, "the reference solution at size %d is not accurate enough for error %g: its own error is %g", n,
                target, estimated);
  return text;
}

// Where each size's runs are measured against: the positions at t_end, exact where the scene has
// an exact solution (the rope), else the reference solution (the soft body: dopri5 at rtol
// 1e-13, analysis/convergence.hpp), whose own estimated error must stay a hundredth of the
// target's.
Eigen::VectorXd target_positions(const ScalingConfig& c, const std::vector<double>& p, int n) {
  const SceneKernel& s = scene_of(c);
  if (s.has_exact) return s.exact(p, c.t_end).x;
  const ReferenceSolution ref = reference_solution(s, p, c.t_end);
  if (!(ref.estimated_error <= 0.01 * c.target_error))
    throw std::runtime_error(fmt_reference_error(ref.estimated_error, c.target_error, n));
  return Eigen::Map<const Eigen::VectorXd>(ref.x.data(), std::ssize(ref.x));
}

// What every row at one size shares, made once before the rows: the parameters, the positions
// the runs are measured against, the scene's modes (each method's dt*) and its masses.
struct Size {
  int n;
  std::vector<double> params;
  Eigen::VectorXd target;
  std::vector<Mode> modes;
  int masses;
};

Size size_of(const ScalingConfig& c, int n) {
  std::vector<double> p = sized(c, n);
  Eigen::VectorXd target = target_positions(c, p, n);
  std::vector<Mode> modes = scene_of(c).modes(p);
  const int masses = scaling_masses(c, n);
  return {n, std::move(p), std::move(target), std::move(modes), masses};
}

// The largest |x_i - x_i(t_end)| over the masses; inf for a run that did not finish.
double max_error(const Eigen::VectorXd& x, const Eigen::VectorXd& exact, bool ok) {
  return ok && x.allFinite() ? (x - exact).cwiseAbs().maxCoeff() : std::numeric_limits<double>::infinity();
}

// What a run at a knob gave: its error (NaN: not run, it would take more than max_steps) and its
// counts.
struct Trial {
  double error;
  Counts counts;
};

// A run at `knob` (a step, or a tolerance) gives a Trial; the search keeps the largest knob whose
// error is at or below the target, with its counts. Error ~ C knob^p: the next knob aims at 0.7
// of the target with p the slope between the last two finite errors in log-log (the declared
// order before there are two, and where the slope is not between 0.5 and order + 1: the stiff
// modes of the rope reduce a method's order, Radau IIA's to about 2 here), the change bounded by
// 1/16 .. 4 and the knob by `most`. Stops within a factor 0.35 .. 1 of the target, or at a knob
// not run (smaller ones would need still more steps).
template <class Run> void search(ScalingRow& row, double start, double most, double order, double target, Run&& run) {
  double knob = std::min(start, most), last_knob = 0, last_error = 0;
  row.dt = kNaN;
  for (row.runs = 0; row.runs < kSearchRuns; ++row.runs) {
    const Trial trial = run(knob);
    const double e = trial.error;
    if (std::isnan(e)) break;
    if (e <= target && !(knob <= row.dt)) {
      const Counts& n = trial.counts;
      row.dt = knob, row.error = e, row.steps = n.steps, row.forces = n.forces, row.jacobians = n.jacobians;
      row.rejected = n.rejected, row.factorisations = n.factorisations, row.solves = n.solves, row.newton = n.newton;
    }
    if (e <= target && e > 0.35 * target) break;  // within a factor 3 of the target: close enough
    double p = order;
    if (last_knob > 0 && std::isfinite(e) && e > 0 && last_error > 0) {
      const double slope = std::log(e / last_error) / std::log(knob / last_knob);
      if (slope >= 0.5 && slope <= order + 1) p = slope;
    }
    if (std::isfinite(e) && e > 0) last_knob = knob, last_error = e;
    const double factor = std::isfinite(e) && e > 0 ? std::pow(0.7 * target / e, 1 / p) : 1.0 / 16;
    const double next = std::min(most, knob * std::clamp(factor, 1.0 / 16, 4.0));
    if (next == knob) break;  // at the largest knob allowed, and below the target there
    knob = next;
  }
  ++row.runs;
}

ScalingRow method_row(const ScalingConfig& c, const Size& size, std::size_t m) {
  const std::vector<double>& p = size.params;
  const Eigen::VectorXd& exact = size.target;
  const std::size_t scene = scene_index(c.scene);
  const MethodInfo& info = method_info(m);
  ScalingRow row{std::string(info.name), info.implicit, false, size.n, size.masses};
  row.dt_stable = modes_predicted_threshold(m, size.modes);  // analysis/mode_stability.hpp
  const double most = std::min(0.95 * row.dt_stable, c.t_end / 2);
  if (!(most * c.max_steps >= c.t_end)) {  // no stable step covers t_end in max_steps
    row.dt = kNaN;
    return row;
  }
  const PairKernel& k = pair_kernel(m, scene);
  // a whole number of steps ends at t_end: dt = t_end / ceil(t_end / knob)
  search(row, std::min(most, c.t_end / 20), most, info.order, c.target_error, [&](double knob) {
    RunSpec spec;
    spec.errors = false;
    spec.dt = c.t_end / std::ceil(c.t_end / knob * (1 - 1e-12));
    spec.steps = steps_for(c.t_end, spec.dt);
    if (spec.steps > c.max_steps) return Trial{kNaN, {}};
    Counts counts;
    const AnyResult res = k.run_counted(p, spec, counts);
    return Trial{max_error(res.final.x, exact, res.status == RunStatus::Ok && res.steps == spec.steps), counts};
  });
  if (row.reached()) {
    row.capped = row.dt >= most && 0.95 * row.dt_stable <= c.t_end / 2;  // the search stopped at 0.95 dt*
    row.dt = c.t_end / static_cast<double>(row.steps);
  }
  return row;
}

AdaptiveSpec adaptive_spec(double tol, double t_end) {
  AdaptiveSpec spec;
  spec.tol = {tol, tol};
  spec.t_end = t_end;
  spec.errors = false;
  return spec;
}

// dopri5 (steplab's) or a peer (analysis/peers.hpp) at a tolerance.
ScalingRow peer_row(const ScalingConfig& c, const Size& size, const std::string& solver) {
  const std::vector<double>& p = size.params;
  const Eigen::VectorXd& exact = size.target;
  const std::size_t scene = scene_index(c.scene);
  const PeerInfo& peer = *find_peer(solver);
  ScalingRow row{solver, peer.implicit, true, size.n, size.masses, kNaN};
  if (solver == "dopri5") {
    search(row, 1e-4, 1e-2, 1, c.target_error, [&](double tol) {
      const AnyAdaptiveResult res = scene_kernel(scene).dopri5(p, adaptive_spec(tol, c.t_end));
      return Trial{max_error(res.run.final.x, exact, res.run.status == RunStatus::Ok), counts_of(res.stats)};
    });
    return row;
  }
  const SceneKernel& s = scene_kernel(scene);
  const std::shared_ptr<const void> made = s.make(p);
  search(row, 1e-4, 1e-2, 1, c.target_error, [&](double tol) {
    PeerCounts counts;
    const State<Eigen::Dynamic> end = run_sized_peer(peer, s, made.get(), tol, c.t_end, counts);
    return Trial{max_error(end.x, exact, !counts.failed), counts};
  });
  return row;
}

double run_seconds(const ScalingConfig& c, const ScalingRow& row) {
  const std::vector<double> p = sized(c, row.n);
  const std::size_t scene = scene_index(c.scene);
  std::vector<double> times;
  if (!row.adaptive) {
    RunSpec spec;
    spec.errors = false;
    spec.dt = row.dt;
    spec.steps = row.steps;
    times = pair_kernel(*find_method(row.solver), scene).timings(p, spec, kRepeats, kSeconds);
  } else if (row.solver == "dopri5") {
    times = scene_kernel(scene).dopri5_timings(p, adaptive_spec(row.dt, c.t_end), kRepeats, kSeconds);
  } else {  // the scene made once, outside the timed runs
    const PeerInfo& peer = *find_peer(row.solver);
    const SceneKernel& s = scene_kernel(scene);
    const std::shared_ptr<const void> made = s.make(p);
    PeerCounts counts;
    times = repeated_timings([&] { run_sized_peer(peer, s, made.get(), row.dt, c.t_end, counts); }, kRepeats, kSeconds);
  }
  return *std::min_element(times.begin(), times.end());
}

ScalingFit fit_of(const ScalingConfig& c, std::span<const ScalingRow> rows) {
  std::vector<double> masses, run, step, stable;
  for (const ScalingRow& r : rows) {
    masses.push_back(r.masses);
    run.push_back(r.reached() && r.steps > 0 ? scaling_cost(c, r) : kNaN);
    step.push_back(run.back() / static_cast<double>(r.steps));
    stable.push_back(r.dt_stable);
  }
  ScalingFit f{rows.front().solver, fit_exponent(masses, step), fit_exponent(masses, run), fit_exponent(masses, stable)};
  f.step.early = f.run.early = begins_early(masses, step);
  return f;
}

}  // namespace

bool begins_early(std::span<const double> masses, std::span<const double> step_cost) {
  std::vector<std::size_t> known;
  for (std::size_t k = 0; k < masses.size() && known.size() < 2; ++k)
    if (std::isfinite(step_cost[k]) && step_cost[k] > 0) known.push_back(k);
  if (known.size() < 2) return false;
  const std::size_t a = known[0], b = known[1];
  return std::log(step_cost[b] / step_cost[a]) < kAsymptoticSlope * std::log(masses[b] / masses[a]);
}

Exponent fit_exponent(std::span<const double> masses, std::span<const double> y) {
  std::vector<double> n, v;
  for (std::size_t k = 0; k < masses.size(); ++k)
    if (std::isfinite(y[k]) && y[k] > 0) n.push_back(std::log(masses[k])), v.push_back(std::log(y[k]));
  Exponent e;
  e.sizes = static_cast<int>(n.size());
  if (n.empty()) return e;
  e.decades = (*std::max_element(n.begin(), n.end()) - *std::min_element(n.begin(), n.end())) / std::log(10.0);
  if (e.sizes < kFitSizes || e.decades < kFitDecades - 1e-9) return e;
  const LineFit line = fit_line(n, v);
  e.value = line.slope, e.lo = line.ci95_lo, e.hi = line.ci95_hi;
  return e;
}

double scaling_cost(const ScalingConfig& c, const ScalingRow& r) { return c.timing ? r.seconds : double(r.forces + r.jacobians) * r.masses; }

int scaling_masses(const ScalingConfig& c, int n) {
  const SceneKernel& s = scene_of(c);
  return static_cast<int>(s.initial(sized(c, n)).x.size()) / s.coords_per_mass;
}

std::vector<std::string> scaling_adaptive_solvers(std::string_view scene) {
  return peer_names(peer_scenes(scene_kernel(scene_index(scene))));
}

bool scales(const SceneKernel& s) { return s.size_param >= 0 && s.modes; }

ScalingConfig scaling_config(std::string_view scene) {
  ScalingConfig c;
  c.scene = std::string(scene);
  c.adaptive = scaling_adaptive_solvers(scene);
  c.params = default_param_values(scene_index(scene));
  ScalingDefaults d = scaling_defaults(scene);
  c.sizes = std::move(d.sizes), c.max_steps = d.max_steps;
  return c;
}

ScalingResult scaling_study(const ScalingConfig& c) {
  if (!scales(scene_of(c))) throw std::logic_error("scaling_study: the " + c.scene + " has no size parameter or no modes");
  for (const std::string& a : c.adaptive)
    if (const PeerInfo* p = find_peer(a); !p || !p->built || !peer_runs_on(*p, peer_scenes(scene_of(c))))
      throw std::logic_error("scaling_study: " + a + " is not an adaptive solver built for the " + c.scene);
  ScalingResult out;
  out.config = c;
  const std::size_t nm = c.methods.size(), ns = c.sizes.size(), np = c.adaptive.size();
  std::vector<Size> sizes;
  for (int n : c.sizes) sizes.push_back(size_of(c, n));
  out.rows = study_map<ScalingRow>((nm + np) * ns, c.workers, [&](std::size_t task) {
    const std::size_t solver = task / ns, k = task % ns;
    return solver < nm ? method_row(c, sizes[k], c.methods[solver]) : peer_row(c, sizes[k], c.adaptive[solver - nm]);
  });
  if (c.timing)
    for (ScalingRow& r : out.rows)
      if (r.reached()) r.seconds = run_seconds(c, r);
  for (std::size_t s = 0; s < nm + np; ++s) out.fits.push_back(fit_of(c, out.rows_of(s)));
  // crossover: the first size where the cheapest implicit method beats every explicit one (steplab's methods)
  for (std::size_t k = 0; k < ns && out.crossover == 0; ++k) {
    double explicit_best = std::numeric_limits<double>::infinity(), implicit_best = explicit_best;
    std::string implicit_name;
    for (std::size_t s = 0; s < nm; ++s) {
      const ScalingRow& r = out.rows_of(s)[k];
      if (!r.reached()) continue;
      const double cost = scaling_cost(c, r);
      if (r.implicit && cost < implicit_best) implicit_best = cost, implicit_name = r.solver;
      if (!r.implicit && cost < explicit_best) explicit_best = cost;
    }
    if (implicit_best < explicit_best) out.crossover = c.sizes[k], out.crossover_method = implicit_name;
  }
  return out;
}

}  // namespace steplab
