// `steplab study stability` and `steplab study damping`: on the spring, the thresholds dt*
// predicted and measured over dampings and the (dt, damping) map, and the energy growth over damping
// and dt (analysis/studies/stability.hpp); on a scene that declares its modes, its thresholds
// (analysis/studies/mode_stability.hpp, written by mode_stability.cpp). Their commands, their
// parameters, tables and JSON (steplab.stability/2).
#include "reports/studies/studies.hpp"

#include <cmath>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/stability.hpp"
#include "core/scenes/spring.hpp"
#include "reports/data/inputs.hpp"
#include "reports/data/run_json.hpp"
#include "reports/data/study_command.hpp"

namespace steplab {
namespace {

// Where a method is stable again beyond dt*: a number; "never" where it is not; null where dt* is
// unbounded (nothing lies beyond it).
Json again_json(double again, double dt) {
  if (std::isinf(dt)) return nullptr;
  return std::isinf(again) ? Json("never") : Json(again);
}

}  // namespace

// The spring's study: thresholds over dampings and the (dt, damping) map (`study stability`), the
// energy's rate over a sweep of steps (`study damping`, whose key in a configuration is sweep_dts).
constexpr StudyParam<StabilityConfig> kStabilityParams[] = {
    {"threshold-dampings", "dampings at which to find dt*", kNonNegative, &StabilityConfig::threshold_dampings},
    {"dts", "steps of the damping sweep", kPositive, &StabilityConfig::sweep_dts, {}, "sweep_dts"},
    {"map-dt-points", "map: steps, log-spaced", {2, 4096}, &StabilityConfig::map_dt_points},
    {"map-damping-points", "map: dampings, 0 to twice critical", {2, 4096}, &StabilityConfig::map_damping_points},
    {"map-dt-min", "map: smallest step", kPositive, &StabilityConfig::map_dt_min},
    {"map-dt-max", "map: largest step", kPositive, &StabilityConfig::map_dt_max},
};

std::span<const StudyParam<StabilityConfig>> stability_params() { return kStabilityParams; }

void check_stability(const StabilityConfig& c, const ParamNamer& name) {
  if (!(c.map_dt_min < c.map_dt_max))
    throw UsageError(fmt::format("{}{} {} is not below {} {}; accepted: min < max", name.origin, name("map-dt-min"),
                                 short_number(c.map_dt_min), name("map-dt-max"), short_number(c.map_dt_max)));
}

// JSON has no infinity: a threshold of every step is the string "unbounded".
Json threshold_json(double x) { return std::isinf(x) ? Json("unbounded") : Json(x); }
std::string threshold_text(double x) { return std::isinf(x) ? "unbounded" : fmt::format("{:.6g}", x); }
// Where stability comes back (StableSet::again): infinite is never.
std::string again_text(double x) { return std::isinf(x) ? "never" : fmt::format("{:.6g}", x); }

Json stability_json(const std::vector<double>& params, const std::vector<ThresholdRow>& thresholds,
                    const std::vector<SweepRow>& sweep, const StabilityMap* map) {
  Json j;
  j["schema"] = schema::stability;
  j["scene"] = Spring::name;  // the study of the damped spring's linear regime (analysis/studies/stability.hpp)
  Json p = scene_params_json(scene_index(Spring::name), params);
  p["stable_rate_tolerance"] = kStableRate;
  p["rate_steps"] = kRateSteps;
  j["params"] = std::move(p);
  Json t = Json::array();
  for (const ThresholdRow& r : thresholds)
    t.push_back({{"method", method_info(r.method).name}, {"damping", r.damping}, {"dt_theory", threshold_json(r.dt_theory)},
                 {"dt_measured", threshold_json(r.dt_measured)},
                 {"stable_again_theory", again_json(r.again_theory, r.dt_theory)},
                 {"stable_again_measured", again_json(r.again_measured, r.dt_measured)}});
  j["thresholds"] = std::move(t);
  Json s = Json::array();
  for (const SweepRow& r : sweep)
    s.push_back({{"method", method_info(r.method).name},
                 {"dt", r.dt},
                 {"damping", r.damping},
                 {"rate_measured", finite_or_null(r.run.rate)},
                 {"rate_theory", finite_or_null(r.rate_theory)},
                 {"energy_ratio_final", finite_or_null(r.run.energy_ratio_final)},
                 {"energy_ratio_max", finite_or_null(r.run.energy_ratio_max)},
                 {"error_final", finite_or_null(r.run.error_final)},
                 {"stable", r.run.stable()},
                 {"steps", r.run.steps},
                 {"status", to_string(r.run.status)}});
  j["sweep"] = std::move(s);
  Json m = Json::object();
  if (map) {
    m["dt"] = map->dt;
    m["damping"] = map->damping;
    Json stable = Json::object(), predicted = Json::object(), boundary = Json::object();
    const auto grid = [](const std::vector<std::vector<bool>>& cells) {
      Json rows = Json::array();
      for (const auto& row : cells) rows.push_back(Json(std::vector<bool>(row)));
      return rows;
    };
    for (std::size_t i = 0; i < map->methods.size(); ++i) {
      const std::string name(method_info(map->methods[i]).name);
      stable[name] = grid(map->stable[i]);
      predicted[name] = grid(map->predicted[i]);
      Json b = Json::array();
      for (double x : map->boundary[i]) b.push_back(threshold_json(x));
      boundary[name] = std::move(b);
    }
    m["stable"] = std::move(stable);
    m["predicted"] = std::move(predicted);
    m["boundary"] = std::move(boundary);
  }
  j["map"] = std::move(m);
  return j;
}

std::string thresholds_table(const std::vector<ThresholdRow>& rows) {
  std::string out = fmt::format("Stability thresholds dt* (largest stable step; unbounded: stable at every step tried, 0: at none)\n\n"
                                "{:<18} {:>8} {:>12} {:>12} {:>10}  {}\n", "method", "damping", "predicted", "measured", "rel. diff",
                                "stable again from (predicted / measured)");
  for (const ThresholdRow& r : rows) {
    const bool finite = std::isfinite(r.dt_theory) && r.dt_theory > 0;
    const std::string again = std::isinf(r.again_theory) && std::isinf(r.again_measured)
                                  ? "-"
                                  : again_text(r.again_theory) + " / " + again_text(r.again_measured);
    out += fmt::format("{:<18} {:>8g} {:>12} {:>12} {:>10}  {}\n", method_info(r.method).name, r.damping,
                       threshold_text(r.dt_theory), threshold_text(r.dt_measured),
                       finite ? fmt::format("{:+.1e}", r.dt_measured / r.dt_theory - 1) : "-", again);
  }
  return out;
}

std::string sweep_table(const std::vector<SweepRow>& rows) {
  std::string out = fmt::format("Damping sweep: energy growth rate d ln E / dt, measured (least squares) and predicted (2 ln rho / h)\n\n"
                                "{:<18} {:>6} {:>8} {:>13} {:>13} {:>11} {:>11} {:>11} {:>7}\n",
                                "method", "dt", "damping", "measured", "predicted", "E(T)/E0", "max E/E0", "error", "stable");
  for (const SweepRow& r : rows)
    out += fmt::format("{:<18} {:>6g} {:>8.4g} {:>13.5e} {:>13.5e} {:>11.3e} {:>11.3e} {:>11.3e} {:>7}\n",
                       method_info(r.method).name, r.dt, r.damping, r.run.rate, r.rate_theory, r.run.energy_ratio_final,
                       r.run.energy_ratio_max, r.run.error_final, r.run.stable() ? "yes" : "no");
  return out;
}

std::string map_summary(const StabilityMap& map) {
  std::string out = fmt::format("Stability map: {} steps from {:.3g} to {:.3g} x {} dampings from 0 to {:.3g}\n\n"
                                "{:<18} {:>14} {:>22}\n", map.dt.size(), map.dt.front(), map.dt.back(), map.damping.size(),
                                map.damping.back(), "method", "stable cells", "disagree w/ predicted");
  for (std::size_t i = 0; i < map.methods.size(); ++i) {
    int stable = 0;
    for (const auto& row : map.stable[i])
      for (bool cell : row) stable += cell;
    out += fmt::format("{:<18} {:>14} {:>22}\n", method_info(map.methods[i]).name,
                       fmt::format("{}/{}", stable, map.dt.size() * map.damping.size()), disagreeing_cells(map, i));
  }
  return out;
}

std::string amplitude_table_text(const AmplitudeTable& t) {
  std::string out = "max amplitude max |p_y - L| over N = (int)(10 / step) steps\n" + fmt::format("{:>12}", "step");
  for (std::size_t m : t.methods) out += fmt::format(" {:>17}", method_info(m).name);
  out += "\n";
  for (std::size_t i = 0; i < t.steps.size(); ++i) {
    out += fmt::format("{:>12.5e}", t.steps[i]);
    for (double a : t.amplitude[i]) out += std::isfinite(a) ? fmt::format(" {:>17.5e}", a) : fmt::format(" {:>17}", "inf");
    out += "\n";
  }
  return out;
}

namespace {

// `study damping` and `study stability` share these (the spring only).
struct StabilityArgs : StudyArgs {
  std::string dampings;  // damping sweep; empty: 0 .. 2 x critical (21) + 0.1
};

StabilityConfig stability_config(StabilityArgs& a, Context& ctx) {
  StabilityConfig c;
  c.params = a.scene.values(a.scene.scene_index());
  c.methods = resolve_methods(a.methods, false);
  c.workers = ctx.workers(resolve_thread_count(a.threads));
  c.pack_width = resolve_lanes(a.lanes);
  return c;
}

// The scenes each stability command takes: damping the spring's alone; stability the spring's
// (thresholds over dampings, the map) or a scene's that declares its modes.
bool spring_scene(const SceneKernel& s) { return runs_spring_study(s); }
bool stability_scene(const SceneKernel& s) { return runs_spring_study(s) || s.modes != nullptr; }

void add_stability_options(CLI::App* app, StabilityArgs& a, bool sweep, bool map) {
  // study stability: the spring or a scene with modes; study damping: the spring
  a.scene.add_to(app, map ? stability_scene : spring_scene, map);
  app->add_option("--methods", a.methods, "comma-separated methods (default every numerical method)");
  // damping: the sweep's steps (and its dampings); stability: the thresholds' dampings and the map
  const ParamFilter sweep_steps = [](std::string_view p) { return p == "dts"; }, the_rest = [](std::string_view p) { return p != "dts"; };
  add_params(app, stability_params(), a.params, StabilityConfig{}, sweep ? sweep_steps : the_rest);
  if (sweep) app->add_option("--dampings", a.dampings, "comma-separated dampings (default 0 to twice critical in 21 steps, and 0.1)");
  add_threads_option(app, a.threads);
  add_lanes_option(app, a.lanes);
  add_shard_option(app, a.shard);
  app->add_option("--json", a.json, map ? fmt::format("write JSON (schema {} on the spring, {} on a scene with modes) to this "
                                                      "file", schema::stability, schema::mode_stability)
                                        : fmt::format("write JSON (schema {}) to this file", schema::stability));
}

int run_damping(StabilityArgs& a, Context& ctx) {
  StabilityConfig c = stability_config(a, ctx);
  read_params(stability_params(), a.params, c);
  if (!a.dampings.empty()) c.sweep_dampings = number_list("--dampings", a.dampings, Bound::NonNegative);
  using Rows = std::vector<SweepRow>;
  return run_study(ctx, a, false, [&] { return damping_sweep(c); }, sweep_table,
                   [&](const Rows& r) { return stability_json(c.params, {}, r, nullptr); });
}

// The spring's study (thresholds over dampings, the map: analysis/studies/stability.hpp) on the spring;
// the modes' study on any other scene that declares its modes (core/scene.hpp).
bool modes_study(const SceneKernel& s) { return s.modes != nullptr; }

// A scene's thresholds: predicted from its modes, measured on the whole scene (analysis/studies/mode_stability.hpp).
int mode_stability_command(StabilityArgs& a, Context& ctx) {
  for (const char* spring_only : {"--threshold-dampings", "--map-dt-points", "--map-damping-points", "--map-dt-min", "--map-dt-max"})
    if (a.scene.app->count(spring_only) > 0)
      throw UsageError(fmt::format("{} applies to the spring's study; the {}'s damping is among its own parameters",
                                   spring_only, a.scene.scene));
  ModeStabilityConfig c;
  c.scene = a.scene.scene_index();
  c.params = a.scene.values(c.scene);
  c.methods = resolve_methods(a.methods, false, c.scene);
  c.workers = ctx.workers(resolve_thread_count(a.threads));
  resolve_lanes(a.lanes);  // checked; the runs of a scene of run-time size go one at a time
  using Rows = std::vector<ModeThresholdRow>;
  return run_study(ctx, a, false, [&] { return mode_threshold_study(c); },
                   [&](const Rows& r) { return mode_thresholds_table(scene_name(c.scene), r); },
                   [&](const Rows& r) { return mode_stability_json(c, r); });
}

int run_stability(StabilityArgs& a, Context& ctx) {
  const SceneKernel& scene = scene_kernel(a.scene.scene_index());
  if (!runs_spring_study(scene)) {
    if (modes_study(scene)) return mode_stability_command(a, ctx);
    const std::string accepted = scene_list([](const SceneKernel& s) { return runs_spring_study(s) || modes_study(s); });
    throw UsageError(fmt::format("--scene '{}' is not accepted by study stability; accepted: {} (the spring, or a scene "
                                 "that declares its modes)", a.scene.scene, accepted));
  }
  StabilityConfig c = stability_config(a, ctx);
  read_params(stability_params(), a.params, c);
  check_stability(c, option_names());
  using Result = std::pair<std::vector<ThresholdRow>, StabilityMap>;
  return run_study(ctx, a, false, [&] { return Result{threshold_study(c), stability_map(c)}; },
                   [](const Result& r) { return thresholds_table(r.first) + "\n" + map_summary(r.second); },
                   [&](const Result& r) { return stability_json(c.params, r.first, {}, &r.second); });
}

CLI::App* add_damping(CLI::App* study, StabilityArgs& a) {
  CLI::App* cmd = study->add_subcommand("damping", "spring: energy growth rate measured and predicted over damping and dt");
  add_stability_options(cmd, a, true, false);
  return cmd;
}

CLI::App* add_stability(CLI::App* study, StabilityArgs& a) {
  CLI::App* cmd = study->add_subcommand("stability", "stability thresholds dt* predicted and measured: the spring (and a (dt, "
                                                     "damping) map) or any scene that declares its modes (the rope of N masses)");
  add_stability_options(cmd, a, false, true);
  return cmd;
}

}  // namespace

StudyCommand damping_command(CLI::App* study) { return study_command(study, add_damping, run_damping); }
StudyCommand stability_command(CLI::App* study) { return study_command(study, add_stability, run_stability); }

}  // namespace steplab
