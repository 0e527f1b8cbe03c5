#include "reports/document/findings.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/peers/peers.hpp"
#include "analysis/studies/long_time.hpp"
#include "reports/document/figure_styles.hpp"
#include "reports/document/report_text.hpp"

namespace steplab {

std::vector<std::size_t> methods_of(const Findings& f, const std::vector<std::size_t>& rows) {
  std::vector<std::size_t> out;
  for (std::size_t i : rows) out.push_back(f.rows[i].method);
  return out;
}

bool tied(double margin, bool timed) { return timed ? margin < kTieMargin : margin == 1; }

std::string_view to_text(Trend t) {
  switch (t) {
    case Trend::StaysInfinite: return "stays unbounded";
    case Trend::Rises: return "rises";
    case Trend::Falls: return "falls";
    case Trend::StaysTheSame: return "stays the same";
    case Trend::Mixed: return "does not move one way";
    case Trend::NotMeasured: return "not measured";
  }
  return "?";
}

bool same_within(double a, double b, double relative) {
  if (a == b) return true;
  return std::isfinite(a) && std::isfinite(b) && std::abs(a - b) <= relative * std::max(std::abs(a), std::abs(b));
}

Trend trend(const std::vector<double>& dt) {
  if (std::any_of(dt.begin(), dt.end(), [](double x) { return std::isnan(x); })) return Trend::NotMeasured;
  if (std::all_of(dt.begin(), dt.end(), [](double x) { return std::isinf(x); })) return Trend::StaysInfinite;
  // Two measured dt* closer than the threshold search resolves them (analysis/studies/stability.hpp) are equal.
  bool up = false, down = false;
  for (std::size_t i = 0; i + 1 < dt.size(); ++i)
    if (!same_within(dt[i + 1], dt[i], kSameThreshold)) up |= dt[i + 1] > dt[i], down |= dt[i + 1] < dt[i];
  return up && down ? Trend::Mixed : up ? Trend::Rises : down ? Trend::Falls : Trend::StaysTheSame;
}

std::vector<FamilyTrend> family_trends(const ReportData& d, double damping) {
  std::vector<FamilyTrend> out;
  for (Family f : kReportFamilies) {
    const std::vector<std::size_t> fam = family_members(d.methods, f);
    if (fam.size() < 2 || method_info(fam.front()).order == method_info(fam.back()).order) continue;
    FamilyTrend t{f, fam, {}, Trend::Mixed};
    for (std::size_t m : fam) {
      const ThresholdRow* r = find_threshold(d, m, damping);
      t.dt.push_back(r ? r->dt_measured : NAN);
    }
    t.trend = trend(t.dt);
    out.push_back(std::move(t));
  }
  return out;
}

std::string correlation_words(double rho) {
  const double a = std::abs(rho);
  const char* strength = a < 0.3 ? "weak" : a < 0.7 ? "moderate" : "strong";
  return std::string(strength) + (rho >= 0 ? " positive" : " negative");
}

double spearman_chance(std::size_t n) { return 1.96 / std::sqrt(static_cast<double>(n) - 1); }

std::string chance_words(double rho, std::size_t n) {
  const double limit = spearman_chance(n);
  if (limit >= 1) return fmt::format("no evidence either way, since no ranking of {} methods reaches the 5 % level", n);
  if (std::abs(rho) <= limit) return fmt::format("within chance for {} methods (beyond it from |rho| > {:.2f})", n, limit);
  return fmt::format("beyond chance at the 5 % level (|rho| > {:.2f})", limit);
}

std::string_view to_text(EnergyKind k) {
  switch (k) {
    case EnergyKind::Bounded: return "bounded";
    case EnergyKind::Grows: return "grows";
    case EnergyKind::Decays: return "decays";
    case EnergyKind::Damped: return "damped out";
    case EnergyKind::Blows: return "blows up";
  }
  return "?";
}

std::vector<EnergyBehaviour> energy_behaviour(const ReportData& d) {
  std::vector<EnergyBehaviour> out;
  for (std::size_t i = 0; i < d.methods.size() && i < d.energy.size(); ++i) {
    const RunResult<1>& run = d.energy[i];
    if (method_info(d.methods[i]).exact_flow || run.samples.empty()) continue;
    EnergyBehaviour e{d.methods[i]};
    const double e0 = run.samples.front().energy, t_end = run.samples.back().t;
    for (const auto& s : run.samples) {
      const double r = s.energy / e0;
      e.lo = std::min(e.lo, r), e.hi = std::max(e.hi, r);
      double& half = s.t <= t_end / 2 ? e.first_half : e.second_half;
      half = std::max(half, std::abs(r - 1));
    }
    e.final_ratio = run.samples.back().energy / e0;
    e.round_off = kRoundOff * 0x1p-53 * std::sqrt(t_end / d.config.large_dt);
    if (run.status != RunStatus::Ok) e.ended = run.failed_t;
    e.kind = run.status != RunStatus::Ok || e.hi > kBlownRatio                                   ? EnergyKind::Blows
             : e.lo < 1 / kBlownRatio                                                             ? EnergyKind::Damped
             : e.second_half <= kBoundedGrowth * e.first_half || e.second_half <= e.round_off ? EnergyKind::Bounded
             : e.final_ratio > 1                                                                  ? EnergyKind::Grows
                                                                                                  : EnergyKind::Decays;
    out.push_back(e);
  }
  return out;
}

std::vector<std::size_t> methods_of_kind(const std::vector<EnergyBehaviour>& e, EnergyKind k) {
  std::vector<std::size_t> out;
  for (const EnergyBehaviour& b : e)
    if (b.kind == k) out.push_back(b.method);
  return out;
}

std::vector<StiffClaim> stiff_claims(const OrderReduction& r) {
  std::vector<StiffClaim> out;
  const ConvergenceSweep& s = r.sweep;
  for (std::size_t m = 0; m < r.methods.size(); ++m) {
    const MethodReduction& mr = r.methods[m];
    const StiffTheory& t = mr.theory;
    StiffClaim c{mr.method, StiffVerdict::Keeps, t.classical, t.stiff};
    c.non_stiff_order = mr.non_stiff.order, c.stiff_order = mr.stiff.order;
    c.keeps_to = mr.keeps_to, c.reduced_from = mr.reduced_from;
    c.starter = method_kernel(mr.method).starter;
    if (t.stiff < 0) c.verdict = StiffVerdict::Unstable;
    else if (!mr.stiff.reached || !mr.stiff.fitted) c.verdict = StiffVerdict::NotReached;
    else if (!mr.stiff.holds || !mr.non_stiff.holds) c.verdict = StiffVerdict::Differs;
    else if (t.stiff < t.classical) c.verdict = StiffVerdict::Falls;
    else if (t.stiff > t.classical) c.verdict = StiffVerdict::Rises;
    if (c.verdict == StiffVerdict::Keeps) {
      // Kept at every stiffness only if every fit between the limits keeps it too.
      double worst = 0;
      for (std::size_t v = 0; v < s.values.size(); ++v) {
        const OrderFit& f = s.studies[v].fits[m].fit;
        if (!f.fitted || mr.past_stable[v]) continue;
        const double off = std::abs(f.order - t.classical);
        const bool keeps = off <= kStiffTolerance || (f.bound_lo <= t.classical && t.classical <= f.bound_hi);
        if (!keeps && off > worst) {
          worst = off, c.verdict = StiffVerdict::Strays;
          c.stray_order = f.order, c.stray_lo = f.bound_lo, c.stray_hi = f.bound_hi, c.stray_value = s.values[v];
          c.stray_h_lambda = mr.h_lambda[v];
        }
      }
    }
    out.push_back(c);
  }
  return out;
}

double point_cost(const WorkPoint& p, bool timed) { return timed ? p.seconds : static_cast<double>(p.force_evaluations); }

std::string cost_text(bool timed, double seconds, long long forces) {
  if (!timed) return fmt::format("{} force evaluations", forces);
  if (seconds < 1e-3) return fmt::format("{:.3g} µs", seconds * 1e6);
  return seconds < 1 ? fmt::format("{:.3g} ms", seconds * 1e3) : fmt::format("{:.3g} s", seconds);
}

const WorkPoint* cheapest_point(const SceneWork& w, const std::string& solver, double level, bool timed) {
  const WorkPoint* best = nullptr;
  for (const WorkPoint& p : w.points)
    if (p.method == solver && p.status == RunStatus::Ok && p.error <= level && (!best || point_cost(p, timed) < point_cost(*best, timed)))
      best = &p;
  return best;
}

LevelWinner level_winner(const SceneWork& w, double level, bool timed) {
  LevelWinner out;
  std::vector<std::string> solvers;
  for (const WorkPoint& p : w.points)
    if (std::find(solvers.begin(), solvers.end(), p.method) == solvers.end()) solvers.push_back(p.method);
  const WorkPoint* second = nullptr;
  for (const std::string& s : solvers) {
    const WorkPoint* p = cheapest_point(w, s, level, timed);
    if (!p) continue;
    if (!out.point || point_cost(*p, timed) < point_cost(*out.point, timed)) second = out.point, out.point = p;
    else if (!second || point_cost(*p, timed) < point_cost(*second, timed)) second = p;
  }
  if (!out.point) return out;
  if (second) {
    out.next = second->method, out.margin = point_cost(*second, timed) / point_cost(*out.point, timed);
  }
  out.tie = second && tied(out.margin, timed);
  if (out.tie)
    for (const std::string& s : solvers)
      if (const WorkPoint* p = cheapest_point(w, s, level, timed);
          p && p != out.point && p->method != out.next && tied(point_cost(*p, timed) / point_cost(*out.point, timed), timed))
        out.also.push_back(p);
  std::sort(out.also.begin(), out.also.end(), [&](const WorkPoint* a, const WorkPoint* b) {  // by cost, then by name
    return std::pair(point_cost(*a, timed), a->method) < std::pair(point_cost(*b, timed), b->method);
  });
  if (!timed && !out.tie && solves(out.point->method)) {
    const WorkPoint* against = nullptr;  // the cheapest explicit solver's run at the level
    for (const std::string& s : solvers)
      if (!solves(s))
        if (const WorkPoint* p = cheapest_point(w, s, level, false); p && (!against || point_cost(*p, false) < point_cost(*against, false)))
          against = p;
    if (against) out.undecided = against->method;
  }
  double edge = 0;  // the largest step or the loosest tolerance the winner's sweep tried
  for (const WorkPoint& p : w.points)
    if (p.method == out.point->method) edge = std::max(edge, p.setting);
  out.at_edge = out.point->setting == edge;
  return out;
}

std::vector<MethodRate> rates_of(const Findings& f, const std::vector<std::size_t>& rows, bool undamped) {
  std::vector<MethodRate> out;
  for (std::size_t i : rows) {
    const MethodFinding& r = f.rows[i];
    out.push_back({r.method, undamped ? r.energy_rate_undamped : r.energy_rate_large_dt, undamped ? r.energy_max_undamped : r.energy_max_large_dt});
  }
  return out;
}

namespace {
bool is_weak(const MethodRate& r) { return r.rate < kWeakRate && !(r.energy_max > kBlownRatio); }
}  // namespace

std::vector<std::size_t> weakly(const std::vector<MethodRate>& runs) {
  std::vector<std::size_t> out;
  for (const MethodRate& r : runs)
    if (is_weak(r)) out.push_back(r.method);
  return out;
}

std::vector<std::size_t> strongly(const std::vector<MethodRate>& runs) {
  std::vector<std::size_t> out;
  for (const MethodRate& r : runs)
    if (std::isfinite(r.rate) && r.rate >= kWeakRate) out.push_back(r.method);
  return out;
}

std::vector<std::size_t> far_from_e0(const std::vector<MethodRate>& runs) {
  std::vector<std::size_t> out;
  for (const MethodRate& r : runs)
    if (std::isfinite(r.rate) && r.rate < kWeakRate && r.energy_max > kBlownRatio) out.push_back(r.method);
  return out;
}

std::string unstable_words(const std::vector<MethodRate>& runs) {
  const std::vector<std::size_t> weak = weakly(runs);
  std::vector<std::string> strong;  // the others, a blown-up run (no finite rate) among them; one far from E0 with its E/E0
  std::vector<std::string> rates;
  for (const MethodRate& r : runs)
    if (is_weak(r)) rates.push_back(fmt::format("{:.3g}", r.rate));
    else if (std::isfinite(r.rate) && r.rate < kWeakRate) strong.push_back(fmt::format("`{}` (its E/E0 up to {:.3g})", name(r.method), r.energy_max));
    else strong.push_back(fmt::format("`{}`", name(r.method)));
  if (weak.empty()) return and_list(strong);
  const std::string w = fmt::format("weakly (energy growing {} per unit time) {}", and_list(rates), method_list(weak));
  return strong.empty() ? w : fmt::format("{}, and {}", and_list(strong), w);
}

std::vector<std::string> LevelWinner::tied_with() const {
  std::vector<std::string> out{next};
  for (const WorkPoint* p : also) out.push_back(p->method);
  return out;
}

std::string winner_words(const LevelWinner& w) {
  if (w.tie) {
    std::vector<std::string> names = w.tied_with();
    names.insert(names.begin(), w.point->method);
    return "a tie of " + quoted_list(names);
  }
  if (!w.undecided.empty())
    return fmt::format("`{}` or `{}` (undecided: force evaluations leave out the implicit one's solves)", w.point->method, w.undecided);
  return "`" + w.point->method + "`";
}

bool solves(const std::string& solver) {
  if (const auto m = find_method(solver)) return method_info(*m).implicit;
  const PeerInfo* peer = find_peer(solver);
  return peer && peer->implicit;
}

CellVerdict cell_verdict(const ScalingCell& m, double error, bool timed) {
  if (m.cheapest.empty()) return CellVerdict::None;
  if (m.motion < error) return CellVerdict::Still;
  if (!timed && solves(m.cheapest) && !m.best_explicit.empty()) return CellVerdict::Undecided;
  return tied(m.rival_margin, timed) ? CellVerdict::Tie : CellVerdict::Win;
}

bool implicit_wins(const ScalingCell& m, bool timed) {
  if (m.cheapest.empty() || m.cheapest != m.best_implicit) return false;
  const double over = std::fmin(m.explicit_over_implicit, m.implicit_peer_over_implicit);  // NaN: neither side reached the target
  return std::isnan(over) || (timed && !tied(over, true));  // untimed: undecided (its solves uncounted)
}

MapTally map_tally(const ScalingResult& r, std::size_t target) {
  const bool timed = r.config.timing;
  const std::size_t nk = r.blocks.size() / r.config.targets.size();
  MapTally out;
  for (std::size_t k = 0; k < nk; ++k) {
    const ScalingBlock& b = r.blocks[target * nk + k];
    for (const ScalingCell& m : b.cells) {
      ++out.cells;
      const CellVerdict v = cell_verdict(m, b.error, timed);
      switch (v) {
        case CellVerdict::Win: ++out.wins[solver_group(m.cheapest)]; break;
        case CellVerdict::Tie: case CellVerdict::Undecided: ++out.ties; break;
        case CellVerdict::Still: ++out.still; break;
        case CellVerdict::None: break;
      }
      if ((v == CellVerdict::Win || v == CellVerdict::Tie) && implicit_wins(m, timed))
        out.implicit.push_back(fmt::format("{:g}/{}", b.stiffness, m.masses));
    }
  }
  return out;
}

std::vector<PeerComparison> implicit_against_peers(const WorkPrecisionResult& r, const SceneWork& w, double level, bool timed) {
  const WorkPoint* best = nullptr;
  for (std::size_t m : r.config.methods)
    if (method_info(m).implicit)
      if (const WorkPoint* p = cheapest_point(w, name(m), level, timed); p && (!best || point_cost(*p, timed) < point_cost(*best, timed)))
        best = p;
  std::vector<PeerComparison> out;
  for (const std::string& solver : r.config.adaptive)
    if (const PeerInfo* peer = find_peer(solver); peer && peer->implicit)  // CVODE, ARKODE's DIRK tables, RADAU5
      out.push_back({level, best, solver, cheapest_point(w, solver, level, timed)});
  return out;
}

}  // namespace steplab
