// As the system grows: every scene of run-time size with modes (by default the rope of N masses
// and the soft body of n x n masses) refined (analysis/scaling.hpp), every method and the peers;
// cost against N, the stable step against its 1/N prediction (the first scene's figure), the
// exponents, the crossover, steplab's cheapest against CVODE.
#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "analysis/kernel.hpp"
#include "analysis/peers.hpp"
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
  for (std::size_t s = 0; s < r.fits.size(); ++s) {
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
                   : r.crossover == 0
                       ? fmt::format("- At none of these sizes is an implicit method's whole run cheaper than every explicit one's.\n")
                       : fmt::format("- From N = {} on (of these sizes), `{}` is cheaper than every explicit method.\n",
                                     scaling_masses(c, r.crossover), r.crossover_method);
  const ScalingRow* best = nullptr;
  std::vector<const ScalingRow*> cvode;
  for (const ScalingRow& w : r.rows) {
    if (w.n != c.sizes.back() || !w.reached()) continue;
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

ScalingConfig config_for(const ReportData& d, const ReportSizes& s) {
  ScalingConfig c = scaling_config(scene_name(s.scene));  // the scene's defaults, as `study scaling --scene ...`
  c.sizes = s.sizes;
  c.target_error = d.config.scaling_error;
  c.t_end = d.config.scaling_t_end;
  c.methods = d.numerical_methods();
  c.timing = d.config.timing;
  c.workers = d.workers;
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
      "error at t = {:g} against {}, the largest over the masses, is at most {:g}, and that run's cost by {}. Its stable "
      "step dt* comes from its modes (`steplab study stability --scene {}` measures it too). A fixed-step method's search is "
      "capped at 0.95 dt*: it is told where its steps stop being stable, which no adaptive solver is told. The peers: "
      "Boost.Odeint's dopri5 and SUNDIALS CVODE ({}) with Adams-Moulton, with BDF and with BDF capped at order 2 (A-stable), "
      "each with Newton on the analytic Jacobian and {}. Every solver is timed alike: the scene made outside, the solver's "
      "set-up, run and clean-up inside, the minimum of repeats.\n\n",
      k.title, params_but_size(scene, c.params), size_name, at, c.t_end, against, c.target_error,
      c.timing ? "run time" : "force and Jacobian evaluations times N", k.name, cvode_build_text(), solver);
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
      if (d.config.covers(s.scene)) r_.push_back(scaling_study(config_for(d, s)));
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
    std::string scaled;
    for (const std::string& a : first.config.adaptive) scaled += (scaled.empty() ? "" : " ") + a;
    return {{"fig11_scaling", fmt::format("costname='{}'; limited='{}'; scaled='{}'", first.config.timing ? "run time (s)" : "evaluations x N",
                                          limited, scaled)}};
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
    }
    return md;
  }

 private:
  std::vector<ScalingResult> r_;  // one per covered scene of config.scaling
};

}  // namespace

std::unique_ptr<Section> make_growth_section() { return std::make_unique<Growth>(); }

}  // namespace steplab
