// Is the energy kept? The spring over a long run at the sheet's large step, and what it shows
// (findings.hpp, energy_behaviour): bounded for the symplectic methods, a steady drift for the
// others, a blow-up where the step is unstable. Two figures: E/E0 of the sheet's four methods on a
// log axis, undamped and damped, beside the exact flow's (the hand-out's); E/E0 - 1 of every
// method on a linear axis, a panel per family (the atlas's).
//
// E is the oscillation energy about the rest point, E = m v^2 / 2 + k (y - y_eq)^2 / 2 (spring.hpp).
// Undamped it is conserved: the exact E/E0 is 1. Damped, dE/dt = -gamma v^2 <= 0, and over a
// period E falls on average as e^(-gamma t / m).
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "core/scenes/spring.hpp"
#include "analysis/studies/long_time.hpp"
#include "reports/document/claims.hpp"
#include "reports/document/findings.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"

namespace steplab {
namespace {

class Energy : public Section {
 public:
  std::string title() const override { return "Is the energy kept?"; }
  unsigned needs() const override { return kStabilityStudy; }

  void write_data(const ReportData& d, const DataDir& dat) const override {
    for (std::size_t i = 0; i < d.methods.size() && i < d.energy.size(); ++i) {
      if (d.energy[i].samples.empty()) continue;
      const double e0 = d.energy[i].samples.front().energy;
      std::string s = "# t energy_ratio_minus_1\n";
      for (const auto& p : d.energy[i].samples) s += num(p.t) + " " + num(p.energy / e0 - 1) + "\n";
      dat.write("energy_" + name(d.methods[i]) + ".dat", s);
    }
    // The sheet's figure: E/E0 of its methods undamped and damped (finite and positive: a log
    // axis), and the exact flow's.
    for (std::size_t i : sheet_rows(d))
      for (const auto& [runs, file] : {std::pair{&d.energy, "sheet_"}, std::pair{&d.energy_damped, "sheet_damped_"}}) {
        const auto& samples = (*runs)[i].samples;
        std::string s = "# t energy_ratio\n";
        for (const auto& p : samples)
          if (const double r = p.energy / samples.front().energy; std::isfinite(r) && r > 0) s += num(p.t) + " " + num(r) + "\n";
        dat.write(file + name(d.methods[i]) + ".dat", s);
      }
    const ReportScene& osc = d.config.oscillator;
    std::vector<double> undamped = osc.params;
    undamped[static_cast<std::size_t>(scene_kernel(osc.scene).damping_param)] = 0;
    const auto energy = [&](const std::vector<double>& p, double t) {
      const AnyState y = scene_kernel(osc.scene).exact(p, t);
      const Spring s(p);
      return s.energy(Vec<1>::Constant(y.x[0]), Vec<1>::Constant(y.v[0]));
    };
    std::string exact = "# t energy_ratio_undamped energy_ratio_damped\n";
    for (int k = 0; k <= 2000; ++k) {
      const double t = d.config.energy_t_end * k / 2000.0;
      exact += num(t) + " " + num(energy(undamped, t) / energy(undamped, 0)) + " " + num(energy(osc.params, t) / energy(osc.params, 0)) + "\n";
    }
    dat.write("sheet_exact.dat", exact);
  }

  // A panel per family of the methods whose energy stays an energy error (not blown up); the
  // axis spans the largest of their excursions.
  std::vector<FigureSpec> figures(const ReportData& d) const override {
    const std::vector<EnergyBehaviour> e = energy_behaviour(d);
    // the runs the family panels draw: neither damped out nor blown up
    const auto banded = [](const EnergyBehaviour& b) { return b.kind != EnergyKind::Damped && b.kind != EnergyKind::Blows; };
    double reach = 0;
    for (const EnergyBehaviour& b : e)
      if (banded(b)) reach = std::max({reach, b.hi - 1, 1 - b.lo});
    const auto drawn = [&](std::size_t m) {
      for (const EnergyBehaviour& b : e)
        if (b.method == m) return banded(b);
      return false;
    };
    std::vector<FigureSpec> out;
    std::vector<std::string> sheet;
    for (std::size_t i : sheet_rows(d)) sheet.push_back(name(d.methods[i]));
    if (!sheet.empty())
      out.push_back({"energy_sheet", "", {{"undamped", sheet}, {fmt::format("damping {}", d.config.damping()), sheet}}});
    // The family panels, where they add methods to the sheet's.
    const auto beyond = [&](std::size_t m) { return drawn(m) && !method_info(m).exact_flow && std::find(sheet.begin(), sheet.end(), name(m)) == sheet.end(); };
    std::vector<Panel> panels = family_panels(d.methods, drawn);
    if (!panels.empty() && std::any_of(d.methods.begin(), d.methods.end(), beyond)) out.push_back({"energy", fmt::format("reach={}", num(reach > 0 ? 1.1 * reach : 1e-3)), std::move(panels)});
    return out;
  }

