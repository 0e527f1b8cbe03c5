// The summary: one row per method, grouped by family, with what the answers below rest on.
#include <algorithm>

#include <fmt/format.h>

#include "analysis/kernel.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"

namespace steplab {
namespace {

class Summary : public Section {
 public:
  std::string title() const override { return "Summary"; }
  unsigned needs() const override { return kFindings; }
  std::string markdown(Page& page) const override {
    const ReportConfig& c = page.data.config;
    const double gamma = c.damping();
    std::string md = "## " + title() + "\n\n";
    // Widths for pandoc: the dashes of the rule set the columns' relative widths in the PDF.
    md += fmt::format("| family | method | order | fitted order [bound] | stable: dt {} / undamped dt {} | dt* undamped | "
                      "dt* at damping {} | stable again from | energy growth at dt {} (1/s) |\n"
                      "|---------|--------------|---:|-------------------:|-------:|-----:|-----:|-----:|-----:|\n",
                      c.large_dt, c.small_dt, gamma, c.large_dt);
    std::vector<const MethodFinding*> rows;
    for (const MethodFinding& r : page.findings.rows) rows.push_back(&r);
    std::sort(rows.begin(), rows.end(),
              [](const MethodFinding* a, const MethodFinding* b) { return family_order_less(a->method, b->method); });
    const auto yes = [](bool b) { return b ? "yes" : "**no**"; };
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const MethodFinding& r = *rows[i];
      const Family f = method_info(r.method).family;
      const bool first = i == 0 || method_info(rows[i - 1]->method).family != f;  // the family named once per group
      md += fmt::format("| {} | `{}` | {} | {} | {} / {} | {} | {} | {} | {:.3g} |\n", first ? to_string(f) : "", name(r.method),
                        order_text(r.method), fitted_text(*r.fit), yes(r.stable_large_dt), yes(r.stable_undamped),
                        dt_text(r.dt_undamped_measured), dt_text(r.dt_measured),
                        std::isinf(r.again_measured) ? "-" : dt_text(r.again_measured), r.growth_large_dt);
    }
    // Where the details are: the report's section, or the study that has them if it is not chosen.
    const auto in = [&](const char* section, const char* title, const char* study) {
      return c.has_section(section) ? std::string(title) : fmt::format("`steplab study {}`", study);
    };
    md += fmt::format("\nFitted orders: spring, final position error over t = {}, the asymptotic order and its bound (see "
                      "{}). dt*: the largest step with every smaller step stable, measured (energy growth rate <= {:g} "
                      "per unit time over {} steps; {} sets it beside the prediction from the spectral "
                      "radius of the whole step map, a multistep method's memory included). \"Stable again from\": where a "
                      "method whose stable set is not an interval is stable again beyond dt* (at damping {}).\n\n",
                      c.conv_t_end, in("convergence", "Convergence", "convergence"), kStableRate, kRateSteps,
                      in("stability", "the Stability section", "stability"), gamma);
    return md;
  }
};

}  // namespace

std::unique_ptr<Section> make_summary_section() { return std::make_unique<Summary>(); }

}  // namespace steplab
