// The hand-in's long run: the sheet's spring swinging in a plane (its equation (1) in two
// dimensions, undamped) over many periods with the hand-in's methods, in one paragraph and one
// figure: which of them keeps the energy bounded and which lets it drift, computed from the runs
// (the full report's "Stable for how long?" has the orbit, the angular momentum and the phase).
#include <algorithm>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "reports/studies/studies.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/claims.hpp"
#include "reports/document/sections/long_time.hpp"

namespace steplab {
namespace {

class HandInLongRun : public Section {
 public:
  std::string title() const override { return "Over a long run"; }
  std::string missing(const ReportConfig& c) const override { return uncovered(c, {scene_index(kLongTimeSheetScene)}); }
  unsigned needs() const override { return kLongTimeStudy; }
  void study(const ReportData& d) override { r_ = d.long_time_swing; }
  void write_data(const ReportData&, const DataDir& dat) const override {
    dat.write(fmt::format("long_time_{}.json", scene_name(r_.config.scene)), long_time_json(r_).dump(1) + "\n");
    write_long_time_data(r_, dat);
  }
  std::vector<FigureSpec> figures(const ReportData&) const override {
    const std::vector<std::string> drawn = drawn_methods();
    if (drawn.empty()) return {};
    return {{"long_time", fmt::format("prefix='lt_{}_'; col=2; ylab='largest relative energy error up to t'", scene_name(r_.config.scene)),
             {{"the sheet spring swinging in a plane", drawn}}}};
  }
  std::string markdown(Page& page) const override {
    const LongTimeConfig& c = r_.config;
    std::string md = fmt::format("## {}\n\n", title());
    md += fmt::format("Stable, but for how long? The sheet's spring swings in a plane ({}: equation (1) in two dimensions, released at "
                      "rest length) for {:g} periods of {:.3g} s at {} steps a period. Every step's energy is read and the largest relative "
                      "error up to t is fitted against t on log-log axes from {:g} periods on (growth exponent near 0: bounded; near 1: "
                      "a drift). ",
                      params_text(c.scene, c.params), c.periods, r_.period, c.steps_per_period.front(), c.fit_from);
    md += structure_answer(r_, page.ledger, "long_run", "long_run") + symmetry_note(r_) + "\n\n";
    if (!drawn_methods().empty())
      md += page.figure("long_time", "The sheet's spring swinging in a plane: the largest relative energy error up to t (in periods). " +
                                         extremes_sentence(r_, page.ledger, "long_run"));
    return md;
  }

 private:
  LongTimeResult r_;

  // The methods with samples to draw.
  std::vector<std::string> drawn_methods() const {
    std::vector<std::string> out;
    for (const LongTimeRow& row : r_.rows)
      if (!row.times.empty()) out.push_back(name(row.method));
    return out;
  }
};

}  // namespace

std::unique_ptr<Section> make_long_run_section() { return std::make_unique<HandInLongRun>(); }

}  // namespace steplab
