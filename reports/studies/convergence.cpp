// `steplab study convergence`: each method's error against the step on a scene, its fitted order
// beside the theory's (analysis/studies/convergence.hpp); --sweep NAME=V1,V2,... the study at each
// value of one scene parameter. Its command, its parameters, its tables (the order fits' caveats
// marked beside them) and its JSON (steplab.convergence/2; with --sweep, order_reduction.cpp's);
// and the old framework's local error tables.
#include "reports/studies/studies.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/peers/peers.hpp"
#include "analysis/studies/convergence.hpp"
#include "reports/data/inputs.hpp"
#include "reports/data/output.hpp"
#include "reports/data/run_json.hpp"
#include "reports/data/study_command.hpp"

namespace steplab {

// What an order fit cannot vouch for (analysis/fits/order_fit.hpp, step 7): its flag, its name in
// the JSON, its mark in the table and the mark's legend under it.
struct FitCaveat {
  bool OrderFit::*flag;
  const char *name, *mark, *legend;
};
constexpr std::array<FitCaveat, 3> kFitCaveats{{
    {&OrderFit::few_points, "few_points", "~",
     "fitted over fewer than 5 points: its interval comes from the plain slope, which the next error term biases; it may "
     "miss the true order. More points (--points, --dt-min) make it a bound."},
    {&OrderFit::non_monotone, "non_monotone", "*",
     "the errors in its window do not approach their order monotonically (an error not below the one at the next larger "
     "step, or local orders that turn down and up): the slope is not an order."},
    {&OrderFit::wide, "wide", "?", "its bound is wider than +-0.5: not a finding."},
}};

constexpr StudyParam<ConvergenceConfig> kConvergenceParams[] = {
    {"dt-max", "largest step", kPositive, &ConvergenceConfig::dt_max},
    {"dt-min", "smallest step", kPositive, &ConvergenceConfig::dt_min},
    {"points", "steps in the geometric sweep", {3, 1000}, &ConvergenceConfig::points},
    {"t-end", "simulated time of every run", kPositive, &ConvergenceConfig::t_end, "10; 1 against a reference solution, as on falling"},
};

std::span<const StudyParam<ConvergenceConfig>> convergence_params() { return kConvergenceParams; }

void check_convergence(const ConvergenceConfig& c, const ParamNamer& name) {
  check_sweep(c.dt_min, c.dt_max, c.t_end, name);
  if (sweep_steps(c.t_end, c.dt_max, c.dt_min, c.points).size() < 3)
    throw UsageError(fmt::format("{}{}, {}, {} and {} leave fewer than 3 distinct steps; accepted: a wider range", name.origin, name("dt-max"),
                                 name("dt-min"), name("points"), name("t-end")));
}

Json fit_caveats(const OrderFit& f) {
  Json out = Json::array();
  for (const FitCaveat& c : kFitCaveats)
    if (f.fitted && f.*c.flag) out.push_back(c.name);
  return out;
}

Json convergence_json(const ConvergenceResult& r) {
  const ConvergenceConfig& c = r.config;
  Json j;
  j["schema"] = schema::convergence;
  j["scene"] = scene_name(c.scene);
  Json p = scene_params_json(c.scene, c.params);
  p["t_end"] = c.t_end;
  p["dt_max"] = c.dt_max;
  p["dt_min"] = c.dt_min;
  p["points"] = c.points;
  p["fit_error"] = to_string(c.fit_error);
  p["timing"] = c.timing;
  // the settings of the methods on springs, where one of them ran
  for (std::size_t m : c.methods) p.update(settings_json(method_info(m), c.settings));
  j["params"] = std::move(p);
  if (r.uses_reference) {
    const ReferenceSolution& ref = r.reference;
    j["reference"] = {{"method", "dopri5"},          {"rtol", ref.rtol},
                      {"atol", ref.rtol},            {"steps", ref.steps},
                      {"check_rtol", ref.check_rtol}, {"check_steps", ref.check_steps},
                      {"estimated_error", ref.estimated_error}, {"floor", ref.floor}};
  } else {
    j["reference"] = "exact";
  }
  Json results = Json::array();
  for (const ConvergenceRecord& rec : r.records) {
    Json e;
    e["method"] = method_info(rec.method).name;
    e["dt"] = rec.dt;
    e["status"] = to_string(rec.status);
    e["steps"] = rec.steps;
    e["diverged_step"] = rec.failed_step >= 0 ? Json(rec.failed_step) : Json(nullptr);
    e["error_final"] = finite_or_null(rec.error_final);
    e["error_velocity_final"] = finite_or_null(rec.error_v_final);
    e["error_max"] = finite_or_null(rec.error_max);
    e["error_rms"] = finite_or_null(rec.error_rms);
    e["roundoff_floor"] = rec.floor;
    e["seconds"] = rec.seconds >= 0 ? Json(rec.seconds) : Json(nullptr);
    results.push_back(std::move(e));
  }
  j["results"] = std::move(results);
  Json fits = Json::array();
  for (const ConvergenceFit& f : r.fits) {
    const MethodInfo& info = method_info(f.method);
    Json e;
    e["method"] = info.name;
    e["declared_order"] = info.exact_flow ? Json(nullptr) : Json(info.order);
    e["exact"] = f.fit.exact;
    if (f.fit.fitted) {
      e["order"] = f.fit.order;
      e["order_bound"] = {finite_or_null(f.fit.bound_lo), finite_or_null(f.fit.bound_hi)};
      e["correction_power"] = f.fit.correction_power;
      e["window_slope"] = f.fit.line.slope;
      e["window_ci95"] = {finite_or_null(f.fit.line.ci95_lo), finite_or_null(f.fit.line.ci95_hi)};
      e["r2"] = f.fit.line.r2;
      e["n_points"] = f.fit.line.n;
      e["dt_range"] = {f.fit.dt_lo, f.fit.dt_hi};
    } else {
      e["order"] = nullptr;
      e["order_bound"] = nullptr;
      e["correction_power"] = nullptr;
      e["window_slope"] = nullptr;
      e["window_ci95"] = nullptr;
      e["r2"] = nullptr;
      e["n_points"] = 0;
      e["dt_range"] = nullptr;
    }
    e["order_extrapolated"] = f.fit.fitted ? finite_or_null(f.fit.extrapolated) : Json(nullptr);
    e["local_orders"] = f.fit.local_slopes;
    e["diverged_skipped"] = f.fit.diverged_skipped;
    e["caveats"] = fit_caveats(f.fit);
    e["note"] = f.fit.note;
    fits.push_back(std::move(e));
  }
  j["fits"] = std::move(fits);
  return j;
}

std::string convergence_table(const ConvergenceResult& r) {
  const ConvergenceConfig& c = r.config;
  std::string out = fmt::format("Convergence on {}: t_end {}, {} steps from {:.3g} to {:.3g}; {} position error\n\n",
                                scene_name(c.scene), c.t_end, r.dts.size(), r.dts.front(), r.dts.back(),
                                to_string(c.fit_error));
  if (r.uses_reference)
    out += fmt::format("Errors against a reference solution: dopri5 at rtol = atol = {:g} ({} steps); its error, from "
                       "a second one at {:g}, is {:.2e}; errors below {:.2e} are not fitted.\n\n",
                       r.reference.rtol, r.reference.steps, r.reference.check_rtol, r.reference.estimated_error,
                       r.reference.floor);
  out += fmt::format("{:>10}", "dt");
  for (const auto& f : r.fits) out += fmt::format(" {:>18}", method_info(f.method).name);
  out += "\n";
  for (std::size_t i = 0; i < r.dts.size(); ++i) {
    out += fmt::format("{:>10.4g}", r.dts[i]);
    for (std::size_t m = 0; m < r.fits.size(); ++m) {
      const ConvergenceRecord& rec = r.records[m * r.dts.size() + i];
      const double e = error_of(rec, c.fit_error);
      out += rec.status != RunStatus::Ok ? fmt::format(" {:>18}", to_string(rec.status)) : fmt::format(" {:>18.5e}", e);
    }
    out += "\n";
  }
  out += fmt::format("\n{:<18} {:>8} {:>8} {:>20} {:>2} {:>7} {:>8} {:>20} {:>9} {:>6} {:>21}\n", "method", "declared", "order",
                     "bound", "q", "aitken", "slope", "slope 95% interval", "R^2", "points", "dt range");
  int skipped = 0;
  std::array<bool, kFitCaveats.size()> marked{};  // a caveat some row is marked with: its legend below
  for (const auto& f : r.fits) skipped += f.fit.diverged_skipped;
  for (const auto& f : r.fits) {
    const MethodInfo& info = method_info(f.method);
    const std::string declared = info.exact_flow ? "exact" : std::to_string(info.order);
    if (f.fit.exact) {
      out += fmt::format("{:<18} {:>8} {:>8}   every error at the round-off floor\n", info.name, declared, "exact");
    } else if (!f.fit.fitted) {
      out += fmt::format("{:<18} {:>8} {:>8}   {}\n", info.name, declared, "-", f.fit.note);
    } else {
      const LineFit& l = f.fit.line;
      std::string mark;
      for (std::size_t k = 0; k < kFitCaveats.size(); ++k)
        if (f.fit.*kFitCaveats[k].flag) mark += std::string(" ") + kFitCaveats[k].mark, marked[k] = true;
      out += fmt::format("{:<18} {:>8} {:>8.4f} {:>20} {:>2} {:>7} {:>8.4f} {:>20} {:>9.6f} {:>6} {:>21}{}\n", info.name, declared,
                         f.fit.order, fmt::format("[{:.4f}, {:.4f}]", f.fit.bound_lo, f.fit.bound_hi), f.fit.correction_power,
                         std::isnan(f.fit.extrapolated) ? std::string("-") : fmt::format("{:.3f}", f.fit.extrapolated), l.slope,
                         fmt::format("[{:.4f}, {:.4f}]", l.ci95_lo, l.ci95_hi), l.r2, l.n,
                         fmt::format("{:.3g} .. {:.3g}", f.fit.dt_lo, f.fit.dt_hi), mark);
    }
  }
  out += "\nq: the next error term modelled (1 or 2); 0: fewer than 5 points, the plain slope and its interval stand in. "
         "aitken: the local orders' limit by Aitken's delta-squared (-: no converging trend). docs/studies.md, orders.\n";
  for (std::size_t k = 0; k < kFitCaveats.size(); ++k)
    if (marked[k]) out += fmt::format("{}: {}\n", kFitCaveats[k].mark, kFitCaveats[k].legend);
  if (skipped > 0) out += fmt::format("\n{} diverged runs (marked 'diverged' above) are left out of the fits.\n", skipped);
  return out;
}

std::string local_error_tables(const LocalErrorResult& r) {
  const auto header = [&](const char* first) {
    std::string h = fmt::format("{:>12} {:>12}", "step", first);
    for (const auto& c : r.columns) h += fmt::format(" {:>17}", method_info(c.method).name);
    return h + "\n";
  };
  const auto table = [&](const char* title, const std::vector<double>& exact_col, auto member) {
    std::string t = fmt::format("{}\n", title) + header("analytic");
    for (std::size_t i = 0; i < r.steps.size(); ++i) {
      t += fmt::format("{:>12.5e} {:>12.5e}", r.steps[i], exact_col[i]);
      for (const auto& c : r.columns) t += fmt::format(" {:>17.5e}", (c.*member)[i]);
      t += "\n";
    }
    return t + "\n";
  };
  std::string out = fmt::format("One step from the analytic state at t = {} (local errors)\n\n", r.config.t0);
  out += table("velocity change v - v_start", r.exact_dv, &LocalErrorColumn::dv);
  out += table("displacement p - p_start", r.exact_dx, &LocalErrorColumn::dx);
  std::string e = "local error |(p, v) - (p, v)_analytic|\n" + header("");
  for (std::size_t i = 0; i < r.steps.size(); ++i) {
    e += fmt::format("{:>12.5e} {:>12}", r.steps[i], "");
    for (const auto& c : r.columns) e += fmt::format(" {:>17.5e}", c.error[i]);
    e += "\n";
  }
  out += e + "\nobserved local order (expected: global order + 1)\n";
  for (const auto& c : r.columns) {
    const MethodInfo& info = method_info(c.method);
    if (c.order.exact) out += fmt::format("{:<18} exact (every error at the round-off floor)\n", info.name);
    else if (!c.order.fitted) out += fmt::format("{:<18} - ({})\n", info.name, c.order.note);
    else
      out += fmt::format("{:<18} {:.3f}  [{:.3f}, {:.3f}] over {} steps, expected {}\n", info.name, c.order.line.slope,
                         c.order.line.ci95_lo, c.order.line.ci95_hi, c.order.line.n, info.order + 1);
  }
  return out;
}

namespace {

struct ConvergenceArgs : StudyArgs {
  SettingsArgs settings;  // of the methods on springs, for every run of theirs
  std::string error = "final";
  std::string sweep;  // NAME=V1,V2,...: the study at each value of one scene parameter
  bool reference = false;
  bool timing = false;
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
    return run_study(ctx, a, false, [&] { return order_reduction(convergence_sweep(c, param, values)); }, order_reduction_table,
                     order_reduction_json);
  }
  return run_study(ctx, a, c.timing, [&] { return convergence_study(c); }, convergence_table, convergence_json);
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
