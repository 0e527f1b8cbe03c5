// `study stability` on a scene that declares its modes (analysis/studies/mode_stability.hpp): its
// JSON (schema::mode_stability) and its table.
#include "reports/studies/studies.hpp"

#include <cmath>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/stability.hpp"

namespace steplab {

Json mode_stability_json(const ModeStabilityConfig& c, const std::vector<ModeThresholdRow>& rows) {
  Json j;
  j["schema"] = schema::mode_stability;
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

// Beyond this relative difference a measured dt* and its prediction are marked as disagreeing: the
// threshold search resolves dt* to far better than that (analysis/studies/mode_stability.hpp).
constexpr double kModeAgreement = 0.01;

std::string mode_thresholds_table(std::string_view scene, const std::vector<ModeThresholdRow>& rows) {
  std::string out = fmt::format(
      "Stability thresholds dt* of the {} (largest stable step; unbounded: stable at every step tried, 0: at none)\n"
      "predicted: the smallest dt* over its modes (each a damped spring); measured: runs of the whole {}\n\n"
      "{:<18} {:>12} {:>6} {:>12} {:>10} {:>14}\n",
      scene, scene, "method", "predicted", "mode", "measured", "rel. diff", "dt* omega_max");
  bool marked = false;
  for (const ModeThresholdRow& r : rows) {
    const bool finite = std::isfinite(r.dt_theory) && r.dt_theory > 0;
    const bool differ = finite ? std::abs(r.dt_measured / r.dt_theory - 1) > kModeAgreement : r.dt_measured != r.dt_theory;
    marked |= differ;
    out += fmt::format("{:<18} {:>12} {:>6} {:>12} {:>10} {:>14}{}\n", method_info(r.method).name, threshold_text(r.dt_theory),
                       r.binding_mode == 0 ? std::string("-") : std::to_string(r.binding_mode), threshold_text(r.dt_measured),
                       finite ? fmt::format("{:+.1e}", r.dt_measured / r.dt_theory - 1) : "-",
                       finite ? fmt::format("{:.5f}", r.dt_theory * r.omega_max) : "-", differ ? "  !" : "");
  }
  if (marked)
    out += fmt::format(
        "\n!: measured and predicted differ by more than {:g} %. The prediction is exact for the linearisation the scene's "
        "modes() declares. On a linear scene trust it: runs that show no growth were too short to see a barely excited "
        "mode grow. On a nonlinear one each answers its own question: the prediction is about small motions near the "
        "state the modes linearise, the measurement about the motion from the scene's start (unstable: its energy ends "
        "above its start where every mode is damped, grows faster than {:g}/s where not); a measured dt* above the "
        "prediction there is an instability that saturates below the start's energy (docs/studies.md, stability).\n",
        100 * kModeAgreement, kStableRate);
  return out;
}

}  // namespace steplab
