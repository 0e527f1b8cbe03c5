// `steplab study ...`: reads and checks the arguments, runs the study, prints its table and
// writes its JSON.
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include <fmt/format.h>

#include "analysis/studies/convergence.hpp"
#include "analysis/kernel/kernel.hpp"
#include "analysis/peers/peers.hpp"
#include "reports/cli/commands.hpp"
#include "reports/data/inputs.hpp"
#include "reports/data/output.hpp"
#include "reports/cli/shards.hpp"
#include "reports/data/studies.hpp"

namespace steplab {

std::vector<std::size_t> resolve_methods(const std::string& list, bool with_analytic, std::optional<std::size_t> scene) {
  std::vector<std::size_t> out;
  if (list.empty()) {
    for (std::size_t i = 0; i < method_count(); ++i)
      if ((in_ode_studies(i) || (with_analytic && method_info(i).exact_flow)) && (!scene || applies(i, *scene))) out.push_back(i);
    return out;
  }
  for (const std::string& name : split_list(list)) {
    const std::size_t m = resolve_method(name);
    if (std::find(out.begin(), out.end(), m) != out.end())
      throw UsageError(fmt::format("--methods names '{}' twice; accepted: each method once", name));
    if (scene && !applies(m, *scene))
      throw UsageError(fmt::format("--methods '{}' {}", name, why_not(m, *scene)));
    out.push_back(m);
  }
  return out;
}

Solvers resolve_solvers(const std::string& list, const std::vector<std::string>& available, std::string_view scene, bool no_peers,
                        std::span<const PeerInfo> table) {
  Solvers out{{}, no_peers ? std::vector<std::string>{} : available};
  const std::optional<std::size_t> index = find_scene(scene);
  if (list.empty()) return {resolve_methods(list, false, index), out.adaptive};
  const auto accepted = [&] { return fmt::format("{}; and here {}", method_names(), fmt::join(available, ", ")); };
  std::vector<std::string> named;
  for (const std::string& name : split_list(list)) {
    const auto it = std::find_if(table.begin(), table.end(), [&](const PeerInfo& p) { return p.name == name; });
    const PeerInfo* peer = it == table.end() ? nullptr : &*it;
    if (!peer) {
      if (!find_method(name)) {
        std::vector<std::string> names = method_name_list();
        names.insert(names.end(), available.begin(), available.end());
        throw UsageError(fmt::format("--methods '{}' is unknown{}; accepted: {}", name, did_you_mean(name, names), accepted()));
      }
      const std::size_t m = *find_method(name);
      if (std::find(out.methods.begin(), out.methods.end(), m) != out.methods.end())
        throw UsageError(fmt::format("--methods names '{}' twice; accepted: each method once", name));
      if (index && !applies(m, *index)) throw UsageError(fmt::format("--methods '{}' {}", name, why_not(m, *index)));
      out.methods.push_back(m);
      continue;
    }
    if (!peer->built)
      throw UsageError(fmt::format("--methods '{}' is not built into this steplab (its {} solver is missing from SUNDIALS); "
                                   "accepted here: {}", name, to_string(peer->linear_solver), fmt::join(available, ", ")));
    if (std::find(available.begin(), available.end(), name) == available.end())
      throw UsageError(fmt::format("--methods '{}' does not run on the {}; accepted adaptive solvers there: {}", name, scene,
                                   fmt::join(available, ", ")));
    if (std::find(named.begin(), named.end(), name) != named.end())
      throw UsageError(fmt::format("--methods names '{}' twice; accepted: each method once", name));
    named.push_back(name);
  }
  if (!named.empty()) {
    if (no_peers) throw UsageError("--methods names adaptive solvers and --no-peers leaves them out; accepted: one of the two");
    out.adaptive = named;
  }
  return out;
}

unsigned resolve_thread_count(const std::string& text) {
  return static_cast<unsigned>(parse_count("--threads", text, 0, 1024));
}

int resolve_lanes(const std::string& text) {
  if (text == "auto") return 0;
  const long long n = parse_count("--lanes", text, 1, 64);
  if (!cpu_has_width(static_cast<int>(n)))  // also false for a width that is none of 1, 2, 4, 8
    throw UsageError(fmt::format("--lanes {} is not a pack width this CPU steps; accepted: auto, 1 (one run at a time), "
                                 "2 (SSE2){}{}",
                                 text, cpu_has_width(4) ? ", 4 (AVX2)" : "", cpu_has_width(8) ? ", 8 (AVX-512)" : ""));
  return static_cast<int>(n);
}

void add_threads_option(CLI::App* app, std::string& threads, const std::string& help) {
  app->add_option("--threads", threads, help)->capture_default_str();
}

void add_lanes_option(CLI::App* app, std::string& lanes) {
  lanes = "auto";
  app->add_option("--lanes", lanes,
                  "runs of a method stepped together in SIMD lanes, where its kernel is packed (docs/design.md, \"Why a "
                  "step is fast\"): auto (4 with AVX2, else 2), 2 (SSE2), 4 (AVX2), 8 (AVX-512), or 1: one at a time. "
                  "The output is the same")
      ->capture_default_str();
}

namespace {

struct ConvergenceArgs {
  SceneArgs scene;
  SettingsArgs settings;  // of the methods on springs, for every run of theirs
  std::string methods;  // comma-separated; empty: every numerical method
  std::map<std::string, std::string> params;  // as typed, by name (convergence_params(); t-end empty: the study's)
  std::string error = "final";
  std::string sweep;  // NAME=V1,V2,...: the study at each value of one scene parameter
  bool reference = false;
  std::string threads = "0";
  std::string lanes;  // the pack width: auto, 1, 2, 4 or 8 (add_lanes_option)
  std::string shard;  // i/N: write part i of N to --json (reports/cli/shards.hpp)
  bool timing = false;
  std::string json;
};

// --sweep NAME=V1,V2,...: a parameter of the scene (not a count: those set its size) and its
// values, each within the parameter's bound, strictly increasing.
std::pair<std::size_t, std::vector<double>> parse_sweep(const std::string& text, std::size_t scene) {
  const std::span<const ParamSpec> params = scene_kernel(scene).params;
  std::string accepted;
  for (const ParamSpec& p : params)
    if (!p.is_count) accepted += fmt::format("{}{}", accepted.empty() ? "" : ", ", p.name);
  const std::size_t eq = text.find('=');
  const std::string name = text.substr(0, eq);
  const auto it = std::find_if(params.begin(), params.end(), [&](const ParamSpec& p) { return p.name == name && !p.is_count; });
  if (eq == std::string::npos || it == params.end())
    throw UsageError(fmt::format("--sweep '{}' names no parameter of {} that can be swept; accepted: NAME=V1,V2,... with NAME one of {}",
                                 text, scene_name(scene), accepted));
  const std::string list = text.substr(eq + 1);
  if (list.empty()) throw UsageError(fmt::format("--sweep {}= has no values; accepted: {}=V1,V2,... increasing", name, name));
  const std::vector<double> values = number_list("--sweep " + name, list, it->bound);
  check_increasing(fmt::format("--sweep {} values", name), values);
  return {static_cast<std::size_t>(it - params.begin()), values};
}

int run_convergence(ConvergenceArgs& a, Context& ctx) {
  ConvergenceConfig c;
  c.scene = a.scene.scene_index();
  const bool has_exact = scene_kernel(c.scene).has_exact;
  c.reference = a.reference || !has_exact;
  c.params = a.scene.values(c.scene);
  c.methods = resolve_methods(a.methods, false, c.scene);
  c.settings = a.settings.resolve(c.methods);
  c.t_end = c.reference ? 1.0 : 10.0;  // contacts make longer runs against a reference chaotic
  read_params(convergence_params(), a.params, c);
  check_convergence(c, option_names());
  if (a.error == "final") c.fit_error = ErrorKind::Final;
  else if (a.error == "max") c.fit_error = ErrorKind::Max;
  else if (a.error == "rms") c.fit_error = ErrorKind::Rms;
  else throw UsageError(fmt::format("--error '{}' is unknown{}; accepted: final, max, rms", a.error,
                                     did_you_mean(a.error, {"final", "max", "rms"})));
  if (c.reference && c.fit_error != ErrorKind::Final)
    throw UsageError(fmt::format("--error {} needs the exact solution along the run; against the reference solution "
                                 "(--scene {}{}) accepted: final",
                                 a.error, a.scene.scene, a.reference ? ", --reference" : ""));
  c.workers = ctx.workers(resolve_thread_count(a.threads));
  c.pack_width = resolve_lanes(a.lanes);
  c.timing = a.timing;
  if (!a.sweep.empty()) {
    const auto [param, values] = parse_sweep(a.sweep, c.scene);
    if (!a.shard.empty()) throw UsageError("--sweep runs in one process; accepted: --sweep or --shard, not both");
    if (ctx.stop_after_validation(a.json)) return 0;
    const OrderReduction r = order_reduction(convergence_sweep(c, param, values));
    std::fputs(order_reduction_table(r).c_str(), stdout);
    if (!a.json.empty()) write_atomic(a.json, order_reduction_json(r).dump(1) + "\n");
    return 0;
  }
  return run_study(ctx, a.shard, a.json, c.timing, [&] { return convergence_study(c); },
                   [](const ConvergenceResult& r) { return convergence_table(r); }, [](const ConvergenceResult& r) { return convergence_json(r); });
}

CLI::App* add_convergence(CLI::App* study, ConvergenceArgs& a) {
  CLI::App* cmd = study->add_subcommand("convergence", "errors against the exact solution over a dt sweep, fitted orders");
  a.scene.add_to(cmd);
  cmd->add_option("--methods", a.methods, "comma-separated methods (default every numerical method)");
  add_params(cmd, convergence_params(), a.params, ConvergenceConfig{});
  cmd->add_flag("--reference", a.reference,
                "errors against a reference solution (dopri5 at rtol 1e-13) even where an exact one exists; "
                "a scene without one always uses it");
  cmd->add_option("--error", a.error, "error the order is fitted to: final, max, rms")->capture_default_str();
  add_threads_option(cmd, a.threads);
  add_lanes_option(cmd, a.lanes);
  add_shard_option(cmd, a.shard);
  a.settings.add_to(cmd);
  cmd->add_flag("--timing", a.timing, "also time every run (work-precision; not reproducible byte for byte)");
  cmd->add_option("--sweep", a.sweep, "NAME=V1,V2,...: the study at each value of the scene's parameter NAME "
                  "(increasing), each method's order read against it (e.g. --scene target --sweep stiffness=1,1e2,1e4)");
  cmd->add_option("--json", a.json, fmt::format("write JSON (schema {}; with --sweep {}) to this file", schema::convergence,
                                                schema::convergence_sweep));
  return cmd;
}

}  // namespace

StudyCommand convergence_command(CLI::App* study) { return study_command(study, add_convergence, run_convergence); }

}  // namespace steplab

