// Stability on the spring in detail: dt* predicted from each method's step map against dt*
// measured, at every damping; the energy growth rate against damping at the sheet's step; and
// the measured edge of stability over (dt, damping) against the predicted one.
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

// A measured dt* agrees with the step map's prediction within this, relative (same_within).
constexpr double kAgree = 0.01;

class Stability : public Section {
 public:
  std::string title() const override { return "Stability in detail"; }
  unsigned needs() const override { return kStabilityStudy; }
  void write_data(const ReportData& d, const DataDir& dat) const override {
    dat.write("stability.json", stability_document(d).dump(1) + "\n");  // the claims cite it (claims.hpp)
    for (std::size_t i = 0; i < d.methods.size(); ++i) {
      const std::string m = name(d.methods[i]);
      std::string s = "# damping rate_measured\n";
      for (const SweepRow& r : d.sweep)
        if (r.method == d.methods[i] && r.dt == d.config.large_dt) s += num(r.damping) + " " + num(r.run.rate) + "\n";
      dat.write("sweep_" + m + ".dat", s);
      s = "# damping rate_predicted\n";
      for (std::size_t g = 0; g < d.curve_damping.size(); ++g) s += num(d.curve_damping[g]) + " " + num(d.curve_rate[i][g]) + "\n";
      dat.write("predicted_" + m + ".dat", s);
    }
    // The map's edge per method: at each damping, the measured dt* (the first unstable step of the
    // map's row, every smaller one stable) and the predicted one; where the row is stable again
    // further out, that step too (a block of its own).
    for (std::size_t i = 0; i < d.map.methods.size(); ++i) {
      std::string s = "# damping dt_star_measured dt_star_predicted (index 0); damping stable_again_measured (index 1)\n", again;
      for (std::size_t g = 0; g < d.map.damping.size(); ++g) {
        const std::vector<bool>& row = d.map.stable[i][g];
        const auto first_unstable = std::find(row.begin(), row.end(), false);
        const std::size_t k = static_cast<std::size_t>(first_unstable - row.begin());
        const double measured = k == 0 ? NAN : k == row.size() ? d.map.dt.back() : d.map.dt[k - 1];
        const double predicted = std::min(d.map.boundary[i][g], d.map.dt.back());
        s += num(d.map.damping[g]) + " " + num(measured) + " " + num(predicted > 0 ? predicted : NAN) + "\n";
        const auto back = std::find(first_unstable, row.end(), true);
        if (back != row.end()) again += num(d.map.damping[g]) + " " + num(d.map.dt[static_cast<std::size_t>(back - row.begin())]) + "\n";
      }
      dat.write("edge_" + name(d.map.methods[i]) + ".dat", s + "\n\n" + (again.empty() ? "NaN NaN\n" : again));
    }
  }

  std::vector<FigureSpec> figures(const ReportData& d) const override {
    std::vector<FigureSpec> out;
    const std::vector<Panel> families = family_panels(d.methods);
    if (!families.empty()) out.push_back({"damping", "", families});
    // the edge: the methods with a step of the map where they turn unstable (not those stable throughout)
    const auto has_edge = [&](std::size_t m) {
      const auto it = std::find(d.map.methods.begin(), d.map.methods.end(), m);
      if (it == d.map.methods.end()) return false;
      for (const std::vector<bool>& row : d.map.stable[static_cast<std::size_t>(it - d.map.methods.begin())])
        if (std::find(row.begin(), row.end(), false) != row.end()) return true;
      return false;
    };
    std::vector<Panel> edges = family_panels(d.methods, has_edge);
    if (!edges.empty())
      out.push_back({"maps", fmt::format("dtmin={}; dtmax={}", num(d.map.dt.front()), num(d.map.dt.back())), std::move(edges)});
    return out;
  }

