// `steplab study collision`: the bounce and the falling triangle on the penalty ground, each
// method's energy at each bounce and its depth (analysis/studies/collision.hpp). Its command, its
// parameters, its table on stdout and its JSON (steplab.collision/2) with --json.
#include "reports/studies/studies.hpp"

#include <cmath>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/collision.hpp"
#include "analysis/studies/defaults.hpp"
#include "reports/data/inputs.hpp"
#include "reports/data/run_json.hpp"
#include "reports/data/study_command.hpp"

namespace steplab {
namespace {

Json collision_run_json(const CollisionRun& run, bool bounce) {
  Json j;
  j["method"] = method_info(run.method).name;
  j["dt"] = run.dt;
  j["status"] = to_string(run.status);
  j["diverged_at"] = run.status == RunStatus::Ok ? Json(nullptr) : Json{{"step", run.failed_step}, {"t", run.failed_t}};
  j["energy_ratio_final"] = finite_or_null(run.energy_ratio_final);
  j["energy_ratio_max"] = finite_or_null(run.energy_ratio_max);
  j["max_penetration"] = finite_or_null(run.max_penetration);
  if (bounce) {
    Json b = Json::array();
    for (const BounceEvent& e : run.bounces)
      b.push_back({{"t", e.t}, {"energy_ratio", finite_or_null(e.energy_ratio)}, {"rebound_height", finite_or_null(e.rebound_height)}});
    j["bounces"] = std::move(b);
    j["energy_ratio_last_bounce"] = run.bounces.empty() ? Json(nullptr) : finite_or_null(run.bounces.back().energy_ratio);
  } else {
    Json p = Json::array();
    for (const auto& s : run.path) p.push_back({{"t", s.t}, {"x", vec_json<6>(s.x)}, {"energy", finite_or_null(s.energy)}});
    j["path"] = std::move(p);
  }
  return j;
}

}  // namespace

Json collision_json(const CollisionResult& r) {
  const CollisionConfig& c = r.config;
  Json j;
  j["schema"] = schema::collision;
  j["params"] = {{scene_name(c.rebound_scene), scene_params_json(c.rebound_scene, c.rebound_params)},
                 {scene_name(c.body_scene), scene_params_json(c.body_scene, c.body_params)},
                 {"t_end", c.t_end},
                 {"triangle_dt", c.triangle_dt}};
  Json b = Json::array(), t = Json::array();
  for (const CollisionRun& run : r.bounce) b.push_back(collision_run_json(run, true));
  for (const CollisionRun& run : r.triangle) t.push_back(collision_run_json(run, false));
  j["bounce"] = std::move(b);
  j["triangle"] = std::move(t);
  Json ref = Json::array();
  for (const CollisionRun& run : r.triangle_reference) {
    Json e = collision_run_json(run, false);
    e.erase("path");
    ref.push_back(std::move(e));
  }
  j["triangle_reference"] = std::move(ref);
  return j;
}

std::string collision_table(const CollisionResult& r) {
  std::string out = fmt::format("Undamped bounce over {} s: energy ratio E/E0 after the first and last bounce\n\n"
                                "{:<18} {:>7} {:>8} {:>11} {:>11} {:>11} {:>12} {:>10}\n",
                                r.config.t_end, "method", "dt", "bounces", "E/E0 first", "E/E0 last", "max E/E0",
                                "last apex", "max depth");
  for (const CollisionRun& run : r.bounce) {
    const bool any = !run.bounces.empty();
    double rebound = NAN;  // the last completed apex
    for (const BounceEvent& e : run.bounces)
      if (std::isfinite(e.rebound_height)) rebound = e.rebound_height;
    out += fmt::format("{:<18} {:>7g} {:>8} {:>11.6f} {:>11.6f} {:>11.6f} {:>12.5f} {:>10.5f}{}\n", method_info(run.method).name,
                       run.dt, run.bounces.size(), any ? run.bounces.front().energy_ratio : NAN,
                       any ? run.bounces.back().energy_ratio : NAN, run.energy_ratio_max,
                       rebound, run.max_penetration,
                       run.status == RunStatus::Ok ? "" : fmt::format("  {} at step {}", to_string(run.status), run.failed_step));
  }
  out += fmt::format("\nFalling triangle over {} s at dt {}\n\n{:<18} {:>16} {:>11} {:>11} {:>10}\n", r.config.t_end,
                     r.config.triangle_dt, "method", "status", "E/E0 end", "max E/E0", "max depth");
  for (const CollisionRun& run : r.triangle)
    out += fmt::format("{:<18} {:>16} {:>11.5f} {:>11.5f} {:>10.5f}\n", method_info(run.method).name,
                       run.status == RunStatus::Ok ? "ok" : fmt::format("{} @{}", to_string(run.status), run.failed_step),
                       run.energy_ratio_final, run.energy_ratio_max, run.max_penetration);
  for (const CollisionRun& run : r.triangle_reference)  // the reference: RK4 at small steps
    out += fmt::format("{:<18} {:>16} {:>11.5f} {:>11.5f} {:>10.5f}\n", fmt::format("rk4 at {:g}", run.dt),
                       run.status == RunStatus::Ok ? "reference" : to_string(run.status), run.energy_ratio_final,
                       run.energy_ratio_max, run.max_penetration);
  return out;
}

namespace {

constexpr StudyParam<CollisionConfig> kCollisionParams[] = {
    {"dts", "steps for the bounce", kPositive, &CollisionConfig::dts},
    {"t-end", "simulated time", kPositive, &CollisionConfig::t_end},
    {"triangle-dt", "step for the falling triangle", kPositive, &CollisionConfig::triangle_dt},
};

}  // namespace

std::span<const StudyParam<CollisionConfig>> collision_params() { return kCollisionParams; }

void check_collision(const CollisionConfig& c) {
  for (double dt : c.dts) step_count(c.t_end, dt);
  step_count(c.t_end, c.triangle_dt);
  for (double dt : c.reference_dts) step_count(c.t_end, dt);
}

namespace {

// Its scene parameters: the bounce's and the triangle's (ground, mass, gravity), each given to
// the scenes that have it.
struct CollisionArgs : StudyArgs {};

// The collision study's scenes: the rebound scene and the contact body (analysis/studies/defaults.hpp).
bool collision_scene(const SceneKernel& s) { return s.name == kReboundScene || s.name == kContactBodyScene; }

int run_collision(CollisionArgs& a, Context& ctx) {
  CollisionConfig c;
  // A parameter given applies to each scene that has it (--ground-stiffness to both, --stiffness
  // to the triangle's springs).
  const auto values_for = [&](std::string_view scene) {
    SceneArgs only = a.scene;
    only.scene = std::string(scene);
    const std::size_t index = only.scene_index();
    for (auto& [name, text] : only.text)
      if (!has_param(index, name)) text.clear();
    only.app = nullptr;
    return only.values(index);
  };
  const std::size_t bounce = c.rebound_scene, body = c.body_scene;
  std::string accepted;  // the parameters of either collision scene
  for (const auto& [name, text] : a.scene.text)
    if (has_param(bounce, name) || has_param(body, name)) accepted += (accepted.empty() ? "--" : ", --") + name;
  for (const auto& [name, text] : a.scene.text)
    if (a.scene.given(name) && !has_param(bounce, name) && !has_param(body, name))
      throw UsageError(fmt::format("--{} does not apply to the collision scenes; accepted: {}", name, accepted));
  c.rebound_params = values_for(scene_name(bounce));
  c.body_params = values_for(scene_name(body));
  c.methods = resolve_methods(a.methods, false);
  read_params(collision_params(), a.params, c);
  check_collision(c);
  c.workers = ctx.workers(resolve_thread_count(a.threads));
  return run_study(ctx, a, false, [&] { return collision_study(c); }, collision_table, collision_json);
}

CLI::App* add_collision(CLI::App* study, CollisionArgs& a) {
  CLI::App* cmd = study->add_subcommand("collision", "the bounce and the falling triangle on the penalty ground");
  a.scene.add_to(cmd, collision_scene, false);
  cmd->add_option("--methods", a.methods, "comma-separated methods (default every numerical method)");
  add_params(cmd, collision_params(), a.params, CollisionConfig{});
  add_threads_option(cmd, a.threads);
  a.add_shard_and_json(cmd, schema::collision);
  return cmd;
}

}  // namespace

StudyCommand collision_command(CLI::App* study) { return study_command(study, add_collision, run_collision); }

}  // namespace steplab
