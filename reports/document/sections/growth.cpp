// As the system grows: every scene of run-time size with modes (by default the rope of N masses
// and the soft body of n x n masses) refined (analysis/scaling.hpp), every method and the peers;
// cost against N, the stable step against its 1/N prediction (the first scene's figure), the
// exponents, the crossover, steplab's cheapest against CVODE; and on the first scene, stiffened
// as well, the crossover map: which family is cheapest in each cell (size, stiffness), at the
// report's error and at the visual one.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

#include <fmt/format.h>

#include "analysis/kernel.hpp"
#include "analysis/peers.hpp"
#include "reports/document/figure_styles.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"
#include "reports/data/study_output.hpp"

namespace steplab {
namespace {

// A scene's parameters but its size (the sizes replace it).
std::string params_but_size(std::size_t scene, const std::vector<double>& params) {
  return params_text(scene, params, scene_kernel(scene).size_param);
}

// The exponents, and where a fixed-step method's step was held at its cap 0.95 dt* (told by the modes).
std::string exponents_table(const ScalingResult& r) {
  std::string md = "| solver | cost ~ N^p^: one step | whole run | dt* ~ N^q^ | step at 0.95 dt* |\n|---|---:|---:|---:|---|\n";
  const auto p = [](const Exponent& e) { return exponent_text(e); };
  for (std::size_t s = 0; s < r.solvers(); ++s) {  // the first block's: the report's error, the first stiffness
    const ScalingFit& f = r.fits[s];
    std::vector<int> capped;
    for (const ScalingRow& w : r.rows_of(s))
      if (w.reached() && w.capped) capped.push_back(w.masses);
    md += fmt::format("| `{}` | {} | {} | {} | {} |\n", f.solver, p(f.step), p(f.run), p(f.stable),
                      capped.empty() ? "-" : "N = " + join(capped));
  }
  return md + "\nExponents with their 95 % intervals; " + exponent_rule_text() + ".\n\n";
}

// The crossover sentence, and steplab's cheapest against each CVODE configuration at the largest
// size, in cost and in force evaluations, with their counts.
std::string findings(const ScalingResult& r) {
  const ScalingConfig& c = r.config;
  const auto any_row = [&](bool implicit) {
    return std::any_of(r.rows.begin(), r.rows.end(), [&](const ScalingRow& w) { return !w.adaptive && w.implicit == implicit; });
  };
  const bool explicit_ones = any_row(false), implicit_ones = any_row(true);
  std::string md = !explicit_ones || !implicit_ones  // a crossover needs both among the report's methods
                       ? fmt::format("- This report has no {} fixed-step method, so where implicit pays is not read here.\n",
                                     explicit_ones ? "implicit" : "explicit")
                   : r.blocks.front().crossover == 0
                       ? fmt::format("- At none of these sizes is an implicit method's whole run cheaper than every explicit one's.\n")
                       : fmt::format("- From N = {} on (of these sizes), `{}` is cheaper than every explicit method.\n",
                                     scaling_masses(c, r.blocks.front().crossover), r.blocks.front().crossover_method);
  const ScalingRow* best = nullptr;
  std::vector<const ScalingRow*> cvode;
  for (std::size_t s = 0; s < r.solvers(); ++s) {  // the first block's
    const ScalingRow& w = r.rows_of(s).back();
    if (!w.reached()) continue;
    const PeerInfo* peer = w.adaptive ? find_peer(w.solver) : nullptr;
    if (peer && peer->is_cvode()) cvode.push_back(&w);
    else if (peer && peer->library != "steplab") continue;  // the other peers
    else if (!best || scaling_cost(c, w) < scaling_cost(c, *best)) best = &w;
  }
  if (!best) return md + "\n";
  const std::string what = c.timing ? "run time" : "evaluations x N";
  for (const ScalingRow* p : cvode) {
    const PeerInfo& peer = *find_peer(p->solver);
    md += fmt::format("- At N = {}, steplab's cheapest, `{}`{}, costs {:.3g} times what CVODE with {} and its {} solver "
                      "(`{}`) costs in {} and {:.3g} times its force evaluations ({}; CVODE: {}).\n",
                      scaling_masses(c, c.sizes.back()), best->solver,
                      best->capped ? " (its step at the cap 0.95 dt*, from the modes)" : "",
                      scaling_cost(c, *best) / scaling_cost(c, *p), cvode_method_words(peer),
                      peer.linear_solver, p->solver, what, double(best->forces) / double(p->forces), counts_text(best->counts()),
                      counts_text(p->counts()));
  }
  return md + "\n";
}

// The map's searches try no step that needs more steps than this: at the stiffest cells the
// methods that are not A-stable pay their stable step N^2 (steps ~ N, each ~ N), and a row beyond
// it is "not reached", which the map reads as it reads any other (`make report` stays within a
// minute; `study scaling` goes to 2 000 000).
constexpr long long kReportMapSteps = 200'000;

// The counts of the best implicit, explicit and CVODE rows of cell `m` of block b.
std::string far_counts(const ScalingResult& r, std::size_t b, const ScalingCell& m) {
  std::string out;
  for (std::size_t s = 0; s < r.solvers(); ++s) {
    const ScalingRow& w = r.rows_of(b * r.solvers() + s).back();
    if (w.reached() && (w.solver == m.best_implicit || w.solver == m.best_explicit || w.solver == m.best_cvode))
      out += fmt::format("{}`{}` {}", out.empty() ? "" : "; ", w.solver, counts_text(w.counts()));
  }
  return out.empty() ? "none" : out;
}

// The map's findings at each target: the cells each group wins, where implicit wins and by how
// much against the best explicit solver and CVODE, and where the target exceeds the body's motion.
std::string map_findings(const ScalingResult& r) {
  const ScalingConfig& c = r.config;
  const std::size_t nk = r.blocks.size() / c.targets.size();
  std::string md;
  for (std::size_t t = 0; t < c.targets.size(); ++t) {
    std::map<std::string, int> wins;
    std::vector<std::string> implicit_cells;
    const ScalingBlock* stiffest = &r.blocks[t * nk + nk - 1];
    std::vector<std::string> still;  // the stiffnesses where the body moves less than the target at every size
    double still_motion = 0;
    int cells = 0;
    for (std::size_t k = 0; k < nk; ++k) {
      const ScalingBlock& b = r.blocks[t * nk + k];
      double motion = 0;
      for (const ScalingCell& m : b.cells) motion = std::max(motion, m.motion);
      if (motion < b.error) still.push_back(fmt::format("{:g}", b.stiffness)), still_motion = std::max(still_motion, motion);
      for (const ScalingCell& m : b.cells) {
        ++cells;
        if (m.cheapest.empty()) continue;
        ++wins[solver_group(m.cheapest)];
        if (m.cheapest == m.best_implicit)
          implicit_cells.push_back(fmt::format("{:g}/{}", b.stiffness, m.masses));
      }
    }
    std::string tally;
    for (const auto& [group, n] : wins) tally += fmt::format("{}{} {}", tally.empty() ? "" : ", ", group, n);
    md += fmt::format("- At error {}: the cheapest solver's group, cells won: {} (of {}).", target_text(c, *stiffest),
                      tally, cells);
    md += implicit_cells.empty()
              ? " No implicit fixed-step method is the cheapest anywhere"
              : fmt::format(" An implicit fixed-step method is the cheapest in {} of them (stiffness/N: {})", implicit_cells.size(),
                            fmt::join(implicit_cells, ", "));
    const ScalingCell& far = stiffest->cells.back();  // the stiffest, largest cell
    const auto times = [](double over) { return std::isnan(over) ? std::string("-") : fmt::format("{:.3g}", 1 / over); };
    md += fmt::format("; at stiffness {:g} and N = {}, the cheapest implicit method, `{}`, costs {} times what the best explicit "
                      "solver (`{}`) costs and {} times what the best CVODE (`{}`) costs; counts there: {}.",
                      stiffest->stiffness, far.masses, far.best_implicit.empty() ? "none" : far.best_implicit, times(far.explicit_over_implicit),
                      far.best_explicit.empty() ? "none reached" : far.best_explicit, times(far.cvode_over_implicit),
                      far.best_cvode.empty() ? "none reached" : far.best_cvode, far_counts(r, t * nk + nk - 1, far));
    if (!still.empty())
      md += fmt::format(" At stiffness {} the body moves less than this target (at most {:.2g}): a run that stays at rest "
                        "meets it, and only stability tells the solvers apart.",
                        fmt::join(still, ", "), still_motion);
    md += "\n";
  }
  return md + "\n";
}

ScalingConfig config_for(const ReportData& d, const ReportSizes& s) {
  ScalingConfig c = scaling_config(scene_name(s.scene));  // the scene's defaults, as `study scaling --scene ...`
  c.sizes = s.sizes;
  c.targets = {{d.config.scaling_error, false}};
  c.timing_seconds = kTimingSeconds;  // the report's timing budget per run (analysis/convergence.hpp)
  c.t_end = d.config.scaling_t_end;
  for (std::size_t m : d.numerical_methods())
    if (applies(m, s.scene)) c.methods.push_back(m);  // a scene without Jacobians: the explicit methods
  c.timing = d.config.timing;
  c.workers = d.workers;
  return c;
}

// The peers on the map: CVODE as its guide would set it up for stiff oscillations, Adams or BDF of
// orders 1-2 (A-stable); its BDF of orders up to 5, unstable near the imaginary axis, crawls over
// the stiff scenes' lightly damped fast modes (up to 200 000 steps a run at K 5000, N 128), which
// the section's study above already shows; and the explicit adaptive solvers.
bool map_peer(const PeerInfo& p) {
  return !p.is_cvode() || p.cvode.adams || (p.cvode.max_order >= 1 && p.cvode.max_order <= 2);
}

// The map's study: the scene at the map's sizes, stiffened, at the report's error and the visual one.
ScalingConfig map_config(const ReportData& d, const ReportSizes& s) {
  ScalingConfig c = config_for(d, s);
  const SceneKernel& k = scene_kernel(s.scene);
  c.sizes = d.config.scaling_map_sizes;
  for (double f : d.config.scaling_stiffening) c.stiffnesses.push_back(f * c.params[k.stiffness_param]);
  c.targets.push_back({d.config.scaling_visual, true});
  c.max_steps = kReportMapSteps;
  std::erase_if(c.adaptive, [](const std::string& a) { return !map_peer(*find_peer(a)); });
  return c;
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
  const std::string solver = k.jacobian_bandwidth >= 0 ? "its banded LU" : "SuiteSparse's KLU";
  if (!first)
    return fmt::format("{} ({}), at {}: the same measure against {}, dt* from its modes, CVODE with {} as its linear "
                       "solver.\n\n", k.title, params_but_size(scene, c.params), at, against, solver);
  return fmt::format(
      "{} ({}), refined by its {} to {}: each method's step (each adaptive solver's tolerance) searched until the position "
      "error over the whole motion (the largest over the masses and {} frames to t = {:g}; a fixed step divides the frame "
      "interval) against {} is at most {:g}, and that run's cost by {}. Its stable "
      "step dt* comes from its modes (`steplab study stability --scene {}` measures it too). A fixed-step method's search is "
      "capped at 0.95 dt*: it is told where its steps stop being stable, which no adaptive solver is told. The peers: "
      "Boost.Odeint's dopri5 and SUNDIALS CVODE ({}) with Adams-Moulton, with BDF and with BDF capped at order 2 (A-stable), "
      "each with Newton on the analytic Jacobian and {}. Every solver is timed alike: the scene made outside, the solver's "
      "set-up, run and clean-up inside, the minimum of repeats.\n\n",
      k.title, params_but_size(scene, c.params), size_name, at, c.frames, c.t_end, against, c.targets.front().value,
      c.timing ? "run time" : "force and Jacobian evaluations times N", k.name, cvode_build_text(), solver);
}

// scaling_map.dat: a gnuplot index per target, a line per cell: its column (size) and row
// (stiffness) index, the colour of its cheapest solver's group, the solver and its margin.
std::string map_data(const ScalingResult& r) {
  const ScalingConfig& c = r.config;
  const std::size_t nk = r.blocks.size() / c.targets.size();
  std::string t = "# size_index stiffness_index rgb cheapest margin (index: target)\n";
  for (std::size_t target = 0; target < c.targets.size(); ++target) {
    if (target > 0) t += "\n\n";
    for (std::size_t k = 0; k < nk; ++k)
      for (std::size_t n = 0; n < c.sizes.size(); ++n) {
        const ScalingCell& m = r.blocks[target * nk + k].cells[n];
        const std::string hue = m.cheapest.empty() ? "#FFFFFF" : solver_hue(m.cheapest);
        t += fmt::format("{} {} {} \"{}\" \"{}\"\n", n, k, std::stoi(hue.substr(1), nullptr, 16),
                         m.cheapest.empty() ? "none" : m.cheapest, std::isnan(m.margin) ? "" : fmt::format("x{:.2f}", m.margin));
      }
  }
  return t;
}

// fig13_map's variables: the panels' titles, the tics (masses, stiffnesses: words), the axis name.
std::string map_vars(const ScalingResult& r) {
  const ScalingConfig& c = r.config;
  const std::size_t nk = r.blocks.size() / c.targets.size();
  std::string xt, yt, titles;
  for (std::size_t n = 0; n < c.sizes.size(); ++n) xt += fmt::format("{}{}", n ? " " : "", scaling_masses(c, c.sizes[n]));
  for (std::size_t k = 0; k < nk; ++k) yt += fmt::format("{}{:g}", k ? " " : "", r.blocks[k].stiffness);
  for (std::size_t t = 0; t < c.targets.size(); ++t)
    titles += fmt::format("; tt{}='error {}'", t + 1, target_text(c, r.blocks[t * nk]));
  const SceneKernel& s = scene_kernel(scene_index(c.scene));
  return fmt::format("ntargets={}; xlabels='{}'; ylabels='{}'; ylab='{}'{}", c.targets.size(), xt, yt,
                     s.params[s.stiffness_param].name, titles);
}

// The map's paragraph, figure and findings.
std::string map_markdown(const ScalingResult& r, Page& page) {
  const ScalingConfig& c = r.config;
  std::vector<std::string> stiff;
  for (std::size_t k = 0; k < r.blocks.size() / c.targets.size(); ++k) stiff.push_back(fmt::format("{:g}", r.blocks[k].stiffness));
  const SceneKernel& s = scene_kernel(scene_index(c.scene));
  std::vector<int> masses;
  for (int n : c.sizes) masses.push_back(scaling_masses(c, n));
  std::string md = fmt::format(
      "**When does implicit pay?** The {} above stiffened as well, at N = {}: its {} at {}, each cell (size, stiffness) the same "
      "study, every method and the peers but CVODE's BDF of orders up to 5 (its orders 1-2 stand for it; a search tries no step "
      "that needs more than {} steps), at the error above and at a "
      "visual one ({}); a margin below about 1.2 is within the timing's noise on runs this short. Each cell is coloured by the group of its cheapest "
      "solver (a method's family; CVODE; the explicit adaptive solvers), labelled with it and its margin over the next "
      "cheapest. `steplab study scaling --scene {} --sizes {} --stiffness {} --error {:g},{:g}% --max-steps {}` gives this map, with every peer and "
      "every count.\n\n",
      s.name, join(masses), s.params[s.stiffness_param].name, fmt::join(stiff, ", "), c.max_steps,
      target_text(c, r.blocks.back()),
      s.name, join(c.sizes), fmt::join(stiff, ","), c.targets.front().value, 100 * c.targets.back().value, c.max_steps);
  md += page.figure("fig13_map", fmt::format("{}: the cheapest solver in each cell (masses N, {}); colour by group: explicit "
                                             "Runge-Kutta blue, symplectic splitting vermillion, implicit Runge-Kutta green, "
                                             "Adams-Bashforth purple, BDF orange, CVODE sky blue, explicit adaptive grey",
                                             s.title, s.params[s.stiffness_param].name));
  return md + map_findings(r);
}

class Growth : public Section {
 public:
  std::string title() const override { return "As the system grows"; }
  std::string missing(const ReportConfig& c) const override {
    for (const ReportSizes& s : c.scaling)
      if (c.covers(s.scene)) return "";
    return "none of the chosen scenes is of run-time size";
  }
  void study(const ReportData& d) override {
    for (const ReportSizes& s : d.config.scaling)
      if (d.config.covers(s.scene)) {
        if (r_.empty() && scene_kernel(s.scene).stiffness_param >= 0 && !d.config.scaling_map_sizes.empty())
          map_ = scaling_study(map_config(d, s));
        r_.push_back(scaling_study(config_for(d, s)));
      }
  }

