// What accuracy costs: work-precision on the spring and the stiff chain (analysis/
// work_precision.hpp) with the adaptive peers; the cheapest solver per error level (a margin
// within the timing's noise is a tie), steplab's implicit methods against CVODE, the chain's
// stable against accurate steps, and the stiffness crossover. Every sentence is computed from
// d.work (findings.hpp: point_cost, level_winner, implicit_against_peers). "Evaluations" are
// force evaluations; Jacobians and factorisations are counted beside them.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/peers/peers.hpp"
#include "reports/studies/studies.hpp"
#include "reports/document/claims.hpp"
#include "reports/document/findings.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"
#include "reports/document/sections/answers.hpp"

namespace steplab {
namespace {

std::string scene_word(const SceneWork& w) { return std::string(scene_name(w.scene)); }

// "`rk4` 4.49 µs", with "(tie: `x`)" where the runner-up is within the noise and a dagger where
// the winning run is at the edge of its sweep.
std::string winner_cell(const LevelWinner& win, bool timed) {
  if (!win.point) return "none";
  return fmt::format("`{}` {}{}{}", win.point->method,
                     timed ? cost_text(true, win.point->seconds, 0) : std::to_string(win.point->force_evaluations),
                     win.tie                  ? fmt::format(" (tie: {})", quoted_list(win.tied_with()))
                     : !win.undecided.empty() ? fmt::format(" (undecided: `{}`)", win.undecided)
                                              : "",
                     win.at_edge ? " $\\dagger$" : "");
}

// A run's counts in a table cell: "46 steps, 276 F, 138 J, 46 LU".
std::string counts_cell(const WorkPoint& p) {
  std::string out = fmt::format("{} steps, {} F", p.steps, p.force_evaluations);
  if (p.jacobian_evaluations > 0) out += fmt::format(", {} J", p.jacobian_evaluations);
  if (p.factorisations > 0) out += fmt::format(", {} LU", p.factorisations);
  return out;
}

// The other libraries' solvers a hand-out sentence names, each with its library: the hand-out's
// reader meets `odeint_dopri5` there first, without the atlas's table of peers.
std::string peers_named(const std::string& text) {
  std::vector<std::string> named;
  for (const PeerInfo& p : peers())
    if (!p.is_steplab() && text.find(fmt::format("`{}`", p.name)) != std::string::npos)
      named.push_back(fmt::format("`{}` of {}", p.name, p.library()));
  return named.empty() ? std::string()
                       : fmt::format(" The solvers named from other libraries: {}, each set up as the atlas's table of peers says.",
                                     and_list(named));
}

class Cost : public Section {
 public:
  std::string title() const override { return "What accuracy costs"; }
  std::string brief(Page& page) const override {
    const std::string answer = answer_paragraph(cost_answer(page));
    return brief_markdown(title(), without_final_newlines(answer) + peers_named(answer));
  }
  unsigned needs() const override { return kWorkPrecisionStudy; }
  void write_data(const ReportData& d, const DataDir& dat) const override {
    dat.write("work_precision.json", work_precision_json(d.work).dump(1) + "\n");
    for (const SceneWork& w : d.work.scenes)
      for (const std::string& m : curve_names(d)) {
        std::string s = "# dt_or_tolerance error_max seconds force_evaluations\n";
        for (const WorkPoint& p : w.points)
          if (p.method == m && p.status == RunStatus::Ok && p.error > 0)
            s += fmt::format("{} {} {} {}\n", num(p.setting), num(p.error), num(p.seconds), p.force_evaluations);
        dat.write(fmt::format("wp_{}_{}.dat", scene_word(w), m), s);
      }
  }

