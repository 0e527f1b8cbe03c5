#include "analysis/studies/scaling.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>

#include "analysis/studies/convergence.hpp"
#include "analysis/fits/fit.hpp"
#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/defaults.hpp"
#include "analysis/studies/mode_stability.hpp"
#include "analysis/kernel/shard.hpp"
#include "analysis/peers/sized_peers.hpp"
#include "analysis/kernel/noise.hpp"
#include "analysis/kernel/timing.hpp"

namespace steplab {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

// A row crosses a shard as bytes (analysis/kernel/shard.hpp).
template <class F> void encode_fields(ScalingRow& r, F&& f) {
  f(r.solver), f(r.target), f(r.stiffness), f(r.implicit), f(r.adaptive), f(r.n), f(r.masses), f(r.dt_stable), f(r.dt);
  f(r.capped), f(r.error), f(r.steps), f(r.forces), f(r.jacobians), f(r.rejected), f(r.factorisations), f(r.solves);
  f(r.newton), f(r.seconds), f(r.spread), f(r.runs);
}

namespace {

// Timed runs: at least one and ScalingConfig::timing_seconds in all, the minimum kept; so a run
// shorter than that is timed at least twice, and a run of the largest sizes (seconds alone) once.
constexpr std::size_t kRepeats = 1;

const SceneKernel& scene_of(const ScalingConfig& c) { return scene_kernel(scene_index(c.scene)); }

// The study's parameters with the scene's size parameter (core/scene.hpp, size_param) at n and
// its stiffness parameter at `stiffness` (NaN: the scene has none).
std::vector<double> sized(const ScalingConfig& c, int n, double stiffness) {
  std::vector<double> p = c.params;
  const SceneKernel& s = scene_of(c);
  p[s.size_param] = n;
  if (s.stiffness_param >= 0) p[s.stiffness_param] = stiffness;
  return p;
}

std::string fmt_reference_error(double estimated, double target, int n) {
  char text[200];
  std::snprintf(text, sizeof text, "the reference solution at size %d is not accurate enough for error %g: its own error is %g", n,
                target, estimated);
  return text;
}

// The frame times t_k = k t_end / frames, k = 0 .. frames (t_frames = t_end exactly).
double frame_time(const ScalingConfig& c, int k) { return steplab::frame_time(k, c.frames, c.t_end); }

// The positions at the frames k = 0 .. frames the runs are measured against: exact where the
// scene has an exact solution (the rope), else the reference solution at the frames
// (analysis/studies/convergence.hpp), whose own error there must stay a hundredth of the smallest
// target's.
std::vector<Eigen::VectorXd> frame_positions(const ScalingConfig& c, const std::vector<double>& p, int n, double smallest_target) {
  const SceneKernel& s = scene_of(c);
  std::vector<Eigen::VectorXd> frames;
  if (s.has_exact) {
    for (int k = 0; k <= c.frames; ++k) frames.push_back(s.exact(p, frame_time(c, k)).x);
    return frames;
  }
  ReferenceSolution ref = reference_solution(s, p, c.t_end, c.frames);
  if (!(ref.frames_error <= 0.01 * smallest_target)) throw std::runtime_error(fmt_reference_error(ref.frames_error, smallest_target, n));
  return std::move(ref.frames);
}

// What every row of one cell (stiffness, size) shares, made once before the rows: the
// parameters, the positions at the frames the runs are measured against, the scene's modes (each
// method's dt*), its masses and the targets' absolute errors.
struct Cell {
  int n;
  double stiffness;
  std::vector<double> params;
  std::vector<Eigen::VectorXd> frames;
  std::vector<Mode> modes;
  int masses;
  std::vector<double> errors;
};

Cell cell_of(const ScalingConfig& c, int n, double stiffness, std::vector<double> errors) {
  std::vector<double> p = sized(c, n, stiffness);
  std::vector<Eigen::VectorXd> frames = frame_positions(c, p, n, *std::min_element(errors.begin(), errors.end()));
  std::vector<Mode> modes = scene_of(c).modes(p);
  const int masses = scaling_masses(c, n);
  return {n, stiffness, std::move(p), std::move(frames), std::move(modes), masses, std::move(errors)};
}

// The largest |x_i(t_k) - x_i*(t_k)| over the coordinates and the frames k = 1 .. frames, `at(k)`
// a run's positions at frame k; inf for a run that did not finish.
template <class At> double frames_error(const Cell& cell, bool ok, At&& at) {
  if (!ok) return std::numeric_limits<double>::infinity();
  double e = 0;
  for (std::size_t k = 1; k < cell.frames.size(); ++k) {
    const Eigen::VectorXd& x = at(k);
    if (!x.allFinite()) return std::numeric_limits<double>::infinity();
    e = std::max(e, (x - cell.frames[k]).cwiseAbs().maxCoeff());
  }
  return e;
}

// The same from a run's samples (a fixed-step run's, dopri5's dense output): one at each frame.
double frames_error(const Cell& cell, bool ok, const std::vector<Sample<Eigen::Dynamic>>& samples) {
  return frames_error(cell, ok && samples.size() == cell.frames.size(),
                      [&](std::size_t k) -> const Eigen::VectorXd& { return samples[k].x; });
}

// What a run at a knob gave: its error (NaN: not run, it would take more than max_steps) and its
// counts.
struct Trial {
  double error;
  Counts counts;
};

// The runs one solver made in one cell, by knob (a number of steps, or a tolerance): each target's
// search asks them again where it lands on the same knob (a step capped at dt* lands there for
// every target), and a run is deterministic, so it is made once.
using Trials = std::map<double, Trial>;
template <class Run> Trial remembered(Trials& made, double knob, Run&& run) {
  const auto it = made.find(knob);
  return it != made.end() ? it->second : made.emplace(knob, run()).first->second;
}

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

// A fixed-step run of `steps` steps with a sample at every frame: its output between steps
// (core/dense_output.hpp), or, where the steps divide the frames, the state at step k steps/frames.
RunSpec frame_run(const ScalingConfig& c, long long steps) {
  RunSpec spec;
  spec.errors = false;
  spec.steps = steps;
  spec.dt = c.t_end / static_cast<double>(steps);
  if (c.steps_divide_frames) spec.max_samples = c.frames + 1;  // SamplePlan: step k (steps / frames), exactly frame k
  else spec.outputs = c.frames + 1;
  return spec;
}

ScalingRow method_row(const ScalingConfig& c, const Cell& cell, int target, std::size_t m, Trials& made) {
  const std::size_t scene = scene_index(c.scene);
  const MethodInfo& info = method_info(m);
  ScalingRow row{std::string(info.name), target, cell.stiffness, info.implicit, false, cell.n, cell.masses};
  row.dt_stable = modes_predicted_threshold(m, cell.modes);  // analysis/studies/mode_stability.hpp
  const double frame = c.t_end / c.frames;
  const double most = std::min(0.95 * row.dt_stable, c.steps_divide_frames ? frame : c.t_end);
  if (!(most * c.max_steps >= c.t_end)) {  // no stable step covers t_end in max_steps
    row.dt = kNaN;
    return row;
  }
  const PairKernel& k = pair_kernel(m, scene);
  // steps_divide_frames: steps = frames j, dt = frame / ceil(frame / knob), a whole number of
  // steps to each frame; else any whole number of steps to t_end
  const auto steps_for_knob = [&](double knob) {
    return c.steps_divide_frames ? c.frames * static_cast<long long>(std::ceil(frame / knob * (1 - 1e-12)))
                                 : static_cast<long long>(std::ceil(c.t_end / knob * (1 - 1e-12)));
  };
  search(row, std::min(most, frame), most, info.order, cell.errors[target], [&](double knob) {
    const long long steps = steps_for_knob(knob);
    if (steps > c.max_steps) return Trial{kNaN, {}};
    return remembered(made, static_cast<double>(steps), [&] {
      Counts counts;
      const AnyResult res = k.run_counted(cell.params, frame_run(c, steps), counts);
      return Trial{frames_error(cell, res.status == RunStatus::Ok && res.steps == steps, res.samples), counts};
    });
  });
  if (row.reached()) {
    row.capped = row.dt >= most && 0.95 * row.dt_stable <= (c.steps_divide_frames ? frame : c.t_end);  // stopped at 0.95 dt*
    row.dt = c.t_end / static_cast<double>(row.steps);
  }
  return row;
}

AdaptiveSpec adaptive_spec(const ScalingConfig& c, double tol) {
  AdaptiveSpec spec;
  spec.tol = {tol, tol};
  spec.t_end = c.t_end;
  spec.errors = false;
  spec.max_samples = c.frames + 1;  // its dense output at every frame
  return spec;
}

// dopri5 (steplab's) or a peer (analysis/peers/peers.hpp) at a tolerance.
ScalingRow peer_row(const ScalingConfig& c, const Cell& cell, int target, const std::string& solver, Trials& made) {
  const std::size_t scene = scene_index(c.scene);
  const PeerInfo& peer = *find_peer(solver);
  ScalingRow row{solver, target, cell.stiffness, peer.implicit, true, cell.n, cell.masses, kNaN};
  const double error = cell.errors[target];
  if (solver == "dopri5") {
    search(row, 1e-4, 1e-2, 1, error, [&](double tol) {
      return remembered(made, tol, [&] {
        const AnyAdaptiveResult res = scene_kernel(scene).dopri5(cell.params, adaptive_spec(c, tol));
        return Trial{frames_error(cell, res.run.status == RunStatus::Ok, res.run.samples), counts_of(res.stats)};
      });
    });
    return row;
  }
  const SceneKernel& s = scene_kernel(scene);
  const std::shared_ptr<const void> scene_made = s.make(cell.params);
  search(row, 1e-4, 1e-2, 1, error, [&](double tol) {
    return remembered(made, tol, [&] {
      PeerCounts counts;
      std::vector<Eigen::VectorXd> x(cell.frames.size());
      run_sized_peer(peer, s, scene_made.get(), tol, c.t_end, counts, {c.frames, [&](int k, const Eigen::VectorXd& at) { x[k] = at; }});
      return Trial{frames_error(cell, !counts.failed, [&](std::size_t f) -> const Eigen::VectorXd& { return x[f]; }), Counts(counts)};
    });
  });
  return row;
}

double run_seconds(const ScalingConfig& c, const ScalingRow& row) {
  const std::vector<double> p = sized(c, row.n, row.stiffness);
  const std::size_t scene = scene_index(c.scene);
  std::vector<double> times;
  if (!row.adaptive) {
    times = pair_kernel(*find_method(row.solver), scene).timings(p, frame_run(c, row.steps), kRepeats, c.timing_seconds);
  } else if (row.solver == "dopri5") {
    times = scene_kernel(scene).dopri5_timings(p, adaptive_spec(c, row.dt), kRepeats, c.timing_seconds);
  } else {  // the scene made once, outside the timed runs; the frames kept as the search's runs kept them
    const PeerInfo& peer = *find_peer(row.solver);
    const SceneKernel& s = scene_kernel(scene);
    const std::shared_ptr<const void> made = s.make(p);
    PeerCounts counts;
    std::vector<Eigen::VectorXd> x(static_cast<std::size_t>(c.frames) + 1);
    const PeerFrames frames{c.frames, [&](int k, const Eigen::VectorXd& at) { x[k] = at; }};
    times = repeated_timings([&] { run_sized_peer(peer, s, made.get(), row.dt, c.t_end, counts, frames); }, kRepeats, c.timing_seconds);
  }
  return *std::min_element(times.begin(), times.end());
}

}  // namespace

std::vector<double> scaling_stiffnesses(const ScalingConfig& c) {
  const SceneKernel& s = scene_of(c);
  if (s.stiffness_param < 0) return {kNaN};
  return c.stiffnesses.empty() ? std::vector<double>{c.params[s.stiffness_param]} : c.stiffnesses;
}

double absolute_error(const ScalingConfig& c, const ErrorTarget& t, double stiffness) {
  if (!t.of_extent) return t.value;
  const SceneKernel& s = scene_of(c);
  const Eigen::VectorXd x = s.initial(sized(c, *std::max_element(c.sizes.begin(), c.sizes.end()), stiffness)).x;
  double extent = 0;
  for (int axis = 0; axis < s.coords_per_mass; ++axis) {
    const auto along = Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<>>(x.data() + axis, x.size() / s.coords_per_mass,
                                                                                  Eigen::InnerStride<>(s.coords_per_mass));
    extent = std::max(extent, along.maxCoeff() - along.minCoeff());
  }
  return t.value * extent;
}

std::string target_text(const ScalingConfig& c, const ScalingBlock& b) {
  const ErrorTarget& t = c.targets[static_cast<std::size_t>(b.target)];
  char text[120];
  if (t.of_extent)
    std::snprintf(text, sizeof text, "%g %% of the extent, %.3g", 100 * t.value, b.error);
  else
    std::snprintf(text, sizeof text, "%g", t.value);
  return text;
}

double scaling_cost(const ScalingConfig& c, const ScalingRow& r) { return c.timing ? r.seconds : double(r.forces) * r.masses; }

int scaling_masses(const ScalingConfig& c, int n) {
  const SceneKernel& s = scene_of(c);
  return static_cast<int>(s.initial(sized(c, n, scaling_stiffnesses(c).front())).x.size()) / s.coords_per_mass;
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
  if (c.targets.empty() || c.frames < 1) throw std::logic_error("scaling_study: no target, or no frame");
  ScalingResult out;
  out.config = c;
  const std::vector<double> stiffnesses = scaling_stiffnesses(c);
  const std::size_t nm = c.methods.size(), ns = c.sizes.size(), nk = stiffnesses.size(), nsolvers = out.solvers();
  const std::size_t nt = c.targets.size();
  std::vector<double> errors(nt * nk);  // each (target, stiffness)'s absolute error, target-major
  for (std::size_t b = 0; b < nt * nk; ++b) errors[b] = absolute_error(c, c.targets[b / nk], stiffnesses[b % nk]);
  std::vector<Cell> cells;  // stiffness-major
  for (std::size_t k = 0; k < nk; ++k) {
    std::vector<double> at;  // the targets' errors at this stiffness
    for (std::size_t t = 0; t < nt; ++t) at.push_back(errors[t * nk + k]);
    for (int n : c.sizes) cells.push_back(cell_of(c, n, stiffnesses[k], at));
  }
  // task: (stiffness * solvers + solver) * ns + size, each target's row; then the rows' order:
  // ((target * nk + stiffness) * solvers + solver) * ns + size
  const std::size_t tasks = nk * nsolvers * ns;
  const std::vector<std::vector<ScalingRow>> found = study_map<std::vector<ScalingRow>>(tasks, c.workers, [&](std::size_t task) {
    const std::size_t size = task % ns, solver = task / ns % nsolvers, k = task / ns / nsolvers;
    const Cell& cell = cells[k * ns + size];
    Trials made;
    std::vector<ScalingRow> rows;
    for (int t = 0; t < static_cast<int>(nt); ++t)
      rows.push_back(solver < nm ? method_row(c, cell, t, c.methods[solver], made) : peer_row(c, cell, t, c.adaptive[solver - nm], made));
    return rows;
  });
  // In a shard (analysis/kernel/shard.hpp) the tasks of other parts have no rows here: they stand
  // as empty rows, so that every index below holds; a shard writes its tasks' results, not these.
  for (std::size_t t = 0; t < nt; ++t)
    for (std::size_t task = 0; task < tasks; ++task) out.rows.push_back(found[task].empty() ? ScalingRow{} : found[task][t]);
  if (c.timing) {  // a run timed once, in two passes (the second in reverse: its spread, noise.hpp); the
                   // rows of other targets that chose the same run share its time
    using Key = std::tuple<std::string, int, double, double>;
    const auto key = [](const ScalingRow& r) { return Key{r.solver, r.n, r.stiffness, r.adaptive ? r.dt : static_cast<double>(r.steps)}; };
    std::map<Key, ScalingRow*> first;  // each run's first row, timed
    std::vector<ScalingRow*> runs;
    for (ScalingRow& r : out.rows)
      if (r.reached() && first.emplace(key(r), &r).second) runs.push_back(&r);
    time_in_two_passes(runs, [&](const ScalingRow& r) { return run_seconds(c, r); });
    for (ScalingRow& r : out.rows)
      if (r.reached()) {
        const ScalingRow& timed = *first.at(key(r));
        r.seconds = timed.seconds, r.spread = timed.spread;
      }
  }
  for (std::size_t b = 0; b < nt * nk; ++b) {
    ScalingBlock block;
    block.target = static_cast<int>(b / nk), block.error = errors[b], block.stiffness = stiffnesses[b % nk];
    for (std::size_t k = 0; k < ns; ++k) {
      const Cell& at = cells[b % nk * ns + k];
      ScalingCell cell;
      cell.n = at.n, cell.masses = at.masses;
      for (const Eigen::VectorXd& x : at.frames) cell.motion = std::max(cell.motion, (x - at.frames.front()).cwiseAbs().maxCoeff());
      block.cells.push_back(std::move(cell));
    }
    out.blocks.push_back(std::move(block));
  }
  answer_rows(out);
  return out;
}

}  // namespace steplab