#include "analysis/studies/stability.hpp"

namespace steplab {
namespace {

// `study damping` and `study stability` share these (the spring only).
struct StabilityArgs {
  SceneArgs scene;
  std::string methods;
  std::map<std::string, std::string> params;  // stability_params(), as typed
  std::string dampings;                       // damping sweep; empty: 0 .. 2 x critical (21) + 0.1
  std::string threads = "0";
  std::string lanes;  // the pack width: auto, 1, 2, 4 or 8 (add_lanes_option)
  std::string shard;  // i/N: write part i of N to --json (reports/cli/shards.hpp)
  std::string json;
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
  return run_study(ctx, a.shard, a.json, false, [&] { return damping_sweep(c); }, [](const Rows& r) { return sweep_table(r); },
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
  return run_study(ctx, a.shard, a.json, false, [&] { return mode_threshold_study(c); },
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
  return run_study(ctx, a.shard, a.json, false, [&] { return Result{threshold_study(c), stability_map(c)}; },
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

int amplitude_command(const std::vector<double>& spring_params, double step, const Context& ctx) {
  if (ctx.dry_run) return 0;
  std::vector<std::size_t> methods = resolve_methods("", true);
  std::rotate(methods.begin(), methods.end() - 1, methods.end());  // the analytic column first
  const AmplitudeTable t = amplitude_table(spring_params, methods, step, 10);
  std::fputs(amplitude_table_text(t).c_str(), stdout);
  return 0;
}

}  // namespace steplab

#include "reports/document/report.hpp"

namespace steplab {

int report_command(ReportArgs& a, Context& ctx) {
  const ReportConfig base = a.sheet ? sheet_report_config() : default_report_config();
  ReportConfig c = a.config.empty() ? base : read_report_config(a.config, base);
  const auto list = [](const std::string& text) { return text.empty() ? std::vector<std::string>{} : split_list(text); };
  if (a.methods_given) choose_methods(c, list(a.methods), "--methods");
  if (a.scenes_given) choose_scenes(c, list(a.scenes), "--scenes");
  if (a.sections_given) choose_sections(c, list(a.sections), "--sections");
  check_choice(c, "--methods");
  if (a.print_config) {
    std::fputs((report_config_json(c).dump(1) + "\n").c_str(), stdout);
    return 0;
  }
  if (a.out.empty()) throw UsageError("--out is empty; accepted: a folder path");
  if (ctx.dry_run) return 0;
  check_report_folder(a.out);
  check_writable((std::filesystem::path(a.out).parent_path().empty() ? std::filesystem::path(".")
                                                                     : std::filesystem::path(a.out).parent_path()) /
                 ".steplab-write-check");
  return write_report(c, a.out, a.force, ctx.progress);
}

}  // namespace steplab
