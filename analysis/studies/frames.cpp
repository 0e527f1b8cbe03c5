#include "analysis/studies/frames.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <utility>

#include "analysis/fits/fit.hpp"
#include "analysis/kernel/shard.hpp"
#include "analysis/studies/defaults.hpp"

namespace steplab {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The order rows: substeps doubled from 128 to 1024 a frame, where the default rope's fastest mode
// is resolved (omega h from about 0.6 down to 0.08: an order is a limit as h -> 0, and at fewer
// substeps the stiff modes' damping, not the step's error, sets the error), at settings that
// either hold the sweeps fixed (one) or carry the solve to convergence (XPBD's sweeps: at these
// steps k h^2 / m <= 0.2 and Gauss-Seidel gains about a digit every few sweeps; Baraff-Witkin's
// CG to 1e-12).
constexpr int kOrderSubsteps[] = {128, 256, 512, 1024};
constexpr int kConvergedSweeps = 50;

// A run has flown apart, and is unstable though its state is finite, where its error passes
// kFlownApart times the span of the reference's motion (the widest, over the axes, of the box its
// positions fill over every frame). A state with every mass inside that box has an error of at most
// the span, so such a run has some mass ten spans outside the region the true motion fills: on a
// pinned body, the springs along its path from the pin stretched many times their length. Its energy
// would not say so: PBD on the default rope, bounded and within 0.65 m of the reference on a rope
// 5 m long, ends with up to 5.5e4 times its start's energy (its stiff springs held a little
// stretched), while Baraff-Witkin at one substep a frame sends a mass of the cloth of 32 a side
// 275 m from where the reference has it, off a sheet 1 m wide.
constexpr double kFlownApart = 10;

struct Reference {
  std::vector<AnyState> frames;
  SpringMeasures measures;
  double agreement = kNaN;  // the RK4 reference against half its substeps (NaN: the exact motion)
  double span = 0;          // the widest over the axes of the box its positions fill over the frames
};

long long frame_count(const FramesConfig& c) { return std::llround(c.t_end * c.fps); }

RunSpec frame_spec(const FramesConfig& c, const FrameSetup& s, bool samples) {
  RunSpec spec;
  spec.dt = 1 / (c.fps * s.substeps);
  spec.steps = frame_count(c) * s.substeps;
  spec.max_samples = samples ? frame_count(c) + 1 : 0;  // one at each frame (SamplePlan: every substeps-th step)
  spec.errors = false;
  spec.settings = s.settings;
  return spec;
}

// The largest difference of positions between two runs' frames, over the frames and the
// coordinates; NaN where they have not as many frames (one ended early) or a difference is not finite.
double largest_difference(const std::vector<AnyState>& a, const std::vector<AnyState>& b) {
  if (a.size() != b.size()) return kNaN;
  double out = 0;
  for (std::size_t f = 0; f < a.size(); ++f) {
    const double e = (a[f].x - b[f].x).cwiseAbs().maxCoeff();
    if (!std::isfinite(e)) return kNaN;
    out = std::max(out, e);
  }
  return out;
}

// The widest, over the axes, of the box the positions of `frames` fill (d coordinates a mass).
double spread(std::span<const AnyState> frames, int d) {
  double out = 0;
  for (int axis = 0; axis < d; ++axis) {
    double lo = INFINITY, hi = -INFINITY;
    for (const AnyState& f : frames)
      for (Eigen::Index i = axis; i < f.x.size(); i += d) lo = std::min(lo, f.x[i]), hi = std::max(hi, f.x[i]);
    out = std::max(out, hi - lo);
  }
  return out;
}

std::vector<AnyState> frames_of(const AnyResult& r) {
  std::vector<AnyState> out;
  for (const auto& s : r.samples) out.push_back({s.x, s.v});
  return out;
}

// The reference's frames: the exact motion, or RK4 at `substeps` a frame.
std::vector<AnyState> reference_frames(const FramesConfig& c, int substeps) {
  const SceneKernel& sk = scene_kernel(c.scene);
  std::vector<AnyState> out;
  if (sk.exact) {
    for (long long k = 0; k <= frame_count(c); ++k) out.push_back(sk.exact(c.params, static_cast<double>(k) / c.fps));
    return out;
  }
  const std::size_t rk4 = *find_method("rk4");
  return frames_of(pair_kernel(rk4, c.scene).run(c.params, frame_spec(c, {rk4, substeps, {}}, true)));
}

Reference reference(const FramesConfig& c) {
  const SceneKernel& sk = scene_kernel(c.scene);
  Reference ref;
  ref.frames = reference_frames(c, c.reference_substeps);
  // RK4 at reference_substeps a frame, and at half as many: where both are in RK4's asymptotic
  // range the finer's error is about 1/15 of their difference, which bounds it from above.
  if (!sk.exact) ref.agreement = largest_difference(reference_frames(c, c.reference_substeps / 2), ref.frames);
  ref.measures = sk.spring_measures(c.params, ref.frames);
  ref.span = spread(ref.frames, sk.coords_per_mass);
  return ref;
}

FrameRun measure(const FramesConfig& c, const Reference& ref, const FrameSetup& s) {
  const PairKernel& k = pair_kernel(s.method, c.scene);
  const RunSpec spec = frame_spec(c, s, true);
  FrameRun out;
  out.setup = s;
  const AnyResult r = k.run_counted ? k.run_counted(c.params, spec, out.counts) : k.run(c.params, spec);
  if (!k.run_counted) out.counts.steps = r.steps;
  out.status = r.status;
  const std::vector<AnyState> frames = frames_of(r);
  out.error = r.status == RunStatus::Ok ? largest_difference(frames, ref.frames) : kNaN;
  out.stable = std::isfinite(out.error) && out.error <= kFlownApart * ref.span;
  const int springs = ref.measures.springs;
  const MethodInfo& info = method_info(s.method);
  if (takes_sweeps(info)) out.projections = out.counts.steps * s.settings.sweeps * springs;
  const Counts& n = out.counts;
  out.spring_visits = static_cast<double>(out.projections + (n.forces + n.jacobians + n.factorisations + n.solves) * springs) /
                      static_cast<double>(frame_count(c));
  if (!out.stable) {
    out.error = out.stretch = out.energy_lost = kNaN;
    return out;
  }
  const SpringMeasures m = scene_kernel(c.scene).spring_measures(c.params, frames);
  out.stretch = -std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < frames.size(); ++f) out.stretch = std::max(out.stretch, m.stretch[f] - ref.measures.stretch[f]);
  out.energy_lost = (ref.measures.energy.back() - m.energy.back()) / c.t_end;
  return out;
}

