// `steplab study work-precision`: cost against error on the spring and the stiff chain, the
// cheapest method per error level, the chain's stability limits, the stiffness sweep and its
// crossover (analysis/studies/work_precision.hpp). Its command, its parameters, its tables on
// stdout and its JSON (steplab.work_precision/2) with --json; and a run's counts in words, which
// the report's sections share.
#include "reports/studies/studies.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/peers/peers.hpp"
#include "analysis/studies/work_precision.hpp"
#include "reports/data/inputs.hpp"
#include "reports/data/output.hpp"
#include "reports/data/run_json.hpp"
#include "reports/data/study_command.hpp"

namespace steplab {

std::string counts_text(const Counts& n) {
  std::string t = fmt::format("{} steps, {} forces", n.steps, n.forces);
  if (n.rejected > 0) t += fmt::format(", {} rejected", n.rejected);
  if (n.jacobians > 0) t += fmt::format(", {} Jacobians", n.jacobians);
  if (n.factorisations > 0) t += fmt::format(", {} factorisations", n.factorisations);
  return t;
}

namespace {

Json null_if_negative(double x) { return x >= 0 ? Json(x) : Json(nullptr); }
Json name_or_null(const std::string& s) { return s.empty() ? Json(nullptr) : Json(s); }

Json point_counts(const SceneWork& w, std::ptrdiff_t i) { return i < 0 ? Json(nullptr) : counts_json(w.points[i].counts()); }

}  // namespace

namespace {

constexpr StudyParam<WorkPrecisionConfig> kWorkPrecisionParams[] = {
    {"points", "fixed-step methods: steps in each scene's dt sweep", {3, 100}, &WorkPrecisionConfig::points},
    {"stiffnesses", "comma-separated k2 of the stiffness sweep (the chain's k1 is 5)", kPositive, &WorkPrecisionConfig::stiffnesses},
};

}  // namespace

std::span<const StudyParam<WorkPrecisionConfig>> work_precision_params() { return kWorkPrecisionParams; }

Json work_precision_json(const WorkPrecisionResult& r) {
  const WorkPrecisionConfig& c = r.config;
  Json j;
  j["schema"] = schema::work_precision;
  j["params"] = {{"t_end", c.t_end},          {"sweep_t_end", c.sweep_t_end},   {"points", c.points},
                 {"tolerances", c.tolerances}, {"error_levels", c.error_levels}, {"stiffnesses", c.stiffnesses},
                 {"crossover_error", c.crossover_error}, {"timing", c.timing}, {"adaptive_solvers", c.adaptive}};
  j["peer_builds"] = peer_builds_json();
  Json scenes = Json::array();
  for (const SceneWork& w : r.scenes) {
    Json s;
    s["scene"] = scene_name(w.scene);
    s["params"] = scene_params_json(w.scene, w.params);
    Json pts = Json::array();
    for (const WorkPoint& p : w.points) {
      Json point = {{"method", p.method},
                    {"adaptive", p.adaptive},
                    {p.adaptive ? "tolerance" : "dt", p.setting},
                    {"status", to_string(p.status)},
                    {"error_max", std::isfinite(p.error) ? Json(p.error) : Json(nullptr)}};
      point.update(counts_json(p.counts()));
      point["seconds"] = null_if_negative(p.seconds);
      point["seconds_spread"] = p.seconds >= 0 ? Json(p.spread) : Json(nullptr);
      pts.push_back(std::move(point));
    }
    s["points"] = std::move(pts);
    Json cheapest = Json::array();
    for (const Cheapest& ch : w.cheapest)
      cheapest.push_back({{"error_level", ch.error_level},
                          {"by_time", name_or_null(ch.by_time)},
                          {"seconds", null_if_negative(ch.seconds)},
                          {"by_time_counts", point_counts(w, ch.time_point)},
                          {"by_forces", name_or_null(ch.by_forces)},
                          {"forces", ch.by_forces.empty() ? Json(nullptr) : Json(ch.forces)},
                          {"by_forces_counts", point_counts(w, ch.forces_point)}});
    s["cheapest"] = std::move(cheapest);
    scenes.push_back(std::move(s));
  }
  j["scenes"] = std::move(scenes);
  Json limits = Json::array();
  for (const StableStep& l : r.limits)
    limits.push_back({{"method", l.method},
                      {"largest_stable_dt", l.largest_stable_dt},
                      {"next_tried_dt", std::isfinite(l.next_tried_dt) ? Json(l.next_tried_dt) : Json()},
                      {"accuracy_dt", null_if_negative(l.accuracy_dt)}});
  j["chain_step_limits"] = std::move(limits);
  Json rows = Json::array();
  for (const StiffnessRow& s : r.stiffness)
    rows.push_back({{"stiffness2", s.stiffness2},
                    {"ratio", s.ratio},
                    {"best_explicit", name_or_null(s.best_explicit)},
                    {"explicit_seconds", null_if_negative(s.explicit_seconds)},
                    {"explicit_forces", s.explicit_forces},
                    {"best_implicit", name_or_null(s.best_implicit)},
                    {"implicit_seconds", null_if_negative(s.implicit_seconds)},
                    {"implicit_forces", s.implicit_forces}});
  j["stiffness_sweep"] = std::move(rows);
  j["crossover_ratio"] = null_if_negative(r.crossover_ratio);
  return j;
}

std::string work_precision_table(const WorkPrecisionResult& r) {
  const bool timed = r.config.timing;
  std::string out;
  for (const SceneWork& w : r.scenes) {
    out += fmt::format("Cheapest run with its largest error at most the level, {} (t_end {}):\n", scene_name(w.scene),
                       r.config.t_end);
    out += fmt::format("{:>8}  {:<64} {}\n", "error", timed ? "by run time (minimum of repeats)" : "", "by force evaluations");
    for (const Cheapest& ch : w.cheapest)
      out += fmt::format("{:>8.0e}  {:<64} {}\n", ch.error_level,
                         ch.by_time.empty() ? (timed ? "none" : "")
                                            : fmt::format("{} {:.3g} s ({})", ch.by_time, ch.seconds, counts_text(w.points[ch.time_point].counts())),
                         ch.by_forces.empty() ? "none"
                                                   : fmt::format("{} {} ({})", ch.by_forces, ch.forces,
                                                                 counts_text(w.points[ch.forces_point].counts())));
    out += "\n";
  }
  out += fmt::format(
      "Chain: largest stable step of each explicit method, and the step at which it reaches error {:.0e} on the slow mode\n"
      "alone (the masses moving as one), which is what accuracy alone would ask:\n",
      kLimitErrorLevel);
  for (const StableStep& l : r.limits)
    out += l.accuracy_dt < 0
               ? fmt::format("  {:<18} stable to {:<10.3g} accuracy alone: below the sweep's smallest step\n", l.method,
                             l.largest_stable_dt)
               : fmt::format("  {:<18} stable to {:<10.3g} accuracy alone {:<10.3g} ({:.3g}x the stable step)\n", l.method,
                             l.largest_stable_dt, l.accuracy_dt, l.accuracy_dt / l.largest_stable_dt);
  out += fmt::format("\nStiffness sweep (chain, t_end {}): cheapest run reaching error {:.0e}, {}\n", r.config.sweep_t_end,
                     r.config.crossover_error, timed ? "by run time" : "by force evaluations");
  for (const StiffnessRow& s : r.stiffness)
    out += fmt::format("  k2 {:<8g} k2/k1 {:<8g} explicit {:<18} {:<10}  implicit {:<18} {}\n", s.stiffness2, s.ratio,
                       s.best_explicit, timed ? fmt::format("{:.3g} s", s.explicit_seconds) : std::to_string(s.explicit_forces),
                       s.best_implicit, timed ? fmt::format("{:.3g} s", s.implicit_seconds) : std::to_string(s.implicit_forces));
  out += r.crossover_ratio > 0
             ? fmt::format("From k2/k1 = {:g} on, an implicit method is cheaper than every explicit one at error {:.0e}.\n",
                           r.crossover_ratio, r.config.crossover_error)
             : "No stiffness of the sweep makes an implicit method cheaper than every explicit one.\n";
  return out;
}

namespace {

struct WorkPrecisionArgs : StudyArgs {
  bool no_timing = false;  // cost by evaluations only: reproducible byte for byte
};

CLI::App* add_work_precision(CLI::App* study, WorkPrecisionArgs& a) {
  CLI::App* cmd = study->add_subcommand("work-precision", "cost against error on the spring and the stiff chain; "
                                                          "cheapest method per error level; stiffness crossover");
  cmd->add_option("--methods", a.methods,
                  fmt::format("comma-separated methods and adaptive solvers ({}; default every numerical method, and every "
                              "adaptive solver where the list names none)", fmt::join(peer_names(PeerScenes::FixedSize), ", ")));
  add_params(cmd, work_precision_params(), a.params, WorkPrecisionConfig{});
  add_threads_option(cmd, a.threads, "worker threads for the error runs (timings run one at a time)");
  add_lanes_option(cmd, a.lanes);
  add_shard_option(cmd, a.shard);
  cmd->add_flag("--no-timing", a.no_timing, "cost by force evaluations only (reproducible byte for byte)");
  cmd->add_option("--json", a.json, fmt::format("write JSON (schema {}) to this file", schema::work_precision));
  return cmd;
}

int run_work_precision(WorkPrecisionArgs& a, Context& ctx) {
  WorkPrecisionConfig c;
  Solvers solvers = resolve_solvers(a.methods, adaptive_solvers(), "spring and chain", false);
  c.methods = std::move(solvers.methods);
  c.adaptive = std::move(solvers.adaptive);
  read_params(work_precision_params(), a.params, c);
  c.workers = ctx.workers(resolve_thread_count(a.threads));
  resolve_lanes(a.lanes);  // checked; the work-precision runs go one at a time
  c.timing = !a.no_timing;
  return run_study(ctx, a, c.timing, [&] { return work_precision_study(c); }, work_precision_table, work_precision_json);
}

}  // namespace

StudyCommand work_precision_command(CLI::App* study) { return study_command(study, add_work_precision, run_work_precision); }

}  // namespace steplab