  void write_data(const ReportData&, const DataDir& dat) const override {
    for (const ScalingResult& r : r_) dat.write(fmt::format("scaling_{}.json", r.config.scene), scaling_json(r).dump(1) + "\n");
    if (r_.empty()) return;
    const ScalingResult& first = r_.front();  // the figure's
    for (std::size_t s = 0; s < first.solvers(); ++s) {
      const std::span<const ScalingRow> rows = first.rows_of(s);
      const ScalingRow& smallest = rows.front();
      std::string t = "# masses run_cost step_cost dt_stable dt_stable_one_over_n\n";
      for (const ScalingRow& w : rows) {
        const double cost = scaling_cost(first.config, w);
        // 1/N prediction from the smallest size: dt*(N) = dt*(N0) N0 / N
        t += fmt::format("{} {} {} {} {}\n", w.n, w.reached() ? num(cost) : "NaN", w.reached() && w.steps > 0 ? num(cost / w.steps) : "NaN",
                         num(w.dt_stable), num(smallest.dt_stable * smallest.n / w.n));
      }
      dat.write("scaling_" + smallest.solver + ".dat", t);
    }
    if (map_) {
      dat.write("scaling_map.json", scaling_json(*map_).dump(1) + "\n");
      dat.write("scaling_map.dat", map_data(*map_));
    }
  }

