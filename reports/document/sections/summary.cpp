// The summary: one row per method, grouped by family, with what the answers rest on: its order
// (declared and fitted), its largest stable step dt* undamped and at the spring's damping, and
// whether it is stable at the sheet's two tests. Where the report has its frame-budget section,
// the methods on springs join the table: measured on the sheet's spring by the same studies (run
// here for them alone: Report::springs), their frame-budget answer in that section.
#include <algorithm>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "reports/document/claims.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"

namespace steplab {
namespace {

// The family's name, shortened for a narrow column.
std::string_view short_family(Family f) {
  switch (f) {
    case Family::ExplicitRungeKutta: return "explicit RK";
    case Family::ImplicitRungeKutta: return "implicit RK";
    case Family::Splitting: return "splitting";
    default: return to_string(f);
  }
}

// dt* with where the method is stable again beyond it: "0.2183, again from 0.7899".
std::string threshold_cell(double dt, double again) {
  return std::isfinite(again) && std::isfinite(dt) ? fmt::format("{}, again from {}", table_dt(dt), table_dt(again)) : table_dt(dt);
}

class Summary : public Section {
 public:
  std::string title() const override { return "Summary"; }
  unsigned needs() const override { return kFindings; }
  std::string markdown(Page& page) const override {
    const ReportConfig& c = page.data.config;
    const double gamma = c.damping();
    std::string md = "## " + title() + "\n\n";
    // The dashes of the rule set pandoc's column widths in the PDF.
    md += fmt::format("| family | method | order | fitted order [bound] | dt* undamped | dt* at damping {} | stable at dt {} damped, "
                      "at dt {} undamped |\n|------|-----------|--|-----------|------|-------|-------|\n",
                      gamma, c.large_dt, c.small_dt);
    std::vector<const MethodFinding*> rows;
    for (const MethodFinding& r : page.findings.rows) rows.push_back(&r);
    if (page.springs_findings)
      for (const MethodFinding& r : page.springs_findings->rows) rows.push_back(&r);
    std::sort(rows.begin(), rows.end(),
              [](const MethodFinding* a, const MethodFinding* b) { return family_order_less(a->method, b->method); });
    const auto yes = [](bool b) { return b ? "yes" : "**no**"; };
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const MethodFinding& r = *rows[i];
      const Family f = method_info(r.method).family;
      const bool first = i == 0 || method_info(rows[i - 1]->method).family != f;  // the family named once per group
      md += fmt::format("| {} | `{}` | {} | {} | {} | {} | {}, {} |\n", first ? short_family(f) : "", name(r.method),
                        order_text(r.method), fitted_text(*r.fit), threshold_cell(r.dt_undamped_measured, r.again_undamped_measured),
                        threshold_cell(r.dt_measured, r.again_measured), yes(r.stable_large_dt), yes(r.stable_undamped));
    }
    if (Ledger* l = page.ledger) {  // its last column, over each stability study it shows
      for (const ShownStudy& x : shown_studies(page)) {
        claim_unstable_at(*l, x.study, fmt::format("summary.unstable_at_large_dt{}", x.id), "summary",
                          fmt::format("the summary table's last column, at dt {}: no", c.large_dt), c.large_dt, gamma,
                          methods_of(x.f, x.f.unstable_large));
        claim_unstable_at(*l, x.study, fmt::format("summary.unstable_undamped{}", x.id), "summary",
                          fmt::format("the summary table's last column, at dt {} undamped: no", c.small_dt), c.small_dt, 0.0,
                          methods_of(x.f, x.f.unstable_undamped));
      }
    }
    md += fmt::format(
        "\nFitted order: on the spring, the final position error over t = {}, with its bound (Convergence). dt*: the "
        "largest step with every smaller step stable, measured ($\\infty$: every step tried is stable); where a method is "
        "stable again beyond it, from where. Stable: energy growing by at most {:g} per unit time over {} steps.{}\n\n",
        c.convergence.t_end, kStableRate, kRateSteps, !c.has_section("physics") ? "" : page.handout ? " The terms: the atlas's appendix." : " The terms: the appendix.");
    if (page.springs)
      md += fmt::format("The methods on springs ({}) are measured here on the sheet's spring, a single spring, where one XPBD "
                        "sweep or one CG iteration solves the step: at a frame budget on a rope of many springs they are the "
                        "frame-budget section's. PBD claims no order: its stiffness is set at a frame of 1/60 s, so at other "
                        "steps it is another material, and its rest is not the spring's equilibrium (about which dt* is predicted): its dt* "
                        "is the runs' alone.\n\n",
                        method_list(page.springs->methods));
    return md;
  }
};

}  // namespace

std::unique_ptr<Section> make_summary_section() { return std::make_unique<Summary>(); }

}  // namespace steplab