  // A figure per scene, common axes in it; its panels of at most six solvers (solver_panels), each
  // of them with a point to draw.
  std::vector<FigureSpec> figures(const ReportData& d) const override {
    const bool timed = d.config.timing;
    std::vector<FigureSpec> out;
    for (std::size_t k = 0; k < d.work.scenes.size(); ++k) {
      std::string vars = fmt::format("xcol={}; xname='{}'; ", timed ? 3 : 4, timed ? "run time (s)" : "force evaluations");
      const SceneWork& w = d.work.scenes[k];
      double x0 = INFINITY, x1 = 0, y0 = INFINITY, y1 = 0;
      for (const WorkPoint& p : w.points) {
        if (p.status != RunStatus::Ok || !(p.error > 0)) continue;
        const double x = point_cost(p, timed);
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, p.error), y1 = std::max(y1, p.error);
      }
      if (!(x0 <= x1)) x0 = 1, x1 = 10, y0 = 1e-10, y1 = 1;
      const auto has_points = [&](std::string_view solver) {
        return std::any_of(w.points.begin(), w.points.end(),
                           [&](const WorkPoint& p) { return p.method == solver && p.status == RunStatus::Ok && p.error > 0; });
      };
      std::vector<Panel> panels = solver_panels(d.work.config.methods, d.work.config.adaptive, has_points);
      for (std::size_t p = 1; p <= panels.size(); ++p)
        vars += fmt::format("pscene{0}='{1}'; xlo{0}={2}; xhi{0}={3}; ylo{0}={4}; yhi{0}={5}; ", p, scene_word(w), num(x0 / 1.5),
                            num(x1 * 1.5), num(y0 / 3), num(std::min(y1 * 3, 1e3)));
      if (!panels.empty()) out.push_back({"work_precision", vars, std::move(panels), work_precision_figure(w.scene)});
    }
    return out;
  }

  std::string markdown(Page& page) const override {
    const ReportData& d = page.data;
    const WorkPrecisionResult& r = d.work;
    const bool timed = d.config.timing;
    std::string md = "## " + title() + "\n\n";
    md += fmt::format(
        "Each point is one run to t = {}: its largest position error against the exact solution at its steps, and its cost "
        "in {}. The fixed-step methods run over dt sweeps, the adaptive solvers over tolerances {:.0e} .. {:.0e} (rtol = "
        "atol). Every solver is timed alike: the scene made outside, the solver's set-up, run and clean-up inside, the "
        "minimum of repeats. The adaptive solvers, each set up as its documentation advises for such a problem:\n\n",
        r.config.t_end, timed ? "run time" : "force evaluations (an untimed report)", r.config.tolerances.front(),
        r.config.tolerances.back());
    md += peers_table(r);
    if (r.stiff >= 0 && scene_kernel(r.scenes[static_cast<std::size_t>(r.stiff)].scene).modes) {
      const SceneWork& stiff = r.scenes[static_cast<std::size_t>(r.stiff)];
      md += fmt::format("The {} ({}) has a slow mode near the sheet's spring and a stiff, damped one about {:.0f} times faster.\n\n",
                        scene_word(stiff), params_text(stiff.scene, stiff.params), fast_over_slow(stiff));
    }
    md += cheapest_table(page, timed);
    for (const SceneWork& w : r.scenes) {
      const auto reached = [](const WorkPoint& p) { return p.status == RunStatus::Ok && p.error > 0; };
      const WorkPoint* least = least_and_most(w.points, reached, &WorkPoint::error).first;  // the smallest error any run reaches
      if (!page.has(work_precision_figure(w.scene)) || !least) continue;  // a figure only of scenes with such a point
      constexpr Digits kError{true, 2};
      const std::string smallest = fmt::format("The smallest error reached, {}, is `{}`'s.", printed(least->error, kError), least->method);
      md += page.figure(work_precision_figure(w.scene),
                        fmt::format("Work against precision on the {}: the largest error along a run against its {}; the "
                                    "explicit fixed-step methods, the symplectic splittings, the implicit methods and the "
                                    "adaptive solvers in panels of at most six. {}",
                                    scene_word(w), timed ? "run time" : "force evaluations", smallest));
      if (!page.ledger) continue;
      const Kept errors = kept_evidence(w.points, reached, least, nullptr, [&](const WorkPoint& p, std::size_t) {
        return work_point_at(*page.ledger, page.data, w, p, "error_max");
      });
      claim_extreme(*page.ledger, claim_text(fmt::format("cost.smallest_error.{}", scene_name(w.scene)), "cost", smallest), errors.values,
                    errors.least, Extreme::Least, kError);
    }
    md += peer_table(page, timed) + dopri5_sentences(page, timed);
    if (r.stiff >= 0) md += limits_text(r, page.ledger) + stiffness_text(page, timed);
    return md;
  }

