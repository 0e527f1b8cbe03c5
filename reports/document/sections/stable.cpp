// The sheet's first question: which methods are stable at its large step, and without damping?
// The exact flow is the reference, in none of the lists.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "reports/document/claims.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"

namespace steplab {
namespace {

class Stable : public Section {
 public:
  std::string title() const override { return "Which methods are stable, and which are not?"; }
  unsigned needs() const override { return kFindings; }
  std::string markdown(Page& page) const override {
    const Findings& f = page.findings;
    const ReportConfig& c = page.data.config;
    const auto methods = [&](const std::vector<std::size_t>& rows) { return method_list(methods_of(f, rows)); };
    std::string md = "## " + title() + "\n\n";
    const std::vector<MethodRate> large_rates = rates_of(f, f.unstable_large, false), undamped_rates = rates_of(f, f.unstable_undamped, true);
    const std::string large = fmt::format("- At the sheet's large step dt = {} (damping {}): stable: {}; unstable: {}.", c.large_dt,
                                          c.damping(), methods(f.stable_large), f.unstable_large.empty() ? "none" : unstable_words(large_rates));
    const std::string undamped = fmt::format("- Without damping (dt = {}): stable: {}; unstable: {}.", c.small_dt, methods(f.stable_undamped),
                                             f.unstable_undamped.empty() ? "none" : unstable_words(undamped_rates));
    md += large + "\n" + undamped + "\n";
    if (Ledger* l = page.ledger) {
      claim_unstable_at(*l, {page.data}, "stable.unstable_at_large_dt", "stable", large, c.large_dt, c.damping(), methods_of(f, f.unstable_large));
      claim_unstable_runs(*l, {page.data}, "stable", "at_large_dt", large, c.large_dt, c.damping(), large_rates, true);
      claim_unstable_at(*l, {page.data}, "stable.unstable_undamped", "stable", undamped, c.small_dt, 0.0, methods_of(f, f.unstable_undamped));
      claim_unstable_runs(*l, {page.data}, "stable", "undamped", undamped, c.small_dt, 0.0, undamped_rates, true);
    }
    // Unstable at every small step undamped (predicted dt* = 0): at every step tried, or stable again further out.
    std::vector<std::string> again;
    for (std::size_t i : f.unstable_small_undamped)
      if (std::find(f.never_stable_undamped.begin(), f.never_stable_undamped.end(), i) == f.never_stable_undamped.end()) {
        const MethodFinding& r = f.rows[i];
        const double from = std::isfinite(r.again_undamped_measured) ? r.again_undamped_measured : r.again_undamped_theory;
        again.push_back(std::isfinite(from) ? fmt::format("`{}` (stable again from dt = {})", name(r.method), dt_text(from))
                                            : fmt::format("`{}` (stable at a larger step of the (dt, damping) map)", name(r.method)));
      }
    if (!f.never_stable_undamped.empty())
      md += fmt::format("- Without damping no step is stable for {}: the step map's spectral radius exceeds 1 at every "
                        "small h, and neither the threshold search nor the map (up to dt = {}) finds a stable step.\n",
                        methods(f.never_stable_undamped), c.stability.map_dt_max);
    if (!again.empty())
      md += fmt::format("- Without damping no small step is stable for {}, but a larger one is: {} stable steps are not one "
                        "interval from 0.\n",
                        and_list(again), again.size() == 1 ? "its" : "their");
    if (!f.always_stable.empty()) {
      const std::string every = fmt::format("- Stable at every step tried (dt* = $\\infty$ at damping {}): {}.", c.damping(), methods(f.always_stable));
      md += every + "\n";
      if (page.ledger)
        claim_unbounded_at(*page.ledger, {page.data}, "stable.stable_at_every_step", "stable", every, c.damping(), methods_of(f, f.always_stable));
    }
    return md + "\n";
  }
};

}  // namespace

std::unique_ptr<Section> make_stable_section() { return std::make_unique<Stable>(); }

}  // namespace steplab
