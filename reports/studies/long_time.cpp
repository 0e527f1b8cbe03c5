// `steplab study long-time`: a scene with invariants over many periods (by default Kepler's orbit
// over 10^5 of them), each method's invariant errors and their growth exponents, the position
// error and when it reaches the orbit's size (analysis/studies/long_time.hpp). Its command, its
// parameters, its table on stdout and its JSON (steplab.long_time/1) with --json.
#include "reports/studies/studies.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/defaults.hpp"
#include "analysis/studies/long_time.hpp"
#include "reports/data/inputs.hpp"
#include "reports/data/output.hpp"
#include "reports/data/run_json.hpp"
#include "reports/data/study_command.hpp"

namespace steplab {
namespace {

Json growth_json(const GrowthFit& g) {
  if (!g.fitted) return nullptr;
  return {{"exponent", g.exponent}, {"ci95", {g.lo, g.hi}}};
}

constexpr StudyParam<LongTimeConfig> kLongTimeParams[] = {
    {"steps-per-period", "comma-separated steps a period: the step is the period over each", {1, 1e6},
     &LongTimeConfig::steps_per_period, "500 on kepler, 100 elsewhere"},
    {"periods", "how long, in periods", {1, 1e7}, &LongTimeConfig::periods},
    {"samples-per-decade", "log-spaced sample times a decade", {1, 100}, &LongTimeConfig::samples_per_decade},
    // from 1: the samples begin at one period
    {"fit-from", "the growth exponents are fitted from this many periods on", {1, 1e7}, &LongTimeConfig::fit_from},
};

}  // namespace

std::span<const StudyParam<LongTimeConfig>> long_time_params() { return kLongTimeParams; }

void check_long_time(const LongTimeConfig& c, const ParamNamer& name) {
  if (!(c.fit_from < c.periods))
    throw UsageError(fmt::format("{}{} {} is not below {} {}; accepted: fit-from < periods (the growth is fitted from fit-from on)",
                                 name.origin, name("fit-from"), short_number(c.fit_from), name("periods"), short_number(c.periods)));
  for (int n : c.steps_per_period)
    if (c.periods * n > 1e10)
      throw UsageError(fmt::format("{}{} {} at {} {} is {:g} steps; accepted: at most 1e10", name.origin, name("periods"), short_number(c.periods),
                                   name("steps-per-period"), n, c.periods * n));
}

std::string growth_text(const GrowthFit& g) {
  return g.fitted ? fmt::format("{:.2f} [{:.2f}, {:.2f}]", g.exponent, g.lo, g.hi) : "-";
}

Json long_time_json(const LongTimeResult& r) {
  const LongTimeConfig& c = r.config;
  Json j;
  j["schema"] = schema::long_time;
  j["scene"] = scene_name(c.scene);
  j["params"] = scene_params_json(c.scene, c.params);
  j["period"] = r.period, j["extent"] = r.extent, j["periods"] = c.periods;
  j["samples_per_decade"] = c.samples_per_decade, j["fit_from_periods"] = c.fit_from;
  j["round_off_level"] = fmt::format("{} u sqrt(steps), u = 2^-53", kRoundOff);
  j["invariants"] = r.invariants;
  Json rows = Json::array();
  for (const LongTimeRow& row : r.rows) {
    const MethodInfo& info = method_info(row.method);
    Json e = {{"method", info.name},
              {"family", to_string(info.family)},
              {"symplectic", info.symplectic},
              {"steps_per_period", row.steps_per_period},
              {"dt", row.dt},
              {"status", to_string(row.status)},
              {"ended_periods", row.ended},
              {"times_periods", row.times}};
    if (takes_sweeps(info) || takes_cg(info)) e["settings"] = settings_json(info, c.settings);
    Json inv = Json::object();
    for (std::size_t q = 0; q < r.invariants.size() && q < row.error.size(); ++q)
      inv[r.invariants[q]] = {{"relative_error", row.error[q]},
                              {"error_at_end", row.error[q].empty() ? Json(nullptr) : finite_or_null(row.error[q].back())},
                              {"growth", growth_json(row.growth[q])},
                              {"round_off", row.round_off[q] != 0}, {"change_at_end", finite_or_null(row.change[q])}};
    e["invariants"] = std::move(inv);
    if (r.has_exact) {
      e["position_error"] = row.position_error;
      e["position_growth"] = growth_json(row.position_growth);
      e["out_of_phase_periods"] = row.out_of_phase > 0 ? finite_or_null(row.out_of_phase) : Json(nullptr);
      e["out_of_phase_extrapolated"] = row.out_of_phase_extrapolated;
    }
    rows.push_back(std::move(e));
  }
  j["rows"] = std::move(rows);
  return j;
}

std::string long_time_table(const LongTimeResult& r) {
  const LongTimeConfig& c = r.config;
  std::string s = fmt::format(
      "Long-time study of {} ({}): {:g} periods of {:.6g}, each invariant's largest relative error up to the end and its growth\n"
      "exponent in t from {:g} periods on (95 % interval: near 0 bounded, near 1 a drift, near 0.5 round-off's random walk)\n",
      scene_name(c.scene), scene_kernel(c.scene).title, c.periods, r.period, c.fit_from);
  if (r.has_exact) s += fmt::format("position: its error's growth exponent, and when it reaches the extent {:g} (out of phase)\n", r.extent);
  s += "\nmethod              steps/period  ended (periods)";
  for (const std::string& n : r.invariants) s += fmt::format("  {:>11}  {:<20}", n.substr(0, 11), "growth");
  if (r.has_exact) s += "  position growth       out of phase";
  s += "\n";
  bool any_round_off = false, any_extrapolated = false;
  for (const LongTimeRow& row : r.rows) {
    s += fmt::format("{:<20}{:>12}  {:>15}", method_info(row.method).name, row.steps_per_period,
                     row.status == RunStatus::Ok ? fmt::format("{:g}", row.ended) : fmt::format("{:.4g} {}", row.ended, to_string(row.status)));
    for (std::size_t q = 0; q < r.invariants.size(); ++q) {
      const bool has = q < row.error.size() && !row.error[q].empty();
      const bool ro = has && row.round_off[q];
      any_round_off = any_round_off || ro;
      s += fmt::format("  {:>11}  {:<20}", has ? fmt::format("{:.3g}{}", row.error[q].back(), ro ? " R" : "") : "-",
                       has ? growth_text(row.growth[q]) : "-");
    }
    if (r.has_exact) {
      any_extrapolated = any_extrapolated || row.out_of_phase_extrapolated;
      s += fmt::format("  {:<20}  {}", growth_text(row.position_growth),
                       row.out_of_phase > 0 ? fmt::format("{:.3g}{}", row.out_of_phase, row.out_of_phase_extrapolated ? " (extrapolated)" : "")
                                            : "-");
    }
    s += "\n";
  }
  if (any_round_off)
    s += fmt::format("\nR: within round-off's level ({} u sqrt(steps)): the method's own error is below what double precision resolves "
                     "over this run, and the exponent is round-off's, not the method's.\n", kRoundOff);
  if (any_extrapolated) s += "(extrapolated): the run ended first; the time follows the fitted growth past its last sample.\n";
  return s;
}

namespace {

bool has_invariants(const SceneKernel& s) { return s.period != nullptr; }

struct LongTimeArgs : StudyArgs {
  SettingsArgs settings;
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
  a.add_shard_and_json(cmd, schema::long_time);
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
  return run_study(ctx, a, false, [&] { return long_time_study(c); }, long_time_table, long_time_json);
}

}  // namespace

StudyCommand long_time_command(CLI::App* study) { return study_command(study, add_long_time, run_long_time); }

}  // namespace steplab
