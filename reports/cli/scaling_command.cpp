// `study scaling`: the rope of N masses or the soft body of n x n masses refined, every method and
// the peers at each size (analysis/scaling.hpp); a table on stdout, --json the data (schema
// steplab.scaling/2).
#include <cmath>
#include <cstdio>

#include <fmt/format.h>

#include "analysis/defaults.hpp"
#include "analysis/kernel.hpp"
#include "analysis/scaling.hpp"
#include "reports/cli/commands.hpp"
#include "reports/data/inputs.hpp"
#include "reports/data/output.hpp"
#include "reports/data/run_json.hpp"
#include "reports/cli/parts.hpp"
#include "reports/data/study_output.hpp"

namespace steplab {

CLI::App* add_scaling_command(CLI::App* study, ScalingArgs& a) {
  CLI::App* cmd = study->add_subcommand("scaling", "rope of N masses or soft body of n x n: cost of a step and of a run at a "
                                                   "given error, largest stable step, against N; fitted exponents, crossover");
  a.scene.scene = std::string(kDefaultSizedScene);  // any scene that scales() (analysis/scaling.hpp)
  a.scene.add_to(cmd);
  cmd->add_option("--methods", a.methods, "comma-separated methods and adaptive solvers (dopri5, odeint_dopri5, cvode_adams_band, "
                                          "cvode_bdf_band, cvode_bdf_max2_band on the rope, cvode_adams_klu, cvode_bdf_klu, "
                                          "cvode_bdf_max2_klu on the soft body; default: "
                                          "every numerical method, and every adaptive solver where the list names none)");
  cmd->add_option("--sizes", a.sizes, "comma-separated sizes: the rope's numbers of masses (1 .. 100000), the soft body's "
                                      "grid sides n (1 .. 300; default 16,64,256,1024 masses on the rope, 4,8,16 on the soft body)");
  cmd->add_option("--error", a.error, "target position error (largest over the coordinates at t_end)")->capture_default_str();
  cmd->add_option("--t-end", a.t_end, "simulated time")->capture_default_str();
  cmd->add_option("--max-steps", a.max_steps, "a search tries no step that needs more steps than this (default: 2000000 "
                                              "on the rope, 200000 on the soft body, whose implicit steps cost a sparse solve each)");
  cmd->add_option("--threads", a.threads, "worker threads for the searches (timings run one at a time)")->capture_default_str();
  cmd->add_flag("--no-timing", a.no_timing, "cost by force and Jacobian evaluations only (reproducible byte for byte)");
  cmd->add_flag("--no-peers", a.no_peers, "steplab's fixed-step methods only (no dopri5, CVODE, Boost.Odeint)");
  add_shard_option(cmd, a.shard);
  cmd->add_option("--json", a.json, "write JSON (schema steplab.scaling/2) to this file");
  return cmd;
}

Json scaling_json(const ScalingResult& r) {
  const ScalingConfig& c = r.config;
  Json j;
  j["schema"] = "steplab.scaling/2";
  const std::size_t scene = scene_index(c.scene);
  const SceneKernel& s = scene_kernel(scene);
  const std::string size_key = param_key(s.params[s.size_param]);  // masses (rope), grid (soft body)
  j["scene"] = c.scene;
  Json p = scene_params_json(scene, c.params);
  p.erase(size_key);
  p["sizes"] = c.sizes;
  p["target_error"] = c.target_error;
  p["t_end"] = c.t_end;
  p["max_steps"] = c.max_steps;
  p["timing"] = c.timing;
  j["params"] = std::move(p);
  j["peer_builds"] = peer_builds_json();
  const auto num = [](double x) { return std::isnan(x) ? Json(nullptr) : threshold_json(x); };
  Json rows = Json::array();
  for (const ScalingRow& w : r.rows) {
    Json row = {{"solver", w.solver}, {"implicit", w.implicit}, {"adaptive", w.adaptive}, {size_key, w.n},
                {"dt_stable", num(w.dt_stable)}, {w.adaptive ? "tolerance" : "dt", num(w.dt)},
                {"error", w.reached() ? Json(w.error) : Json(nullptr)}, {"counts", counts_json(w.counts())},
                {"seconds", w.reached() && c.timing ? Json(w.seconds) : Json(nullptr)}, {"search_runs", w.runs}};
    if (!w.adaptive) row["dt_capped_at_stable"] = w.capped;
    row["masses"] = w.masses;
    rows.push_back(std::move(row));
  }
  j["rows"] = std::move(rows);
  const auto exponent = [&](const Exponent& e) {
    return Json{{"exponent", num(e.value)}, {"ci95", e.fitted() ? Json::array({e.lo, e.hi}) : Json(nullptr)},
                {"sizes", e.sizes}, {"decades", e.decades}, {"early", e.early}};
  };
  Json fits = Json::array();
  for (const ScalingFit& f : r.fits)
    fits.push_back({{"solver", f.solver}, {"step", exponent(f.step)}, {"run", exponent(f.run)}, {"stable_step", exponent(f.stable)}});
  j["exponents"] = std::move(fits);
  j["crossover"] = r.crossover == 0 ? Json(nullptr)
                                    : Json({{size_key, r.crossover}, {"masses", scaling_masses(c, r.crossover)}, {"method", r.crossover_method}});
  return j;
}

std::string exponent_text(const Exponent& e) {
  if (!e.fitted()) return "-";
  return fmt::format("{:.2f} [{:.2f}, {:.2f}]{}", e.value, e.lo, e.hi, e.early ? "*" : "");
}

std::string exponent_rule_text() {
  return fmt::format("- not fitted: fewer than {} sizes, or less than {:g} decades of N, where the quantity is known; "
                     "* the sizes begin below the asymptotic regime (a step's cost grows by less than N^{:g} from the "
                     "smallest size to the next: fixed overheads still dominate)",
                     kFitSizes, kFitDecades, kAsymptoticSlope);
}

std::string scaling_table(const ScalingResult& r) {
  const ScalingConfig& c = r.config;
  const char* unit = c.timing ? "run [s]" : "evals x N";
  std::string out = fmt::format("{}, error {:g} (largest over the coordinates at t = {:g}, against the {}); cost by {}\n\n"
                                "{:<20} {:>7} {:>11} {:>12} {:>10} {:>9} {:>6} {:>9} {:>7} {:>7} {:>8} {:>12} {:>12}\n",
                                scene_kernel(scene_index(c.scene)).title, c.target_error, c.t_end,
                                scene_kernel(scene_index(c.scene)).has_exact ? "exact solution" : "reference solution", c.timing ? "run time" : "force + Jacobian evaluations x N", "solver",
                                "N", "dt*", "dt / tol", "error", "steps", "rej", "forces", "jacs", "LUs", "Newton", unit, "per step");
  bool capped = false;
  for (const ScalingRow& w : r.rows) {
    const double cost = scaling_cost(c, w);
    const auto count = [&](long long x) { return w.reached() ? std::to_string(x) : std::string("-"); };
    capped = capped || (w.reached() && w.capped);
    out += fmt::format("{:<20} {:>7} {:>11} {:>12} {:>10} {:>9} {:>6} {:>9} {:>7} {:>7} {:>8} {:>12} {:>12}\n", w.solver, w.masses,
                       std::isnan(w.dt_stable) ? "-" : threshold_text(w.dt_stable),
                       w.reached() ? fmt::format("{:.4g}{}", w.dt, w.capped ? "^" : "") : "not reached",
                       w.reached() ? fmt::format("{:.2e}", w.error) : "-", count(w.steps), count(w.rejected), count(w.forces),
                       count(w.jacobians), count(w.factorisations), count(w.newton),
                       w.reached() ? fmt::format("{:.4g}", cost) : "-", w.reached() && w.steps > 0 ? fmt::format("{:.4g}", cost / w.steps) : "-");
  }
  if (capped)
    out += "^ the step search stopped at its cap, 0.95 dt*: dt* predicted from the exact modes, which no adaptive solver is told\n";
  out += fmt::format("\nExponents p of cost ~ N^p, q of dt* ~ N^q (least squares over the sizes reached, 95 % intervals)\n"
                     "{:<18} {:>20} {:>20} {:>20}\n", "solver", "one step", "whole run", "dt*");
  for (const ScalingFit& f : r.fits)
    out += fmt::format("{:<18} {:>20} {:>20} {:>20}\n", f.solver, exponent_text(f.step), exponent_text(f.run), exponent_text(f.stable));
  out += exponent_rule_text() + "\n";
  out += r.crossover == 0 ? std::string("\nNo size here at which an implicit method's run is cheaper than every explicit one's.\n")
                          : fmt::format("\nFrom N = {} on the sizes here, {} is cheaper than every explicit method.\n",
                                        scaling_masses(c, r.crossover), r.crossover_method);
  return out;
}

int scaling_command(ScalingArgs& a, Context& ctx) {
  const SceneKernel& scene = scene_kernel(a.scene.scene_index());
  if (!scales(scene)) {
    throw UsageError(fmt::format("--scene '{}' is not accepted by study scaling; accepted: {} (a scene of run-time size "
                                 "that declares its modes)", a.scene.scene, scene_list(scales)));
  }
  ScalingConfig c = scaling_config(a.scene.scene);  // the scene's default sizes, step cap and solvers
  c.params = a.scene.values(a.scene.scene_index());
  Solvers solvers = resolve_solvers(a.methods, c.adaptive, scene.name, a.no_peers);
  c.methods = std::move(solvers.methods);
  c.adaptive = std::move(solvers.adaptive);
  if (!a.sizes.empty()) {
    c.sizes.clear();
    const ParamSpec& size = scene.params[scene.size_param];  // --masses, --grid: its range
    for (const std::string& s : split_list(a.sizes)) c.sizes.push_back(static_cast<int>(parse_count("--sizes", s, 1, static_cast<long long>(size.max_count))));
  }
  c.target_error = parse_number("--error", a.error, Bound::Positive);
  c.t_end = parse_number("--t-end", a.t_end, Bound::Positive);
  if (!a.max_steps.empty()) c.max_steps = parse_count("--max-steps", a.max_steps, 1, 1'000'000'000);
  c.workers = ctx.workers(resolve_thread_count(a.threads));
  c.timing = !a.no_timing;
  begin_shard(ctx, a.shard, a.json, c.timing);
  if (ctx.stop_after_validation(a.json)) return 0;
  const ScalingResult r = scaling_study(c);
  if (finish_shard(ctx, a.json)) return 0;
  std::fputs(scaling_table(r).c_str(), stdout);
  if (!a.json.empty()) write_atomic(a.json, scaling_json(r).dump(1) + "\n");
  return 0;
}

}  // namespace steplab
