// Cost: work-precision on the spring (final error against the measured run time).
#include "reports/section.hpp"

namespace steplab {
namespace {

class Cost : public Section {
 public:
  std::vector<FigureSpec> figures(const ReportData& d) const override {
    if (!d.config.timing) return {};  // no timings, no work-precision
    return {{"fig7_work_precision", ""}};
  }
  std::string markdown(Page& page) const override {
    std::string md = "## Cost\n\n";
    if (page.data.config.timing)
      md += page.figure("fig7_work_precision", "work-precision on the spring: final error against the measured run time (integration only), a panel per family");
    else
      md += "Work-precision is left out: the configuration turned timing off (`convergence.timing`).\n\n";
    return md;
  }
};

}  // namespace

std::unique_ptr<Section> make_cost_section() { return std::make_unique<Cost>(); }

}  // namespace steplab
