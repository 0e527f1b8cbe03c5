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
#include "reports/cli/parts.hpp"
#include "reports/data/inputs.hpp"
#include "reports/data/output.hpp"
#include "reports/data/schemas.hpp"
#include "reports/data/study_output.hpp"

namespace steplab {
namespace {

bool has_invariants(const SceneKernel& s) { return s.period != nullptr; }

}  // namespace

CLI::App* add_long_time_command(CLI::App* study, LongTimeArgs& a) {
  CLI::App* cmd = study->add_subcommand("long-time", "stable for how long? A scene's invariants (energy, angular momentum) "
                                                     "over many periods, their growth exponents, the phase error");
  a.scene.scene = std::string(kLongTimeScene);
  a.scene.add_to(cmd, has_invariants);
  cmd->add_option("--methods", a.methods, "comma-separated methods (default every numerical method that runs on the scene)");
  cmd->add_option("--steps-per-period", a.steps_per_period, "comma-separated steps a period: the step is the period over each "
                                                            "(1 .. 1000000; default 500 on kepler, 100 elsewhere)");
  cmd->add_option("--periods", a.periods, "how long, in periods (1 .. 1e7)")->capture_default_str();
  cmd->add_option("--samples-per-decade", a.samples_per_decade, "log-spaced sample times a decade (1 .. 100)")->capture_default_str();
  cmd->add_option("--fit-from", a.fit_from, "the growth exponents are fitted from this many periods on")->capture_default_str();
  a.settings.add_to(cmd);
  cmd->add_option("--threads", a.threads, "worker threads, 0 = all cores")->capture_default_str();
  add_shard_option(cmd, a.shard);
  cmd->add_option("--json", a.json, fmt::format("write JSON (schema {}) to this file", schema::long_time));
  return cmd;
}

int long_time_command(LongTimeArgs& a, Context& ctx) {
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
  if (!a.steps_per_period.empty()) {
    c.steps_per_period.clear();
    for (const std::string& n : split_list(a.steps_per_period))
      c.steps_per_period.push_back(static_cast<int>(parse_count("--steps-per-period", n, 1, 1'000'000)));
  }
  c.periods = parse_number("--periods", a.periods, Bound::Positive);
  if (c.periods < 1 || c.periods > 1e7)
    throw UsageError(fmt::format("--periods {} is out of range; accepted: 1 .. 1e7", a.periods));
  for (int n : c.steps_per_period)
    if (c.periods * n > 1e10)
      throw UsageError(fmt::format("--periods {} at --steps-per-period {} is {:g} steps; accepted: at most 1e10", a.periods, n, c.periods * n));
  c.samples_per_decade = static_cast<int>(parse_count("--samples-per-decade", a.samples_per_decade, 1, 100));
  c.fit_from = parse_number("--fit-from", a.fit_from, Bound::Positive);
  if (c.fit_from >= c.periods)
    throw UsageError(fmt::format("--fit-from {} is not below --periods {}; accepted: 0 < fit-from < periods", a.fit_from, a.periods));
  c.workers = ctx.workers(resolve_thread_count(a.threads));
  begin_shard(ctx, a.shard, a.json, false);
  if (ctx.stop_after_validation(a.json)) return 0;
  const LongTimeResult r = long_time_study(c);
  if (finish_shard(ctx, a.json)) return 0;
  std::fputs(long_time_table(r).c_str(), stdout);
  if (!a.json.empty()) write_atomic(a.json, long_time_json(r).dump(1) + "\n");
  return 0;
}

}  // namespace steplab
