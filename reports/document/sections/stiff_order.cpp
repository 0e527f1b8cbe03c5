// Does the order hold when stiff? The fitted order against the stiffness of the stiffened scene
// (by default the mass pulled to a moving target, the second-order Prothero-Robinson problem),
// each method's theory beside it (analysis/studies/order_reduction.hpp): which methods keep their order
// at every stiffness, which stray between the limits, which fall or rise and to what, and where
// the transition lies in h |lambda| (findings.hpp, stiff_claims).
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/order_reduction.hpp"
#include "reports/studies/studies.hpp"
#include "reports/document/claims.hpp"
#include "reports/document/findings.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"
#include "reports/document/sections/answers.hpp"

namespace steplab {
namespace {

std::string order_or_dash(const OrderFit& f) { return f.fitted ? fmt::format("{:.2f}", f.order) : "-"; }
std::string x(double v) { return std::isnan(v) ? std::string("?") : dt_text(v); }

class StiffOrder : public Section {
 public:
  std::string title() const override { return "Does the order hold when stiff?"; }
  std::string brief(Page& page) const override { return brief_markdown(title(), answer_paragraph(stiff_answer(page))); }
  unsigned needs() const override { return kStiffOrderStudy; }
  std::string missing(const ReportConfig& c) const override { return uncovered(c, {c.stiffened.scene}); }

  void write_data(const ReportData& d, const DataDir& dat) const override {
    const OrderReduction& r = d.stiff_order;
    dat.write("stiff_order.json", order_reduction_json(r).dump(1) + "\n");
    const std::vector<double>& v = r.sweep.values;
    for (std::size_t m = 0; m < r.methods.size(); ++m) {
      const MethodReduction& mr = r.methods[m];
      std::string s = "# stiffness order bound_lo bound_hi h_lambda (fitted values only)\n";
      for (std::size_t i = 0; i < v.size(); ++i) {
        const OrderFit& f = r.sweep.studies[i].fits[m].fit;
        if (f.fitted && !mr.past_stable[i]) s += fmt::format("{} {} {} {} {}\n", num(v[i]), num(f.order), num(f.bound_lo), num(f.bound_hi), num(mr.h_lambda[i]));
      }
      // the theory's two limits, each over the sweep's first two and last two values
      std::string t = "# stiffness order: the non-stiff limit, then the stiff one\n";
      const std::size_t n = v.size();
      t += fmt::format("{} {}\n{} {}\n\n\n", num(v[0]), mr.theory.classical, num(v[std::min<std::size_t>(1, n - 1)]), mr.theory.classical);
      t += mr.theory.stiff >= 0 ? fmt::format("{} {}\n{} {}\n", num(v[n >= 2 ? n - 2 : 0]), mr.theory.stiff, num(v[n - 1]), mr.theory.stiff)
                                : "NaN NaN\n";
      dat.write("stiff_" + name(mr.method) + ".dat", s);
      dat.write("stiff_theory_" + name(mr.method) + ".dat", t);
    }
  }

  // A panel per family, of the methods with a fitted order to draw.
  std::vector<FigureSpec> figures(const ReportData& d) const override {
    const OrderReduction& r = d.stiff_order;
    const std::vector<double>& v = r.sweep.values;  // every panel over the whole sweep
    if (v.empty()) return {};
    const auto fitted = [&](std::size_t method) {
      for (std::size_t m = 0; m < r.methods.size(); ++m)
        if (r.methods[m].method == method)
          for (std::size_t i = 0; i < v.size(); ++i)
            if (r.sweep.studies[i].fits[m].fit.fitted && !r.methods[m].past_stable[i]) return true;
      return false;
    };
    std::vector<Panel> panels = family_panels(d.methods, fitted);
    if (panels.empty()) return {};
    return {{"stiff_order", fmt::format("kmin={}; kmax={}", num(v.front() / 3), num(v.back() * 3)), std::move(panels)}};
  }

  static constexpr const char* kTheory =
      "The theory (appendix): a Runge-Kutta method keeps order p while h |lambda| is small; as it grows, a stiffly accurate "
      "one falls to its stage order q, one with |R(infinity)| < 1 or R(infinity) = -1 to q + 1, one with R(infinity) = 1 to q; "
      "a multistep method's own error vanishes as 1 / lambda, leaving its one-step start's.";

