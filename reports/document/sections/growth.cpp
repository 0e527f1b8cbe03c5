// As the system grows: the rope of N masses and the soft body of n x n masses refined
// (analysis/scaling.hpp), every method and the peers; cost against N, the stable step against its
// 1/N prediction (the rope), the exponents, the crossover, steplab's cheapest against CVODE.
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
std::string params_but_size(std::string_view scene, const std::vector<double>& params) {
  const std::string all = params_text(*find_scene(scene), params);
  return all.substr(all.find(", ") + 2);
}

// The exponents, and where a fixed-step method's step was held at its cap 0.95 dt* (told by the modes).
std::string exponents_table(const ScalingResult& r) {
  std::string md = "| solver | cost ~ N^p^: one step | whole run | dt* ~ N^q^ | step at 0.95 dt* |\n|---|---:|---:|---:|---|\n";
  const auto p = [](double x) { return std::isnan(x) ? std::string("-") : fmt::format("{:.2f}", x); };
  for (std::size_t s = 0; s < r.fits.size(); ++s) {
    const ScalingFit& f = r.fits[s];
    std::vector<int> capped;
    for (const ScalingRow& w : r.rows_of(s))
      if (w.reached() && w.capped) capped.push_back(w.masses);
    md += fmt::format("| `{}` | {} | {} | {} | {} |\n", f.solver, p(f.step_exponent), p(f.run_exponent), p(f.stable_exponent),
                      capped.empty() ? "-" : "N = " + join(capped));
  }
  return md + "\n";
}

// The crossover sentence, and steplab's cheapest against each CVODE configuration at the largest
// size, in cost and in force evaluations, with their counts.
std::string findings(const ScalingResult& r) {
  const ScalingConfig& c = r.config;
  std::string md = r.crossover == 0
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

ScalingConfig config_for(const ReportData& d, std::string_view scene, const std::vector<int>& sizes) {
  ScalingConfig c = scaling_config(scene);  // the scene's defaults, as `study scaling --scene ...`
  c.sizes = sizes;
  c.target_error = d.config.scaling_error;
  c.t_end = d.config.scaling_t_end;
  c.methods = d.numerical_methods();
  c.timing = d.config.timing;
  c.workers = d.workers;
  return c;
}

class Growth : public Section {
 public:
  void study(const ReportData& d) override {
    r_ = scaling_study(config_for(d, "rope", d.config.scaling_sizes));
    soft_ = scaling_study(config_for(d, "softbody", d.config.scaling_grids));
  }

  void write_data(const ReportData&, const DataDir& dat) const override {
    dat.write("scaling.json", scaling_json(r_).dump(1) + "\n");
    dat.write("scaling_softbody.json", scaling_json(soft_).dump(1) + "\n");
    for (std::size_t s = 0; s < r_.solvers(); ++s) {
      const std::span<const ScalingRow> rows = r_.rows_of(s);
      const ScalingRow& first = rows.front();
      std::string t = "# masses run_cost step_cost dt_stable dt_stable_one_over_n\n";
      for (const ScalingRow& w : rows) {
        const double cost = scaling_cost(r_.config, w);
        // 1/N prediction from the smallest size: dt*(N) = dt*(N0) N0 / N
        t += fmt::format("{} {} {} {} {}\n", w.n, w.reached() ? num(cost) : "NaN", w.reached() && w.steps > 0 ? num(cost / w.steps) : "NaN",
                         num(w.dt_stable), num(first.dt_stable * first.n / w.n));
      }
      dat.write("scaling_" + first.solver + ".dat", t);
    }
  }

  // The explicit methods with a finite stable step at every size: the last panel's.
  std::vector<FigureSpec> figures(const ReportData&) const override {
    std::string limited;
    for (std::size_t s = 0; s < r_.solvers(); ++s) {
      const std::span<const ScalingRow> rows = r_.rows_of(s);
      const bool limited_everywhere = !rows.front().implicit && !rows.front().adaptive &&
                                      std::all_of(rows.begin(), rows.end(), [](const ScalingRow& w) {
                                        return std::isfinite(w.dt_stable) && w.dt_stable > 0;
                                      });
      if (!limited_everywhere) continue;
      if (!limited.empty()) limited += ' ';
      limited += rows.front().solver;
    }
    std::string scaled;
    for (const std::string& a : r_.config.adaptive) scaled += (scaled.empty() ? "" : " ") + a;
    return {{"fig11_scaling", fmt::format("costname='{}'; limited='{}'; scaled='{}'", r_.config.timing ? "run time (s)" : "evaluations x N",
                                          limited, scaled)}};
  }

  std::string markdown(Page& page) const override {
    const ScalingConfig& c = r_.config;
    std::string md = "## As the system grows\n\n";
    md += fmt::format("The hanging rope of N masses, a refinement of one rope (total mass, stiffness, rest length and damping "
                      "kept: {}), at N = {}: each method's step (each adaptive solver's tolerance) searched until the position "
                      "error at t = {:g}, the largest over the masses, is at most {:g}, and that run's cost by {}. Its stable "
                      "step dt* comes from its modes (`steplab study stability --scene rope` measures it too). A fixed-step "
                      "method's search is capped at 0.95 dt*: it is told where its steps stop being stable, which no adaptive "
                      "solver is told. The peers: Boost.Odeint's dopri5 and SUNDIALS CVODE ({}) with Adams-Moulton, with BDF and with BDF "
                      "capped at order 2 (A-stable), "
                      "each with Newton on the analytic Jacobian and its banded LU. Every solver is timed alike: the scene made "
                      "outside, the solver's set-up, run and clean-up inside, the minimum of repeats.\n\n",
                      params_but_size("rope", c.params), join(c.sizes), c.t_end,
                      c.target_error, c.timing ? "run time" : "force and Jacobian evaluations times N", cvode_build_text());
    md += exponents_table(r_) + findings(r_);
    md += page.figure("fig11_scaling", "rope of N masses: whole-run cost at the target error against N, a panel per family and "
                                              "one for the adaptive solvers; last panel: explicit methods' dt* against N, "
                                              "dashed its 1/N prediction from the smallest N");
    const ScalingConfig& s = soft_.config;
    std::vector<int> masses;
    for (int n : s.sizes) masses.push_back(scaling_masses(s, n));
    md += fmt::format("The soft body, the falling triangle refined to n x n masses joined by structural and shear springs ({}), "
                      "at N = {} masses (n = {}): the same measure against its reference solution (dopri5 at rtol 1e-13), dt* "
                      "from its fastest mode linearised on the ground (its frequency grows as n: dt* ~ N^-1/2^), CVODE with "
                      "SuiteSparse's KLU as its linear solver.\n\n",
                      params_but_size("softbody", s.params), join(masses), join(s.sizes));
    md += exponents_table(soft_) + findings(soft_);
    return md;
  }

 private:
  ScalingResult r_, soft_;
};

}  // namespace

std::unique_ptr<Section> make_growth_section() { return std::make_unique<Growth>(); }

}  // namespace steplab
