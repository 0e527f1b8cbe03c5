// The sheet's second question in short, for the hand-in: is stability correlated with the order?
// Answered from the measured dt* two ways: methods of one order set side by side (if their dt*
// differ, the order does not decide stability), and each family's methods by order (within one
// construction the order may move dt* up or down). The full report's families section says the
// same at length, with the stability regions.
#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "reports/document/claims.hpp"
#include "reports/document/findings.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"

namespace steplab {
namespace {

// dt* in a sentence: "unbounded" where every step tried is stable.
std::string dt_words(double x) { return std::isinf(x) ? "unbounded" : dt_text(x); }

// Two measured dt* differ when one is 0 or inf and the other not, or when they are a factor 2 apart:
// well beyond the threshold search's resolution, which is a few per cent.
bool differ(double a, double b) {
  if (a == b) return false;
  if (a == 0 || b == 0 || std::isinf(a) || std::isinf(b)) return true;
  return std::max(a, b) > 2 * std::min(a, b);
}

class Order : public Section {
 public:
  std::string title() const override { return "Is stability correlated with the order?"; }
  unsigned needs() const override { return kFindings; }

  std::string markdown(Page& page) const override {
    const double gamma = page.data.config.damping();
    std::map<int, std::vector<const MethodFinding*>> by_order;
    for (const MethodFinding& r : page.findings.rows)
      if (!method_info(r.method).exact_flow) by_order[method_info(r.method).order].push_back(&r);
    const auto dts = [](const std::vector<const MethodFinding*>& rows) {
      std::vector<std::string> out;
      for (const MethodFinding* r : rows)
        out.push_back(fmt::format("`{}` {} ({} undamped)", name(r->method), dt_words(r->dt_measured), dt_words(r->dt_undamped_measured)));
      return and_list(out);
    };
    std::string md = "## " + title() + "\n\n";
    md += fmt::format("The largest stable step dt* measured on the spring at damping {} (and undamped), by order:\n\n", gamma);
    bool same_order_differ = false, same_order = false;
    for (const auto& [order, rows] : by_order) {
      md += fmt::format("- order {}: {}.\n", order, dts(rows));
      same_order |= rows.size() > 1;
      for (const MethodFinding* a : rows)
        for (const MethodFinding* b : rows) same_order_differ |= differ(a->dt_measured, b->dt_measured);
    }
    md += "\n";
    // Each family's methods among these, by order: how dt* moves along them (trend: the family
    // table's words and rule, findings.hpp).
    std::vector<std::string> trends;
    const std::vector<FamilyTrend> families = family_trends(page.data, gamma);
    for (const FamilyTrend& t : families)
      trends.push_back(fmt::format("in the {} family dt* {} with the order (`{}` {}, `{}` {})", to_string(t.family), to_text(t.trend),
                                   name(t.members.front()), dt_words(t.dt.front()), name(t.members.back()), dt_words(t.dt.back())));
    if (same_order_differ)
      md += "**Not as a rule.** Methods of the same order are stable up to very different steps: how a method is built "
            "(explicit, symplectic, implicit) sets its stability, not its order.";
    else if (same_order)
      md += "Methods of the same order are stable up to about the same step here, so these data do not separate order from "
            "construction.";
    else
      md += "No two of these methods share an order, so only a family's methods set side by side can answer it.";
    if (!trends.empty()) md += fmt::format(" Within one family, whose methods share a construction, at damping {}: {}.", gamma, and_list(trends));
    if (page.findings.spearman_n >= 3)
      md += fmt::format(" Over these {} methods, Spearman's rank correlation between order and dt* is {:.2f} ({}): {}.",
                        page.findings.spearman_n, page.findings.spearman, correlation_words(page.findings.spearman),
                        chance_words(page.findings.spearman, page.findings.spearman_n));
    if (Ledger* l = page.ledger) {
      const std::string said = md.substr(md.rfind("\n\n") + 2);  // the paragraph
      if (page.findings.spearman_n >= 3) claim_spearman(*l, spearman_points({page.data}, page.findings), page.findings.spearman, "order.correlation", "order", said, 2);
      for (const FamilyTrend& t : families)
        claim_family_trend(*l, {page.data}, fmt::format("order.trend.{}", id_word(to_string(t.family))), "order", said, t, gamma);
    }
    md += "\n\n";
    return md;
  }
};

}  // namespace

std::unique_ptr<Section> make_order_section() { return std::make_unique<Order>(); }

}  // namespace steplab
