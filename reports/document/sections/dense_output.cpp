// Output between steps: each fixed-step method's state inside its steps (core/dense_output.hpp),
// the order of that output measured beside the order of its steps on the sheet's spring
// (analysis/studies/dense_output.hpp). The scaling study's frames and the map use it.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/dense_output.hpp"
#include "analysis/studies/defaults.hpp"
#include "reports/data/inputs.hpp"
#include "reports/studies/studies.hpp"
#include "reports/document/report.hpp"
#include "reports/document/claims.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"

namespace steplab {
namespace {

// A fitted order within this of theory keeps it: the fitted step orders' own spread on an
// eight-point sweep.
constexpr double kKept = 0.15;

std::string fitted_text(const OrderFit& f) {
  if (f.exact) return "exact";
  return f.fitted ? fmt::format("{:.2f} [{:.2f}, {:.2f}]", f.order, f.bound_lo, f.bound_hi) : "-";
}

class DenseOutputSection : public Section {
 public:
  std::string title() const override { return "Output between steps"; }
  std::string missing(const ReportConfig& c) const override { return uncovered(c, {scene_index(kSheetOscillator)}); }
  void study(const ReportData& d) override {
    DenseOutputConfig c;
    c.scene = scene_index(kSheetOscillator);
    c.params = default_param_values(c.scene);
    c.methods = dense_output_methods(c.scene, d.numerical_methods());
    c.workers = d.workers;
    r_ = dense_output_study(c);
  }
  void write_data(const ReportData&, const DataDir& dat) const override {
    dat.write("dense_output.json", dense_output_json(r_).dump(1) + "\n");
  }
  std::string markdown(Page& page) const override {
    const DenseOutputConfig& c = r_.config;
    std::string md = fmt::format("## {}\n\n", title());
    if (page.ledger)
      page.ledger->theory("dense_output", "Theory: the output's order is min(p, 4) for the cubic and min(p, 6) for the quintic.");
    md += fmt::format(
        "A frame, a plotted point or a contact between two steps needs the state there. Each fixed-step method gives it from "
        "its step's two ends by Hermite interpolation: from the positions and velocities (a cubic, no force evaluated) below "
        "order 3, and with the accelerations too (a quintic: the accelerations at the step's two ends, the start's kept from the step before where "
        "that one held an output too) from order 3 up; Radau IIA and Gauss-Legendre too, whose own collocation polynomial is of order 3 and 2 inside the step. Theory: "
        "the output's order is min(p, 4) for the cubic and min(p, 6) for the quintic{}. "
        "Measured on the {} ({}) to t = {:g}, the largest position error at the steps and at {} evenly spaced times that fall "
        "inside them (a prime number of intervals), over steps {:g} .. {:g}. ",
        std::all_of(r_.fits.begin(), r_.fits.end(), [](const DenseOutputFit& f) { return f.predicted == f.declared; })
            ? ", the step's own p for every method here"
            : "",
        scene_name(c.scene), params_text(c.scene, c.params), c.t_end, c.outputs, c.dt_max, c.dt_min);
    // the orders go to data/dense_output/ (a table of fifteen rows repeating one finding would
    // not earn its half page); the text gives the finding and its largest exception
    std::vector<std::string> kept, lost, kept_names, fitted_names;  // the names: the claims' sets
    const DenseOutputFit* widest = nullptr;  // the largest gap between the two fitted orders
    const auto gap = [](const DenseOutputFit& f) { return std::abs(f.outputs.order - f.steps.order); };
    for (const DenseOutputFit& f : r_.fits) {
      const bool keeps = f.outputs.fitted && std::abs(f.outputs.order - f.predicted) <= kKept;
      (keeps ? kept : lost).push_back(fmt::format("`{}` ({})", name(f.method), fitted_text(f.outputs)));
      if (keeps) kept_names.push_back(name(f.method));
      if (f.outputs.fitted && f.steps.fitted) {
        fitted_names.push_back(name(f.method));
        if (!widest || gap(f) > gap(*widest)) widest = &f;
      }
    }
    const std::size_t start = md.size();
    if (page.ledger) page.ledger->document(kDenseOutputDocument, [&] { return dense_output_json(r_); });
    if (lost.empty()) {
      md += fmt::format("Between steps every one of the {} methods keeps the order of its steps, within {:g} of theory", kept.size(), kKept);
      if (widest) {
        md += fmt::format(" (the largest gap between the two fitted orders: {:.3f}, `{}`, {:.3f} between steps against {:.3f} at them)",
                          gap(*widest), name(widest->method), widest->outputs.order, widest->steps.order);
        if (page.ledger)  // every gap at most the largest as printed (to 3 decimals)
          claim_members(*page.ledger, claim_text("dense_output.largest_gap", "dense_output", md.substr(start)), kDenseOutputDocument,
                        "/fits", Json::object(), "method", true,
                        test_difference("/outputs/order", "/steps/order", "<=", std::stod(fmt::format("{:.3f}", gap(*widest))) + 5e-4),
                        fitted_names);
      }
      md += ": the output costs no order. So the scaling study below lets a fixed step be any size and interpolates its frames, "
            "as the adaptive solvers do, rather than making the step divide the frame interval. Each method's two orders with "
            "their bounds are in `data/dense_output/dense_output.json`.\n\n";
    } else {
      md += fmt::format("Between steps {} keep{} the order theory gives {} (within {:g}); {} do{} not.\n\n", and_list(kept),
                        kept.size() == 1 ? "s" : "", kept.size() == 1 ? "it" : "them", kKept, and_list(lost),
                        lost.size() == 1 ? "es" : "");
    }
    if (page.ledger) {
      claim_members(*page.ledger, claim_text("dense_output.kept", "dense_output", md.substr(start)), kDenseOutputDocument, "/fits",
                    Json::object(), "method", true, test_difference("/outputs/order", "/predicted_output_order", "<=", kKept),
                    kept_names);
    }
    return md;
  }

 private:
  static constexpr const char* kDenseOutputDocument = "dense_output/dense_output.json";
  DenseOutputResult r_;
};

}  // namespace

std::unique_ptr<Section> make_dense_output_section() { return std::make_unique<DenseOutputSection>(); }

}  // namespace steplab
