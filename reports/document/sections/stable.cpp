// The sheet's first question: which methods are stable at its large step, and without damping?
#include <fmt/format.h>

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
    const auto methods = [&](const std::vector<std::size_t>& rows) {
      std::vector<std::size_t> m;
      for (std::size_t i : rows) m.push_back(f.rows[i].method);
      return method_list(m);
    };
    std::string md = "## " + title() + "\n\n";
    md += fmt::format("- At the sheet's large step dt = {} (damping {}): stable: {}; unstable: {}.\n", c.large_dt, c.damping(),
                      methods(f.stable_large), methods(f.unstable_large));
    md += fmt::format("- Without damping (dt = {}): stable: {}; unstable: {}.\n", c.small_dt, methods(f.stable_undamped),
                      methods(f.unstable_undamped));
    if (!f.never_stable_undamped.empty())
      md += fmt::format("- Without damping no step at all is stable for {} (predicted dt* = 0: the step map's spectral radius "
                        "exceeds 1 for every h > 0 tried).\n", methods(f.never_stable_undamped));
    if (!f.always_stable.empty())
      md += fmt::format("- Stable at every step (dt* = inf at damping {}): {}.\n", c.damping(), methods(f.always_stable));
    return md + "\n";
  }
};

}  // namespace

std::unique_ptr<Section> make_stable_section() { return std::make_unique<Stable>(); }

}  // namespace steplab
