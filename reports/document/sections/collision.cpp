// Collision: the undamped bounce's energy per method and step, orders against the exact bounce,
// and the falling triangle.
#include <fmt/format.h>

#include "analysis/kernel.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"
#include "reports/data/study_output.hpp"

namespace steplab {
namespace {

class Collision : public Section {
 public:
  std::string title() const override { return "Collision"; }
  unsigned needs() const override { return kCollisionStudy | kConvergenceStudy; }
  void write_data(const ReportData& d, const DataDir& dat) const override {
    dat.write("collision.json", collision_json(d.collision).dump(1) + "\n");
    for (const CollisionRun& r : d.collision.triangle) {
      std::string s = "# t centre_y\n";
      for (const auto& p : r.path) s += num(p.t) + " " + num((p.x[1] + p.x[3] + p.x[5]) / 3) + "\n";
      dat.write("triangle_" + name(r.method) + ".dat", s);
    }
    for (std::size_t m : d.collision.config.methods) {
      std::string s = "# dt energy_ratio_after_last_bounce\n";
      for (const CollisionRun& r : d.collision.bounce)
        if (r.method == m && !r.bounces.empty()) s += num(r.dt) + " " + num(r.bounces.back().energy_ratio) + "\n";
      dat.write("bounce_" + name(m) + ".dat", s);
    }
  }

  std::vector<FigureSpec> figures(const ReportData& d) const override {
    const std::vector<Panel> families = family_panels(d.collision.config.methods);
    return {{"fig8_triangle", "", families}, {"fig9_bounce_energy", "", families}};
  }

  std::string markdown(Page& page) const override {
    const ReportData& d = page.data;
    const ReportConfig& c = d.config;
    std::string md = "## " + title() + "\n\n";
    md += fmt::format("The undamped bounce (dropped from y = 0 onto the penalty ground y = -1; {}) and the falling triangle ({}), "
                      "over {} s.\n\n", params_text(c.rebound.scene, c.rebound.params), params_text(c.body.scene, c.body.params),
                      c.collision_t_end);
    md += "| method | dt | bounces | E/E0 after the first | E/E0 after the last | deepest penetration |\n|---|---:|---:|---:|---:|---:|\n";
    for (const CollisionRun& r : d.collision.bounce)
      md += fmt::format("| `{}` | {} | {} | {} | {} | {:.4f} |\n", name(r.method), r.dt, r.bounces.size(),
                        r.bounces.empty() ? "-" : fmt::format("{:.4f}", r.bounces.front().energy_ratio),
                        r.bounces.empty() ? "-" : fmt::format("{:.4f}", r.bounces.back().energy_ratio), r.max_penetration);
    md += "\nOrders against the exact bounce (the contact's kink costs order):\n\n" + fits_table(d.convergence_on(c.rebound.scene)) + "\n";
    md += page.figure("fig8_triangle", fmt::format("falling triangle: height of its centre against time, dt {}, a panel per family", c.triangle_dt));
    md += page.figure("fig9_bounce_energy", "bounce: energy ratio after the last bounce against dt, a panel per family");
    return md;
  }
};

}  // namespace

std::unique_ptr<Section> make_collision_section() { return std::make_unique<Collision>(); }

}  // namespace steplab
