#include "reports/data/studies.hpp"

#include <cmath>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/peers/peers.hpp"
#include "core/scenes/spring.hpp"
#include "reports/data/run_json.hpp"

namespace steplab {

Json scene_params_json(std::size_t scene, const std::vector<double>& values) {
  return params_json(scene_kernel(scene).params, values);
}

Json peer_builds_json() {
  Json out = Json::array();
  for (const PeerBuild& b : peer_builds())
    out.push_back({{"library", b.library}, {"version", b.version}, {"optimised", b.optimised}, {"flags", b.flags}});
  return out;
}

}  // namespace steplab

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

}  // namespace steplab

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
