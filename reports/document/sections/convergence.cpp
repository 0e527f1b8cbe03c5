// Convergence: errors against dt on the oscillator (the spring), fitted orders on each of the
// report's scenes with an exact solution (the rebound scene's in the collision section).
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "reports/studies/studies.hpp"
#include "reports/document/claims.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"

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
    // reference slopes 1, 2, 4 from the sweep's largest dt under the lowest fitted curve there, each
    // over two decades or the four decades of error it falls (so their left ends, where the figure
    // labels them, lie apart)
    double anchor = INFINITY;
    const double top = conv.dts.front();
    for (const ConvergenceFit& f : conv.fits)
      if (f.fit.fitted) anchor = std::min(anchor, std::exp(f.fit.line.intercept + f.fit.line.slope * std::log(top)));
    if (!std::isfinite(anchor)) anchor = 1;
    std::string ref;
    for (int p : {1, 2, 4}) {
      ref += fmt::format("# slope {}\n", p);
      for (double x : {top / std::pow(10.0, std::min(2.0, 4.0 / p)), top}) ref += num(x) + " " + num(0.1 * anchor * std::pow(x / top, p)) + "\n";
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
    return {{"convergence", "", family_panels(d.methods, has_points)}};
  }

  std::string markdown(Page& page) const override {
    const ReportData& d = page.data;
    const ReportConfig& c = d.config;
    const ConvergenceResult& shown = drawn(d);
    std::string md = "## " + title() + "\n\n";
    md += fmt::format(
        "Errors against the exact solution at t = {} over {} steps from {} to {}. The order is the asymptotic one: over the "
        "steps where the local slopes have settled, ln e = a + p ln dt + b dt^q^ is fitted with the next error term "
        "modelled. Its *bound* is round-off noise (95 %) plus the truncation left over: a bound on the order, not a "
        "confidence interval (truncation error is smooth, not random).\n\n",
        c.convergence.t_end, shown.dts.size(), c.convergence.dt_max, c.convergence.dt_min);
    for (const ConvergenceResult& r : d.convergence)
      if (r.uses_reference)
        md += fmt::format("{} has no exact solution: its errors are final-position errors against a reference solution "
                          "(dopri5 at rtol = atol = {:g}, its own error estimated at {:.2g}).\n\n",
                          scene_kernel(r.config.scene).title, r.reference.rtol, r.reference.estimated_error);
    int diverged = 0, runs = 0;
    for (const ConvergenceResult& r : d.convergence)
      for (const ConvergenceRecord& rec : r.records) diverged += rec.status != RunStatus::Ok, ++runs;
    if (diverged > 0)
      md += fmt::format("{} of the {} runs diverged (a non-finite state, recorded with its step in `data/`); the fits and the "
                        "figure leave them out.\n\n", diverged, runs);
    for (const ConvergenceResult& r : d.convergence) {
      if (r.config.scene == c.rebound.scene) continue;  // in the collision section
      if (r.config.scene == c.oscillator.scene && c.has_section("summary")) {
        md += "Spring: its fitted orders are the summary's; the steps each was fitted over are in data/convergence/ "
              "(`convergence_spring.json`).\n\n";
        continue;
      }
      md += scene_fits(r, page.ledger);
    }
    const std::string on = shown.config.scene == c.oscillator.scene ? "the spring" : std::string(scene_kernel(shown.config.scene).title);
    // the shallowest and the steepest fitted line
    const auto drawn_fit = [](const ConvergenceFit& f) { return f.fit.fitted && !method_info(f.method).exact_flow; };
    const auto [flat, steep] = least_and_most(shown.fits, drawn_fit, [](const ConvergenceFit& f) { return f.fit.order; });
    if (!page.has("convergence")) return md;
    constexpr Digits kOrder{false, 2};
    const auto order_of = [](const ConvergenceFit& f) { return f.fit.order; };
    const auto names = [&](const std::vector<const ConvergenceFit*>& tied) {  // the fits that print alike: a tie, named as one
      std::vector<std::size_t> methods;
      for (const ConvergenceFit* f : tied) methods.push_back(f->method);
      return method_list(methods);
    };
    const std::vector<const ConvergenceFit*> flats = printed_ties(shown.fits, drawn_fit, order_of, flat, kOrder),
                                             steeps = printed_ties(shown.fits, drawn_fit, order_of, steep, kOrder);
    const std::string range = flat ? fmt::format("The fitted orders run from {} ({}) to {} ({}).", printed(flat->fit.order, kOrder),
                                                 names(flats), printed(steep->fit.order, kOrder), names(steeps))
                                   : std::string("No method's errors reach their asymptotic range.");
    md += page.figure("convergence", fmt::format("Error against dt on {}, a panel per family: least-squares lines over the "
                                                 "fitted window (solid), slopes 1, 2 and 4 for reference (grey, dashed). {}", on, range));
    if (page.ledger && flat) {  // the caption's two ends, over the fitted lines it draws
      const std::string file = cite_convergence(*page.ledger, shown);
      claim_range(*page.ledger, "convergence.orders", "convergence", range,
                  kept_evidence(shown.fits, drawn_fit, flat, steep, [&](const ConvergenceFit& f, std::size_t) {
                    return row_field(*page.ledger, file, "/fits", {{"method", name(f.method)}}, "order");
                  }),
                  kOrder);
      for (const std::vector<const ConvergenceFit*>* tied : {&flats, &steeps})  // each named beside an end prints as it does
        for (std::size_t k = 1; k < tied->size(); ++k)
          claim_ratio(*page.ledger, claim_text(fmt::format("convergence.orders.tie.{}", name((*tied)[k]->method)), "convergence", range),
                      {{row_field(*page.ledger, file, "/fits", {{"method", name((*tied)[k]->method)}}, "order")}, {}}, (*tied)[k]->fit.order,
                      kOrder);
    }
    return md;
  }

 private:
  // A scene's fits: the methods exact on it (to round-off) in a sentence, the others in a table,
  // or in the sentence too where they are few.
  static std::string scene_fits(const ConvergenceResult& r, Ledger* l) {
    std::vector<std::size_t> exact;
    std::vector<const ConvergenceFit*> fitted;
    for (const ConvergenceFit& f : r.fits)
      if (!method_info(f.method).exact_flow) (f.fit.exact ? exact.push_back(f.method) : fitted.push_back(&f));
    const std::string scene(scene_kernel(r.config.scene).title);
    if (exact.empty()) return scene + ":\n\n" + fits_table(r) + "\n";
    std::string md = fmt::format("{}: exact to round-off for {}", scene, method_list(exact));
    if (l) {
      const std::string file = cite_convergence(*l, r);
      claim_members(*l, claim_text(fmt::format("convergence.exact.{}", scene_name(r.config.scene)), "convergence", md), file, "/fits",
                    Json::object(), "method", true, test_field("/exact", "==", true), method_names(exact));
    }
    if (fitted.empty()) return md + ".\n\n";
    if (fitted.size() > 3) return md + "; the others:\n\n" + fits_table(r) + "\n";
    std::vector<std::string> others;
    for (const ConvergenceFit* f : fitted) others.push_back(fmt::format("`{}` {}", name(f->method), fitted_text(*f)));
    return md + fmt::format("; {} at {}.\n\n", fitted.size() == 1 ? "the other converges" : "the others converge", and_list(others));
  }
};

}  // namespace

std::unique_ptr<Section> make_convergence_section() { return std::make_unique<Convergence>(); }

}  // namespace steplab
