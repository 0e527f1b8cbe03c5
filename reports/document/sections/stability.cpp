// Stability on the spring: thresholds predicted and measured, the undamped energy at the large
// step, growth rates against damping, and the (dt, damping) maps grouped by family.
#include <cmath>

#include <fmt/format.h>

#include "analysis/kernel.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"
#include "reports/data/study_output.hpp"

namespace steplab {
namespace {

class Stability : public Section {
 public:
  std::string title() const override { return "Stability"; }
  unsigned needs() const override { return kStabilityStudy; }
  void write_data(const ReportData& d, const DataDir& dat) const override {
    dat.write("stability.json", stability_json(d.config.oscillator.params, d.thresholds, d.sweep, &d.map).dump(1) + "\n");
    for (std::size_t i = 0; i < d.methods.size(); ++i) {
      const std::string m = name(d.methods[i]);
      std::string s = "# t energy_ratio\n";
      const double e0 = d.energy[i].samples.empty() ? 1 : d.energy[i].samples.front().energy;
      for (const auto& p : d.energy[i].samples) s += num(p.t) + " " + num(p.energy / e0) + "\n";
      dat.write("energy_" + m + ".dat", s);
      s = "# damping rate_measured\n";
      for (const SweepRow& r : d.sweep)
        if (r.method == d.methods[i] && r.dt == d.config.large_dt) s += num(r.damping) + " " + num(r.run.rate) + "\n";
      dat.write("sweep_" + m + ".dat", s);
      s = "# damping rate_predicted\n";
      for (std::size_t g = 0; g < d.curve_damping.size(); ++g) s += num(d.curve_damping[g]) + " " + num(d.curve_rate[i][g]) + "\n";
      dat.write("predicted_" + m + ".dat", s);
      s = "# dt damping stable\n";
      for (std::size_t g = 0; g < d.map.damping.size(); ++g)
        for (std::size_t k = 0; k < d.map.dt.size(); ++k)
          s += num(d.map.dt[k]) + " " + num(d.map.damping[g]) + " " + (d.map.stable[i][g][k] ? "1" : "0") + "\n";
      dat.write("map_" + m + ".dat", s);
      s = "# dt* damping\n";
      for (std::size_t g = 0; g < d.map.damping.size(); ++g) {
        const double b = d.map.boundary[i][g];
        if (b > 0 && std::isfinite(b)) s += num(std::min(b, d.map.dt.back())) + " " + num(d.map.damping[g]) + "\n";
      }
      dat.write("boundary_" + m + ".dat", s);
    }
  }

  std::vector<FigureSpec> figures(const ReportData& d) const override {
    const std::vector<Panel> families = family_panels(d.methods);
    return {{"fig4_energy", "", families}, {"fig5_damping", "", families}, {"fig6_maps", "", families}};
  }

  std::string markdown(Page& page) const override {
    const ReportData& d = page.data;
    const ReportConfig& c = d.config;
    std::string md = "## " + title() + "\n\n";
    md += "dt*: the largest step with every smaller step stable. Where a method is stable again beyond dt* (its stable set "
          "is not an interval), the last column says from where.\n\n"
          "| method | damping | dt* predicted | dt* measured | stable again from (predicted / measured) |\n|---|---:|---:|---:|---:|\n";
    for (const ThresholdRow& r : d.thresholds)
      md += fmt::format("| `{}` | {} | {} | {} | {} |\n", name(r.method), r.damping, dt_text(r.dt_theory), dt_text(r.dt_measured),
                        std::isinf(r.again_theory) && std::isinf(r.again_measured)
                            ? "-"
                            : dt_text(r.again_theory) + " / " + dt_text(r.again_measured));
    md += "\n";
    std::string ended;
    for (std::size_t i = 0; i < d.energy.size(); ++i)
      if (d.energy[i].status != RunStatus::Ok)
        ended += fmt::format("{}`{}` at t = {:g}", ended.empty() ? "" : ", ", name(d.methods[i]), d.energy[i].failed_t);
    const int energy_fig = page.next_figure();
    md += page.figure("fig4_energy", fmt::format("energy ratio E/E0 against time without damping at dt {} (log scale), a panel per family", c.large_dt));
    if (!ended.empty()) md += fmt::format("In figure {} the curves of runs that diverged end where they did: {}.\n\n", energy_fig, ended);
    md += page.figure("fig5_damping", fmt::format("energy growth rate against damping at dt {}: measured (points), predicted "
                                                  "2 ln(rho)/h (lines), a panel per family", c.large_dt));
    md += page.figure("fig6_maps", "measured stable (dark) and unstable (light) steps over (dt, damping), one row per family; "
                                   "predicted dt* (line). Cells that disagree with the prediction at that cell: see `data/stability.json`");
    std::size_t disagree = 0;
    for (std::size_t i = 0; i < d.map.methods.size(); ++i) disagree += disagreeing_cells(d.map, i);
    const std::size_t cells = d.map.methods.size() * d.map.damping.size() * d.map.dt.size();
    md += fmt::format("Of the map's {} cells, {} disagree with the step matrix's prediction at that cell.\n\n", cells, disagree);
    return md;
  }
};

}  // namespace

std::unique_ptr<Section> make_stability_section() { return std::make_unique<Stability>(); }

}  // namespace steplab
