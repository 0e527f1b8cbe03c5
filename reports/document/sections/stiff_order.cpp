// Does the order hold when stiff? The fitted order against the stiffness of the stiffened scene
// (by default the mass pulled to a moving target, the second-order Prothero-Robinson problem),
// each method's theory beside it (analysis/order_reduction.hpp): which methods keep their order,
// which fall and to what, and where the transition lies in h |lambda|.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analysis/kernel.hpp"
#include "analysis/order_reduction.hpp"
#include "reports/data/study_output.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"

namespace steplab {
namespace {

std::string order_or_dash(const OrderFit& f) { return f.fitted ? fmt::format("{:.2f}", f.order) : "-"; }


class StiffOrder : public Section {
 public:
  std::string title() const override { return "Does the order hold when stiff?"; }
  std::string missing(const ReportConfig& c) const override { return uncovered(c, {c.stiffened.scene}); }

  void study(const ReportData& d) override {
    const ReportConfig& rc = d.config;
    ConvergenceConfig c = stiff_order_config(rc.stiffened.scene, rc.stiffened.params, rc.stiff_order, d.numerical_methods());
    c.workers = d.workers;
    r_ = order_reduction(c, rc.stiff_order.stiffnesses);
  }

  void write_data(const ReportData&, const DataDir& dat) const override {
    dat.write("stiff_order.json", order_reduction_json(r_).dump(1) + "\n");
    const std::vector<double>& v = r_.sweep.values;
    for (std::size_t m = 0; m < r_.methods.size(); ++m) {
      const MethodReduction& mr = r_.methods[m];
      std::string s = "# stiffness order bound_lo bound_hi h_lambda (fitted values only)\n";
      for (std::size_t i = 0; i < v.size(); ++i) {
        const OrderFit& f = r_.sweep.studies[i].fits[m].fit;
        if (f.fitted && !mr.past_stable[i]) s += fmt::format("{} {} {} {} {}\n", num(v[i]), num(f.order), num(f.bound_lo), num(f.bound_hi), num(mr.h_lambda[i]));
      }
      // the theory's two limits, each over the sweep's first two and last two values
      std::string t = "# stiffness order: the non-stiff limit, then the stiff one\n";
      const std::size_t n = v.size();
      t += fmt::format("{} {}\n{} {}\n\n\n", num(v[0]), mr.theory.classical, num(v[std::min<std::size_t>(1, n - 1)]), mr.theory.classical);
      if (mr.theory.stiff >= 0) t += fmt::format("{} {}\n{} {}\n", num(v[n >= 2 ? n - 2 : 0]), mr.theory.stiff, num(v[n - 1]), mr.theory.stiff);
      dat.write("stiff_" + name(mr.method) + ".dat", s);
      dat.write("stiff_theory_" + name(mr.method) + ".dat", t);
    }
  }

  // A panel per family, of the methods with a fitted order to draw.
  std::vector<FigureSpec> figures(const ReportData& d) const override {
    const std::vector<double>& v = r_.sweep.values;  // every panel over the whole sweep
    const auto fitted = [&](std::size_t method) {
      for (std::size_t m = 0; m < r_.methods.size(); ++m)
        if (r_.methods[m].method == method)
          for (std::size_t i = 0; i < v.size(); ++i)
            if (r_.sweep.studies[i].fits[m].fit.fitted && !r_.methods[m].past_stable[i]) return true;
      return false;
    };
    return {{"fig12_stiff_order", fmt::format("kmin={}; kmax={}", num(v.front() / 3), num(v.back() * 3)),
             family_panels(d.methods, fitted)}};
  }

  std::string markdown(Page& page) const override {
    const ConvergenceSweep& s = r_.sweep;
    const ConvergenceConfig& c = s.studies.front().config;
    const std::string scene(scene_name(c.scene));
    std::string md = "## " + title() + "\n\n";
    md += fmt::format(
        "A method of order p is often chosen because it is stable at large steps; on a stiff problem its measured order "
        "can fall to its stage order (order reduction; Prothero and Robinson 1974, Hairer and Wanner II, IV.15). Measured "
        "on `{}` ({}), whose exact solution is the same at every stiffness: the order of the largest position error over "
        "t <= {} fitted over {} steps from {} to {}, at stiffness {}. |lambda|, the slower eigenvalue of its mode, "
        "grows as the square root of the stiffness: h |lambda| at the middle step goes from {} to {}. The theory "
        "(`analysis/order_reduction.hpp`): a Runge-Kutta method keeps order p while h |lambda| is small; as it grows, a "
        "stiffly accurate one falls to its stage order q, one with R(infinity) = -1 or |R(infinity)| < 1 to q + 1, one with "
        "R(infinity) = 1 to q once h^2^ |lambda| is large against t; a multistep method's own error O(h^p^ / lambda) "
        "vanishes, leaving the error of its one-step start.\n\n",
        scene, params_text(c.scene, c.params, scene_kernel(c.scene).stiffness_param), c.t_end, s.studies.front().dts.size(),
        dt_text(s.studies.front().dts.front()), dt_text(s.studies.front().dts.back()), words_of(s.values),
        dt_text(middle_h_lambda(0)), dt_text(middle_h_lambda(s.values.size() - 1)));
    md += page.figure("fig12_stiff_order", fmt::format("Fitted order against the stiffness on `{}`, a panel per family; dashed: "
                                                       "the theory's two limits.", scene));
    md += table();
    md += sentences();
    md += "\n\n";
    return md;
  }

