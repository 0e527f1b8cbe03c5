// `steplab study scaling`: the rope of N masses or the soft body of n x n masses refined and
// stiffened, every method and the peers in each cell, at each target (analysis/studies/scaling.hpp).
// Its command, its parameters, a table per (target, stiffness) block and the crossover map on
// stdout, its JSON (schema::scaling) with --json, and the words the report's sections share (the
// fitted exponents, the stiffness a block is at).
#include "reports/studies/studies.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/peers/peers.hpp"
#include "analysis/studies/defaults.hpp"
#include "analysis/studies/scaling.hpp"
#include "reports/data/inputs.hpp"
#include "reports/data/output.hpp"
#include "reports/data/run_json.hpp"
#include "reports/data/study_command.hpp"

namespace steplab {

// Its measure's parameters (the sizes, targets and stiffnesses depend on the scene: its command
// reads them); t-end is also the report's scaling.t_end.
constexpr StudyParam<ScalingConfig> kScalingParams[] = {
    {"t-end", "simulated time", kPositive, &ScalingConfig::t_end},
    {"frames", "output frames up to t_end where the error is measured; a fixed-step method interpolates each inside its "
               "step (its output between steps)", {1, 10'000}, &ScalingConfig::frames},
    {"max-steps", "a search tries no step that needs more steps than this", {1, 1e9}, &ScalingConfig::max_steps,
     "2000000 on the rope, 200000 on the soft body, whose implicit steps cost a sparse solve each"},
};

std::span<const StudyParam<ScalingConfig>> scaling_params() { return kScalingParams; }

Json scaling_json(const ScalingResult& r) {
  const ScalingConfig& c = r.config;
  Json j;
  j["schema"] = schema::scaling;
  const std::size_t scene = scene_index(c.scene);
  const SceneKernel& s = scene_kernel(scene);
  const std::string size_key = param_key(s.params[s.size_param]);  // masses (rope), grid (soft body)
  const auto num = [](double x) { return std::isnan(x) ? Json(nullptr) : threshold_json(x); };
  j["scene"] = c.scene;
  Json p = scene_params_json(scene, c.params);
  p.erase(size_key);
  if (s.stiffness_param >= 0) p.erase(param_key(s.params[s.stiffness_param]));
  p["sizes"] = c.sizes;
  Json stiffnesses = Json::array();
  for (double k : scaling_stiffnesses(c)) stiffnesses.push_back(num(k));
  p["stiffnesses"] = std::move(stiffnesses);
  Json targets = Json::array();
  for (const ErrorTarget& t : c.targets) targets.push_back({{"value", t.value}, {"of_extent", t.of_extent}});
  p["targets"] = std::move(targets);
  p["frames"] = c.frames;
  p["steps_divide_frames"] = c.steps_divide_frames;
  p["t_end"] = c.t_end;
  p["max_steps"] = c.max_steps;
  p["timing"] = c.timing;
  j["params"] = std::move(p);
  j["peer_builds"] = peer_builds_json();
  Json rows = Json::array();
  for (const ScalingRow& w : r.rows) {
    Json row = {{"solver", w.solver}, {"target", w.target}, {"stiffness", num(w.stiffness)}, {"implicit", w.implicit},
                {"adaptive", w.adaptive}, {size_key, w.n}, {"dt_stable", num(w.dt_stable)}, {w.adaptive ? "tolerance" : "dt", num(w.dt)},
                {"error", w.reached() ? Json(w.error) : Json(nullptr)}, {"counts", counts_json(w.counts())},
                {"seconds", w.reached() && c.timing ? Json(w.seconds) : Json(nullptr)},
                {"seconds_spread", w.reached() && c.timing ? Json(w.spread) : Json(nullptr)}, {"search_runs", w.runs}};
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
    fits.push_back({{"solver", f.solver}, {"target", f.target}, {"stiffness", num(f.stiffness)}, {"step", exponent(f.step)},
                    {"run", exponent(f.run)}, {"stable_step", exponent(f.stable)}});
  j["exponents"] = std::move(fits);
  const auto name = [](const std::string& x) { return x.empty() ? Json(nullptr) : Json(x); };
  Json blocks = Json::array();
  for (const ScalingBlock& b : r.blocks) {
    Json map = Json::array();
    for (const ScalingCell& m : b.cells)
      map.push_back({{size_key, m.n}, {"masses", m.masses}, {"cheapest", name(m.cheapest)}, {"next", name(m.next)},
                     {"margin", num(m.margin)}, {"rival", name(m.rival)}, {"rival_margin", num(m.rival_margin)},
                     {"best_implicit", name(m.best_implicit)}, {"best_explicit", name(m.best_explicit)},
                     {"best_implicit_peer", name(m.best_implicit_peer)}, {"explicit_over_implicit", num(m.explicit_over_implicit)},
                     {"implicit_peer_over_implicit", num(m.implicit_peer_over_implicit)}, {"motion", m.motion}});
    blocks.push_back({{"target", b.target}, {"error", b.error}, {"stiffness", num(b.stiffness)},
                      {"crossover", b.crossover == 0 ? Json(nullptr)
                                                     : Json({{size_key, b.crossover}, {"masses", scaling_masses(c, b.crossover)},
                                                             {"method", b.crossover_method}})},
                      {"map", std::move(map)}});
  }
  j["blocks"] = std::move(blocks);
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

std::string stiffness_text(const ScalingConfig& c, double k) {
  const SceneKernel& s = scene_kernel(scene_index(c.scene));
  return std::isnan(k) ? std::string() : fmt::format(", {} {:g}", s.params[s.stiffness_param].name, k);
}

namespace {

// One (target, stiffness): its rows, exponents and crossover.
std::string block_table(const ScalingResult& r, std::size_t b) {
  const ScalingConfig& c = r.config;
  const ScalingBlock& block = r.blocks[b];
  const char* unit = c.timing ? "run [s]" : "evals x N";
  const SceneKernel& scene = scene_kernel(scene_index(c.scene));
  std::string out = fmt::format("{}{}, error {} (largest over the coordinates and {} frames to t = {:g}, against the {}); cost by {}\n\n"
                                "{:<20} {:>7} {:>11} {:>12} {:>10} {:>9} {:>6} {:>9} {:>7} {:>7} {:>8} {:>12} {:>12}\n",
                                scene.title, stiffness_text(c, block.stiffness), target_text(c, block),
                                c.frames, c.t_end, scene.has_exact ? "exact solution" : "reference solution",
                                c.timing ? "run time" : "force evaluations x N", "solver", "N", "dt*", "dt / tol", "error",
                                "steps", "rej", "forces", "jacs", "LUs", "Newton", unit, "per step");
  bool capped = false;
  for (std::size_t s = 0; s < r.solvers(); ++s)
    for (const ScalingRow& w : r.rows_of(b * r.solvers() + s)) {
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
  for (std::size_t s = 0; s < r.solvers(); ++s) {
    const ScalingFit& f = r.fits[b * r.solvers() + s];
    out += fmt::format("{:<18} {:>20} {:>20} {:>20}\n", f.solver, exponent_text(f.step), exponent_text(f.run), exponent_text(f.stable));
  }
  out += exponent_rule_text() + "\n";
  out += !c.timing ? std::string("\nUntimed, where implicit pays is not read: force evaluations leave out the implicit methods' "
                                 "factorisations and solves.\n")
         : block.crossover == 0
             ? std::string("\nNo size here at which an implicit method's run is cheaper than every explicit one's by more than the "
                           "timing's noise.\n")
             : fmt::format("\nAt N = {}, the first size here where one is, {}'s run is cheaper than every explicit method's by more "
                           "than the timing's noise.\n",
                           scaling_masses(c, block.crossover), block.crossover_method);
  return out;
}

std::string ratio_text(double x) { return std::isnan(x) ? "-" : fmt::format("{:.3g}", x); }

}  // namespace

std::string scaling_map_table(const ScalingResult& r) {
  const ScalingConfig& c = r.config;
  std::string out;
  const std::size_t nk = r.blocks.size() / c.targets.size();
  for (std::size_t t = 0; t < c.targets.size(); ++t) {
    out += fmt::format("\nThe map at error {}: per cell the cheapest solver x its margin over the cheapest of another group; the cheapest implicit "
                       "fixed-step method's cost against the best explicit solver's and the best adaptive implicit peer's (> 1: implicit cheaper); "
                       "the body's motion (largest displacement from rest; ! below the target: a run at rest meets it)\n"
                       "{:>10} {:>7}  {:<32} {:<26} {:>8} {:>8} {:>10}\n",
                       target_text(c, r.blocks[t * nk]), "stiffness", "N", "cheapest x margin",
                       "best implicit", "vs expl", "vs peer", "motion");
    for (std::size_t k = 0; k < nk; ++k) {
      const ScalingBlock& b = r.blocks[t * nk + k];
      for (const ScalingCell& m : b.cells)
        out += fmt::format("{:>10} {:>7}  {:<32} {:<26} {:>8} {:>8} {:>10}\n", std::isnan(b.stiffness) ? "-" : fmt::format("{:g}", b.stiffness),
                           m.masses, m.cheapest.empty() ? "none reached" : fmt::format("{} x {}", m.cheapest, ratio_text(m.rival_margin)),
                           m.best_implicit.empty() ? "-" : m.best_implicit, ratio_text(m.explicit_over_implicit), ratio_text(m.implicit_peer_over_implicit),
                           fmt::format("{:.2e}{}", m.motion, m.motion < b.error ? "!" : ""));
    }
  }
  return out;
}

std::string scaling_table(const ScalingResult& r) {
  std::string out;
  for (std::size_t b = 0; b < r.blocks.size(); ++b) {
    if (b > 0) out += '\n';
    out += block_table(r, b);
  }
  return out + scaling_map_table(r);
}

namespace {

struct ScalingArgs : StudyArgs {
  std::string sizes;  // empty: the scene's default sizes (scaling_config, analysis/studies/scaling.hpp)
  std::string error = "1e-4,1%";  // targets: absolute, or N% of the body's extent
  bool steps_divide_frames = false;
  bool no_timing = false;
  bool no_peers = false;
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
  a.add_shard_and_json(cmd, schema::scaling);
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
  return run_study(ctx, a, c.timing, [&] { return scaling_study(c); }, scaling_table, scaling_json);
}

}  // namespace

StudyCommand scaling_command(CLI::App* study) { return study_command(study, add_scaling, run_scaling); }

}  // namespace steplab
