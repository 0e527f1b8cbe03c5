// What the scaling study's rows say (analysis/studies/scaling.hpp): the exponents of each series, and
// per (target, stiffness) the crossover and the map's cells.
#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/fits/fit.hpp"
#include "analysis/peers/peers.hpp"
#include "analysis/studies/scaling.hpp"

namespace steplab {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

ScalingFit fit_of(const ScalingConfig& c, std::span<const ScalingRow> rows) {
  std::vector<double> masses, run, step, stable;
  for (const ScalingRow& r : rows) {
    masses.push_back(r.masses);
    run.push_back(r.reached() && r.steps > 0 ? scaling_cost(c, r) : kNaN);
    step.push_back(run.back() / static_cast<double>(r.steps));
    stable.push_back(r.dt_stable);
  }
  const ScalingRow& first = rows.front();
  ScalingFit f{first.solver, first.target, first.stiffness, fit_exponent(masses, step), fit_exponent(masses, run),
               fit_exponent(masses, stable)};
  f.step.early = f.run.early = begins_early(masses, step);
  return f;
}

// An adaptive implicit peer: CVODE (its Adams too: Newton's iteration), ARKODE's DIRK tables, RADAU5.
bool is_implicit_peer(const ScalingRow& r) {
  const PeerInfo* p = r.adaptive ? find_peer(r.solver) : nullptr;
  return p && p->implicit;
}

// The map's cell at size k of block b (its rows: series b * solvers + s, entry k).
void answer_cell(const ScalingResult& r, std::size_t b, std::size_t k, ScalingCell& cell) {
  const ScalingConfig& c = r.config;
  constexpr double inf = std::numeric_limits<double>::infinity();
  double cheapest = inf, next = inf, implicit = inf, explicit_ = inf, peer = inf;
  const ScalingRow *first = nullptr, *second = nullptr;  // the cheapest row and the next
  for (std::size_t s = 0; s < r.solvers(); ++s) {
    const ScalingRow& w = r.rows_of(b * r.solvers() + s)[k];
    if (!w.reached()) continue;
    const double cost = scaling_cost(c, w);
    if (cost < cheapest) next = cheapest, second = first, cheapest = cost, first = &w;
    else if (cost < next) next = cost, second = &w;
    if (!w.adaptive && w.implicit && cost < implicit) implicit = cost, cell.best_implicit = w.solver;
    if (!w.implicit && !is_implicit_peer(w) && cost < explicit_) explicit_ = cost, cell.best_explicit = w.solver;
    if (is_implicit_peer(w) && cost < peer) peer = cost, cell.best_implicit_peer = w.solver;
  }
  const auto ratio = [](double num, double den) { return std::isfinite(num) && std::isfinite(den) ? num / den : kNaN; };
  if (first) cell.cheapest = first->solver;
  if (second) cell.next = second->solver;
  cell.margin = ratio(next, cheapest);
  cell.explicit_over_implicit = ratio(explicit_, implicit);
  cell.implicit_peer_over_implicit = ratio(peer, implicit);
  if (!first) return;
  // The rival: the cheapest run of another group.
  const std::string group = solver_group(first->solver);
  const ScalingRow* rival = cheapest_run(r, b, k, [&](const ScalingRow& w) { return solver_group(w.solver) != group; });
  if (rival) cell.rival = rival->solver;
  cell.rival_margin = rival ? scaling_cost(c, *rival) / cheapest : kNaN;
}

// The first size where the cheapest implicit fixed-step method's run is cheaper than every
// explicit one's (steplab's methods, dopri5 among the explicit) by more than the timing's noise
// (kTieMargin, analysis/kernel/noise.hpp). Untimed it is not read: the
// force evaluations leave out the implicit methods' factorisations and solves.
void answer_crossover(const ScalingResult& r, std::size_t b, ScalingBlock& block) {
  const ScalingConfig& c = r.config;
  if (!c.timing) return;
  for (std::size_t k = 0; k < c.sizes.size() && block.crossover == 0; ++k) {
    const auto [imp, exp] = crossover_sides(r, b, k);
    if (imp && (!exp || kTieMargin * imp->seconds < exp->seconds))
      block.crossover = c.sizes[k], block.crossover_method = imp->solver;
  }
}

}  // namespace

bool begins_early(std::span<const double> masses, std::span<const double> step_cost) {
  std::vector<std::size_t> known;
  for (std::size_t k = 0; k < masses.size() && known.size() < 2; ++k)
    if (std::isfinite(step_cost[k]) && step_cost[k] > 0) known.push_back(k);
  if (known.size() < 2) return false;
  const std::size_t a = known[0], b = known[1];
  return std::log(step_cost[b] / step_cost[a]) < kAsymptoticSlope * std::log(masses[b] / masses[a]);
}

Exponent fit_exponent(std::span<const double> masses, std::span<const double> y) {
  std::vector<double> n, v;
  for (std::size_t k = 0; k < masses.size(); ++k)
    if (std::isfinite(y[k]) && y[k] > 0) n.push_back(std::log(masses[k])), v.push_back(std::log(y[k]));
  Exponent e;
  e.sizes = static_cast<int>(n.size());
  if (n.empty()) return e;
  e.decades = (*std::max_element(n.begin(), n.end()) - *std::min_element(n.begin(), n.end())) / std::log(10.0);
  if (e.sizes < kFitSizes || e.decades < kFitDecades - 1e-9) return e;
  const LineFit line = fit_line(n, v);
  e.value = line.slope, e.lo = line.ci95_lo, e.hi = line.ci95_hi;
  return e;
}

void answer_rows(ScalingResult& r) {
  r.fits.clear();
  for (std::size_t s = 0; s < r.series(); ++s) r.fits.push_back(fit_of(r.config, r.rows_of(s)));
  for (std::size_t b = 0; b < r.blocks.size(); ++b) {
    answer_crossover(r, b, r.blocks[b]);
    for (std::size_t k = 0; k < r.blocks[b].cells.size(); ++k) answer_cell(r, b, k, r.blocks[b].cells[k]);
  }
}

CrossoverSides crossover_sides(const ScalingResult& r, std::size_t b, std::size_t k) {
  CrossoverSides out;
  for (std::size_t s = 0; s < r.config.methods.size(); ++s) {
    const ScalingRow& w = r.rows_of(b * r.solvers() + s)[k];
    if (!w.reached()) continue;
    const ScalingRow*& side = w.implicit ? out.implicit : out.explicit_;
    if (!side || w.seconds < side->seconds) side = &w;
  }
  return out;
}

}  // namespace steplab
