#include "reports/study_output.hpp"

#include <cmath>

#include <fmt/format.h>

#include "core/scenes.hpp"
#include "reports/run_json.hpp"

namespace steplab {
namespace {

// JSON has no infinity; a diverged run's error is null.
Json number_or_null(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

}  // namespace

Json scene_params_json(std::size_t scene, const std::vector<double>& values) {
  return with_scene(scene, [&]<class S>() { return params_json<S>(values); });
}

Json convergence_json(const ConvergenceResult& r) {
  const ConvergenceConfig& c = r.config;
  Json j;
  j["schema"] = "steplab.convergence/1";
  j["scene"] = scene_names[c.scene];
  Json p = scene_params_json(c.scene, c.params);
  p["t_end"] = c.t_end;
  p["dt_max"] = c.dt_max;
  p["dt_min"] = c.dt_min;
  p["points"] = c.points;
  p["fit_error"] = to_string(c.fit_error);
  j["params"] = std::move(p);
  Json results = Json::array();
  for (const ConvergenceRecord& rec : r.records) {
    Json e;
    e["method"] = method_infos[rec.method].name;
    e["dt"] = rec.dt;
    e["status"] = to_string(rec.status);
    e["steps"] = rec.steps;
    e["diverged_step"] = rec.failed_step >= 0 ? Json(rec.failed_step) : Json(nullptr);
    e["error_final"] = number_or_null(rec.error_final);
    e["error_velocity_final"] = number_or_null(rec.error_v_final);
    e["error_max"] = number_or_null(rec.error_max);
    e["error_rms"] = number_or_null(rec.error_rms);
    e["roundoff_floor"] = rec.floor;
    results.push_back(std::move(e));
  }
  j["results"] = std::move(results);
  Json fits = Json::array();
  for (const ConvergenceFit& f : r.fits) {
    const MethodInfo& info = method_infos[f.method];
    Json e;
    e["method"] = info.name;
    e["declared_order"] = info.exact_flow ? Json(nullptr) : Json(info.order);
    e["exact"] = f.fit.exact;
    if (f.fit.fitted) {
      e["order"] = f.fit.line.slope;
      e["ci95"] = {number_or_null(f.fit.line.ci95_lo), number_or_null(f.fit.line.ci95_hi)};
      e["r2"] = f.fit.line.r2;
      e["n_points"] = f.fit.line.n;
      e["dt_range"] = {f.fit.dt_lo, f.fit.dt_hi};
    } else {
      e["order"] = nullptr;
      e["ci95"] = nullptr;
      e["r2"] = nullptr;
      e["n_points"] = 0;
      e["dt_range"] = nullptr;
    }
    e["order_extrapolated"] = f.fit.fitted ? number_or_null(f.fit.extrapolated) : Json(nullptr);
    e["local_orders"] = f.fit.local_slopes;
    e["note"] = f.fit.note;
    fits.push_back(std::move(e));
  }
  j["fits"] = std::move(fits);
  return j;
}

std::string convergence_table(const ConvergenceResult& r) {
  const ConvergenceConfig& c = r.config;
  std::string out = fmt::format("Convergence on {}: t_end {}, {} steps from {:.3g} to {:.3g}; {} position error\n\n",
                                scene_names[c.scene], c.t_end, r.dts.size(), r.dts.front(), r.dts.back(),
                                to_string(c.fit_error));
  out += fmt::format("{:>10}", "dt");
  for (const auto& f : r.fits) out += fmt::format(" {:>18}", method_infos[f.method].name);
  out += "\n";
  for (std::size_t i = 0; i < r.dts.size(); ++i) {
    out += fmt::format("{:>10.4g}", r.dts[i]);
    for (std::size_t m = 0; m < r.fits.size(); ++m) {
      const ConvergenceRecord& rec = r.records[m * r.dts.size() + i];
      const double e = c.fit_error == ErrorKind::Final ? rec.error_final
                       : c.fit_error == ErrorKind::Max ? rec.error_max : rec.error_rms;
      out += rec.status != RunStatus::Ok ? fmt::format(" {:>18}", to_string(rec.status)) : fmt::format(" {:>18.5e}", e);
    }
    out += "\n";
  }
  out += fmt::format("\n{:<18} {:>8} {:>8} {:>20} {:>9} {:>6} {:>21} {:>12}\n", "method", "declared", "order",
                     "95% interval", "R^2", "points", "dt range", "extrapolated");
  for (const auto& f : r.fits) {
    const MethodInfo& info = method_infos[f.method];
    const std::string declared = info.exact_flow ? "exact" : std::to_string(info.order);
    if (f.fit.exact) {
      out += fmt::format("{:<18} {:>8} {:>8}   every error at the round-off floor\n", info.name, declared, "exact");
    } else if (!f.fit.fitted) {
      out += fmt::format("{:<18} {:>8} {:>8}   {}\n", info.name, declared, "-", f.fit.note);
    } else {
      const LineFit& l = f.fit.line;
      out += fmt::format("{:<18} {:>8} {:>8.4f} {:>20} {:>9.6f} {:>6} {:>21} {:>12.4f}\n", info.name, declared, l.slope,
                         fmt::format("[{:.4f}, {:.4f}]", l.ci95_lo, l.ci95_hi), l.r2, l.n,
                         fmt::format("{:.3g} .. {:.3g}", f.fit.dt_lo, f.fit.dt_hi), f.fit.extrapolated);
    }
  }
  return out;
}

}  // namespace steplab

namespace steplab {

std::string local_error_tables(const LocalErrorResult& r) {
  const auto header = [&](const char* first) {
    std::string h = fmt::format("{:>12} {:>12}", "step", first);
    for (const auto& c : r.columns) h += fmt::format(" {:>17}", method_infos[c.method].name);
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
    const MethodInfo& info = method_infos[c.method];
    if (c.order.exact) out += fmt::format("{:<18} exact (every error at the round-off floor)\n", info.name);
    else if (!c.order.fitted) out += fmt::format("{:<18} - ({})\n", info.name, c.order.note);
    else
      out += fmt::format("{:<18} {:.3f}  [{:.3f}, {:.3f}] over {} steps, expected {}\n", info.name, c.order.line.slope,
                         c.order.line.ci95_lo, c.order.line.ci95_hi, c.order.line.n, info.order + 1);
  }
  return out;
}

}  // namespace steplab
