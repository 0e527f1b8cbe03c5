// The report's configuration with small studies, for the tests of reports/document/.
#pragma once

#include <stdexcept>
#include <string_view>
#include <vector>

#include "analysis/kernel/kernel.hpp"
#include "reports/document/report.hpp"
#include "reports/document/report_config.hpp"

namespace steplab {

// The report's sizes for a scene of run-time size.
inline std::vector<int>& sizes_of(ReportConfig& c, std::string_view scene) {
  for (ReportSizes& s : c.scaling)
    if (scene_name(s.scene) == scene) return s.sizes;
  throw std::logic_error("no sizes for that scene");
}

// Small studies, so the whole pipeline runs in about a second.
inline ReportConfig small_config() {
  ReportConfig c = default_report_config();
  c.convergence.points = 8;
  c.convergence.dt_min = 1e-3;
  c.timing = false;
  c.work_precision.points = 4;
  c.work_precision.stiffnesses = {5, 5e4};
  c.stability.map_dt_points = 6;
  c.stability.map_damping_points = 4;
  c.collision.dts = {0.002};
  c.collision.t_end = 2;
  c.energy_t_end = 10;
  c.cannonball_t_end = 5;
  sizes_of(c, "rope") = {4, 8};
  sizes_of(c, "softbody") = {2, 3};
  c.scaling_map_sizes = {4, 8};
  c.scaling_stiffening = {1, 1000};
  c.long_time_periods = 100;
  return c;
}

// The report's Markdown for `c`, its figures named as PNG, no source link.
inline std::string markdown(const ReportConfig& c) { return report_markdown(build_report(c), "png", ""); }

}  // namespace steplab