 private:
  static std::vector<std::string> curve_names(const ReportData& d) {
    std::vector<std::string> out;
    for (std::size_t m : d.work.config.methods) out.push_back(name(m));
    for (const std::string& p : d.work.config.adaptive) out.push_back(p);
    return out;
  }

  // omega_fast / omega_slow of a scene's modes (core/scene.hpp).
  static double fast_over_slow(const SceneWork& w) {
    const std::vector<Mode> modes = scene_kernel(w.scene).modes(w.params);
    return modes.back().omega / modes.front().omega;
  }

  static std::string peers_table(const WorkPrecisionResult& r) {
    std::string md = "| solver | library | set-up |\n|--------------|----------|-----------------------------|\n";
    for (const std::string& a : r.config.adaptive) {
      const PeerInfo* p = find_peer(a);
      if (!p) continue;
      md += fmt::format("| `{}` | {} | {} |\n", a, p->library(), p->lib->setup(*p));
    }
    return md + "\n";
  }

  // Each cell a claim (claim_cheapest): the winner, tied or by its margin.
  static std::string cheapest_table(const Page& page, bool timed) {
    const WorkPrecisionResult& r = page.data.work;
    const auto cell = [&](const SceneWork& w, double level, bool by_time) {
      const LevelWinner win = level_winner(w, level, by_time);
      const std::string text = winner_cell(win, by_time);
      if (page.ledger)
        claim_cheapest(*page.ledger, page.data,
                       fmt::format("cost.cheapest.{}.{}.{:.0e}", scene_word(w), by_time ? "time" : "forces", level), "cost",
                       fmt::format("the cheapest run table, error {:.0e}, {} by {}: {}", level, scene_word(w),
                                   by_time ? "run time" : "force evaluations", text),
                       w, level, by_time, win);
      return text;
    };
    std::string md = "The cheapest run at each error level:\n\n| error at most |";
    for (const SceneWork& w : r.scenes)
      md += timed ? fmt::format(" {0}: by run time | {0}: by force evaluations |", scene_word(w)) : fmt::format(" {}: by force evaluations |", scene_word(w));
    md += "\n|---|" + std::string(timed ? "---|---|---|---|" : "---|---|") + "\n";
    for (const double level : r.config.error_levels) {
      md += fmt::format("| {:.0e} |", level);
      for (const SceneWork& w : r.scenes) {
        if (timed) md += fmt::format(" {} |", cell(w, level, true));
        md += fmt::format(" {} |", cell(w, level, false));
      }
      md += "\n";
    }
    return md + fmt::format("\nTie: the runner-up within {:g} times the winner's run time (each run timed in two passes apart "
                            "in time, the faster kept). "
                            "Undecided: an implicit method fewest in force evaluations against the cheapest explicit one, "
                            "whose force evaluations are all its work while the implicit one's Jacobians and solves go uncounted. "
                            "$\\dagger$: the winning run is its sweep's largest step or loosest tolerance; a larger one, not "
                            "tried, might be cheaper still.\n\n", kTieMargin);
  }

