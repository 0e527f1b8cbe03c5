// The report's parameters: every study's settings, with defaults embedded here. A JSON file
// (`steplab report --config FILE`) overrides any of them; `steplab report --print-config`
// prints the defaults in that format. Unknown keys, wrong types and values out of range are
// refused with a UsageError naming the key.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/studies/collision.hpp"
#include "analysis/studies/convergence.hpp"
#include "analysis/studies/defaults.hpp"
#include "analysis/studies/stability.hpp"
#include "analysis/studies/work_precision.hpp"

namespace steplab {

// A scene of the report and its parameter values, in its table's order.
struct ReportScene {
  std::size_t scene;
  std::vector<double> params;
};

// The sizes the report refines a scene of run-time size to (its size parameter's values).
struct ReportSizes {
  std::size_t scene;
  std::vector<int> sizes;
};

struct ReportConfig {
  // What the report covers: methods (table indices, in the table's order; the exact flow may be
  // one), scenes (table indices, in the table's order) and sections (names, in the report's
  // order). Default: every method, the report's own scenes (own_scenes()), the full report's
  // sections. A section that needs a scene not covered is left out with one line saying so.
  std::vector<std::size_t> methods;
  std::vector<std::size_t> covered;
  std::vector<std::string> sections;
  bool covers(std::size_t scene) const;
  bool has_section(std::string_view name) const;
  // The exercise's hand-in (`--sheet`, known by its own question section "stable"): its PDF shows
  // every section whole, where the full report's hand-out leaves some to the atlas.
  bool hand_in() const { return has_section("stable"); }
  // The report's own scenes: the four below, the stiffened one and the scaling ones. (The cost section's stiff chain
  // is its own contrast to the spring, not a scene of the report.)
  std::vector<std::size_t> own_scenes() const;
  // Convergence: the covered scenes below that have an exact solution, in that order, then each
  // covered scene that is not one of the report's own (a user's: against its exact solution or,
  // without one, a reference solution) and not of run-time size, in the table's order.
  std::vector<std::size_t> convergence_scenes() const;
  // The report's scenes (analysis/studies/defaults.hpp): the sheet's damped spring (the stability study's
  // oscillator) and cannon ball, and the collision study's rebound scene and contact body. The
  // config file keys each by its scene's name.
  ReportScene oscillator, projectile, rebound, body;
  std::array<const ReportScene*, 4> scenes() const { return {&oscillator, &projectile, &rebound, &body}; }
  std::array<ReportScene*, 4> scenes() { return {&oscillator, &projectile, &rebound, &body}; }
  double damping() const;  // the oscillator's damping parameter
  // convergence (every scene with an exact solution): its step sweep (convergence_params())
  ConvergenceConfig convergence;
  // work-precision (spring and chain): its dt sweep points and the stiffness sweep's k2
  // (work_precision_params()); whether the report's runs are timed (else costed by counts alone,
  // reproducible byte for byte), keyed in the configuration beside them
  WorkPrecisionConfig work_precision;
  bool timing = true;
  // stability (spring): its thresholds' dampings, the damping sweep's steps and the map
  // (stability_params()); the report's study runs on the oscillator's parameters
  StabilityConfig stability;
  // the sheet's two stability tests: a large step (with the spring's damping), and no damping,
  // keyed in the configuration beside them
  double large_dt = 0.05, small_dt = 0.01;
  // collision: its steps and time (collision_params())
  CollisionConfig collision;
  // as the system grows: every scene of run-time size with modes, its defaults at these sizes
  std::vector<ReportSizes> scaling;
  double scaling_error = 1e-4, scaling_t_end = 2;
  // the crossover map, on the first of them at these sizes: its default stiffness times each
  // factor, at scaling_error and at the visual target, this fraction of the body's extent
  std::vector<int> scaling_map_sizes{8, 32, 128};
  std::vector<double> scaling_stiffening{1, 10, 100, 1000};
  double scaling_visual = 0.01;
  // does the order hold when stiff: the scene swept (its parameters but the stiffness) and the sweep
  ReportScene stiffened;
  StiffOrderDefaults stiff_order;
  // stable for how long: the orbit and the swinging spring, this many periods (analysis/studies/defaults.hpp)
  double long_time_periods = kLongTimeReportPeriods;
  // figures
  double cannonball_dt = 0.25, cannonball_t_end = 17.5;
  std::vector<double> spring_figure_dts{0.01, 0.05};
  double spring_figure_t_end = 10, energy_t_end = 100;
  unsigned threads = 0;
};

// The crossover map's searches try no step that needs more steps than this: at the stiffest cells
// the methods that are not A-stable pay their stable step N^2 (steps ~ N, each ~ N), and a row
// beyond it is "not reached", which the map reads as it reads any other (`make report` stays
// within a minute; `study scaling` goes to 2 000 000).
inline constexpr long long kReportMapSteps = 200'000;

ReportConfig default_report_config();
// The exercise's hand-in (`steplab report --sheet`): the sheet's four methods and the analytic
// solution (analysis/studies/defaults.hpp) on its two scenes, in the hand-in's sections.
ReportConfig sheet_report_config();
nlohmann::ordered_json report_config_json(const ReportConfig& c);
// `base` overridden by the keys of `user`; UsageError("config: ...") for anything wrong.
ReportConfig report_config_from_json(const nlohmann::ordered_json& user, const ReportConfig& base = default_report_config());
ReportConfig read_report_config(const std::string& path, const ReportConfig& base = default_report_config());
// `c` with its methods, scenes or sections chosen by name (`what` names the option in messages);
// UsageError for an unknown or repeated name, an empty list, or methods without a numerical one.
void choose_methods(ReportConfig& c, const std::vector<std::string>& names, const std::string& what);
void choose_scenes(ReportConfig& c, const std::vector<std::string>& names, const std::string& what);
void choose_sections(ReportConfig& c, const std::vector<std::string>& names, const std::string& what);
// UsageError if a chosen method runs on none of the chosen scenes (the exact flow on scenes
// without an exact solution).
void check_choice(const ReportConfig& c, const std::string& what);

}  // namespace steplab
