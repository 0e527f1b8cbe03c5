// `study scaling`: the rope of N masses or the soft body of n x n masses refined and stiffened,
// every method and the peers in each cell, at each target (analysis/studies/scaling.hpp); a table per
// (target, stiffness) and the map on stdout, --json the data (schema::scaling).
#include <cmath>
#include <cstdio>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "analysis/studies/defaults.hpp"
#include "analysis/kernel/kernel.hpp"
#include "analysis/peers/peers.hpp"
#include "analysis/studies/scaling.hpp"
#include "reports/cli/commands.hpp"
#include "reports/data/inputs.hpp"
#include "reports/data/output.hpp"
#include "reports/data/run_json.hpp"
#include "reports/cli/shards.hpp"
#include "reports/data/studies.hpp"

namespace steplab {

namespace {

// `study scaling`: cost against the number of masses of the rope or the soft body.
struct ScalingArgs {
  SceneArgs scene;  // the scene's parameters (--masses, --grid replaced by each size); scaling_command makes rope the default
  std::string methods;
  std::string sizes;  // empty: the scene's default sizes (scaling_command.cpp)
  std::string error = "1e-4,1%";  // targets: absolute, or N% of the body's extent
  std::map<std::string, std::string> params;  // scaling_params(), as typed (max-steps empty: the scene's)
  bool steps_divide_frames = false;
  std::string threads = "0";
  bool no_timing = false;
  bool no_peers = false;
  std::string shard;
  std::string json;
};

CLI::App* add_scaling(CLI::App* study, ScalingArgs& a) {
  CLI::App* cmd = study->add_subcommand("scaling", "rope of N masses or soft body of n x n: cost of a step and of a run at a "
                                                   "given error, largest stable step, against N; fitted exponents, crossover");
  a.scene.scene = std::string(kDefaultSizedScene);  // any scene that scales() (analysis/studies/scaling.hpp)
  a.scene.add_to(cmd, scales, true, true);
  const auto only_on = [](PeerScenes on) {
    std::vector<std::string> out;
    for (const PeerInfo* p : peers_on(on))
      if (p->scenes == on) out.emplace_back(p->name);
    return out;
  };
  cmd->add_option("--methods", a.methods,
                  fmt::format("comma-separated methods and adaptive solvers ({}; {} on the rope; {} on the soft body; default "
                              "every numerical method, and every adaptive solver where the list names none)",
                              fmt::join(peer_names(PeerScenes::Explicit), ", "), fmt::join(only_on(PeerScenes::Banded), ", "),
                              fmt::join(only_on(PeerScenes::Sparse), ", ")));
  // The scene's stiffness option (--stiffness on the rope and the soft body) takes a list here: the map's axis.
  cmd->add_option("--sizes", a.sizes, "comma-separated sizes: the rope's numbers of masses (1 .. 100000), the soft body's "
                                      "grid sides n (1 .. 300; default 16,64,256,1024 masses on the rope, 4,8,16 on the soft body)");
  cmd->add_option("--error", a.error, "comma-separated target position errors (the largest over the coordinates and the "
                                      "frames), each a number or a percentage of the body's extent at rest (1% the visual one)")
      ->capture_default_str();
  add_params(cmd, scaling_params(), a.params, ScalingConfig{});
  cmd->add_flag("--steps-divide-frames", a.steps_divide_frames, "a fixed step divides the frame interval and each frame is a "
                                                                "step's state (no output between steps), as in an animation loop");
  add_threads_option(cmd, a.threads, "worker threads for the searches (timings run one at a time)");
  cmd->add_flag("--no-timing", a.no_timing, "cost by force evaluations only (reproducible byte for byte)");
  cmd->add_flag("--no-peers", a.no_peers, "steplab's fixed-step methods only (no dopri5, CVODE, Boost.Odeint)");
  add_shard_option(cmd, a.shard);
  cmd->add_option("--json", a.json, fmt::format("write JSON (schema {}) to this file", schema::scaling));
  return cmd;
}

}  // namespace

// --error's list: each a positive number, or a percentage of the body's extent ("1%").
std::vector<ErrorTarget> error_targets(const std::string& text) {
  std::vector<ErrorTarget> out;
  for (std::string item : split_list(text)) {
    const bool percent = !item.empty() && item.back() == '%';
    if (percent) item.pop_back();
    const double v = parse_number("--error", item, Bound::Positive);
    out.push_back({percent ? v / 100 : v, percent});
  }
  if (out.empty()) throw UsageError("--error '' names no target; accepted: positive numbers or percentages of the body's extent, e.g. 1e-4,1%");
  for (std::size_t i = 0; i < out.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (out[i].value == out[j].value && out[i].of_extent == out[j].of_extent)
        throw UsageError(fmt::format("--error names {}{} twice; accepted: each target once", out[i].of_extent ? 100 * out[i].value : out[i].value,
                                     out[i].of_extent ? "%" : ""));
  return out;
}

namespace {

int run_scaling(ScalingArgs& a, Context& ctx) {
  const SceneKernel& scene = scene_kernel(a.scene.scene_index());
  if (!scales(scene)) {
    throw UsageError(fmt::format("--scene '{}' is not accepted by study scaling; accepted: {} (a scene of run-time size "
                                 "that declares its modes)", a.scene.scene, scene_list(scales)));
  }
  ScalingConfig c = scaling_config(a.scene.scene);  // the scene's default sizes, step cap and solvers
  // The scene's stiffness option may be a list: the stiffnesses of the map, each within its bounds.
  if (scene.stiffness_param >= 0) {
    const std::string key(scene.params[scene.stiffness_param].name);
    if (a.scene.given(key)) {
      c.stiffnesses = number_list("--" + key, a.scene.text[key], scene.params[scene.stiffness_param].bound);
      check_distinct("--" + key, c.stiffnesses);
      a.scene.set(key, a.scene.text[key].substr(0, a.scene.text[key].find(',')));
    }
  }
  c.params = a.scene.values(a.scene.scene_index());
  Solvers solvers = resolve_solvers(a.methods, c.adaptive, scene.name, a.no_peers);
  c.methods = std::move(solvers.methods);
  c.adaptive = std::move(solvers.adaptive);
  if (!a.sizes.empty()) {
    c.sizes.clear();
    const ParamSpec& size = scene.params[scene.size_param];  // --masses, --grid: its range
    for (const std::string& s : split_list(a.sizes)) c.sizes.push_back(static_cast<int>(parse_count("--sizes", s, static_cast<long long>(size.min_count), static_cast<long long>(size.max_count))));
    check_distinct("--sizes", std::vector<double>(c.sizes.begin(), c.sizes.end()));
  }
  c.targets = error_targets(a.error);
  read_params(scaling_params(), a.params, c);
  c.steps_divide_frames = a.steps_divide_frames;
  c.workers = ctx.workers(resolve_thread_count(a.threads));
  c.timing = !a.no_timing;
  return run_study(ctx, a.shard, a.json, c.timing, [&] { return scaling_study(c); },
                   [](const ScalingResult& r) { return scaling_table(r); }, [](const ScalingResult& r) { return scaling_json(r); });
}

}  // namespace

StudyCommand scaling_command(CLI::App* study) { return study_command(study, add_scaling, run_scaling); }

}  // namespace steplab