  std::string markdown(Page& page) const override {
    const ReportData& d = page.data;
    const ReportConfig& c = d.config;
    std::vector<double> dampings;
    for (const ThresholdRow& r : d.thresholds)
      if (std::find(dampings.begin(), dampings.end(), r.damping) == dampings.end()) dampings.push_back(r.damping);
    std::sort(dampings.begin(), dampings.end());
    std::string md = "## " + title() + "\n\n";
    md += "dt* measured (predicted from the whole step map's spectral radius, a multistep method's memory included), at each "
          "damping; \"again\": where a method is stable again beyond dt*, measured (predicted).\n\n| method |";
    std::string rule = "|------------|";
    for (double g : dampings) md += fmt::format(" damping {} |", g), rule += "-------|";
    md += "\n" + rule + "\n";
    std::size_t agree = 0;
    std::vector<std::pair<std::size_t, double>> cases;  // (method, damping) of each cell
    for (std::size_t m : d.methods) {
      if (method_info(m).exact_flow) continue;
      md += fmt::format("| `{}` |", name(m));
      for (double g : dampings) {
        const ThresholdRow* r = find_threshold(d, m, g);
        if (!r) {
          md += " - |";
          continue;
        }
        agree += same_within(r->dt_measured, r->dt_theory, kAgree);
        cases.push_back({m, g});
        md += fmt::format(" {} ({}){} |", table_dt(r->dt_measured), table_dt(r->dt_theory),
                          std::isinf(r->again_measured) && std::isinf(r->again_theory)
                              ? ""
                              : fmt::format("; again {} ({})", table_dt(r->again_measured), table_dt(r->again_theory)));
      }
      md += "\n";
    }
    const std::string agreement =
        fmt::format("The measured dt* is within {:g} % of the prediction in {} of these {} cases.", 100 * kAgree, agree, cases.size());
    md += "\n" + agreement + "\n\n";
    if (page.ledger) claim_thresholds_agree(*page.ledger, {d}, "stability.thresholds_agree", "stability", agreement, cases, kAgree, agree);
    const auto measured = [&](const SweepRow& r) { return r.dt == c.large_dt && std::isfinite(r.run.rate); };
    const SweepRow* fastest =  // the fastest measured loss of energy at the figure's dt
        least_and_most(d.sweep, measured, [](const SweepRow& r) { return r.run.rate; }).first;
    if (page.has("damping")) {
      constexpr Digits kRate{true, 3};
      const std::string loss = fastest ? fmt::format("The fastest measured loss: `{}` at damping {:g}, {} per second.", name(fastest->method),
                                                     fastest->damping, printed(fastest->run.rate, kRate))
                                       : std::string("No rate could be fitted.");
      md += page.figure("damping", fmt::format("Energy growth rate d ln E / dt against damping at dt = {}: measured (points), "
                                               "predicted 2 ln(rho) / h from the step map (lines), a panel per family. {}",
                                               c.large_dt, loss));
      if (page.ledger && fastest) {
        std::vector<Json> rows;  // the sweep's rows at the figure's dt with a rate, by their fields
        std::size_t a = 0;
        for (const SweepRow& r : d.sweep)
          if (measured(r)) a = &r == fastest ? rows.size() : a, rows.push_back({{"method", name(r.method)}, {"dt", r.dt}, {"damping", r.damping}});
        claim_stability_extreme(*page.ledger, {d}, claim_text("stability.fastest_loss", "stability", loss), "sweep", rows, a, "rate_measured",
                                Extreme::Least, kRate);
      }
    }
    std::size_t disagree = 0;
    for (std::size_t i = 0; i < d.map.methods.size(); ++i) disagree += disagreeing_cells(d.map, i);
    const std::size_t cells = d.map.methods.size() * d.map.damping.size() * d.map.dt.size();
    const std::string cells_text = fmt::format("Over a grid of {} steps from {} to {} and {} dampings from 0 to {:.3g}, each cell a run: "
                                               "{} of its {} cells disagree with the step map's prediction at that cell.",
                                               d.map.dt.size(), c.stability.map_dt_min, c.stability.map_dt_max, d.map.damping.size(),
                                               d.map.damping.back(), disagree, cells);
    md += cells_text + "\n\n";
    if (page.ledger) claim_map_cells(*page.ledger, {d}, "stability.map_cells", "stability", cells_text, disagree);
    if (page.has("maps"))
      md += page.figure("maps", "The edge of stability over (dt, damping): the measured dt* of each damping's row of runs "
                                "(points: the largest step of the grid with every smaller one stable), the predicted one "
                                "(lines), and where a row is stable again further out (open points), a panel per family. "
                                + fmt::format("{} of the {} cells disagree with the prediction.", disagree, cells));
    return md;
  }
};

}  // namespace

std::unique_ptr<Section> make_stability_section() { return std::make_unique<Stability>(); }

}  // namespace steplab