  // The figure's sentence of what to see: the method whose fitted order falls furthest from the
  // least stiffness to the greatest (each fitted and stable at both).
  static std::string drop_sentence(const OrderReduction& r, Ledger* l, const ReportData& d) {
    const std::vector<ConvergenceResult>& st = r.sweep.studies;
    const std::size_t last = st.size() - 1;
    std::vector<std::size_t> fitted;  // the methods fitted at both ends, below their stability limit
    std::size_t most = r.methods.size();
    double drop = 0;
    for (std::size_t m = 0; m < r.methods.size(); ++m) {
      const OrderFit &a = st.front().fits[m].fit, &b = st[last].fits[m].fit;
      if (!a.fitted || !b.fitted || r.methods[m].past_stable[0] || r.methods[m].past_stable[last]) continue;
      fitted.push_back(m);
      if (a.order - b.order > drop) drop = a.order - b.order, most = m;
    }
    if (most == r.methods.size()) return "No fitted order falls from the least stiffness to the greatest.";
    const std::string text = fmt::format("From k = {:g} to {:g}, `{}` falls furthest: from order {:.2f} to {:.2f}.", r.sweep.values.front(),
                                         r.sweep.values.back(), name(r.methods[most].method), st.front().fits[most].fit.order,
                                         st[last].fits[most].fit.order);
    if (l) {  // the fall from the first stiffness's fit to the last's, the greatest of the fitted methods'
      const std::string file = "stiff_order/stiff_order.json";
      l->document(file, [&] { return order_reduction_json(d.stiff_order); });
      std::vector<std::pair<Evidence, Evidence>> falls;
      std::size_t a = 0;
      for (std::size_t m : fitted) {
        if (m == most) a = falls.size();
        const std::string method = name(r.methods[m].method);
        falls.push_back({row_field(*l, file, "/fits", {{"method", method}, {"value", r.sweep.values.front()}}, "order"),
                         row_field(*l, file, "/fits", {{"method", method}, {"value", r.sweep.values.back()}}, "order")});
      }
      claim_greatest_fall(*l, claim_text("stiff_order.furthest_fall", "stiff_order", text), falls, a);
      for (int end = 0; end < 2; ++end)
        claim_ratio(*l, claim_text(fmt::format("stiff_order.furthest_fall.{}", end ? "stiff" : "non_stiff"), "stiff_order", text),
                    {{end ? falls[a].second : falls[a].first}, {}}, end ? st[last].fits[most].fit.order : st.front().fits[most].fit.order,
                    Digits{false, 2});
    }
    return text;
  }

  std::string markdown(Page& page) const override {
    const OrderReduction& r = page.data.stiff_order;
    const ConvergenceSweep& s = r.sweep;
    const ConvergenceConfig& c = s.studies.front().config;
    const std::string scene(scene_name(c.scene));
    const auto middle_h_lambda = [&](std::size_t i) {
      const std::vector<double>& dts = s.studies[i].dts;
      return std::sqrt(dts.front() * dts.back()) * r.rates[i];
    };
    std::string md = "## " + title() + "\n\n";
    md += fmt::format(
        "A method of order p is often chosen because it is stable at large steps; on a stiff problem its measured order "
        "can fall to its stage order (order reduction; Prothero and Robinson 1974; Hairer and Wanner II, IV.15). Measured "
        "on `{}` ({}), whose exact solution is the same at every stiffness: the order of the largest position error over "
        "t <= {} fitted over {} steps from {} to {}, at stiffness {} to {:g}. h |lambda| at the middle step goes from {} "
        "to {}. {}\n\n",
        scene, params_text(c.scene, c.params, scene_kernel(c.scene).stiffness_param), c.t_end, s.studies.front().dts.size(),
        dt_text(s.studies.front().dts.front()), dt_text(s.studies.front().dts.back()), s.values.front(), s.values.back(),
        dt_text(middle_h_lambda(0)), dt_text(middle_h_lambda(s.values.size() - 1)), kTheory);
    if (page.ledger) page.ledger->theory("stiff_order", kTheory);
    const std::string findings = sentences(r);
    md += findings;
    if (page.ledger) claim_stiff(*page.ledger, page.data, "stiff_order", "stiff_order", findings, stiff_claims(r));
    md += table(r);
    if (page.has("stiff_order"))
      md += page.figure("stiff_order", fmt::format("The fitted order against the stiffness on `{}`, a panel per family, each fit's "
                                                   "bound as an error bar; dashed: the theory's two limits. {}", scene,
                                                   drop_sentence(r, page.ledger, page.data)));
    return md;
  }

