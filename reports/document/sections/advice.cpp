// What to use when: the report's closing advice, each line drawn from the same data as the
// answers (findings.hpp) and shown only where the report ran the study it rests on.
#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/peers/peers.hpp"
#include "reports/studies/studies.hpp"
#include "reports/document/claims.hpp"
#include "reports/document/figure_styles.hpp"
#include "reports/document/findings.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"
#include "reports/document/sections/long_time.hpp"

namespace steplab {
namespace {

// A long run of a conservative system: the methods whose energy stayed bounded, by order.
std::string long_runs(const ReportData& d, Ledger* l) {
  std::vector<EnergyBehaviour> bounded;
  for (const EnergyBehaviour& e : energy_behaviour(d))
    if (e.kind == EnergyKind::Bounded) bounded.push_back(e);
  if (bounded.empty()) return {};
  std::sort(bounded.begin(), bounded.end(), [](const EnergyBehaviour& a, const EnergyBehaviour& b) {
    return std::pair(method_info(a.method).order, a.method) < std::pair(method_info(b.method).order, b.method);
  });
  std::vector<std::string> items;
  for (const EnergyBehaviour& e : bounded)
    items.push_back(fmt::format("`{}` (order {}{}, E/E0 within [{:.4g}, {:.4g}])", name(e.method), method_info(e.method).order,
                                method_info(e.method).symplectic ? ", symplectic" : "", e.lo, e.hi));
  std::string md = fmt::format("- **A long run of an undamped system** (energy must not drift): {}, measured over t = {:g} at dt = {}.",
                               and_list(items), d.config.energy_t_end, d.config.large_dt);
  std::vector<std::size_t> bounded_methods;
  for (const EnergyBehaviour& e : bounded) bounded_methods.push_back(e.method);
  if (l) claim_energy(*l, d, "advice.long_run.energy", "advice", md, EnergyKind::Bounded, bounded_methods);
  // Over many periods of a nonlinear orbit, where the report ran it: bounded by structure.
  const LongTimeResult& orbit = d.long_time_orbit;
  if ((d.studies & kLongTimeStudy) && !orbit.rows.empty()) {
    const LongTimeSides s = sides(orbit);
    std::vector<std::string> kept_bounded;
    for (const LongTimeRow& row : orbit.rows)
      if (std::find(s.bounded.begin(), s.bounded.end(), row.method) != s.bounded.end())
        kept_bounded.push_back(fmt::format("`{}` (energy error {:.2g}, growth {})", name(row.method), row.error[0].back(),
                                           growth_text(row.growth[0])));
    md += fmt::format(" Over {:g} periods of {} at {} steps a period: {}.", orbit.config.periods,
                      scene_kernel(orbit.config.scene).title, orbit.config.steps_per_period.front(), kept_bounded.empty() ? "none stays bounded" : and_list(kept_bounded));
    if (l) claim_long_time(*l, orbit, "long_time", "advice.long_run.orbit", "advice", md, EnergyVerdict::Bounded, s.bounded);
  } else {
    md += " A method whose energy drifts here will drift further over a longer run.";
  }
  return md + "\n";
}

// Accuracy at a price: the cheapest solver at the loosest and the tightest error level on a scene.
std::string cheapest_at(const ReportData& d, const SceneWork& w, std::string_view what, Ledger* l) {
  const bool timed = d.config.timing;
  const std::vector<double>& levels = d.work.config.error_levels;
  std::vector<std::string> parts;
  std::vector<std::pair<double, LevelWinner>> wins;
  for (double level : {levels.front(), d.work.config.crossover_error, levels.back()}) {
    const LevelWinner win = level_winner(w, level, timed);
    if (!win.point) continue;
    parts.push_back(fmt::format("to error {:.0e} {}", level, winner_words(win)));
    wins.emplace_back(level, win);
  }
  if (parts.empty()) return {};
  const std::string md = fmt::format("- **{}** ({}): {}, the cheapest by {} of every fixed-step method and adaptive solver tried.\n",
                                     what, scene_name(w.scene), and_list(parts), timed ? "run time" : "force evaluations");
  if (l)
    for (const auto& [level, win] : wins)
      claim_cheapest(*l, d, fmt::format("advice.cheapest.{}.{:.0e}", scene_name(w.scene), level), "advice", md, w, level, timed, win);
  return md;
}

std::string accuracy(const ReportData& d, Ledger* l) {
  const WorkPrecisionResult& r = d.work;
  std::string md;
  for (std::size_t i = 0; i < r.scenes.size(); ++i)
    md += cheapest_at(d, r.scenes[i], static_cast<int>(i) == r.stiff ? "A stiff system" : "A smooth, non-stiff system", l);
  if (r.crossover_ratio > 0 && d.config.timing) {  // untimed, force evaluations cannot weigh an implicit method's solves
    const std::string line = fmt::format("- **How stiff before implicit pays**: on the chain, from stiffness ratio {:g} on an "
                                         "implicit method is the cheaper at error {:.0e}.\n", r.crossover_ratio, r.config.crossover_error);
    md += line;
    if (l) claim_crossover(*l, d, "advice.crossover", "advice", line);
  }
  return md;
}

// A large system: the group that wins most cells of the map at each target (clear wins only).
std::string large_systems(const ReportData& d, Ledger* l) {
  if (!d.scaling_map) return {};
  const ScalingResult& r = *d.scaling_map;
  const ScalingConfig& c = r.config;
  const std::size_t nk = r.blocks.size() / c.targets.size();
  std::vector<std::string> parts;
  std::vector<MapTally> tallies;
  for (std::size_t t = 0; t < c.targets.size(); ++t) {
    MapTally tally = map_tally(r, t);
    int won = 0;
    std::vector<std::string> groups;
    for (const auto& [group, n] : tally.wins) won += n, groups.push_back(fmt::format("{} {}", group, n));
    parts.push_back(fmt::format("at error {}: {} of {} cells{}, {} ties{}", target_text(c, r.blocks[t * nk]), won == 0 ? "none" : std::to_string(won),
                                tally.cells, groups.empty() ? "" : " (" + and_list(groups) + ")", tally.ties,
                                tally.still > 0 ? fmt::format(", {} where the body moves less than the target", tally.still) : ""));
    tallies.push_back(std::move(tally));
  }
  if (parts.empty() || !c.timing) return {};
  const std::string md = fmt::format("- **A large system** ({} of up to {} masses, stiffened up to {:g} times): the cells where one "
                                     "solver is the cheapest by more than the timing's noise (\"When does implicit pay?\"): {}.\n",
                                     scene_kernel(scene_index(c.scene)).title, scaling_masses(c, c.sizes.back()),
                                     c.stiffnesses.back() / c.stiffnesses.front(), fmt::join(parts, "; "));
  for (std::size_t t = 0; l && t < tallies.size(); ++t) claim_map(*l, r, t, fmt::format("advice.map.target_{}", t), "advice", md, tallies[t]);
  return md;
}

// Contact: the methods that keep the undamped bounce's energy within 1 % at the largest step (not
// in the hand-in, whose collision section shows the falling triangle alone).
std::string contact(const ReportData& d, Ledger* l) {
  const CollisionResult& r = d.collision;
  if (r.bounce.empty() || d.config.hand_in()) return {};
  const double dt = *std::max_element(r.config.dts.begin(), r.config.dts.end());
  std::vector<std::size_t> kept, lost;
  for (const CollisionRun& run : r.bounce)
    if (run.dt == dt && run.status == RunStatus::Ok && !run.bounces.empty())
      (run.bounces.back().energy_ratio >= 0.99 && run.bounces.back().energy_ratio <= 1.01 ? kept : lost).push_back(run.method);
  if (kept.empty()) return {};
  const std::string md = fmt::format("- **Contact with a penalty ground**: at dt = {} the undamped bounce keeps its energy within 1 % "
                                     "with {}; {} gain or lose more.\n", dt, method_list(kept), method_list(lost));
  if (l) {
    l->document(kCollisionDocument, [&] { return collision_json(r); });
    claim_members(*l, claim_text("advice.contact", "advice", md), kCollisionDocument, "/bounce", {{"dt", dt}}, "method", true,
                  test_all({test_field("/status", "==", "ok"), test_field("/energy_ratio_last_bounce", ">=", 0.99),
                            test_field("/energy_ratio_last_bounce", "<=", 1.01)}),
                  method_names(kept));
  }
  return md;
}

// The sheet's spring at its large step: stable there with and without the spring's damping (the
// stability sweep's runs) and its energy bounded (the undamped long run at that step).
std::string sheet_step(const ReportData& d, const Findings& f, Ledger* l) {
  const std::vector<EnergyBehaviour> e = energy_behaviour(d);
  const auto stable_at = [&](std::size_t m, double damping) {
    const SweepRow* r = find_sweep(d, m, d.config.large_dt, damping);
    return r && r->run.stable();
  };
  std::vector<std::size_t> good;
  for (std::size_t i : f.numerical) {
    const std::size_t m = f.rows[i].method;
    const auto b = std::find_if(e.begin(), e.end(), [&](const EnergyBehaviour& x) { return x.method == m; });
    if (stable_at(m, 0.0) && stable_at(m, d.config.damping()) && b != e.end() && b->kind == EnergyKind::Bounded) good.push_back(m);
  }
  if (good.empty()) return {};
  const std::string md = fmt::format("- **The sheet's spring at dt = {}**: stable there with and without damping and its energy "
                                     "bounded: {}.\n",
                                     d.config.large_dt, method_list(good));
  if (l) claim_sheet_step(*l, d, "advice.sheet_step", "advice", md, good);
  return md;
}

class Advice : public Section {
 public:
  std::string title() const override { return "What to use when"; }
  std::string markdown(Page& page) const override {
    const ReportData& d = page.data;
    std::string md;
    if ((d.studies & kFindings) == kFindings) md += sheet_step(d, page.findings, page.ledger) + long_runs(d, page.ledger);
    if (d.studies & kWorkPrecisionStudy) md += accuracy(d, page.ledger);
    if (d.studies & kScalingStudy) md += large_systems(d, page.ledger);
    if (d.studies & kCollisionStudy) md += contact(d, page.ledger);
    if (md.empty()) return "## " + title() + "\n\nThis report ran none of the studies the advice rests on.\n\n";
    return "## " + title() + "\n\nDrawn from the measurements above, each with the data it rests on:\n\n" + md + "\n";
  }
};

}  // namespace

std::unique_ptr<Section> make_advice_section() { return std::make_unique<Advice>(); }

}  // namespace steplab