  // steplab's cheapest implicit method against each adaptive implicit peer on the stiff scene, at the
  // crossover error and the tightest level: a row each, with the counts. Each ratio a claim
  // (cost.peers.<level>.<peer>.cost, .force, .steps), and the range of a peer's cost of a step.
  static std::string peer_table(const Page& page, bool timed) {
    const WorkPrecisionResult& r = page.data.work;
    if (r.stiff < 0) return {};
    const SceneWork& w = r.scenes[static_cast<std::size_t>(r.stiff)];
    const char* cost_field = point_cost_field(timed);
    constexpr Digits digits{true, 3}, range_digits{true, 2};
    std::string rows;
    double per_step_lo = INFINITY, per_step_hi = 0;  // a peer's cost of a step over steplab's: (cost ratio) / (step ratio)
    std::vector<Ratio> per_step;
    for (const double level : {r.config.crossover_error, r.config.error_levels.back()})
      for (const PeerComparison& c : implicit_against_peers(r, w, level, timed)) {
        if (!c.steplab || !c.run) continue;
        const double cost = point_cost(*c.run, timed) / point_cost(*c.steplab, timed);
        const double force = double(c.run->force_evaluations) / double(c.steplab->force_evaluations);
        const double steps = double(c.run->steps) / double(c.steplab->steps);
        per_step_lo = std::min(per_step_lo, cost / steps), per_step_hi = std::max(per_step_hi, cost / steps);
        rows += fmt::format("| {:.0e} | `{}`: {}, {} | `{}`: {}, {} | {} | {} | {} |\n", level, c.steplab->method,
                            cost_text(timed, c.steplab->seconds, c.steplab->force_evaluations), counts_cell(*c.steplab), c.peer,
                            cost_text(timed, c.run->seconds, c.run->force_evaluations), counts_cell(*c.run), printed(cost, digits),
                            printed(force, digits), printed(steps, digits));
        if (!page.ledger) continue;
        const auto at = [&](const WorkPoint* p, const char* field) { return work_point_at(*page.ledger, page.data, w, *p, field); };
        const std::string id = fmt::format("cost.peers.{:.0e}.{}", level, c.peer);
        const std::string row = fmt::format("peer table, error {:.0e}, `{}` against `{}`", level, c.peer, c.steplab->method);
        const struct {
          const char *suffix, *column;
          double value;
          const char* field;
        } columns[] = {{"cost", "cost ratio", cost, cost_field}, {"force", "force ratio", force, "force_evaluations"},
                       {"steps", "step ratio", steps, "steps"}};
        for (const auto& k : columns)
          claim_ratio(*page.ledger, claim_text(fmt::format("{}.{}", id, k.suffix), "cost", fmt::format("{}, {}", row, k.column)),
                      {{at(c.run, k.field)}, {at(c.steplab, k.field)}}, k.value, digits);
        per_step.push_back({{at(c.run, cost_field), at(c.steplab, "steps")}, {at(c.steplab, cost_field), at(c.run, "steps")}});
      }
    if (rows.empty()) return {};
    const std::string range = fmt::format("A step of a peer's costs {} .. {} times one of steplab's method by {}", printed(per_step_lo, range_digits),
                                          printed(per_step_hi, range_digits), timed ? "run time" : "force evaluations");
    if (page.ledger)
      claim_ratios(*page.ledger, claim_text("cost.peers.per_step", "cost", range), per_step, per_step_lo, per_step_hi, range_digits);
    return fmt::format("On the {}, steplab's cheapest implicit method against each adaptive implicit peer (CVODE; ARKODE's "
                       "DIRK tables; RADAU5, the adaptive code of steplab's Radau IIA; F: force evaluations, J: Jacobians, "
                       "LU: factorisations):\n\n| error | steplab | peer | cost ratio | force ratio | step ratio |\n"
                       "|---|-----------------|-----------------|---|---|---|\n{}\nA ratio above 1: the peer costs or takes more. "
                       "{}: the rest of each cost ratio is in how many steps each needs.\n\n",
                       scene_word(w), rows, range);
  }

