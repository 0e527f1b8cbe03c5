// `steplab study long-time`: a scene with invariants over many periods (by default Kepler's orbit
// over 10^5 of them), each method's invariant errors and their growth exponents, the position
// error and when it reaches the orbit's size (analysis/studies/long_time.hpp). Table on stdout,
// JSON (steplab.long_time/1) with --json.
#include <cstdio>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/defaults.hpp"
#include "analysis/studies/long_time.hpp"
#include "reports/cli/commands.hpp"
#include "reports/cli/shards.hpp"
#include "reports/data/inputs.hpp"
#include "reports/data/output.hpp"
#include "reports/data/studies.hpp"

namespace steplab {
namespace {

bool has_invariants(const SceneKernel& s) { return s.period != nullptr; }

// `study long-time`: a scene with invariants over many
// periods, each invariant's error and its growth exponent (analysis/studies/long_time.hpp).
struct LongTimeArgs {
  SceneArgs scene;  // long_time_command makes Kepler's orbit the default
  SettingsArgs settings;
  std::string methods;  // empty: every ODE method that runs on the scene
  std::map<std::string, std::string> params;  // as typed, by name (long_time_params())
  std::string threads = "0";
  std::string shard;  // --shard i/N (reports/cli/shards.hpp)
  std::string json;
};

CLI::App* add_long_time(CLI::App* study, LongTimeArgs& a) {
  CLI::App* cmd = study->add_subcommand("long-time", "stable for how long? A scene's invariants (energy, angular momentum) "
                                                     "over many periods, their growth exponents, the phase error");
  a.scene.scene = std::string(kLongTimeScene);
  a.scene.add_to(cmd, has_invariants);
  cmd->add_option("--methods", a.methods, "comma-separated methods (default every numerical method that runs on the scene)");
  add_params(cmd, long_time_params(), a.params, default_long_time_config(*find_scene(kLongTimeScene)));
  a.settings.add_to(cmd);
  add_threads_option(cmd, a.threads);
  add_shard_option(cmd, a.shard);
  cmd->add_option("--json", a.json, fmt::format("write JSON (schema {}) to this file", schema::long_time));
  return cmd;
}

int run_long_time(LongTimeArgs& a, Context& ctx) {
  const std::size_t scene = a.scene.scene_index();
  if (!has_invariants(scene_kernel(scene)))
    throw UsageError(fmt::format("--scene {} declares no invariants; accepted: {}", scene_name(scene), scene_list(has_invariants)));
  LongTimeConfig c = default_long_time_config(scene);
  c.params = a.scene.values(scene);
  if (const int d = scene_kernel(scene).damping_param; d >= 0 && c.params[static_cast<std::size_t>(d)] != 0)
    throw UsageError(fmt::format("--{} {} makes the {}'s energy decay: it is then no invariant; accepted: 0 for the long-time study",
                                 scene_kernel(scene).params[static_cast<std::size_t>(d)].name, c.params[static_cast<std::size_t>(d)],
                                 scene_name(scene)));
  if (!a.methods.empty()) c.methods = resolve_methods(a.methods, false, scene);
  c.settings = a.settings.resolve(c.methods);
  read_params(long_time_params(), a.params, c);
  check_long_time(c, option_names());
  c.workers = ctx.workers(resolve_thread_count(a.threads));
  return run_study(ctx, a.shard, a.json, false, [&] { return long_time_study(c); },
                   [](const LongTimeResult& r) { return long_time_table(r); }, [](const LongTimeResult& r) { return long_time_json(r); });
}

}  // namespace

StudyCommand long_time_command(CLI::App* study) { return study_command(study, add_long_time, run_long_time); }

}  // namespace steplab
