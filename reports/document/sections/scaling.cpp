// As the system grows: every scene of run-time size with modes (by default the rope of N masses
// and the soft body of n x n masses) refined (analysis/studies/scaling.hpp), every method and the peers;
// cost against N (the first scene's figure), the exponents that are findings, the crossover,
// steplab's cheapest against CVODE; and on the first scene, stiffened as well, the crossover map:
// which group is cheapest in each cell (size, stiffness), a margin within the noise a tie, at the
// report's error and at the visual one. The studies are the report's (ReportData::scaling).
#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/peers/peers.hpp"
#include "reports/studies/studies.hpp"
#include "reports/document/claims.hpp"
#include "reports/document/figure_styles.hpp"
#include "reports/document/findings.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"
#include "reports/document/sections/answers.hpp"

namespace steplab {
namespace {

// An exponent is a finding where it was fitted and its interval is at most +-kExponentHalfWidth.
constexpr double kExponentHalfWidth = 0.5;
bool finding(const Exponent& e) { return e.fitted() && e.hi - e.lo <= 2 * kExponentHalfWidth; }
std::string finding_text(const Exponent& e) { return finding(e) ? exponent_text(e) : "-"; }

// The cost figure's sentence of what to see: how many of the solvers reach the target at the
// largest size (a count, not a timing, which may flip under load).
// A study's data file in the section's folder, and the path the claims cite it by.
std::string scaling_file(const ScalingResult& r) { return fmt::format("scaling_{}.json", r.config.scene); }
std::string scaling_document(const ScalingResult& r) { return "scaling/" + scaling_file(r); }

// How many solvers reach the target at the largest size: a membership claim over those rows (a
// row's dt, or an adaptive solver's tolerance, is null where its solver did not reach it).
std::string reach_sentence(const ScalingResult& r, Ledger* l) {
  int largest = 0, masses = 0;
  std::vector<std::string> reached;
  for (const ScalingRow& w : r.rows) largest = std::max(largest, w.n);
  for (const ScalingRow& w : r.rows)
    if (w.n == largest && (masses = w.masses, w.reached())) reached.push_back(w.solver);
  const std::string text = fmt::format("At N = {}, {} of the {} solvers reach the target.", masses, reached.size(), r.solvers());
  if (l) {
    const std::string file = scaling_document(r);
    l->document(file, [&] { return scaling_json(r); });
    claim_members(*l, claim_text(fmt::format("scaling.{}.reached", r.config.scene), "scaling", text), file, "/rows", {{"masses", masses}},
                  "solver", false, test_any({test_field("/dt", ">", 0), test_field("/tolerance", ">", 0)}), reached);
  }
  return text;
}

std::string params_but_size(std::size_t scene, const std::vector<double>& params) {
  return params_text(scene, params, scene_kernel(scene).size_param);
}

// The exponents that are findings, a row per solver with one; the others in a sentence.
std::string exponents_table(const ScalingResult& r, Ledger* l) {
  std::string rows;
  std::vector<std::string> none;  // the solvers with no exponent that is a finding
  for (std::size_t s = 0; s < r.solvers(); ++s) {  // the first block's: the report's error, the first stiffness
    const ScalingFit& f = r.fits[s];
    if (!finding(f.step) && !finding(f.run) && !finding(f.stable)) {
      none.push_back(f.solver);
      continue;
    }
    std::vector<int> capped;
    for (const ScalingRow& w : r.rows_of(s))
      if (w.reached() && w.capped) capped.push_back(w.masses);
    rows += fmt::format("| `{}` | {} | {} | {} | {} |\n", f.solver, finding_text(f.step), finding_text(f.run), finding_text(f.stable),
                        capped.empty() ? "-" : "N = " + join(capped));
  }
  std::string md;
  if (!rows.empty())
    md += "| solver | cost ~ N^p^: one step | whole run | dt* ~ N^q^ | step at 0.95 dt* |\n|---|---:|---:|---:|---|\n" + rows +
          fmt::format("\nExponents with their 95 % intervals, where the interval is at most +-{:g}; {}.\n\n", kExponentHalfWidth,
                      exponent_rule_text());
  if (!none.empty())
    md += fmt::format("{} no exponent is a finding at these sizes (fewer than {} sizes, under {:g} decades of N, or an interval "
                      "wider than +-{:g}).\n\n",
                      rows.empty() ? "For every solver" : "For " + quoted_list(none), kFitSizes, kFitDecades, kExponentHalfWidth);
  if (l && !r.fits.empty()) {  // the solvers of the first block with no exponent that is a finding (finding() above)
    const std::string file = scaling_document(r);
    const Json& doc = l->document(file, [&] { return scaling_json(r); });
    std::vector<Json> findings;
    for (const char* q : {"/step", "/run", "/stable_step"})
      findings.push_back(test_all({test_field(fmt::format("{}/exponent", q), "!=", nullptr),
                                   test_difference(fmt::format("{}/ci95/1", q), fmt::format("{}/ci95/0", q), "<=", 2 * kExponentHalfWidth)}));
    const Json& first = doc.at("exponents").at(0);
    claim_members(*l, claim_text(fmt::format("scaling.{}.no_exponent", r.config.scene), "scaling", md), file, "/exponents",
                  {{"target", first.at("target")}, {"stiffness", first.at("stiffness")}}, "solver", false,
                  test_not(test_any(std::move(findings))), none);
  }
  return md;
}

// The crossover sentence, and steplab's cheapest against each adaptive implicit peer (CVODE,
// ARKODE's DIRK tables, RADAU5) at the largest size, as a table with the counts.
std::string findings(const ScalingResult& r, Ledger* l) {
  const ScalingConfig& c = r.config;
  const auto any_row = [&](bool implicit) {
    return std::any_of(r.rows.begin(), r.rows.end(), [&](const ScalingRow& w) { return !w.adaptive && w.implicit == implicit; });
  };
  const bool explicit_ones = any_row(false), implicit_ones = any_row(true);
  std::string md = !explicit_ones || !implicit_ones  // a crossover needs both among the report's methods
                       ? fmt::format("This report has no {} fixed-step method here, so where implicit pays is not read.",
                                     explicit_ones ? "implicit" : "explicit")
                   : !c.timing
                       ? std::string("Untimed, where implicit pays is not read: the counts leave out the implicit methods' "
                                     "factorisations and solves (in the data), so fewer evaluations is no win over an explicit method.")
                   : r.blocks.front().crossover == 0
                       ? fmt::format("At none of these sizes is an implicit method's whole run cheaper than every explicit one's "
                                     "by more than the timing's noise ({}x).", kTieMargin)
                       : fmt::format("At N = {}, the first of these sizes where one is, `{}`'s whole run is cheaper than every "
                                     "explicit method's by more than the timing's noise ({}x).",
                                     scaling_masses(c, r.blocks.front().crossover), r.blocks.front().crossover_method, kTieMargin);
  if (l && explicit_ones && implicit_ones)
    claim_scaling_crossover(*l, r, scaling_document(r), fmt::format("scaling.{}.crossover", r.config.scene), "scaling", md);
  const ScalingRow* best = nullptr;
  std::vector<const ScalingRow*> cvode;  // and the other implicit peers
  for (std::size_t s = 0; s < r.solvers(); ++s) {  // the first block's
    const ScalingRow& w = r.rows_of(s).back();
    if (!w.reached()) continue;
    const PeerInfo* peer = w.adaptive ? find_peer(w.solver) : nullptr;
    if (peer && peer->implicit) cvode.push_back(&w);
    else if (peer && !peer->is_steplab()) continue;  // the other peers
    else if (!best || scaling_cost(c, w) < scaling_cost(c, *best)) best = &w;
  }
  if (!best || cvode.empty()) return md + "\n\n";
  md += fmt::format(" At N = {}, steplab's cheapest, `{}`{}, against each adaptive implicit peer ({} in {}):\n\n"
                    "| solver | counts | cost over steplab's |\n|------------|-----------------------|---|\n| `{}` | {} | 1 |\n",
                    scaling_masses(c, c.sizes.back()), best->solver, best->capped ? " (its step at the cap 0.95 dt*)" : "",
                    "cost", c.timing ? "run time" : "force evaluations x N", best->solver, counts_text(best->counts()));
  for (const ScalingRow* p : cvode)
    md += fmt::format("| `{}` | {} | {:.3g} |\n", p->solver, counts_text(p->counts()), scaling_cost(c, *p) / scaling_cost(c, *best));
  return md + "\n";
}

// The measure in words, and the peers' linear solver for the scene.
std::string scene_paragraph(const ScalingResult& r, bool first) {
  const ScalingConfig& c = r.config;
  const std::size_t scene = scene_index(c.scene);
  const SceneKernel& k = scene_kernel(scene);
  std::vector<int> masses;
  for (int n : c.sizes) masses.push_back(scaling_masses(c, n));
  const std::string size_name(k.params[static_cast<std::size_t>(k.size_param)].name);
  const std::string at = masses == c.sizes ? fmt::format("N = {}", join(masses))
                                           : fmt::format("N = {} masses ({} = {})", join(masses), size_name, join(c.sizes));
  const std::string against = k.has_exact ? "its exact solution" : "its reference solution (dopri5 at rtol 1e-13)";
  const std::string solver = k.jacobian_bandwidth >= 0 ? "their banded LU, RADAU5 with its own"
                                                       : "SuiteSparse's KLU, RADAU5 (no sparse solver) with its banded LU as wide as the grid";
  if (!first)
    return fmt::format("**{}** ({}), at {}: the same measure against {}, CVODE and ARKODE with {}.\n\n", k.title,
                       params_but_size(scene, c.params), at, against, solver);
  return fmt::format(
      "**{}** ({}), refined by its {} to {}: each method's step (each adaptive solver's tolerance) searched until the position "
      "error over the whole motion (the largest over the masses and {} frames to t = {:g}) against {} is at most {:g}, and "
      "that run's cost by {}. A fixed-step method interpolates each frame inside the step that holds it (its output between "
      "steps, above), and its step is capped at 0.95 of the dt* its modes predict: it is told where its steps stop being "
      "stable, which no adaptive solver is told. The peers as above, "
      "CVODE and ARKODE with {}.\n\n",
      k.title, params_but_size(scene, c.params), size_name, at, c.frames, c.t_end, against, c.targets.front().value,
      c.timing ? "run time" : "force evaluations times N", solver);
}

// map.dat: a gnuplot index per target, a line per cell: its column (size) and row (stiffness)
// index, the colour of its cheapest solver's group (a tie white), and its two labels: the
// solver and its margin over the cheapest of another group, or "tie" and the two solvers.
std::string map_data(const ScalingResult& r) {
  const ScalingConfig& c = r.config;
  const std::size_t nk = r.blocks.size() / c.targets.size();
  std::string t = "# size_index stiffness_index rgb label1 label2 (index: target)\n";
  for (std::size_t target = 0; target < c.targets.size(); ++target) {
    if (target > 0) t += "\n\n";
    for (std::size_t k = 0; k < nk; ++k)
      for (std::size_t n = 0; n < c.sizes.size(); ++n) {
        const ScalingCell& m = r.blocks[target * nk + k].cells[n];
        const CellVerdict v = cell_verdict(m, r.blocks[target * nk + k].error, c.timing);
        const bool win = v == CellVerdict::Win;
        const std::string hue = win ? solver_hue(m.cheapest) : "#FFFFFF";
        const std::string first = v == CellVerdict::None        ? "none"
                                  : v == CellVerdict::Still     ? "at rest"
                                  : v == CellVerdict::Undecided ? "undecided"
                                  : v == CellVerdict::Tie       ? "tie"
                                                                : m.cheapest;
        const std::string second = v == CellVerdict::None || v == CellVerdict::Still ? ""
                                   : v == CellVerdict::Undecided ? m.cheapest + " " + m.best_explicit
                                   : v == CellVerdict::Tie       ? m.cheapest + " " + m.rival
                                   : m.rival.empty()             ? std::string("alone")
                                                                 : fmt::format("x{:.2f}", m.rival_margin);
        t += fmt::format("{} {} {} \"{}\" \"{}\"\n", n, k, std::stoi(hue.substr(1), nullptr, 16), first, second);
      }
  }
  return t;
}

// The map figure's variables: the panels' titles, the tics (masses, stiffnesses: words), the axis name.
std::string map_vars(const ScalingResult& r) {
  const ScalingConfig& c = r.config;
  const std::size_t nk = r.blocks.size() / c.targets.size();
  std::string xt, yt, titles;
  for (std::size_t n = 0; n < c.sizes.size(); ++n) xt += fmt::format("{}{}", n ? " " : "", scaling_masses(c, c.sizes[n]));
  for (std::size_t k = 0; k < nk; ++k) yt += fmt::format("{}{:g}", k ? " " : "", r.blocks[k].stiffness);
  for (std::size_t t = 0; t < c.targets.size(); ++t) titles += fmt::format("; tt{}='error {}'", t + 1, target_text(c, r.blocks[t * nk]));
  const SceneKernel& s = scene_kernel(scene_index(c.scene));
  return fmt::format("ntargets={}; xlabels='{}'; ylabels='{}'; ylab='{}'{}", c.targets.size(), xt, yt,
                     s.params[static_cast<std::size_t>(s.stiffness_param)].name, titles);
}

// "clear wins BDF 3, CVODE 2" (each group's clear wins), or "no clear win".
std::string wins_text(const MapTally& counts) {
  std::string tally;
  for (const auto& [group, n] : counts.wins) tally += fmt::format("{}{} {}", tally.empty() ? "" : ", ", group, n);
  return tally.empty() ? "no clear win" : "clear wins " + tally;
}

// The map's findings at each target: the clear wins of each group and the ties, where implicit
// wins, its margin against the best explicit solver and CVODE in the stiffest, largest cell, and
// where the target exceeds the body's motion.
std::string map_findings(const ScalingResult& r, Ledger* l) {
  const ScalingConfig& c = r.config;
  const std::size_t nk = r.blocks.size() / c.targets.size();
  std::string md;
  for (std::size_t t = 0; t < c.targets.size(); ++t) {
    const MapTally counts = map_tally(r, t);
    const std::size_t start = md.size();
    const ScalingBlock* stiffest = &r.blocks[t * nk + nk - 1];
    std::vector<std::string> still;  // the stiffnesses where the body moves less than the target at every size
    double still_motion = 0;
    for (std::size_t k = 0; k < nk; ++k) {
      const ScalingBlock& b = r.blocks[t * nk + k];
      double motion = 0;
      for (const ScalingCell& m : b.cells) motion = std::max(motion, m.motion);
      if (motion < b.error) still.push_back(fmt::format("{:g}", b.stiffness)), still_motion = std::max(still_motion, motion);
    }
    md += fmt::format("- At error {}, of {} cells: {}{}.", target_text(c, *stiffest), counts.cells, wins_text(counts),
                      counts.ties ? fmt::format("; {} tie{}{}", counts.ties, counts.ties == 1 ? "" : "s", c.timing ? "" : " or undecided") : "");
    md += counts.implicit.empty() ? " No implicit fixed-step method is clearly the cheapest anywhere."
                                  : fmt::format(" An implicit fixed-step method is clearly the cheapest in {} (stiffness/N: {}).",
                                                counts.implicit.size(), fmt::join(counts.implicit, ", "));
    const ScalingCell& far = stiffest->cells.back();  // the stiffest, largest cell
    const auto times = [](double over) { return std::isnan(over) ? std::string("-") : fmt::format("{:.3g}", over); };
    if (!far.best_implicit.empty() && far.motion >= stiffest->error)  // a cell at rest is a win for no one: no margin stated
      md += fmt::format(" At stiffness {:g} and N = {} the best explicit solver (`{}`) costs {} times the cheapest implicit "
                        "method (`{}`), the best adaptive implicit peer (`{}`) {} times.",
                        stiffest->stiffness, far.masses, far.best_explicit.empty() ? "none reached" : far.best_explicit,
                        times(far.explicit_over_implicit), far.best_implicit,
                        far.best_implicit_peer.empty() ? "none reached" : far.best_implicit_peer, times(far.implicit_peer_over_implicit));
    if (!still.empty())
      md += fmt::format(" At stiffness {} the body moves less than this target (at most {:.2g}): a run that stays at rest "
                        "meets it, so those cells are a win for no one.",
                        fmt::join(still, ", "), still_motion);
    md += "\n";
    if (l) claim_map(*l, r, t, fmt::format("scaling.map.target_{}", t), "scaling", md.substr(start), counts);
  }
  return md + "\n";
}

// The map figure's sentence of what to see: the clear wins of each group and the ties at the first target.
std::string tally_sentence(const ScalingResult& r) {
  const MapTally counts = map_tally(r, 0);
  return fmt::format("At error {}, of {} cells: {}; {} tied or undecided, {} at rest.", target_text(r.config, r.blocks.front()),
                     counts.cells, wins_text(counts), counts.ties, counts.still);
}

// The map's paragraph, figure and findings.
std::string map_markdown(const ScalingResult& r, Page& page) {
  const ScalingConfig& c = r.config;
  std::vector<std::string> stiff;
  for (std::size_t k = 0; k < r.blocks.size() / c.targets.size(); ++k) stiff.push_back(fmt::format("{:g}", r.blocks[k].stiffness));
  const SceneKernel& s = scene_kernel(scene_index(c.scene));
  std::vector<int> masses;
  for (int n : c.sizes) masses.push_back(scaling_masses(c, n));
  const std::string stiffness_name(s.params[static_cast<std::size_t>(s.stiffness_param)].name);
  std::string md = fmt::format(
      "**When does implicit pay?** The {} stiffened as well, at N = {}: its {} at {}, each cell (size, stiffness) the same "
      "study with every method and the peers but CVODE's BDF of orders up to 5 (its orders 1-2 stand for it; a search tries "
      "no step that needs more than {} steps), at the error above and at a visual one ({}). Each cell is coloured by the "
      "group of its cheapest solver (a family; CVODE; ARKODE; RADAU5; the explicit adaptive solvers) and labelled with it and its margin "
      "over the cheapest solver of another group (two members of one family within the noise are still that family's win); a "
      "margin below {:g} (the timing's noise: each run timed in two passes apart in time, the faster kept) is a tie "
      "(white, both named), counted for neither; so is a cell where the body moves less "
      "than the target (\"at rest\"){}. `steplab study scaling --scene "
      "{} --sizes {} --stiffness {} --error {:g},{:g}% --max-steps {}` gives the map with every peer and count.\n\n",
      s.name, join(masses), stiffness_name, fmt::join(stiff, ", "), c.max_steps, target_text(c, r.blocks.back()), kTieMargin,
      c.timing ? "" : ", and, untimed, one whose cheapest is implicit against an explicit solver that reached the target "
                      "(\"undecided\": the counts leave out its solves)",
      s.name, join(c.sizes), fmt::join(stiff, ","), c.targets.front().value, 100 * c.targets.back().value, c.max_steps);
  md += map_findings(r, page.ledger);
  if (page.has("map"))
    md += page.figure("map", fmt::format("{}: the cheapest solver in each cell (masses N, {}); colour by group: explicit "
                                         "Runge-Kutta blue, symplectic splitting vermillion, implicit Runge-Kutta green, "
                                         "Adams-Bashforth purple, BDF orange, CVODE sky blue, ARKODE teal, RADAU5 rose, explicit "
                                         "adaptive grey, a tie or a cell at rest white. {}",
                                         s.title, stiffness_name, tally_sentence(r)));
  return md;
}

class ScalingSection : public Section {
 public:
  std::string title() const override { return "As the system grows"; }
  std::string brief(Page& page) const override { return brief_markdown(title(), answer_paragraph(implicit_answer(page))); }
  unsigned needs() const override { return kScalingStudy; }
  std::string missing(const ReportConfig& c) const override {
    for (const ReportSizes& s : c.scaling)
      if (c.covers(s.scene)) return "";
    return "none of the chosen scenes is of run-time size";
  }