// Whether run a dominates run b: no dearer and more accurate. The cost is the spring visits a
// frame (frame_cost), a count: a dearer by any amount is dearer, equal ones are equal.
bool dominates(const FrameRun& a, const FrameRun& b) { return a.error < b.error && a.spring_visits <= b.spring_visits; }

// Per family, its stable set-ups that no other of the family dominates, cheapest first (by the
// cost the front is drawn against, then by error).
std::vector<FamilyFront> fronts(const std::vector<FrameRun>& runs) {
  std::vector<FamilyFront> out;
  for (Family f : {Family::ExplicitRungeKutta, Family::Splitting, Family::ImplicitRungeKutta, Family::AdamsBashforth, Family::Bdf,
                   Family::PositionBased}) {
    std::vector<std::size_t> members;
    for (std::size_t i = 0; i < runs.size(); ++i)
      if (method_info(runs[i].setup.method).family == f && runs[i].stable) members.push_back(i);
    if (members.empty()) continue;
    FamilyFront front{f, {}};
    for (std::size_t i : members)
      if (std::none_of(members.begin(), members.end(), [&](std::size_t j) { return dominates(runs[j], runs[i]); }))
        front.runs.push_back(i);
    std::stable_sort(front.runs.begin(), front.runs.end(), [&](std::size_t a, std::size_t b) {
      const double ca = frame_cost(runs[a]), cb = frame_cost(runs[b]);
      return ca != cb ? ca < cb : runs[a].error < runs[b].error;
    });
    out.push_back(std::move(front));
  }
  return out;
}

}  // namespace

FramesConfig default_frames_config() {
  FramesConfig c;
  c.scene = scene_index(kFramesScene);
  c.params = default_param_values(c.scene);
  for (const auto& [name, value] : kFramesParams)
    c.params[static_cast<std::size_t>(param_index(scene_kernel(c.scene).params, name))] = value;
  for (std::string_view m : kFramesMethods) c.methods.push_back(*find_method(m));
  return c;
}

