// Convergence: errors against dt on the oscillator (the spring), fitted orders on each of the
// report's scenes with an exact solution (the rebound scene's in the collision section).
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analysis/kernel.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"
#include "reports/data/study_output.hpp"

namespace steplab {
namespace {

// The study the figure draws: the spring's, or without it the first scene's.
const ConvergenceResult& drawn(const ReportData& d) {
  return d.config.covers(d.config.oscillator.scene) ? d.convergence_on(d.config.oscillator.scene) : d.convergence.front();
}

class Convergence : public Section {
 public:
  std::string title() const override { return "Convergence"; }
  unsigned needs() const override { return kConvergenceStudy; }
  void write_data(const ReportData& d, const DataDir& dat) const override {
    for (const ConvergenceResult& r : d.convergence)
      dat.write(fmt::format("convergence_{}.json", scene_name(r.config.scene)), convergence_json(r).dump(1) + "\n");
    const ConvergenceResult& conv = drawn(d);
    const std::size_t nd = conv.dts.size();
    for (std::size_t m : d.methods) {  // the report's methods; a file without rows for one the study could not run
      const auto it = std::find(conv.config.methods.begin(), conv.config.methods.end(), m);
      const std::size_t i = static_cast<std::size_t>(it - conv.config.methods.begin());
      std::string s = "# dt error seconds\n";
      std::string line = "# dt error (the window's least-squares line over its range)\n";
      if (it != conv.config.methods.end()) {
        for (std::size_t k = 0; k < nd; ++k) {
          const ConvergenceRecord& r = conv.records[i * nd + k];
          if (r.status == RunStatus::Ok && r.error_final > 0) s += num(r.dt) + " " + num(r.error_final) + " " + num(r.seconds) + "\n";
        }
        const OrderFit& fit = conv.fits[i].fit;
        if (fit.fitted)
          for (double x : {fit.dt_lo, fit.dt_hi}) line += num(x) + " " + num(std::exp(fit.line.intercept + fit.line.slope * std::log(x))) + "\n";
      }
      dat.write("conv_" + name(m) + ".dat", s);
      dat.write("fit_" + name(m) + ".dat", line);
    }
    // reference slopes 1, 2, 4 over the sweep's largest decade, under the lowest fitted curve there
    double anchor = INFINITY;
    const double top = conv.dts.front();
    for (const ConvergenceFit& f : conv.fits)
      if (f.fit.fitted) anchor = std::min(anchor, std::exp(f.fit.line.intercept + f.fit.line.slope * std::log(top)));
    if (!std::isfinite(anchor)) anchor = 1;
    std::string ref;
    for (int p : {1, 2, 4}) {
      ref += fmt::format("# slope {}\n", p);
      for (double x : {top / 10, top}) ref += num(x) + " " + num(0.1 * anchor * std::pow(x / top, p)) + "\n";
      ref += "\n\n";
    }
    dat.write("reference_slopes.dat", ref);
  }

  // A panel per family, of the methods with an error to draw (not the exact flow's round-off).
  std::vector<FigureSpec> figures(const ReportData& d) const override {
    const ConvergenceResult& conv = drawn(d);
    const std::size_t nd = conv.dts.size();
    const auto has_points = [&](std::size_t m) {
      const auto it = std::find(conv.config.methods.begin(), conv.config.methods.end(), m);
      if (it == conv.config.methods.end()) return false;
      const std::size_t i = static_cast<std::size_t>(it - conv.config.methods.begin());
      for (std::size_t k = 0; k < nd; ++k)
        if (conv.records[i * nd + k].status == RunStatus::Ok && conv.records[i * nd + k].error_final > 0) return true;
      return false;
    };
    return {{"fig3_convergence", "", family_panels(d.methods, has_points)}};
  }

  std::string markdown(Page& page) const override {
    const ReportData& d = page.data;
    const ReportConfig& c = d.config;
    const ConvergenceResult& shown = drawn(d);
    std::string md = "## " + title() + "\n\n";
    md += fmt::format(
        "Errors against the exact solution over {} steps from {} to {} (t = {}). The order is the asymptotic one: over "
        "the range of steps where the local slopes have settled, ln e = a + p ln dt + b dt^q is fitted, the next error "
        "term modelled (q = 1, or 2 for a method whose error expands in dt^2, whichever fits better). Its *bound* is "
        "round-off noise (95 %) plus the truncation left over (the same fit without the two smallest steps, and the other "
        "q): a bound, not a confidence interval. The window's plain least-squares slope is shown beside it; its Student-t "
        "interval is not a statement about the order, because truncation error is smooth, not random.\n\n",
        shown.dts.size(), c.conv_dt_max, c.conv_dt_min, c.conv_t_end);
    for (const ConvergenceResult& r : d.convergence)
      if (r.uses_reference)
        md += fmt::format("{} has no exact solution: its errors are final-position errors against a reference solution "
                          "(dopri5 at rtol = atol = {:g}, its own error estimated at {:.2g}).\n\n",
                          scene_kernel(r.config.scene).title, r.reference.rtol, r.reference.estimated_error);
    const std::string on = shown.config.scene == c.oscillator.scene ? "the spring" : std::string(scene_kernel(shown.config.scene).title);
    md += page.figure("fig3_convergence", fmt::format("error against dt on {}, a panel per family: least-squares lines (solid) and reference slopes 1, 2, 4 (grey, dashed)", on));
    int diverged = 0, runs = 0;
    for (const ConvergenceResult& r : d.convergence)
      for (const ConvergenceRecord& rec : r.records) diverged += rec.status != RunStatus::Ok, ++runs;
    md += diverged == 0 ? fmt::format("All {} runs of the convergence studies stayed finite.\n\n", runs)
                        : fmt::format("{} of the {} runs of the convergence studies diverged (a non-finite state, recorded "
                                      "with its step in `data/`); they are left out of the fits and of figure {}.\n\n",
                                      diverged, runs, page.next_figure() - 1);
    for (const ConvergenceResult& r : d.convergence) {
      if (r.config.scene == c.rebound.scene) continue;  // in the collision section
      md += std::string(scene_kernel(r.config.scene).title);
      if (r.config.scene == c.projectile.scene)
        md += " (constant acceleration: every method of order 2 or more, and every Adams-Bashforth and BDF method, is exact on it)";
      md += ":\n\n" + fits_table(r) + "\n";
    }
    return md;
  }
};

}  // namespace

std::unique_ptr<Section> make_convergence_section() { return std::make_unique<Convergence>(); }

}  // namespace steplab