  std::string markdown(Page& page) const override {
    const ReportData& d = page.data;
    const ReportConfig& c = d.config;
    const std::vector<EnergyBehaviour> e = energy_behaviour(d);
    std::string md = "## " + title() + "\n\n";
    md += fmt::format("The undamped spring has a conserved energy; a method's E/E0 - 1 over a long run at the sheet's step "
                      "(dt = {}, t = {:g}) is what a long simulation would show. E/E0 on a log axis shows growth and decay by powers of "
                      "ten; E/E0 - 1 on a linear axis (the family panels{}) shows a bounded band and a slow drift. A run "
                      "counts as bounded when the largest |E/E0 - 1| over its second half is at most {:g} times that over its "
                      "first, or within round-off ({:g} u sqrt(steps)); as growing or decaying when that keeps growing, E/E0 above or below 1 at the end; as damped out when "
                      "E/E0 falls below 1/{:g} (the method's own damping), as blown up when it passes {:g} or the state "
                      "diverges.\n\n",
                      c.large_dt, c.energy_t_end, page.handout ? ", in the atlas" : "", kBoundedGrowth, kRoundOff, kBlownRatio, kBlownRatio);
    // A line per kind: its runs, each with what shows it (its range, its drift, where it ended).
    const auto item = [](const EnergyBehaviour& b) {
      const std::string n = fmt::format("`{}`{}", name(b.method), method_info(b.method).symplectic ? " (symplectic)" : "");
      switch (b.kind) {
        case EnergyKind::Bounded:
          return b.hi - b.lo <= 2 * b.round_off ? fmt::format("{} within round-off", n) : fmt::format("{} within [{:.4g}, {:.4g}]", n, b.lo, b.hi);
        case EnergyKind::Grows:
        case EnergyKind::Decays: return fmt::format("{} to {:+.3g} %", n, 100 * (b.final_ratio - 1));
        case EnergyKind::Damped: return fmt::format("{} (E/E0 {:.3g} at the end)", n, b.final_ratio);
        case EnergyKind::Blows: break;
      }
      return b.ended >= 0 ? fmt::format("{} (diverged at t = {:g})", n, b.ended) : fmt::format("{} (E/E0 {:.3g} at the end)", n, b.final_ratio);
    };
    const char* heads[] = {"- **Bounded**: ", "- **Grows** slowly (geometrically: unstable at this step), E/E0 - 1 at the end: ",
                           "- **Decays** slowly (the method's own damping), E/E0 - 1 at the end: ", "- **Damped out** by the method: ",
                           "- **Blows up**: "};  // kEnergyKinds' order
    for (std::size_t k = 0; k < std::size(kEnergyKinds); ++k) {
      std::vector<std::string> items;
      for (const EnergyBehaviour& b : e)
        if (b.kind == kEnergyKinds[k]) items.push_back(item(b));
      if (items.empty()) continue;
      const std::string line = heads[k] + and_list(items) + ".\n";
      md += line;
      if (page.ledger)
        claim_energy(*page.ledger, d, fmt::format("energy.{}", id_word(to_text(kEnergyKinds[k]))), "energy", line, kEnergyKinds[k],
                     methods_of_kind(e, kEnergyKinds[k]));
    }
    if (page.has("energy")) md += "The family panels leave out the runs damped out or blown up.\n";
    std::vector<std::size_t> symplectic, symplectic_unbounded;
    for (const EnergyBehaviour& b : e)
      if (method_info(b.method).symplectic) {
        symplectic.push_back(b.method);
        if (b.kind != EnergyKind::Bounded) symplectic_unbounded.push_back(b.method);
      }
    if (symplectic_unbounded.empty() && !symplectic.empty()) {
      std::vector<std::string> orders;  // "whatever its order" only where the symplectic methods have several
      for (std::size_t m : symplectic)
        if (const std::string o = std::to_string(method_info(m).order); std::find(orders.begin(), orders.end(), o) == orders.end()) orders.push_back(o);
      const std::string finding =
          orders.size() > 1 ? fmt::format("Every symplectic method here keeps its energy bounded, whatever its order ({})", and_list(orders))
                            : fmt::format("The symplectic {} here ({}, order {}) {} its energy bounded", symplectic.size() == 1 ? "method" : "methods",
                                          method_list(symplectic), orders.front(), symplectic.size() == 1 ? "keeps" : "keep");
      const std::string theory =
          "below its step limit dt*, a symplectic step conserves a modified energy H + O(dt^p^) (exactly on this linear "
          "spring), so the true energy stays within O(dt^p^) of its start: for all time here, on a nonlinear system over "
          "exponentially long times (Hairer, Lubich and Wanner, IX.8)";
      md += fmt::format("\n{}. Theory: {}.\n\n", finding, theory);
      if (page.ledger) {
        claim_energy(*page.ledger, d, "energy.symplectic_bounded", "energy", finding, EnergyKind::Bounded, symplectic, true);
        page.ledger->theory("energy", theory);
      }
    } else if (!symplectic_unbounded.empty()) {
      md += fmt::format("\nSymplectic, but its energy not bounded here: {}.\n\n", method_list(symplectic_unbounded));
    } else {
      md += "\n";
    }
    if (page.has("energy_sheet")) md += page.figure("energy_sheet", sheet_caption(d, e));
    if (page.has("energy") && !page.handout) {
      const std::string band = band_sentence(e, page.ledger, d);
      md += page.figure("energy", fmt::format("E/E0 - 1 of the undamped spring at dt = {} over t = {:g}, a panel per family "
                                              "(linear axis). {}", c.large_dt, c.energy_t_end, band));
    }
    return md;
  }

