#include <cmath>

#include <fmt/format.h>

#include "analysis/kernel.hpp"
#include "reports/data/study_output.hpp"

namespace steplab {

Json mode_stability_json(const ModeStabilityConfig& c, const std::vector<ModeThresholdRow>& rows) {
  Json j;
  j["schema"] = "steplab.rope_stability/1";
  j["scene"] = scene_name(c.scene);
  Json p = scene_params_json(c.scene, c.params);
  p["run_steps"] = c.steps;
  j["params"] = std::move(p);
  Json t = Json::array();
  for (const ModeThresholdRow& r : rows)
    t.push_back({{"method", method_info(r.method).name},
                 {"omega_max", r.omega_max},
                 {"dt_theory", threshold_json(r.dt_theory)},
                 {"binding_mode", r.binding_mode},
                 {"dt_measured", threshold_json(r.dt_measured)}});
  j["thresholds"] = std::move(t);
  return j;
}

std::string mode_thresholds_table(std::string_view scene, const std::vector<ModeThresholdRow>& rows) {
  std::string out = fmt::format(
      "Stability thresholds dt* of the {} (largest stable step; inf: stable at every step, 0: at none)\n"
      "predicted: the smallest dt* over its modes (each a damped spring); measured: runs of the whole {}\n\n"
      "{:<18} {:>12} {:>6} {:>12} {:>10} {:>14}\n",
      scene, scene, "method", "predicted", "mode", "measured", "rel. diff", "dt* omega_max");
  for (const ModeThresholdRow& r : rows) {
    const bool finite = std::isfinite(r.dt_theory) && r.dt_theory > 0;
    out += fmt::format("{:<18} {:>12} {:>6} {:>12} {:>10} {:>14}\n", method_info(r.method).name, threshold_text(r.dt_theory),
                       r.binding_mode == 0 ? std::string("-") : std::to_string(r.binding_mode), threshold_text(r.dt_measured),
                       finite ? fmt::format("{:+.1e}", r.dt_measured / r.dt_theory - 1) : "-",
                       finite ? fmt::format("{:.5f}", r.dt_theory * r.omega_max) : "-");
  }
  return out;
}

}  // namespace steplab
