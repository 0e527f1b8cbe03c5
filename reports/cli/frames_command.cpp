// `steplab study frames`: a mass-spring scene at a frame rate, each method at substeps x sweeps
// (or CG iterations) = a budget, its error, stretch, energy lost and cost a frame, and each
// family's front (analysis/studies/frames.hpp). Table on stdout, JSON (steplab.frames/4) with
// --json. And the method settings (--sweeps, --cg-iterations, --cg-tolerance) `run` takes.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/frames.hpp"
#include "reports/cli/commands.hpp"
#include "reports/cli/shards.hpp"
#include "reports/data/inputs.hpp"
#include "reports/data/output.hpp"
#include "reports/data/studies.hpp"

namespace steplab {
namespace {

bool mass_spring(const SceneKernel& s) { return s.spring_measures != nullptr; }

std::string names_where(bool (*keep)(const MethodInfo&)) {
  std::string out;
  for (std::size_t m = 0; m < method_count(); ++m)
    if (keep(method_info(m))) out += (out.empty() ? "" : ", ") + std::string(method_info(m).name);
  return out;
}

}  // namespace

void SettingsArgs::add_to(CLI::App* app) {
  app->add_option("--sweeps", sweeps, "Gauss-Seidel sweeps a step of " + names_where(&takes_sweeps) + " (1 .. 1000000; default 1)");
  app->add_option("--cg-iterations", cg_iterations,
                  "most conjugate-gradient iterations a step of " + names_where(&takes_cg) + " (1 .. 1000000; default 100)");
  app->add_option("--cg-tolerance", cg_tolerance,
                  "CG stops once its residual is below this times the right-hand side's (0 < tol < 1; default 1e-8)");
}

MethodSettings SettingsArgs::resolve(const std::vector<std::size_t>& methods) const {
  MethodSettings s;
  const auto refuse = [&](std::string_view option, bool (*takes)(const MethodInfo&)) {
    if (std::none_of(methods.begin(), methods.end(), [&](std::size_t m) { return takes(method_info(m)); }))
      throw UsageError(fmt::format("{} applies to {}; {} {} none", option, names_where(takes),
                                   methods.size() == 1 ? "--method " + std::string(method_info(methods[0]).name) : "--methods",
                                   methods.size() == 1 ? "takes" : "take"));
  };
  if (!sweeps.empty()) {
    refuse("--sweeps", &takes_sweeps);
    s.sweeps = static_cast<int>(parse_count("--sweeps", sweeps, 1, 1'000'000));
  }
  if (!cg_iterations.empty()) {
    refuse("--cg-iterations", &takes_cg);
    s.cg_iterations = static_cast<int>(parse_count("--cg-iterations", cg_iterations, 1, 1'000'000));
  }
  if (!cg_tolerance.empty()) {
    refuse("--cg-tolerance", &takes_cg);
    s.cg_tolerance = parse_number("--cg-tolerance", cg_tolerance, Bound::Positive);
    if (s.cg_tolerance >= 1) throw UsageError(fmt::format("--cg-tolerance {} is not below 1; accepted: 0 < tol < 1", cg_tolerance));
  }
  return s;
}

namespace {

// `study frames`: a mass-spring scene at a frame rate, each
// method at substeps x sweeps (or CG iterations) = budget (analysis/studies/frames.hpp).
struct FramesArgs {
  SceneArgs scene;  // frames_command makes the rope the default, with the study's 32 masses and stiffness 5000
  std::string methods;  // empty: analysis/studies/defaults.hpp, kFramesMethods
  std::map<std::string, std::string> params;  // as typed, by name (frames_params())
  std::string threads = "0";
  bool no_timing = false, no_orders = false;
  std::string shard;  // --shard i/N (reports/cli/shards.hpp)
  std::string json;
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
  add_shard_option(cmd, a.shard);
  cmd->add_option("--json", a.json, fmt::format("write JSON (schema {}) to this file", schema::frames));
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
  return run_study(ctx, a.shard, a.json, c.timing, [&] { return frames_study(c); },
                   [](const FramesResult& r) { return frames_table(r); }, [](const FramesResult& r) { return frames_json(r); });
}

}  // namespace

StudyCommand frames_command(CLI::App* study) { return study_command(study, add_frames, run_frames); }

}  // namespace steplab
