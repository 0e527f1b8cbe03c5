// `steplab study frames`: a mass-spring scene at a frame rate, each method at substeps x sweeps
// (or CG iterations) = a budget, its error, stretch, energy lost and cost a frame, and each
// family's front (analysis/studies/frames.hpp). Its command, its parameters, its table on stdout
// and its JSON (steplab.frames/4) with --json.
#include "reports/studies/studies.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/frames.hpp"
#include "reports/data/inputs.hpp"
#include "reports/data/output.hpp"
#include "reports/data/run_json.hpp"
#include "reports/data/study_command.hpp"

namespace steplab {

std::string frame_settings_text(const FrameSetup& s) {
  const MethodInfo& info = method_info(s.method);
  if (takes_sweeps(info)) return fmt::format("{} sweep{}", s.settings.sweeps, s.settings.sweeps == 1 ? "" : "s");
  if (takes_cg(info)) return fmt::format("{} CG", s.settings.cg_iterations);
  return {};
}

std::string frame_setup_text(const FrameSetup& s) {
  if (method_info(s.method).on_springs) return fmt::format("{} x {}", s.substeps, frame_settings_text(s));
  return fmt::format("{} substep{}", s.substeps, s.substeps == 1 ? "" : "s");
}

namespace {

constexpr StudyParam<FramesConfig> kFramesStudyParams[] = {
    {"fps", "frames a second", kPositive, &FramesConfig::fps},
    {"t-end", "simulated time (a whole number of frames)", kPositive, &FramesConfig::t_end},
    {"budget", "substeps x sweeps (or CG iterations) a frame: every divisor of it as the substeps", {1, 10'000},
     &FramesConfig::budget},
    {"reference-substeps", "RK4's substeps a frame for the reference where the scene has no exact motion (checked against "
                           "half as many)", {2, 1'000'000}, &FramesConfig::reference_substeps},
};

}  // namespace

std::span<const StudyParam<FramesConfig>> frames_params() { return kFramesStudyParams; }

void check_frames(const FramesConfig& c) {
  if (const double frames = c.t_end * c.fps; std::abs(frames - std::round(frames)) > 1e-9 * frames || std::round(frames) < 1)
    throw UsageError(fmt::format("--t-end {} at --fps {} is {} frames; accepted: a whole number of frames, at least 1",
                                 short_number(c.t_end), short_number(c.fps), frames));
}

Json frames_json(const FramesResult& r) {
  const FramesConfig& c = r.config;
  Json j;
  j["schema"] = schema::frames;
  j["scene"] = scene_name(c.scene);
  j["params"] = scene_params_json(c.scene, c.params);
  j["fps"] = c.fps, j["t_end"] = c.t_end, j["budget"] = c.budget, j["timing"] = c.timing;
  j["springs"] = r.springs, j["motion"] = r.motion, j["span"] = r.span, j["extent"] = r.extent;
  j["reference"] = scene_kernel(c.scene).exact ? Json("exact") : Json(fmt::format("rk4 at {} substeps a frame", c.reference_substeps));
  j["reference_agreement"] = finite_or_null(r.reference_agreement);  // NaN with the exact motion
  Json runs = Json::array();
  for (const FrameRun& run : r.runs) {
    Json e = {{"method", method_info(run.setup.method).name},
              {"substeps", run.setup.substeps},
              {"settings", settings_json(method_info(run.setup.method), run.setup.settings)},
              {"status", to_string(run.status)},
              {"stable", run.stable},
              {"error_max", finite_or_null(run.error)},
              {"stretch", finite_or_null(run.stretch)},
              {"energy_lost_per_s", finite_or_null(run.energy_lost)},
              {"projections", run.projections},
              {"spring_visits_per_frame", run.spring_visits},
              {"seconds_per_frame", c.timing ? Json(run.seconds) : Json(nullptr)}};
    e.update(counts_json(run.counts));
    runs.push_back(std::move(e));
  }
  j["runs"] = std::move(runs);
  Json fronts = Json::array();
  for (const FamilyFront& f : r.fronts) fronts.push_back({{"family", to_string(f.family)}, {"runs", f.runs}});
  j["fronts"] = std::move(fronts);
  j["front_cost"] = "spring_visits_per_frame";
  Json orders = Json::array();
  for (const FrameOrder& o : r.orders) {
    Json errors = Json::array();
    for (double e : o.errors) errors.push_back(finite_or_null(e));
    orders.push_back({{"method", method_info(o.setup.method).name}, {"settings", settings_json(method_info(o.setup.method), o.setup.settings)},
                      {"substeps", o.substeps}, {"error_max", std::move(errors)}, {"order", finite_or_null(o.order)}});
  }
  j["orders"] = std::move(orders);
  return j;
}

std::string frames_table(const FramesResult& r) {
  const FramesConfig& c = r.config;
  std::string out = fmt::format("{} ({} springs) at {} frames a second for {} s; error against the {}; budget {} (substeps x "
                                "sweeps or CG iterations)\n",
                                scene_name(c.scene), r.springs, c.fps, c.t_end,
                                scene_kernel(c.scene).exact ? "exact motion"
                                                            : fmt::format("rk4 at {} substeps a frame (within {:.2g} m of it at half as many)",
                                                                          c.reference_substeps, r.reference_agreement),
                                c.budget);
  out += fmt::format("{:<18} {:<16} {:>10} {:>10} {:>12} {:>12} {:>12} {:>7}\n", "method", "per frame", "error", "stretch",
                     "E lost /s", "visits/frame", "us/frame", "front");
  for (std::size_t i = 0; i < r.runs.size(); ++i) {
    const FrameRun& run = r.runs[i];
    bool front = false;
    for (const FamilyFront& f : r.fronts) front = front || std::find(f.runs.begin(), f.runs.end(), i) != f.runs.end();
    const auto num = [](double x) { return std::isfinite(x) ? fmt::format("{:.3g}", x) : std::string("-"); };
    out += fmt::format("{:<18} {:<16} {:>10} {:>10} {:>12} {:>12.4g} {:>12} {:>7}\n", method_info(run.setup.method).name,
                       frame_setup_text(run.setup), run.stable ? num(run.error) : "unstable", num(run.stretch), num(run.energy_lost),
                       run.spring_visits, c.timing ? fmt::format("{:.3g}", 1e6 * run.seconds) : "-", front ? "*" : "");
  }
  out += "front (*): no set-up of its family at as many spring visits a frame or fewer has a smaller error\n";
  if (!r.orders.empty()) {
    out += "\norder in h (substeps a frame doubled, settings fixed):\n";
    for (const FrameOrder& o : r.orders) {
      std::string errs;
      for (std::size_t k = 0; k < o.errors.size(); ++k) errs += fmt::format(" {}:{:.2g}", o.substeps[k], o.errors[k]);
      out += fmt::format("{:<14} {:<18} order {:>6.2f} {}\n", method_info(o.setup.method).name, frame_settings_text(o.setup), o.order,
                         errs);
    }
  }
  return out;
}

namespace {

bool mass_spring(const SceneKernel& s) { return s.spring_measures != nullptr; }


}  // namespace



namespace {

struct FramesArgs : StudyArgs {
  bool no_timing = false, no_orders = false;
};

CLI::App* add_frames(CLI::App* study, FramesArgs& a) {
  CLI::App* cmd = study->add_subcommand("frames", "a mass-spring scene at a frame rate: substeps or sweeps, XPBD or large steps, "
                                                  "at what cost a frame");
  a.scene.scene = std::string(kFramesScene);
  a.scene.add_to(cmd, mass_spring);
  cmd->add_option("--methods", a.methods, "comma-separated methods (default xpbd, pbd, baraff_witkin, symplectic_euler, "
                                          "implicit_euler, rk4)");
  add_params(cmd, frames_params(), a.params, default_frames_config());
  add_threads_option(cmd, a.threads, "worker threads (timings run one at a time)");
  cmd->add_flag("--no-timing", a.no_timing, "cost by spring visits a frame only (reproducible byte for byte)");
  cmd->add_flag("--no-orders", a.no_orders, "leave out the order in h of the methods on springs");
  a.add_shard_and_json(cmd, schema::frames);
  return cmd;
}

int run_frames(FramesArgs& a, Context& ctx) {
  FramesConfig c = default_frames_config();
  c.scene = a.scene.scene_index();
  if (!mass_spring(scene_kernel(c.scene)))
    throw UsageError(fmt::format("--scene {} is not made of springs; accepted: {}", scene_name(c.scene), scene_list(mass_spring)));
  // The study's rope (32 masses, stiffness 5000) where the scene is the rope and the user gave neither.
  if (c.scene == scene_index(kFramesScene))
    for (const auto& [name, value] : kFramesParams)
      if (!a.scene.given(name)) a.scene.set(name, fmt::format("{}", value));
  c.params = a.scene.values(c.scene);
  if (!a.methods.empty()) c.methods = resolve_methods(a.methods, false, c.scene);
  else
    std::erase_if(c.methods, [&](std::size_t m) { return !applies(m, c.scene); });
  read_params(frames_params(), a.params, c);
  check_frames(c);
  c.timing = !a.no_timing;
  c.orders = !a.no_orders;
  c.workers = ctx.workers(resolve_thread_count(a.threads));
  return run_study(ctx, a, c.timing, [&] { return frames_study(c); }, frames_table, frames_json);
}

}  // namespace

StudyCommand frames_command(CLI::App* study) { return study_command(study, add_frames, run_frames); }

}  // namespace steplab
