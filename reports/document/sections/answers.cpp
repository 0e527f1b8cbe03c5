// The report opens with its answers: each question it asks, answered in a sentence or two
// computed from the data, with the figure or section that shows it. A question is asked only if
// the report ran the study that answers it; "What to use when" closes the report (advice.cpp).
#include <algorithm>
#include <cctype>
#include <cmath>

#include <fmt/format.h>

#include "analysis/studies/defaults.hpp"
#include "analysis/kernel/kernel.hpp"
#include "analysis/peers/peers.hpp"
#include "reports/document/claims.hpp"
#include "reports/document/findings.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"
#include "reports/document/sections/answers.hpp"
#include "reports/document/sections/long_time.hpp"

namespace steplab {
namespace {

// " (figure 3)", " (figures 7 and 8)", or "" where the report draws none of them.
std::string see(const Page& page, const std::vector<std::string>& figures) {
  std::vector<std::string> numbers;
  for (const std::string& f : figures)
    if (const int n = page.number(f)) numbers.push_back(std::to_string(n));
  return numbers.empty() ? "" : fmt::format(" (figure{} {})", numbers.size() > 1 ? "s" : "", and_list(numbers));
}
std::string see(const Page& page, const std::string& figure) { return see(page, std::vector<std::string>{figure}); }

// One list of Findings rows (`Findings::unstable_large`, ...) over the sources, as methods.
std::vector<std::size_t> over(const std::vector<ShownStudy>& s, std::vector<std::size_t> Findings::*list) {
  std::vector<std::size_t> out;
  for (const ShownStudy& x : s)
    for (std::size_t m : methods_of(x.f, x.f.*list)) out.push_back(m);
  return out;
}

std::vector<MethodRate> rates_over(const std::vector<ShownStudy>& s, std::vector<std::size_t> Findings::*list, bool undamped) {
  std::vector<MethodRate> out;
  for (const ShownStudy& x : s)
    for (const MethodRate& r : rates_of(x.f, x.f.*list, undamped)) out.push_back(r);
  return out;
}

std::string stable_answer(const Page& page) {
  const std::vector<ShownStudy> src = shown_studies(page);
  const ReportConfig& c = page.data.config;
  const std::vector<std::size_t> unstable_large = over(src, &Findings::unstable_large),
                                 stable_large = over(src, &Findings::stable_large),
                                 unstable_undamped = over(src, &Findings::unstable_undamped),
                                 always = over(src, &Findings::always_stable);
  std::string md = fmt::format("- **Which method is stable?** On the sheet's spring at its step dt = {} (damping {}) ", c.large_dt, c.damping());
  md += unstable_large.empty() ? "every method is stable"
        : stable_large.empty() ? "no method is stable"
                               : fmt::format("every method is stable but {}", unstable_words(rates_over(src, &Findings::unstable_large, false)));
  md += fmt::format("; without damping, at dt = {}, ", c.small_dt);
  md += unstable_undamped.empty() ? "every one is."
                                  : fmt::format("{} {} not: {} energy grows.", unstable_words(rates_over(src, &Findings::unstable_undamped, true)),
                                                unstable_undamped.size() == 1 ? "is" : "are", unstable_undamped.size() == 1 ? "its" : "their");
  if (!always.empty()) md += fmt::format(" Stable at every step tried: {}.", method_list(always));
  md += " Each method's largest stable step dt* is in the summary table";
  md += page.has("regions") ? fmt::format(", the stability regions of the methods that have one in figure {}.", page.number("regions"))
                            : std::string(".");
  if (Ledger* l = page.ledger)
    for (const ShownStudy& x : src) {
      const StabilitySource s = x.study;
      claim_unstable_at(*l, s, fmt::format("answers.unstable_at_large_dt{}", x.id), "answers", md, c.large_dt, c.damping(),
                        methods_of(x.f, x.f.unstable_large));
      claim_unstable_at(*l, s, fmt::format("answers.unstable_undamped{}", x.id), "answers", md, c.small_dt, 0.0,
                        methods_of(x.f, x.f.unstable_undamped));
      const std::vector<MethodRate> large = rates_of(x.f, x.f.unstable_large, false), undamped = rates_of(x.f, x.f.unstable_undamped, true);
      claim_unstable_runs(*l, s, "answers", fmt::format("at_large_dt{}", x.id), md, c.large_dt, c.damping(), large, false);
      claim_unstable_runs(*l, s, "answers", fmt::format("undamped{}", x.id), md, c.small_dt, 0.0, undamped, false);
      claim_unbounded_at(*l, s, fmt::format("answers.stable_at_every_step{}", x.id), "answers", md, c.damping(),
                         methods_of(x.f, x.f.always_stable));
    }
  return md + "\n";
}

std::string order_answer(const Page& page) {
  const Findings& f = page.findings;
  const ReportConfig& c = page.data.config;
  std::string md = "- **Is stability correlated with the order?** ";
  // With the methods on springs that claim an order (PBD claims none: its stiffness is set at one step).
  std::vector<StabilityPoint> pooled;
  std::vector<double> order, dt;  // of the pooled points
  for (const ShownStudy& x : shown_studies(page))
    for (std::size_t i : x.f.numerical)
      if (&x.f == &f || method_info(x.f.rows[i].method).order > 0) {
        pooled.push_back({x.study, x.f.rows[i].method});
        order.push_back(method_info(x.f.rows[i].method).order);
        dt.push_back(x.f.rows[i].dt_measured);
      }
  const bool with_springs = pooled.size() > f.spearman_n;
  const double rho_all = with_springs ? spearman(order, dt) : NAN;
  if (f.spearman_n >= 3) {
    md += fmt::format("{}: over the {} ODE methods, Spearman's rank correlation between the order and dt* (damping {}) is "
                      "{:.2f}, {}, {}",
                      std::abs(f.spearman) < 0.3 ? "Not as a rule" : "Only loosely", f.spearman_n, c.damping(), f.spearman,
                      correlation_words(f.spearman), chance_words(f.spearman, f.spearman_n));
    if (with_springs)
      md += fmt::format("; with the {} methods on springs that claim an order, over {}, it is {:.2f}, {}", pooled.size() - f.spearman_n,
                        pooled.size(), rho_all, chance_words(rho_all, pooled.size()));
    const bool chance = std::abs(f.spearman) <= 1.96 / std::sqrt(f.spearman_n - 1.0) &&
                        (!with_springs || std::abs(rho_all) <= 1.96 / std::sqrt(pooled.size() - 1.0));
    md += chance ? ": no correlation is detectable." : ".";
  }
  std::vector<std::string> ways;
  const std::vector<FamilyTrend> trends = family_trends(page.data, c.damping());
  for (Trend t : {Trend::Rises, Trend::Falls, Trend::StaysInfinite, Trend::Mixed, Trend::StaysTheSame, Trend::NotMeasured}) {
    std::vector<std::string> fams;
    for (const FamilyTrend& ft : trends)
      if (ft.trend == t) fams.emplace_back(to_string(ft.family));
    if (!fams.empty()) ways.push_back(fmt::format("{} in {}", to_text(t), and_list(fams)));
  }
  if (!ways.empty())
    md += fmt::format(" Within a family, whose methods share a construction, at damping {}, dt* {}: how a method is built sets its "
                      "stability more than its order does{}.",
                      c.damping(), and_list(ways),
                      page.has("regions") ? fmt::format(" (figure {} draws the regions of the methods that have one)", page.number("regions")) : "");
  if (Ledger* l = page.ledger) {
    if (f.spearman_n >= 3) claim_spearman(*l, spearman_points({page.data}, f), f.spearman, "answers.order_correlation", "answers", md, 2);
    if (f.spearman_n >= 3 && with_springs) claim_spearman(*l, pooled, rho_all, "answers.order_correlation.with_springs", "answers", md, 2);
    for (const FamilyTrend& ft : trends)
      claim_family_trend(*l, {page.data}, fmt::format("answers.trend.{}", id_word(to_string(ft.family))), "answers", md, ft, c.damping());
  }
  return md + "\n";
}

std::string energy_answer(const Page& page) {
  const std::vector<EnergyBehaviour> e = energy_behaviour(page.data);
  if (e.empty()) return {};
  const ReportConfig& c = page.data.config;
  const std::vector<std::size_t> bounded = methods_of_kind(e, EnergyKind::Bounded), grows = methods_of_kind(e, EnergyKind::Grows),
                                 decays = methods_of_kind(e, EnergyKind::Decays), damped = methods_of_kind(e, EnergyKind::Damped),
                                 blown = methods_of_kind(e, EnergyKind::Blows);
  std::string md = fmt::format("- **Is the energy kept?** Undamped over t = {:g} at dt = {}: ", c.energy_t_end, c.large_dt);
  std::vector<std::string> parts;
  if (!bounded.empty()) parts.push_back(fmt::format("E/E0 stays bounded for {}", method_list(bounded)));
  if (!grows.empty()) parts.push_back(fmt::format("it grows slowly (unstable at this step) for {}", method_list(grows)));
  if (!decays.empty()) parts.push_back(fmt::format("it decays slowly (the method's own damping) for {}", method_list(decays)));
  if (!damped.empty()) parts.push_back(fmt::format("the method damps it out for {}", method_list(damped)));
  if (!blown.empty()) parts.push_back(fmt::format("it blows up for {}", method_list(blown)));
  md += and_list(parts);
  std::vector<std::size_t> symplectic;
  for (std::size_t m : bounded)
    if (method_info(m).symplectic) symplectic.push_back(m);
  if (!symplectic.empty())
    md += fmt::format("; of the bounded ones {} {} symplectic", method_list(symplectic), symplectic.size() == 1 ? "is" : "are");
  md += fmt::format("{}.\n", see(page, "energy"));
  if (Ledger* l = page.ledger) {
    for (EnergyKind kind : kEnergyKinds)
      claim_energy(*l, page.data, fmt::format("answers.energy.{}", id_word(to_text(kind))), "answers", md, kind, methods_of_kind(e, kind));
    if (!symplectic.empty()) claim_energy(*l, page.data, "answers.energy.bounded_symplectic", "answers", md, EnergyKind::Bounded, symplectic, true);
  }
  return md;
}

}  // namespace

// Stable for how long: the orbit's runs by their energy error, and whether the structure or the order decides.
std::string long_time_answer(const Page& page) {
  const LongTimeResult& r = page.data.long_time_orbit;
  const LongTimeSides s = sides(r);
  std::string md = fmt::format("- **Stable for how long?** Over {:g} periods of {} the energy error stays bounded with {} and "
                               "drifts with {}",
                               r.config.periods, scene_kernel(r.config.scene).title, method_list(s.bounded), method_list(s.drifting));
  if (!s.lost.empty()) md += fmt::format("; {} {} the orbit", method_list(s.lost), s.lost.size() == 1 ? "loses" : "lose");
  md += ".";
  if (s.not_by_order)
    md += fmt::format(" Bounded are the symplectic ones, whatever their order: `{}` (order {}) drifts, `{}` (order {}) does not.",
                      name(*s.high_drift), method_info(*s.high_drift).order, name(*s.low_bounded), method_info(*s.low_bounded).order);
  if (!page.handout)  // the hand-out's brief section is that section
    md += fmt::format(" The growth exponents, the angular momentum and the phase are in \"Stable for how long?\"{}.", see(page, "long_time"));
  md += "\n";
  if (page.ledger) claim_long_time_sides(*page.ledger, r, s, "long_time", "answers.long_time", "answers", md);
  return md;
}

std::string stiff_answer(const Page& page) {
  std::vector<std::size_t> keep, unstable;
  std::vector<std::string> falls, rises, strays;
  for (const StiffClaim& s : stiff_claims(page.data.stiff_order)) {
    if (s.verdict == StiffVerdict::Keeps) keep.push_back(s.method);
    else if (s.verdict == StiffVerdict::Unstable) unstable.push_back(s.method);
    else if (s.verdict == StiffVerdict::Falls) falls.push_back(fmt::format("`{}` from {} to {}", name(s.method), s.p, s.stiff));
    else if (s.verdict == StiffVerdict::Rises) rises.push_back(fmt::format("`{}` from {} to {}", name(s.method), s.p, s.stiff));
    else if (s.verdict == StiffVerdict::Strays)
      strays.push_back(fmt::format("`{}` keeps {} in both limits but reaches {:.2f} between them", name(s.method), s.p, s.stray_order));
  }
  std::vector<std::string> parts;
  if (!keep.empty()) parts.push_back(fmt::format("{} keep their order at every stiffness", method_list(keep)));
  if (!falls.empty()) parts.push_back(fmt::format("it falls, as the theory says, for {}", and_list(falls)));
  if (!rises.empty()) parts.push_back(fmt::format("it rises, to the order of its one-step starter's local error, for {}", and_list(rises)));
  if (!strays.empty()) parts.push_back(and_list(strays));
  if (!unstable.empty()) parts.push_back(fmt::format("{} lose stability before the stiff limit", method_list(unstable)));
  if (parts.empty()) return {};
  std::string md = "- **Does the order hold when stiff?** ";
  for (std::size_t i = 0; i < parts.size(); ++i) md += (i ? "; " : "") + parts[i];
  md += fmt::format("{}.\n", see(page, "stiff_order"));
  if (page.ledger) claim_stiff(*page.ledger, page.data, "answers.stiff", "answers", md, stiff_claims(page.data.stiff_order));
  return md;
}

// At the report's crossover error: the cheapest run on each scene (a tie named as one), and on
// the stiff scene steplab's cheapest implicit method against the cheapest adaptive implicit peer
// (CVODE, ARKODE's DIRK tables, RADAU5).
std::string cost_answer(const Page& page) {
  const WorkPrecisionResult& r = page.data.work;
  const bool timed = page.data.config.timing;
  const double level = r.config.crossover_error;
  std::vector<std::string> parts;
  std::vector<std::pair<const SceneWork*, LevelWinner>> wins;
  for (const SceneWork& w : r.scenes) {
    const LevelWinner win = level_winner(w, level, timed);
    if (!win.point) continue;
    wins.emplace_back(&w, win);
    parts.push_back(fmt::format("{} the {} the cheapest run to error {:.0e} is {} ({})", parts.empty() ? "On" : "on", scene_name(w.scene), level,
                                winner_words(win),
                                cost_text(timed, win.point->seconds, win.point->force_evaluations)));
  }
  if (parts.empty()) return {};
  std::string md = "- **What does accuracy cost?** " + and_list(parts);
  if (r.stiff >= 0) {
    const SceneWork& w = r.scenes[static_cast<std::size_t>(r.stiff)];
    const std::vector<PeerComparison> against = implicit_against_peers(r, w, level, timed);
    const PeerComparison* best = nullptr;
    for (const PeerComparison& c : against)
      if (c.steplab && c.run && (!best || point_cost(*c.run, timed) < point_cost(*best->run, timed))) best = &c;
    if (best) {
      // A measured ratio, no verdict: which peer and which method are cheapest is this run's pick
      // (the table of cheapest runs says where they tie).
      const double ratio = point_cost(*best->run, timed) / point_cost(*best->steplab, timed);
      constexpr Digits digits{true, 3};
      const std::string part = fmt::format(
          "; against steplab's cheapest implicit method, `{}` ({} steps), the adaptive implicit peer cheapest in this run, `{}` "
          "({}), takes {} steps at {} times its cost",
          best->steplab->method, best->steplab->steps, best->peer, find_peer(best->peer)->library(), best->run->steps,
          printed(ratio, digits));
      md += part;
      if (page.ledger) {
        const char* field = point_cost_field(timed);
        claim_ratio(*page.ledger, claim_text("answers.peer_cost", "answers", part),
                    {{work_point_at(*page.ledger, page.data, w, *best->run, field)}, {work_point_at(*page.ledger, page.data, w, *best->steplab, field)}},
                    ratio, digits);
      }
    }
  }
  std::vector<std::string> figures;  // a work-precision figure per scene
  for (const SceneWork& w : page.data.work.scenes) figures.push_back(work_precision_figure(w.scene));
  md += see(page, figures) + ".\n";
  if (page.ledger)
    for (const auto& [w, win] : wins)
      claim_cheapest(*page.ledger, page.data, fmt::format("answers.cheapest.{}", scene_name(w->scene)), "answers", md, *w, level, timed, win);
  return md;
}

std::string implicit_answer(const Page& page) {
  if (!page.data.scaling_map) return {};
  const ScalingResult& r = *page.data.scaling_map;
  const ScalingConfig& c = r.config;
  const std::size_t nk = r.blocks.size() / c.targets.size();
  std::vector<std::string> parts;
  std::vector<MapTally> tallies;
  for (std::size_t t = 0; t < c.targets.size(); ++t) {
    const MapTally& m = tallies.emplace_back(map_tally(r, t));
    std::vector<std::string> aside;
    if (m.ties) aside.push_back(fmt::format("in {} two groups tie{}", m.ties, c.timing ? "" : " or it is undecided"));
    if (m.still) aside.push_back(fmt::format("in {} the body moves less than the target, a win for no one", m.still));
    parts.push_back(fmt::format("at error {}, in {} of {} cells{}", target_text(c, r.blocks[t * nk]), m.implicit.size(), m.cells,
                                aside.empty() ? "" : fmt::format(" ({})", fmt::join(aside, "; "))));
  }

  std::string title(scene_kernel(scene_index(c.scene)).title);
  title[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(title[0])));
  const std::string md =
      fmt::format("- **When does implicit pay?** On the {} grown from N = {} to {} and stiffened {:g} times over, an implicit "
                  "fixed-step method is clearly the cheapest solver {}{}.\n",
                  title, scaling_masses(c, c.sizes.front()), scaling_masses(c, c.sizes.back()),
                  c.stiffnesses.back() / c.stiffnesses.front(), fmt::join(parts, "; "), see(page, "map"));
  if (page.ledger)
    for (std::size_t t = 0; t < c.targets.size(); ++t) claim_map(*page.ledger, r, t, fmt::format("answers.map.target_{}", t), "answers", md, tallies[t]);
  return md;
}