  void write_data(const ReportData& d, const DataDir& dat) const override {
    for (const ScalingResult& r : d.scaling) dat.write(scaling_file(r), scaling_json(r).dump(1) + "\n");
    if (d.scaling.empty()) return;
    const ScalingResult& first = d.scaling.front();  // the figure's
    for (std::size_t s = 0; s < first.solvers(); ++s) {
      const std::span<const ScalingRow> rows = first.rows_of(s);
      std::string t = "# masses run_cost step_cost\n";
      for (const ScalingRow& w : rows) {
        const double cost = scaling_cost(first.config, w);
        t += fmt::format("{} {} {}\n", w.n, w.reached() ? num(cost) : "NaN", w.reached() && w.steps > 0 ? num(cost / w.steps) : "NaN");
      }
      dat.write("scaling_" + rows.front().solver + ".dat", t);
    }
    if (d.scaling_map) {
      dat.write("scaling_map.json", scaling_json(*d.scaling_map).dump(1) + "\n");
      dat.write("map.dat", map_data(*d.scaling_map));
    }
  }

  // Panels of at most six solvers (solver_panels), each of those that reached the target at some N.
  std::vector<FigureSpec> figures(const ReportData& d) const override {
    std::vector<FigureSpec> out;
    if (!d.scaling.empty()) {
      const ScalingResult& first = d.scaling.front();
      const auto reached = [&](std::string_view solver) {
        return std::any_of(first.rows.begin(), first.rows.end(), [&](const ScalingRow& w) { return w.solver == solver && w.reached(); });
      };
      std::vector<Panel> panels = solver_panels(first.config.methods, first.config.adaptive, reached);
      if (!panels.empty())
        out.push_back({"scaling", fmt::format("costname='{}'", first.config.timing ? "run time (s)" : "force evaluations x N"),
                       std::move(panels)});
    }
    if (d.scaling_map) out.push_back({"map", map_vars(*d.scaling_map), {}});
    return out;
  }

  std::string markdown(Page& page) const override {
    const ReportData& d = page.data;
    std::string md = "## " + title() + "\n\n";
    for (std::size_t i = 0; i < d.scaling.size(); ++i) {
      const ScalingResult& r = d.scaling[i];
      md += scene_paragraph(r, i == 0) + exponents_table(r, page.ledger) + findings(r, page.ledger);
      if (i == 0 && page.has("scaling"))
        md += page.figure("scaling", fmt::format("{}: the whole run's cost at the target error against N; the explicit "
                                                 "fixed-step methods, the symplectic splittings, the implicit methods and the "
                                                 "adaptive solvers in panels of at most six. {}",
                                                 scene_kernel(scene_index(r.config.scene)).title, reach_sentence(r, page.ledger)));
    }
    if (d.scaling_map) md += map_markdown(*d.scaling_map, page);
    return md;
  }
};

}  // namespace

std::unique_ptr<Section> make_scaling_section() { return std::make_unique<ScalingSection>(); }

}  // namespace steplab
