// The scenes: cannon ball paths and the spring's y(t) per method beside the exact solutions.
#include <fmt/format.h>

#include "analysis/kernel.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"

namespace steplab {
namespace {

class SceneFigures : public Section {
 public:
  std::string title() const override { return "The scenes"; }
  unsigned needs() const override { return kSceneFigures; }
  void write_data(const ReportData& d, const DataDir& dat) const override {
    const ReportConfig& c = d.config;
    for (std::size_t i = 0; i < d.methods.size(); ++i) {
      const std::string m = name(d.methods[i]);
      std::string s = "# x y\n";
      if (c.covers(c.projectile.scene)) {
        for (const auto& p : d.cannon[i].samples) s += num(p.x[0]) + " " + num(p.x[1]) + "\n";
        dat.write("cannon_" + m + ".dat", s);
      }
      if (c.covers(c.oscillator.scene))
        for (std::size_t k = 0; k < d.spring.size(); ++k) {
          s = "# t y\n";
          for (const auto& p : d.spring[k][i].samples) s += num(p.t) + " " + num(p.x[0]) + "\n";
          dat.write(fmt::format("spring{}_{}.dat", k, m), s);
        }
    }
    std::string curve = "# x y\n";
    const ReportScene& projectile = c.projectile;
    if (c.covers(projectile.scene)) {
      for (int k = 0; k <= 400; ++k) {
        const AnyState y = scene_kernel(projectile.scene).exact(projectile.params, c.cannonball_t_end * k / 400.0);
        curve += num(y.x[0]) + " " + num(y.x[1]) + "\n";
      }
      dat.write("cannon_exact.dat", curve);
    }
    curve = "# t y\n";
    const ReportScene& spring = c.oscillator;
    if (c.covers(spring.scene)) {
      for (int k = 0; k <= 2000; ++k) {
        const double t = c.spring_figure_t_end * k / 2000.0;
        curve += num(t) + " " + num(scene_kernel(spring.scene).exact(spring.params, t).x[0]) + "\n";
      }
      dat.write("spring_exact.dat", curve);
    }
  }

  std::vector<FigureSpec> figures(const ReportData& d) const override {
    std::vector<FigureSpec> out;
    if (d.config.covers(d.config.projectile.scene)) out.push_back({"fig1_cannonball", "", family_panels(d.methods)});
    if (d.config.covers(d.config.oscillator.scene)) out.push_back({"fig2_spring", "", family_panels(d.methods)});
    return out;
  }

  std::string markdown(Page& page) const override {
    const ReportConfig& c = page.data.config;
    std::string md = "## " + title() + "\n\n";
    if (c.covers(c.projectile.scene))
      md += page.figure("fig1_cannonball", fmt::format("cannon ball paths at dt {} beside the exact parabola, a panel per family", c.cannonball_dt));
    if (c.covers(c.oscillator.scene))
      md += page.figure("fig2_spring", fmt::format("spring height y(t) per method against the exact solution (grey), a row per family, a column per dt: {}", words(c.spring_figure_dts)));
    return md;
  }
};

}  // namespace

std::unique_ptr<Section> make_scenes_section() { return std::make_unique<SceneFigures>(); }

}  // namespace steplab