std::string work_precision_figure(std::size_t scene) { return "work_precision_" + std::string(scene_name(scene)); }

std::string answer_paragraph(const std::string& bullet) { return bullet.rfind("- ", 0) == 0 ? bullet.substr(2) : bullet; }

namespace {

class Answers : public Section {
 public:
  std::string title() const override { return "Answers"; }
  std::string markdown(Page& page) const override {
    const ReportData& d = page.data;
    std::string md = "## " + title() + "\n\n";
    md += fmt::format("The 2018 exercise sheet asks for {} on a cannon ball and a cube hanging on a damped spring, and two "
                      "questions: which method is stable, and is stability correlated with the order? The answers below, "
                      "and the ones a simulation asks next, are computed from this report's measurements; the sections after "
                      "them show the data.\n\n",
                      method_list(sheet_methods()));
    if ((d.studies & kFindings) == kFindings) {  // one at a time: each records its claims in the page's order
      md += stable_answer(page);
      md += order_answer(page);
      md += energy_answer(page);
    }
    if (page.handout) {  // the hand-out answers the next questions in the brief sections that close it
      return md + "\nThe questions a simulation asks next (stiffness, cost, size, a frame budget, long runs) are answered in "
                  "the short sections that close this hand-out, each with a link to its study in the atlas.\n\n";
    }
    if (d.studies & kStiffOrderStudy) md += stiff_answer(page);
    if (d.studies & kWorkPrecisionStudy) md += cost_answer(page);
    if (d.studies & kScalingStudy) md += implicit_answer(page);
    if ((d.studies & kLongTimeStudy) && !d.long_time_orbit.rows.empty()) md += long_time_answer(page);
    if (d.config.has_section("advice")) md += "\nThe report closes with what to use when.\n";
    return md + "\n";
  }
};

}  // namespace

std::unique_ptr<Section> make_answers_section() { return std::make_unique<Answers>(); }

}  // namespace steplab
