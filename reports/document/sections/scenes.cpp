// The scenes: cannon ball paths and the spring's y(t) per method beside the exact solutions.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "reports/document/claims.hpp"
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
    if (d.config.covers(d.config.projectile.scene)) out.push_back({"cannonball", "", family_panels(d.methods)});
    if (d.config.covers(d.config.oscillator.scene)) out.push_back({"spring", "", family_panels(d.methods)});
    return out;
  }

  std::string markdown(Page& page) const override {
    const ReportData& d = page.data;
    const ReportConfig& c = d.config;
    std::string md = "## " + title() + "\n\n";
    if (c.covers(c.projectile.scene)) {
      const std::vector<Deviation> dev = deviation_of(d, c.projectile, d.cannon);
      const std::string line = fmt::format("The cannon ball at dt = {}: each method's largest distance from the exact parabola over t <= {:g}: {}.",
                                           c.cannonball_dt, c.cannonball_t_end, deviations(dev));
      const std::string far = farthest(dev, "Over the flight");
      md += line + "\n\n" + page.figure("cannonball", fmt::format("Cannon ball paths at dt = {} beside the exact parabola (grey), a panel per "
                                                                  "family. {}", c.cannonball_dt, far));
      cite(page.ledger, "cannonball", c.cannonball_dt, dev, line, far);
    }
    if (c.covers(c.oscillator.scene)) {
      std::string far;  // at the largest step
      for (std::size_t k = 0; k < c.spring_figure_dts.size(); ++k) {
        const std::vector<Deviation> dev = deviation_of(d, c.oscillator, d.spring[k]);
        const std::string line = fmt::format("The spring at dt = {}: each method's largest distance from the exact height over t <= {:g}: {}.",
                                             c.spring_figure_dts[k], c.spring_figure_t_end, deviations(dev));
        md += (k ? " " : "") + line;
        const bool last = k + 1 == c.spring_figure_dts.size();
        if (last) far = farthest(dev, fmt::format("At dt = {}", c.spring_figure_dts[k]));
        cite(page.ledger, "spring", c.spring_figure_dts[k], dev, line, last ? far : "");
      }
      md += "\n\n" + page.figure("spring", fmt::format("The spring's height y(t) against the exact solution (grey), a panel "
                                                       "per family and dt ({}). {}", words(c.spring_figure_dts), far));
    }
    return md;
  }

 private:
  // Each numerical method's largest distance from the exact state over its run (diverged: not ok).
  struct Deviation {
    std::size_t method;
    double worst;
    bool ok;
  };
  template <int D>
  static std::vector<Deviation> deviation_of(const ReportData& d, const ReportScene& scene, const std::vector<RunResult<D>>& runs) {
    std::vector<Deviation> out;
    for (std::size_t i = 0; i < d.methods.size() && i < runs.size(); ++i) {
      if (method_info(d.methods[i]).exact_flow || runs[i].samples.empty()) continue;
      double worst = 0;
      for (const auto& s : runs[i].samples) {
        const AnyState y = scene_kernel(scene.scene).exact(scene.params, s.t);
        double e = 0;
        for (int j = 0; j < s.x.size(); ++j) e += (s.x[j] - y.x[j]) * (s.x[j] - y.x[j]);
        worst = std::max(worst, std::sqrt(e));
      }
      out.push_back({d.methods[i], worst, runs[i].status == RunStatus::Ok});
    }
    return out;
  }
  static constexpr Digits kDistance{true, 2};
  static const Deviation* farthest_run(const std::vector<Deviation>& dev) {
    return least_and_most(dev, [](const Deviation& v) { return v.ok; }, &Deviation::worst).second;
  }
  // "`rk4` 3.2e-10 m, ...", and the figure's sentence of what to see: the farthest of the runs that ended well.
  static std::string deviations(const std::vector<Deviation>& dev) {
    std::vector<std::string> out;
    for (const Deviation& v : dev)
      out.push_back(v.ok ? fmt::format("`{}` {} m", name(v.method), printed(v.worst, kDistance)) : fmt::format("`{}` diverged", name(v.method)));
    return and_list(out);
  }
  static std::string farthest(const std::vector<Deviation>& dev, const std::string& at) {
    const Deviation* far = farthest_run(dev);
    if (!far) return at + " every run diverged.";
    std::vector<std::size_t> tied;  // the runs as far to the printed digits: a tie, named as one
    for (const Deviation* v : printed_ties(dev, [](const Deviation& v) { return v.ok; }, [](const Deviation& v) { return v.worst; }, far, kDistance))
      tied.push_back(v->method);
    return fmt::format("{} the farthest from the exact path {} {}, {} m.", at, tied.size() == 1 ? "is" : "are, tied,", method_list(tied),
                       printed(far->worst, kDistance));
  }
  // The runs of one scene and step as data/scenes/<scene>_<dt>.json (steplab.deviations/1, docs/json.md):
  // each distance `line` states, a ratio claim as printed; the farthest (`far` states it, "" where
  // no sentence does), an extreme claim over the runs that ended well.
  static void cite(Ledger* l, const std::string& scene, double dt, const std::vector<Deviation>& dev, const std::string& line,
                   const std::string& far) {
    if (!l) return;
    Json runs = Json::array();
    for (const Deviation& v : dev)
      runs.push_back({{"method", name(v.method)}, {"status", v.ok ? "ok" : "diverged"}, {"distance_max", v.ok ? Json(v.worst) : Json(nullptr)}});
    const std::string file = fmt::format("scenes/{}_{}.json", scene, dt), id = fmt::format("scenes.{}.{}", scene, id_word(fmt::format("{}", dt)));
    l->document(file, [&] { return Json{{"schema", "steplab.deviations/1"}, {"scene", scene}, {"dt", dt}, {"runs", std::move(runs)}}; });
    const Kept ok = kept_evidence(dev, [](const Deviation& v) { return v.ok; }, nullptr, farthest_run(dev), [&](const Deviation&, std::size_t k) {
      return l->at(file, fmt::format("/runs/{}/distance_max", k));
    });
    for (std::size_t k = 0, i = 0; k < dev.size(); ++k)  // each distance stated, as printed
      if (dev[k].ok) claim_ratio(*l, claim_text(id + "." + name(dev[k].method), "scenes", line), {{ok.values[i++]}, {}}, dev[k].worst, kDistance);
    if (!far.empty() && !ok.values.empty())
      claim_extreme(*l, claim_text(id + ".farthest", "scenes", far), ok.values, ok.most, Extreme::Greatest, kDistance);
  }
};

}  // namespace

std::unique_ptr<Section> make_scenes_section() { return std::make_unique<SceneFigures>(); }

}  // namespace steplab
