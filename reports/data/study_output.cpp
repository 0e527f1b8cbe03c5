#include "reports/data/study_output.hpp"

#include <cmath>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/peers/peers.hpp"
#include "core/scenes/spring.hpp"
#include "reports/data/run_json.hpp"
#include "reports/data/schemas.hpp"

namespace steplab {
namespace {

// JSON has no infinity; a diverged run's error is null.
Json number_or_null(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

}  // namespace

Json fit_caveats(const OrderFit& f) {
  Json out = Json::array();
  if (f.fitted && f.few_points) out.push_back("few_points");
  if (f.fitted && f.non_monotone) out.push_back("non_monotone");
  if (f.fitted && f.wide) out.push_back("wide");
  return out;
}

Json scene_params_json(std::size_t scene, const std::vector<double>& values) {
  return params_json(scene_kernel(scene).params, values);
}

Json peer_builds_json() {
  Json out = Json::array();
  for (const PeerBuild& b : peer_builds())
    out.push_back({{"library", b.library}, {"version", b.version}, {"optimised", b.optimised}, {"flags", b.flags}});
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
    e["error_final"] = number_or_null(rec.error_final);
    e["error_velocity_final"] = number_or_null(rec.error_v_final);
    e["error_max"] = number_or_null(rec.error_max);
    e["error_rms"] = number_or_null(rec.error_rms);
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
      e["order_bound"] = {number_or_null(f.fit.bound_lo), number_or_null(f.fit.bound_hi)};
      e["correction_power"] = f.fit.correction_power;
      e["window_slope"] = f.fit.line.slope;
      e["window_ci95"] = {number_or_null(f.fit.line.ci95_lo), number_or_null(f.fit.line.ci95_hi)};
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
    e["order_extrapolated"] = f.fit.fitted ? number_or_null(f.fit.extrapolated) : Json(nullptr);
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
  bool few = false, non_monotone = false, wide = false;
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
      few = few || f.fit.few_points, non_monotone = non_monotone || f.fit.non_monotone, wide = wide || f.fit.wide;
      const std::string mark = std::string(f.fit.few_points ? " ~" : "") + (f.fit.non_monotone ? " *" : "") + (f.fit.wide ? " ?" : "");
      out += fmt::format("{:<18} {:>8} {:>8.4f} {:>20} {:>2} {:>7} {:>8.4f} {:>20} {:>9.6f} {:>6} {:>21}{}\n", info.name, declared,
                         f.fit.order, fmt::format("[{:.4f}, {:.4f}]", f.fit.bound_lo, f.fit.bound_hi), f.fit.correction_power,
                         std::isnan(f.fit.extrapolated) ? std::string("-") : fmt::format("{:.3f}", f.fit.extrapolated), l.slope,
                         fmt::format("[{:.4f}, {:.4f}]", l.ci95_lo, l.ci95_hi), l.r2, l.n,
                         fmt::format("{:.3g} .. {:.3g}", f.fit.dt_lo, f.fit.dt_hi), mark);
    }
  }
  out += "\nq: the next error term modelled (1 or 2); 0: fewer than 5 points, the plain slope and its interval stand in. "
         "aitken: the local orders' limit by Aitken's delta-squared (-: no converging trend). docs/studies.md, orders.\n";
  if (few) out += "~: fitted over fewer than 5 points: its interval comes from the plain slope, which the next error term biases; "
                  "it may miss the true order. More points (--points, --dt-min) make it a bound.\n";
  if (non_monotone) out += "*: the errors in its window do not approach their order monotonically (an error not below the one at the "
                           "next larger step, or local orders that turn down and up): the slope is not an order.\n";
  if (wide) out += "?: its bound is wider than +-0.5: not a finding.\n";
  if (skipped > 0) out += fmt::format("\n{} diverged runs (marked 'diverged' above) are left out of the fits.\n", skipped);
  return out;
}

}  // namespace steplab

namespace steplab {

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
                 {"rate_measured", number_or_null(r.run.rate)},
                 {"rate_theory", number_or_null(r.rate_theory)},
                 {"energy_ratio_final", number_or_null(r.run.energy_ratio_final)},
                 {"energy_ratio_max", number_or_null(r.run.energy_ratio_max)},
                 {"error_final", number_or_null(r.run.error_final)},
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
  j["energy_ratio_final"] = number_or_null(run.energy_ratio_final);
  j["energy_ratio_max"] = number_or_null(run.energy_ratio_max);
  j["max_penetration"] = number_or_null(run.max_penetration);
  if (bounce) {
    Json b = Json::array();
    for (const BounceEvent& e : run.bounces)
      b.push_back({{"t", e.t}, {"energy_ratio", number_or_null(e.energy_ratio)}, {"rebound_height", number_or_null(e.rebound_height)}});
    j["bounces"] = std::move(b);
  } else {
    Json p = Json::array();
    for (const auto& s : run.path) p.push_back({{"t", s.t}, {"x", vec_json<6>(s.x)}, {"energy", number_or_null(s.energy)}});
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
  return out;
}

}  // namespace steplab