 private:
  // The orders at each stiffness, and the theory's two limits checked. The separator's dashes set
  // pandoc's column widths; the limits' bounds are in data/stiff_order/stiff_order.json.
  static std::string table(const OrderReduction& r) {
    const ConvergenceSweep& s = r.sweep;
    std::string md = "| method | p | stiff |", rule = "|----------------------|--|--|";
    for (double v : s.values) md += fmt::format(" {:g} |", v), rule += "---:|";
    md += " limits |\n" + rule + "------------|\n";
    bool starred = false;
    for (std::size_t m = 0; m < r.methods.size(); ++m) {
      const MethodReduction& mr = r.methods[m];
      md += fmt::format("| `{}` | {} | {} |", name(mr.method), mr.theory.classical, mr.theory.stiff >= 0 ? std::to_string(mr.theory.stiff) : "-");
      for (std::size_t v = 0; v < s.studies.size(); ++v) {
        md += fmt::format(" {}{} |", order_or_dash(s.studies[v].fits[m].fit), mr.past_stable[v] ? "\\*" : "");
        starred |= mr.past_stable[v];
      }
      md += fmt::format(" {} / {} |\n", limit_word(mr.non_stiff, true), limit_word(mr.stiff, mr.theory.stiff >= 0));
    }
    md += fmt::format("\nStiffness across, the fitted order in each cell. Limits: the non-stiff one (the first stiffness) / "
                      "the stiff one (the last), each *holds* when the order is within {} / {} of the theory's and its bound "
                      "contains it, in that limit's regime.", kNonStiffTolerance, kStiffTolerance);
    if (starred) md += " \\*: the fit's steps reach past the method's dt* on this mode: stable and growing runs mixed, not an "
                       "order of the method (left out of the figure).";
    return md + "\n\n";
  }

  // The findings (stiff_claims): who keeps its order at every stiffness, who keeps it in both
  // limits but strays between them, who falls or rises and to what, with the transition.
  static std::string sentences(const OrderReduction& r) {
    std::vector<std::string> keep, stray, fall, rise, unreached, differs, unstable;
    for (const StiffClaim& c : stiff_claims(r)) {
      const std::string n = fmt::format("`{}`", name(c.method));
      const std::string change = fmt::format("{} from {:.2f} to {:.2f} (kept up to h |lambda| = {}, at the stiff order from {})", n,
                                             c.non_stiff_order, c.stiff_order, x(c.keeps_to), x(c.reduced_from));
      switch (c.verdict) {
        case StiffVerdict::Keeps: keep.push_back(fmt::format("{} ({})", n, c.p)); break;
        case StiffVerdict::Strays:
          stray.push_back(fmt::format("{} ({} in both limits, {:.2f} [{:.2f}, {:.2f}] at stiffness {:g}, h |lambda| = {})", n,
                                      c.p, c.stray_order, c.stray_lo, c.stray_hi, c.stray_value, x(c.stray_h_lambda)));
          break;
        case StiffVerdict::Falls: fall.push_back(change); break;
        case StiffVerdict::Rises:
          rise.push_back(c.starter.empty() ? change : fmt::format("{}, from its `{}` start", change, c.starter));
          break;
        case StiffVerdict::NotReached: unreached.push_back(n); break;
        case StiffVerdict::Differs:
          differs.push_back(fmt::format("{} ({:.2f} and {:.2f} against {} and {})", n, c.non_stiff_order, c.stiff_order, c.p, c.stiff));
          break;
        case StiffVerdict::Unstable: unstable.push_back(n); break;
      }
    }
    std::string md;
    if (!keep.empty()) md += fmt::format("- **Keep their order at every stiffness**, as theory says: {}.\n", and_list(keep));
    if (!stray.empty())
      md += fmt::format("- **Keep their order in both limits but stray between them**: {}. The transition is not an order of "
                        "the method: the fit there sees the error change its regime.\n", and_list(stray));
    if (!fall.empty()) md += fmt::format("- **Fall** to the theory's stiff order: {}.\n", and_list(fall));
    if (!rise.empty())
      md += fmt::format("- **Gain** an order in the largest error: {}. The method's own error vanishes as 1 / lambda and what "
                        "stays is the error of the one-step method that makes its first steps.\n", and_list(rise));
    if (!unreached.empty()) md += fmt::format("- The stiff limit is not reached at these steps for {}.\n", and_list(unreached));
    if (!differs.empty()) md += fmt::format("- **Differ from the theory**: {}.\n", and_list(differs));
    if (!unstable.empty())
      md += fmt::format("- **Not stable** as h |lambda| grows: {}: orders only where the stiffness is low enough, no stiff "
                        "limit.\n", and_list(unstable));
    return md + "\n";
  }
};

}  // namespace

std::unique_ptr<Section> make_stiff_order_section() { return std::make_unique<StiffOrder>(); }

}  // namespace steplab