std::vector<FrameSetup> frame_setups(const std::vector<std::size_t>& methods, int budget) {
  std::vector<FrameSetup> out;
  for (std::size_t m : methods)
    for (int s = 1; s <= budget; ++s) {
      if (budget % s != 0) continue;
      FrameSetup setup{m, s, {}};
      if (takes_sweeps(method_info(m))) setup.settings.sweeps = budget / s;
      if (takes_cg(method_info(m))) setup.settings.cg_iterations = budget / s;
      out.push_back(setup);
    }
  return out;
}

double frame_cost(const FrameRun& r) { return r.spring_visits; }

std::vector<AnyState> frame_states(const FramesConfig& c, const FrameSetup& s) {
  return frames_of(pair_kernel(s.method, c.scene).run(c.params, frame_spec(c, s, true)));
}

FramesConfig cloth_frames_config() {
  FramesConfig c = default_frames_config();
  c.scene = scene_index(kClothFramesScene);
  c.params = default_param_values(c.scene);
  c.t_end = kClothFramesSeconds;
  c.reference_substeps = kClothReferenceSubsteps;
  c.orders = false;
  return c;
}

FramesResult frames_study(const FramesConfig& config) {
  FramesResult out;
  out.config = config;
  Reference ref = reference(config);
  out.springs = ref.measures.springs;
  out.reference_agreement = ref.agreement;
  out.span = ref.span;
  out.extent = spread(std::span(ref.frames).first(1), scene_kernel(config.scene).coords_per_mass);
  for (const AnyState& f : ref.frames) out.motion = std::max(out.motion, (f.x - ref.frames.front().x).cwiseAbs().maxCoeff());
  const std::vector<FrameSetup> setups = frame_setups(config.methods, config.budget);
  // Through study_map, one task a set-up and one an order's run: a shard (analysis/kernel/shard.hpp)
  // runs its part of each (an untimed study only: a shard refuses timing).
  out.runs = study_map<FrameRun>(setups.size(), config.workers, [&](std::size_t i) { return measure(config, ref, setups[i]); });
  // Timed one at a time, after the runs in parallel: each alone on its core.
  if (config.timing)
    for (FrameRun& r : out.runs) {
      std::vector<double> t = pair_kernel(r.setup.method, config.scene)
                                  .timings(config.params, frame_spec(config, r.setup, false), 3, config.min_seconds);
      std::nth_element(t.begin(), t.begin() + static_cast<std::ptrdiff_t>(t.size() / 2), t.end());
      r.seconds = t[t.size() / 2] / static_cast<double>(frame_count(config));
    }
  out.fronts = fronts(out.runs);

  if (config.orders) {
    for (std::size_t m : config.methods) {
      if (!method_info(m).on_springs) continue;
      std::vector<MethodSettings> settings(1);  // sweeps 1
      if (takes_sweeps(method_info(m))) {
        if (method_info(m).converges) settings.emplace_back().sweeps = kConvergedSweeps;
      } else {
        settings[0].cg_iterations = 1000, settings[0].cg_tolerance = 1e-12;
      }
      for (const MethodSettings& s : settings) {
        FrameOrder o{{m, 1, s}, {}, {}, kNaN};
        for (int sub : kOrderSubsteps) o.substeps.push_back(sub);
        o.errors.resize(o.substeps.size());
        out.orders.push_back(std::move(o));
      }
    }
    std::vector<std::pair<std::size_t, std::size_t>> cells;
    for (std::size_t o = 0; o < out.orders.size(); ++o)
      for (std::size_t k = 0; k < out.orders[o].substeps.size(); ++k) cells.push_back({o, k});
    const std::vector<double> errors = study_map<double>(cells.size(), config.workers, [&](std::size_t i) {
      FrameSetup s = out.orders[cells[i].first].setup;
      s.substeps = out.orders[cells[i].first].substeps[cells[i].second];
      return measure(config, ref, s).error;
    });
    for (std::size_t i = 0; i < cells.size(); ++i) out.orders[cells[i].first].errors[cells[i].second] = errors[i];
    for (FrameOrder& o : out.orders) {
      std::vector<double> lh, le;
      for (std::size_t k = 0; k < o.substeps.size(); ++k)
        if (std::isfinite(o.errors[k]) && o.errors[k] > 0) lh.push_back(std::log(1 / (config.fps * o.substeps[k]))), le.push_back(std::log(o.errors[k]));
      if (lh.size() >= 2) o.order = fit_line(lh, le).slope;
    }
  }
  out.reference = std::move(ref.frames);
  return out;
}

}  // namespace steplab
