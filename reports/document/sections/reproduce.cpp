// The commands that reproduce every number of the report.
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "analysis/kernel/kernel.hpp"
#include "reports/document/report_text.hpp"
#include "analysis/studies/defaults.hpp"
#include "analysis/studies/frames.hpp"
#include "analysis/studies/dense_output.hpp"
#include "analysis/studies/long_time.hpp"
#include "reports/document/section.hpp"

namespace steplab {
namespace {

// "a,b,c": the methods' names, as --methods takes them; without the exact flow if `numerical`.
std::string comma_names(const std::vector<std::size_t>& methods, bool numerical) {
  std::string out;
  for (std::size_t m : methods)
    if (!(numerical && method_info(m).exact_flow)) {
      if (!out.empty()) out += ',';
      out += method_info(m).name;
    }
  return out;
}

// `var=a,b,c` as a shell assignment broken for the page: a backslash-newline inside a word is
// removed by the shell, so the broken lines assign the same list.
std::string assignment(const std::string& var, const std::string& list) {
  std::string out = var + "=", line;
  std::size_t start = 0;
  while (start < list.size()) {
    std::size_t next = list.find(',', start);
    next = next == std::string::npos ? list.size() : next + 1;
    if (line.size() + next - start > kCodeColumns - var.size()) out += line + "\\\n", line.clear();
    line += list.substr(start, next - start);
    start = next;
  }
  return out + line + "\n";
}

class Reproduce : public Section {
 public:
  std::string title() const override { return "Reproduce"; }
  std::string markdown(Page& page) const override {
    const ReportConfig& c = page.data.config;
    const ReportData& d = page.data;
    std::string md = "## " + title() + "\n\n```sh\n";
    md += "build/steplab report --config data/config.json   # this whole report\n";
    // Each study the report ran, on the report's methods (named once, in $M and $N without the
    // exact flow, where not all of them).
    const bool all = d.methods.size() == method_count();
    const std::string methods = all ? "" : " --methods $M", numerical = all ? "" : " --methods $N";
    if (!all) {  // M with the exact flow, N without: M as $N and it where it is last
      const std::string m = comma_names(d.methods, false), n = comma_names(d.methods, true);
      md += m.size() > n.size() && m.compare(0, n.size() + 1, n + ",") == 0 ? assignment("N", n) + "M=$N" + m.substr(n.size()) + "\n"
                                                                        : assignment("M", m) + assignment("N", n);
    }
    for (const ConvergenceResult& r : d.convergence)
      md += wrapped(fmt::format("build/steplab study convergence --scene {} --dt-max {} --dt-min {} --points {} --t-end {}{}",
                                scene_name(r.config.scene), c.convergence.dt_max, c.convergence.dt_min, c.convergence.points, c.convergence.t_end, methods));
    if (d.studies & kStabilityStudy) {
      md += wrapped(fmt::format("build/steplab study stability --threshold-dampings {} --map-dt-points {} --map-damping-points {} "
                                "--map-dt-min {} --map-dt-max {}{}", join(c.stability.threshold_dampings),
                                c.stability.map_dt_points, c.stability.map_damping_points, c.stability.map_dt_min,
                                c.stability.map_dt_max, methods));
      md += wrapped(fmt::format("build/steplab study damping --dts {}{}", join(c.stability.sweep_dts), methods));
    }
    if (d.studies & kCollisionStudy)
      md += wrapped(fmt::format("build/steplab study collision --dts {} --t-end {} --triangle-dt {}{}", join(c.collision.dts),
                                c.collision.t_end, c.collision.triangle_dt, numerical));
    if (d.studies & kWorkPrecisionStudy)
      md += wrapped(fmt::format("build/steplab study work-precision --points {} --stiffnesses {}{}{}", c.work_precision.points,
                                join(c.work_precision.stiffnesses), c.timing ? "" : " --no-timing", numerical));
    if (c.has_section("stiff_order") && c.covers(c.stiffened.scene))
      md += wrapped(fmt::format("build/steplab study convergence --scene {} --error max --dt-max {} --dt-min {} --points {} --t-end {} "
                                "--sweep {}={}{}", scene_name(c.stiffened.scene), c.stiff_order.dt_max, c.stiff_order.dt_min,
                                c.stiff_order.points, c.stiff_order.t_end,
                                scene_kernel(c.stiffened.scene).params[static_cast<std::size_t>(scene_kernel(c.stiffened.scene).stiffness_param)].name,
                                join(c.stiff_order.stiffnesses), numerical));
    if (c.has_section("scaling"))
      for (const ReportSizes& s : c.scaling)
        if (c.covers(s.scene))
          md += wrapped(fmt::format("build/steplab study scaling --scene {} --sizes {} --error {} --t-end {}{}{}", scene_name(s.scene),
                                    join(s.sizes), c.scaling_error, c.scaling_t_end, c.timing ? "" : " --no-timing", numerical));
    if (const auto& m = d.scaling_map; m && c.has_section("scaling")) {  // the map: its solvers named, the peers with them
      std::vector<std::string> solvers;  // the report's methods as $N where they are those
      if (!all && m->config.methods == d.numerical_methods()) solvers.emplace_back("$N");
      else
        for (std::size_t k : m->config.methods) solvers.emplace_back(method_info(k).name);
      solvers.insert(solvers.end(), m->config.adaptive.begin(), m->config.adaptive.end());
      std::string errors;
      for (const ErrorTarget& t : m->config.targets) errors += fmt::format("{}{:g}{}", errors.empty() ? "" : ",", t.of_extent ? 100 * t.value : t.value, t.of_extent ? "%" : "");
      md += assignment("S", fmt::format("{}", fmt::join(solvers, ",")));
      md += wrapped(fmt::format("build/steplab study scaling --scene {} --sizes {} --stiffness {} --error {} --t-end {} --max-steps {}{} --methods $S",
                                m->config.scene, join(m->config.sizes), join(m->config.stiffnesses), errors, m->config.t_end, m->config.max_steps,
                                c.timing ? "" : " --no-timing"));
    }
    // The studies that run the methods a scene takes: named where the report chose some.
    // The ODE methods (not the position-based ones, on springs only) once as $O where a list is theirs.
    std::vector<std::size_t> ode;
    for (std::size_t m : d.numerical_methods())
      if (in_ode_studies(m)) ode.push_back(m);
    bool named_ode = false;
    const auto on_scene = [&](const std::vector<std::size_t>& ms) {
      if (all) return std::string();
      if (ms == d.numerical_methods()) return std::string(" --methods $N");
      if (ms != ode) return " --methods " + comma_names(ms, true);
      if (!named_ode) md += assignment("O", comma_names(ode, true)), named_ode = true;
      return std::string(" --methods $O");
    };
    for (const LongTimeResult* r : {&d.long_time_orbit, &d.long_time_swing})
      if (!r->rows.empty())
        md += wrapped(fmt::format("build/steplab study long-time --scene {} --periods {:g}{}{}", scene_name(r->config.scene), r->config.periods,
                                  r->config.steps_per_period == default_long_time_config(r->config.scene).steps_per_period
                                      ? std::string()
                                      : " --steps-per-period " + join(r->config.steps_per_period),
                                  on_scene(r->config.methods)));
    if (const std::size_t spring = scene_index(kSheetOscillator); c.has_section("dense_output") && c.covers(spring))
      md += wrapped(fmt::format("build/steplab study dense-output --scene {}{}", kSheetOscillator,
                                on_scene(dense_output_methods(spring, d.numerical_methods()))));
    if (c.has_section("frames") && c.covers(scene_index(kFramesScene)))
      md += wrapped(fmt::format("build/steplab study frames{}", c.timing ? "" : " --no-timing"));  // its defaults: analysis/studies/defaults.hpp
    if (c.has_section("cloth") && c.covers(scene_index(kClothFramesScene))) {
      const FramesConfig f = cloth_frames_config();
      md += wrapped(fmt::format("build/steplab study frames --scene {} --t-end {:g} --reference-substeps {} --no-orders --no-timing",
                                kClothFramesScene, f.t_end, f.reference_substeps));  // the report's cloth: untimed (frames.cpp)
    }
    md += "```\n\n";
    md += "(The scene parameters above as `--mass`, `--stiffness`, ... where not the defaults; every study's data: `data/`.)\n\n";
    return md;
  }
};

}  // namespace

std::unique_ptr<Section> make_reproduce_section() { return std::make_unique<Reproduce>(); }

}  // namespace steplab