 private:
  OrderReduction r_;

  static std::string words_of(const std::vector<double>& v) {
    std::vector<std::string> out;
    for (double x : v) out.push_back(fmt::format("{:g}", x));
    return and_list(out);
  }

  // h |lambda| at the sweep's middle step for value i.
  double middle_h_lambda(std::size_t i) const {
    const std::vector<double>& dts = r_.sweep.studies[i].dts;
    return std::sqrt(dts.front() * dts.back()) * r_.rates[i];
  }

  // Narrow enough for the page: the orders, and one column for the two limits (their bounds are
  // in data/stiff_order.json). The separator's dashes set pandoc's column widths.
  std::string table() const {
    const ConvergenceSweep& s = r_.sweep;
    std::string md = "| method | p | stiff |", rule = "|----------------------|--|--|";
    for (double v : s.values) md += fmt::format(" {:g} |", v), rule += "---:|";
    md += " limits |\n" + rule + "------------|\n";
    bool starred = false;
    for (std::size_t m = 0; m < r_.methods.size(); ++m) {
      const MethodReduction& mr = r_.methods[m];
      md += fmt::format("| `{}` | {} | {} |", name(mr.method), mr.theory.classical, mr.theory.stiff >= 0 ? std::to_string(mr.theory.stiff) : "-");
      for (std::size_t v = 0; v < s.studies.size(); ++v) {
        md += fmt::format(" {}{} |", order_or_dash(s.studies[v].fits[m].fit), mr.past_stable[v] ? "\\*" : "");
        starred |= mr.past_stable[v];
      }
      md += fmt::format(" {} / {} |\n", limit_word(mr.non_stiff, true), limit_word(mr.stiff, mr.theory.stiff >= 0));
    }
    md += "\nLimits: the non-stiff one (the first stiffness) / the stiff one (the last), each *holds* when the order is within "
          "0.05 / 0.15 of the theory's and its bound contains it, in that limit's regime.";
    if (starred) md += " \\*: the fit's steps reach past the method's largest stable step dt* on this mode (from its step map): "
                       "stable and growing runs mixed, not an order of the method (left out of the figure).";
    return md + "\n\n";
  }

  // The findings, from the checks: who keeps its order, who falls and to what (with the
  // transition), whose stiff limit these steps do not reach, who is not stable there at all.
  std::string sentences() const {
    std::vector<std::string> keep, fall, rise, unreached, differs, unstable;
    for (const MethodReduction& mr : r_.methods) {
      const StiffTheory& t = mr.theory;
      const std::string n = fmt::format("`{}`", name(mr.method));
      if (t.stiff < 0) {
        unstable.push_back(n);
        continue;
      }
      if (!mr.stiff.reached || !mr.stiff.fitted) {
        unreached.push_back(fmt::format("{} ({}{})", n, mr.stiff.fitted ? fmt::format("{:.2f} at the largest stiffness, ", mr.stiff.order) : "",
                                        t.long_run > 0 ? fmt::format("R(infinity) = 1 needs h^2^ |lambda| >= {:g} t", t.long_run)
                                                       : std::string("h |lambda| too small")));
        continue;
      }
      if (!mr.stiff.holds || !mr.non_stiff.holds) {
        differs.push_back(fmt::format("{} ({:.2f} and {:.2f} against {} and {})", n, mr.non_stiff.order, mr.stiff.order, t.classical, t.stiff));
        continue;
      }
      const auto x = [](double v) { return std::isnan(v) ? std::string("?") : dt_text(v); };
      const std::string change = fmt::format("{} from {:.2f} to {:.2f} (kept up to h |lambda| = {}, at the stiff order from {})", n,
                                             mr.non_stiff.order, mr.stiff.order, x(mr.keeps_to), x(mr.reduced_from));
      if (t.stiff == t.classical) keep.push_back(fmt::format("{} ({:.2f})", n, mr.stiff.order));
      else (t.stiff < t.classical ? fall : rise).push_back(change);
    }
    std::string md;
    if (!keep.empty()) md += fmt::format("**Keep their order** at every stiffness, as theory says: {}. ", and_list(keep));
    if (!fall.empty()) md += fmt::format("**Fall** to the theory's stiff order: {}. ", and_list(fall));
    if (!rise.empty())
      md += fmt::format("**Gain** an order in the largest error, as the theory says of a multistep method whose own error "
                        "vanishes as 1 / lambda while its one-step start's stays: {}. ", and_list(rise));
    if (!unreached.empty()) md += fmt::format("The stiff limit is not reached at these steps for {}. ", and_list(unreached));
    if (!differs.empty()) md += fmt::format("**Differ from the theory**: {}. ", and_list(differs));
    if (!unstable.empty()) md += fmt::format("Not stable as h |lambda| grows: {}: they have orders only where the stiffness is low "
                                             "enough, and no stiff limit.", and_list(unstable));
    return md;
  }
};

}  // namespace

std::unique_ptr<Section> make_stiff_order_section() { return std::make_unique<StiffOrder>(); }

}  // namespace steplab