  // steplab's dopri5 against Boost.Odeint's, at the error levels both reach: the two ranges, each a
  // claim (cost.dopri5.<scene>.cost and .force).
  static std::string dopri5_sentences(const Page& page, bool timed) {
    const WorkPrecisionResult& r = page.data.work;
    constexpr Digits digits{false, 2};
    const char* cost_field = point_cost_field(timed);
    std::string md;
    for (const SceneWork& w : r.scenes) {
      double lo = INFINITY, hi = 0, flo = INFINITY, fhi = 0;
      std::vector<Ratio> costs, forces;
      for (const double level : r.config.error_levels) {
        const WorkPoint *a = cheapest_point(w, "dopri5", level, timed), *b = cheapest_point(w, "odeint_dopri5", level, timed);
        if (!a || !b || !(point_cost(*b, timed) > 0)) continue;
        const double ratio = point_cost(*a, timed) / point_cost(*b, timed), f = double(a->force_evaluations) / double(b->force_evaluations);
        lo = std::min(lo, ratio), hi = std::max(hi, ratio), flo = std::min(flo, f), fhi = std::max(fhi, f);
        if (!page.ledger) continue;
        const auto at = [&](const WorkPoint* p, const char* field) { return work_point_at(*page.ledger, page.data, w, *p, field); };
        costs.push_back({{at(a, cost_field)}, {at(b, cost_field)}});
        forces.push_back({{at(a, "force_evaluations")}, {at(b, "force_evaluations")}});
      }
      if (!(hi > 0)) continue;
      const std::string line =
          fmt::format("- On the {}, steplab's `dopri5` costs {} .. {} times what `odeint_dopri5` costs at equal error in {}, and {} .. "
                      "{} times its force evaluations (at the error levels both reach).\n",
                      scene_word(w), printed(lo, digits), printed(hi, digits), timed ? "run time" : "force evaluations",
                      printed(flo, digits), printed(fhi, digits));
      md += line;
      if (!page.ledger) continue;
      const std::string id = "cost.dopri5." + scene_word(w);
      claim_ratios(*page.ledger, claim_text(id + ".cost", "cost", line), costs, lo, hi, digits);
      claim_ratios(*page.ledger, claim_text(id + ".force", "cost", line), forces, flo, fhi, digits);
    }
    return md.empty() ? md : md + "\n";
  }

  static std::string limits_text(const WorkPrecisionResult& r, Ledger* l) {
    std::string md = fmt::format(
        "On the chain an explicit method's step is bounded by the stiff mode's stability as well as by accuracy. The largest "
        "stable step of each in the dt sweep (its limit lies between that step and the next one tried, which diverged) "
        "against the step at which it reaches error {:.0e} on the slow mode alone (the masses moving as one, the limit of "
        "an infinitely stiff link); the ratio's range is over where in that interval the limit lies:\n\n"
        "| method | largest stable dt (next tried) | dt for {:.0e} on the slow mode | ratio |\n|---|---|---|---|\n",
        kLimitErrorLevel, kLimitErrorLevel);
    const auto ratio = [](double accuracy, double lo, double hi) {  // accuracy / (the limit in [lo, hi))
      return std::isfinite(hi) ? fmt::format("{:.3g} .. {:.3g}", accuracy / hi, accuracy / lo) : fmt::format("<= {:.3g}", accuracy / lo);
    };
    std::vector<std::string> held, held_names;
    const StableStep* most = nullptr;
    for (const StableStep& s : r.limits) {
      const bool reached = s.accuracy_dt > 0;
      md += fmt::format("| `{}` | {} ({}) | {} | {} |\n", s.method, dt_text(s.largest_stable_dt),
                        std::isfinite(s.next_tried_dt) ? dt_text(s.next_tried_dt) : "none",
                        reached ? dt_text(s.accuracy_dt) : "below the sweep",
                        reached ? ratio(s.accuracy_dt, s.largest_stable_dt, s.next_tried_dt) : "-");
      if (reached && s.accuracy_dt > s.next_tried_dt) {  // held back wherever in the interval its limit lies
        held.push_back("`" + s.method + "`"), held_names.push_back(s.method);
        if (!most || s.accuracy_dt / s.next_tried_dt > most->accuracy_dt / most->next_tried_dt) most = &s;
      }
    }
    md += "\n";
    const std::string line =
        most ? fmt::format("- Held below the step accuracy would allow by stability, wherever in its interval the limit lies: {} of "
                           "{} explicit methods ({}); the most, `{}`, stable to between dt {} and {} where {} would do ({} times "
                           "larger).\n",
                           held.size(), r.limits.size(), and_list(held), most->method, dt_text(most->largest_stable_dt),
                           dt_text(most->next_tried_dt), dt_text(most->accuracy_dt),
                           ratio(most->accuracy_dt, most->largest_stable_dt, most->next_tried_dt))
             : std::string("- No explicit method's stable step is below the step its accuracy alone would need.\n");
    // "held": the rows whose accuracy step is above the next step tried (a null one, none tried or
    // not reached, fails the test).
    if (l) {
      l->document(kWorkDocument, [&] { return work_precision_json(r); });
      claim_members(*l, claim_text("cost.chain_limits.held", "cost", line), kWorkDocument, "/chain_step_limits", Json::object(),
                    "method", false, test_scaled("/accuracy_dt", ">", 1.0, "/next_tried_dt"), held_names);
    }
    return md + line;
  }