  // The explicit methods with a finite stable step at every size: the last panel's.
  std::vector<FigureSpec> figures(const ReportData&) const override {
    if (r_.empty()) return {};
    const ScalingResult& first = r_.front();
    std::string limited;
    for (std::size_t s = 0; s < first.solvers(); ++s) {
      const std::span<const ScalingRow> rows = first.rows_of(s);
      const bool limited_everywhere = !rows.front().implicit && !rows.front().adaptive &&
                                      std::all_of(rows.begin(), rows.end(), [](const ScalingRow& w) {
                                        return std::isfinite(w.dt_stable) && w.dt_stable > 0;
                                      });
      if (!limited_everywhere) continue;
      if (!limited.empty()) limited += ' ';
      limited += rows.front().solver;
    }
    // a panel per family and one of the adaptive solvers, each of the solvers that reached the target at some N
    const auto reached = [&](std::string_view solver) {
      for (std::size_t s = 0; s < first.solvers(); ++s)
        for (const ScalingRow& w : first.rows_of(s))
          if (w.solver == solver && w.reached()) return true;
      return false;
    };
    std::vector<Panel> panels = family_panels(first.config.methods, [&](std::size_t m) { return reached(name(m)); });
    Panel adaptive{"adaptive solvers", {}};
    for (const std::string& a : first.config.adaptive)
      if (reached(a)) adaptive.solvers.push_back(a);
    if (!adaptive.solvers.empty()) panels.push_back(std::move(adaptive));
    std::vector<FigureSpec> out{{"fig11_scaling", fmt::format("costname='{}'; limited='{}'",
                                                              first.config.timing ? "run time (s)" : "evaluations x N", limited),
                                 std::move(panels)}};
    if (map_) out.push_back({"fig13_map", map_vars(*map_), {}});
    return out;
  }

  std::string markdown(Page& page) const override {
    std::string md = "## " + title() + "\n\n";
    for (std::size_t i = 0; i < r_.size(); ++i) {
      const ScalingResult& r = r_[i];
      md += scene_paragraph(r, i == 0) + exponents_table(r) + findings(r);
      if (i == 0)
        md += page.figure("fig11_scaling", fmt::format("{}: whole-run cost at the target error against N, a panel "
                                                       "per family and one for the adaptive solvers; last panel: explicit "
                                                       "methods' dt* against N, dashed its 1/N prediction from the smallest N",
                                                       scene_kernel(scene_index(r.config.scene)).title));
      if (i == 0 && map_) md += map_markdown(*map_, page);
    }
    return md;
  }

 private:
  std::vector<ScalingResult> r_;  // one per covered scene of config.scaling
  std::optional<ScalingResult> map_;  // the first one's, stiffened
};

}  // namespace

std::unique_ptr<Section> make_growth_section() { return std::make_unique<Growth>(); }

}  // namespace steplab