 private:
  // The rows of the sheet's methods among the report's, with samples (not the exact flow: the
  // figure computes that itself).
  static std::vector<std::size_t> sheet_rows(const ReportData& d) {
    std::vector<std::size_t> out;
    for (std::size_t m : sheet_methods())
      for (std::size_t i = 0; i < d.methods.size() && i < d.energy.size() && i < d.energy_damped.size(); ++i)
        if (d.methods[i] == m && !d.energy[i].samples.empty() && !d.energy_damped[i].samples.empty()) out.push_back(i);
    return out;
  }

  // The family figure's sentence of what to see: how high and how low E/E0 reaches among the
  // bounded runs, each an extreme claim over their rows of the energy document.
  static std::string band_sentence(const std::vector<EnergyBehaviour>& e, Ledger* l, const ReportData& d) {
    const auto bounded = [](const EnergyBehaviour& b) { return b.kind == EnergyKind::Bounded; };
    const EnergyBehaviour* high = least_and_most(e, bounded, [](const EnergyBehaviour& b) { return b.hi; }).second;
    const EnergyBehaviour* low = least_and_most(e, bounded, [](const EnergyBehaviour& b) { return b.lo; }).first;
    if (!high) return "No run keeps its energy bounded.";
    constexpr Digits kDigits{true, 3};
    const std::string text = fmt::format("Of the bounded runs, the highest E/E0 is `{}`'s ({}), the lowest `{}`'s ({}).", name(high->method),
                                         printed(high->hi, kDigits), name(low->method), printed(low->lo, kDigits));
    if (l) {  // over the bounded runs' rows of the energy document
      l->document(kEnergyDocument, [&] { return energy_document(d); });
      const auto field = [&](const char* f) {
        return [&, f](const EnergyBehaviour& r, std::size_t) { return row_field(*l, kEnergyDocument, "/rows", {{"method", name(r.method)}}, f); };
      };
      const Kept his = kept_evidence(e, bounded, nullptr, high, field("hi")), los = kept_evidence(e, bounded, low, nullptr, field("lo"));
      claim_extreme(*l, claim_text("energy.band.highest", "energy", text), his.values, his.most, Extreme::Greatest, kDigits);
      claim_extreme(*l, claim_text("energy.band.lowest", "energy", text), los.values, los.least, Extreme::Least, kDigits);
    }
    return text;
  }

  // What the sheet's figure shows, from the kinds the section's list states (and claims) above.
  static std::string sheet_caption(const ReportData& d, const std::vector<EnergyBehaviour>& e) {
    std::vector<std::string> parts;
    for (std::size_t i : sheet_rows(d))
      for (const EnergyBehaviour& b : e)
        if (b.method == d.methods[i]) parts.push_back(fmt::format("`{}` {}", name(b.method), to_text(b.kind)));
    return fmt::format("E/E0 of the sheet's methods at dt = {} over t = {:g} (log axis) beside the exact flow (grey): undamped "
                       "(left) the exact E/E0 is 1; damped (right) the exact energy decays and a method's own damping or "
                       "growth adds to it. Undamped, {}.",
                       d.config.large_dt, d.config.energy_t_end, and_list(parts));
  }
};

}  // namespace

std::unique_ptr<Section> make_energy_section() { return std::make_unique<Energy>(); }

}  // namespace steplab
