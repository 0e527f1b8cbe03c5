// The collision study: its parameters, JSON and table (`study collision`).
#include "reports/data/studies.hpp"

#include <cmath>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "reports/data/run_json.hpp"

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

}  // namespace steplab
