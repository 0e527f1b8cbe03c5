// The commands that reproduce every number of the report.
#include <utility>

#include <fmt/format.h>

#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"

namespace steplab {
namespace {

class Reproduce : public Section {
 public:
  std::string markdown(Page& page) const override {
    const ReportConfig& c = page.data.config;
    std::string md = "## Reproduce\n\n```sh\n";
    md += "build/steplab report --config data/config.json   # this whole report\n";
    for (const ConvergenceResult& r : page.data.convergence)
      md += wrapped(fmt::format("build/steplab study convergence --scene {} --dt-max {} --dt-min {} --points {} --t-end {}",
                                scene_name(r.config.scene), c.conv_dt_max, c.conv_dt_min, c.conv_points, c.conv_t_end));
    md += wrapped(fmt::format("build/steplab study stability --threshold-dampings {} --map-dt-points {} --map-damping-points {} "
                              "--map-dt-min {} --map-dt-max {}", join(c.threshold_dampings), c.map_dt_points,
                              c.map_damping_points, c.map_dt_min, c.map_dt_max));
    md += wrapped(fmt::format("build/steplab study damping --dts {}", join(c.sweep_dts)));
    md += wrapped(fmt::format("build/steplab study collision --dts {} --t-end {} --triangle-dt {}", join(c.collision_dts),
                              c.collision_t_end, c.triangle_dt));
    md += wrapped(fmt::format("build/steplab study work-precision --points {} --stiffnesses {}{}", c.wp_points,
                              join(c.wp_stiffnesses), c.timing ? "" : " --no-timing"));
    for (const ReportSizes& s : c.scaling)
      md += wrapped(fmt::format("build/steplab study scaling --scene {} --sizes {} --error {} --t-end {}{}", scene_name(s.scene),
                                join(s.sizes), c.scaling_error, c.scaling_t_end, c.timing ? "" : " --no-timing"));
    md += "```\n\n";
    md += "(with the scene parameters above as `--mass`, `--stiffness`, ... where they differ from the defaults). The data of "
          "every study is in `data/`.\n\n";
    return md;
  }
};

}  // namespace

std::unique_ptr<Section> make_reproduce_section() { return std::make_unique<Reproduce>(); }

}  // namespace steplab