  static std::string stiffness_text(const Page& page, bool timed) {
    const WorkPrecisionResult& r = page.data.work;
    std::string md = fmt::format(
        "\nThe stiffness sweep: the chain with k2 from {:g} to {:g}, run to t = {}; for each method the first step of a "
        "falling sweep (or tolerance) reaching error {:.0e}, and the cheapest explicit and implicit of those by {}:\n\n"
        "| k2 | k2 / k1 | cheapest explicit | cost | cheapest implicit | cost |\n|---|---|---|---|---|---|\n",
        r.config.stiffnesses.front(), r.config.stiffnesses.back(), r.config.sweep_t_end, r.config.crossover_error,
        timed ? "run time" : "force evaluations");
    for (const StiffnessRow& s : r.stiffness)
      md += fmt::format("| {:g} | {:g} | {} | {} | {} | {} |\n", s.stiffness2, s.ratio,
                        s.best_explicit.empty() ? "none" : "`" + s.best_explicit + "`",
                        s.best_explicit.empty() ? "-" : cost_text(timed, s.explicit_seconds, s.explicit_forces),
                        s.best_implicit.empty() ? "none" : "`" + s.best_implicit + "`",
                        s.best_implicit.empty() ? "-" : cost_text(timed, s.implicit_seconds, s.implicit_forces));
    md += "\n";
    if (!timed)
      md += "- The crossover is not read untimed: force evaluations leave out the implicit methods' Jacobians, factorisations "
            "and solves (counted in the work-precision data), so fewer of them is no win over an explicit method.\n\n";
    else if (r.crossover_ratio > 0) {
      const std::string line = fmt::format("- The crossover: from stiffness ratio k2 / k1 = {:g} on, an implicit method is cheaper "
                                           "than every explicit one at error {:.0e}, by more than {:g} times its run time (the tie "
                                           "margin), on these runs to t = {:g}, each at the first step of its falling sweep that "
                                           "reaches the error: a coarser search than the table of cheapest runs above, whose verdict "
                                           "at one stiffness may differ.\n\n",
                                           r.crossover_ratio, r.config.crossover_error, kTieMargin, r.config.sweep_t_end);
      md += line;
      if (page.ledger) claim_crossover(*page.ledger, page.data, "cost.crossover", "cost", line);
    }
    else
      md += fmt::format("- No stiffness ratio of the sweep makes an implicit method cheaper than every explicit one at error "
                        "{:.0e} by more than {:g} times its run time.\n\n", r.config.crossover_error, kTieMargin);
    return md;
  }
};

}  // namespace

std::unique_ptr<Section> make_cost_section() { return std::make_unique<Cost>(); }

}  // namespace steplab
