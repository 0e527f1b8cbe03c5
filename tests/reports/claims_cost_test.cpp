// The cost, collision and advice sentences of the report, re-derived from their data (classes 9 ..
// 12 and 15 of claims_test.cpp, which runs them on each changed configuration), and the winner of
// an error level on a made-up scene.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "analysis/peers/peers.hpp"
#include "claims.hpp"
#include "reports/studies/studies.hpp"
#include "reports/document/findings.hpp"
#include "reports/document/report_text.hpp"

namespace steplab::claims {

// 9: the cheapest run at each error level on each scene, by time and by force evaluations, a tie
// where the runner-up is within the noise, a dagger where the winning run is at its sweep's edge.
void cost_claims(const ReportData& d, const std::string& md) {
  const WorkPrecisionResult& r = d.work;
  for (const bool timed : {d.config.timing, false}) {
    for (const double level : r.config.error_levels)
      for (const SceneWork& w : r.scenes) {
        std::map<std::string, const WorkPoint*> best;  // each solver's cheapest run reaching the level
        const auto cost = [&](const WorkPoint& p) { return timed ? p.seconds : double(p.force_evaluations); };
        for (const WorkPoint& p : w.points)
          if (p.status == RunStatus::Ok && p.error <= level && (!best.count(p.method) || cost(p) < cost(*best[p.method]))) best[p.method] = &p;
        if (best.empty()) continue;
        std::vector<const WorkPoint*> sorted;
        for (const auto& [solver, p] : best) sorted.push_back(p);
        std::stable_sort(sorted.begin(), sorted.end(), [&](auto a, auto b) { return cost(*a) < cost(*b); });
        const WorkPoint& win = *sorted.front();
        // timed: a tie within 1.5 times, whatever the runs' spreads between their passes
        const bool tie = sorted.size() > 1 && (timed ? cost(*sorted[1]) / cost(win) < 1.5 : cost(*sorted[1]) == cost(win));
        // untimed, an implicit winner against an explicit run that reached the level is undecided
        const auto solves = [](const std::string& s) {
          const auto m = find_method(s);
          return m ? method_info(*m).implicit : find_peer(s) && find_peer(s)->implicit;
        };
        const WorkPoint* against = nullptr;
        if (!timed && !tie && solves(win.method))
          for (const WorkPoint* p : sorted)
            if (!solves(p->method)) {
              against = p;
              break;
            }
        double edge = 0;
        for (const WorkPoint& p : w.points)
          if (p.method == win.method) edge = std::max(edge, p.setting);
        std::vector<std::string> tied;  // the runner-up, then each further run within the margin of its own two runs
        for (std::size_t k = 1; tie && k < sorted.size(); ++k)
          if (k == 1 || (timed ? cost(*sorted[k]) / cost(win) < 1.5 : cost(*sorted[k]) == cost(win)))
            tied.push_back("`" + sorted[k]->method + "`");
        const std::string cell = fmt::format("`{}` {}{}{}", win.method, timed ? cost_text(true, win.seconds, 0) : std::to_string(win.force_evaluations),
                                             tie       ? fmt::format(" (tie: {})", and_list(tied))
                                             : against ? fmt::format(" (undecided: `{}`)", against->method)
                                                       : "",
                                             win.setting == edge ? " $\\dagger$" : "");
        const std::string row = line_with(md, fmt::format("| {:.0e} |", level));
        EXPECT_NE(row.find("| " + cell + " |"), std::string::npos) << cell << "\n" << row;
      }
    if (!d.config.timing) break;  // untimed, both columns are the force evaluations'
  }
}

// 10: the stiff scene's peer table: each adaptive implicit peer (CVODE, ARKODE's DIRK tables,
// RADAU5) against steplab's cheapest implicit method,
// the ratio of their costs.
void peer_claims(const ReportData& d, const std::string& md) {
  const WorkPrecisionResult& r = d.work;
  if (r.stiff < 0) return;
  const SceneWork& w = r.scenes[static_cast<std::size_t>(r.stiff)];
  const bool timed = d.config.timing;
  const auto cost = [&](const WorkPoint& p) { return timed ? p.seconds : double(p.force_evaluations); };
  const auto cheapest = [&](const std::string& solver, double level) {
    const WorkPoint* b = nullptr;
    for (const WorkPoint& p : w.points)
      if (p.method == solver && p.status == RunStatus::Ok && p.error <= level && (!b || cost(p) < cost(*b))) b = &p;
    return b;
  };
  double lo = INFINITY, hi = 0;  // a peer's step's cost over one of steplab's
  for (const double level : {r.config.crossover_error, r.config.error_levels.back()}) {
    const WorkPoint* mine = nullptr;
    for (std::size_t m : r.config.methods)
      if (method_info(m).implicit)
        if (const WorkPoint* p = cheapest(nm(m), level); p && (!mine || cost(*p) < cost(*mine))) mine = p;
    for (const std::string& a : r.config.adaptive) {
      const WorkPoint* peer = find_peer(a)->implicit ? cheapest(a, level) : nullptr;
      if (!mine || !peer) continue;
      lo = std::min(lo, cost(*peer) / peer->steps / (cost(*mine) / mine->steps));
      hi = std::max(hi, cost(*peer) / peer->steps / (cost(*mine) / mine->steps));
      EXPECT_NE(md.find(fmt::format("| `{}`: ", a)), std::string::npos) << a;
      EXPECT_NE(md.find(fmt::format("| {:.3g} | {:.3g} | {:.3g} |", cost(*peer) / cost(*mine),
                                    double(peer->force_evaluations) / double(mine->force_evaluations), double(peer->steps) / double(mine->steps))),
                std::string::npos) << a << " at " << level;
    }
  }
  if (hi > 0) {
    EXPECT_NE(md.find(fmt::format("A step of a peer's costs {:.2g} .. {:.2g} times one of steplab's method", lo, hi)), std::string::npos) << md;
  }
}

// 11: the crossover: the smallest stiffness ratio from which on the cheapest implicit run beats
// every explicit one by more than 1.5 times its run time; untimed, not read (force evaluations
// leave out the implicit methods' solves).
void crossover_claim(const ReportData& d, const std::string& md) {
  const WorkPrecisionResult& r = d.work;
  if (!d.config.timing) {
    EXPECT_NE(md.find("- The crossover is not read untimed"), std::string::npos) << md;
    return;
  }
  double crossover = -1;
  for (std::size_t i = r.stiffness.size(); i-- > 0;) {
    const StiffnessRow& s = r.stiffness[i];
    const bool cheaper = !s.best_implicit.empty() && (s.best_explicit.empty() || 1.5 * s.implicit_seconds < s.explicit_seconds);
    if (!cheaper) break;
    crossover = s.ratio;
  }
  if (crossover > 0) EXPECT_NE(md.find(fmt::format("from stiffness ratio k2 / k1 = {:g} on", crossover)), std::string::npos) << md;
  else EXPECT_NE(md.find("- No stiffness ratio of the sweep"), std::string::npos);
}

// 12: the bounce's orders: kept where the declared order is within 0.15 of the fit or inside its
// bound, if the bound is at most +-0.5 wide; lost where it is not, with a narrow bound or one that
// lies wholly below the order; the others (wide, holding the order or above it) not findings.
void bounce_claims(const ReportData& d, const std::string& md) {
  Names kept, lost, loose;
  for (const ConvergenceFit& f : d.convergence_on(d.config.rebound.scene).fits) {
    if (exact(f.method) || !f.fit.fitted) continue;
    const double p = method_info(f.method).order;
    const bool holds = std::abs(f.fit.order - p) <= 0.15 || (f.fit.bound_lo <= p && p <= f.fit.bound_hi);
    const bool wide = f.fit.bound_hi - f.fit.bound_lo > 1;
    (holds ? (wide ? loose : kept) : (!wide || f.fit.bound_hi < p) ? lost : loose).insert(nm(f.method));
  }
  const std::string line = line_with(md, "Against the exact bounce");
  EXPECT_EQ(names(line, "the contact costs order to", ";"), lost) << line;
  if (kept.empty()) EXPECT_EQ(line.find(" keep their order"), std::string::npos) << line;
  else EXPECT_EQ(names_until(line, lost.empty() ? "fitted over the dt sweep:" : ";", {" keep their order"}), kept) << line;
  EXPECT_EQ(names(line, "the fits of", " have bounds wider"), loose) << line;
}

// 15: the contact advice: the methods within 1 % of the bounce's energy at the largest step.
void contact_claim(const ReportData& d, const std::string& md) {
  const double dt = *std::max_element(d.collision.config.dts.begin(), d.collision.config.dts.end());
  Names kept;
  for (const CollisionRun& r : d.collision.bounce)
    if (r.dt == dt && r.status == RunStatus::Ok && !r.bounces.empty() && std::abs(r.bounces.back().energy_ratio - 1) <= 0.01)
      kept.insert(nm(r.method));
  const std::string line = line_with(md, "- **Contact with a penalty ground**");
  if (kept.empty()) EXPECT_TRUE(line.empty()) << line;
  else EXPECT_EQ(names_until(line, "within 1 % with", {"; "}), kept) << line;
}

}  // namespace steplab::claims

namespace steplab {
namespace {

// level_winner on a scene made up here: a tie within the timing's noise, an edge of the sweep.
TEST(Claims, ATieIsNoWinAndAnEdgeIsMarked) {
  SceneWork w{*find_scene("spring"), {}, {}, {}};
  const auto point = [](std::string m, double setting, double error, double seconds, long long forces) {
    WorkPoint p;
    p.method = std::move(m), p.setting = setting, p.error = error, p.seconds = seconds, p.force_evaluations = forces;
    return p;
  };
  w.points = {point("rk4", 0.1, 1e-5, 1.0e-6, 400), point("rk4", 0.05, 1e-7, 2.0e-6, 800),
              point("dopri5", 1e-4, 1e-5, 1.1e-6, 300), point("bdf2", 0.01, 1e-5, 3e-6, 300)};
  LevelWinner win = level_winner(w, 1e-4, true);
  ASSERT_TRUE(win.point);
  EXPECT_EQ(win.point->method, "rk4");
  EXPECT_TRUE(win.tie);  // dopri5 within x1.1, below the margin of 1.5
  EXPECT_EQ(win.next, "dopri5");
  EXPECT_TRUE(win.at_edge);  // rk4's largest step
  win = level_winner(w, 1e-6, true);
  EXPECT_FALSE(win.tie);      // rk4 alone reaches it
  EXPECT_FALSE(win.at_edge);  // at dt 0.05, below its sweep's largest
  win = level_winner(w, 1e-4, false);  // by force evaluations: dopri5 and bdf2 equal, a tie
  EXPECT_TRUE(win.tie);
}

// A timed win needs a margin of 1.5, whatever the two runs' spreads between their passes (the
// faster pass is kept: a spread says how disturbed the slower one was, not how far the kept time
// moves); untimed, an implicit run fewest in force evaluations is undecided against an explicit one.
TEST(Claims, NoiseMakesTiesAndSolvesUncountedAreUndecided) {
  SceneWork w{*find_scene("spring"), {}, {}, {}};
  const auto point = [](std::string m, double seconds, double spread, long long forces) {
    WorkPoint p;
    p.method = std::move(m), p.setting = 0.1, p.error = 1e-5, p.seconds = seconds, p.spread = spread, p.force_evaluations = forces;
    return p;
  };
  w.points = {point("rk4", 1.0e-6, 1.0, 400), point("dopri5", 1.6e-6, 1.0, 500)};
  EXPECT_FALSE(level_winner(w, 1e-4, true).tie);  // 1.6 >= 1.5
  w.points = {point("rk4", 1.0e-6, 1.3, 400), point("dopri5", 1.6e-6, 1.3, 500)};
  EXPECT_FALSE(level_winner(w, 1e-4, true).tie);  // disturbed passes (1.3 x 1.3 = 1.69 > 1.6) decide nothing
  w.points = {point("rk4", 1.0e-6, 1.0, 400), point("dopri5", 1.4e-6, 1.0, 500)};
  EXPECT_TRUE(level_winner(w, 1e-4, true).tie);  // 1.4 < 1.5
  w.points = {point("bdf2", 1e-6, 1, 200), point("rk4", 1e-6, 1, 400), point("radau_iia5", 1e-6, 1, 300)};
  const LevelWinner win = level_winner(w, 1e-4, false);
  EXPECT_EQ(win.point->method, "bdf2");
  EXPECT_EQ(win.undecided, "rk4");  // bdf2's Newton solves are not in its 200
  EXPECT_FALSE(win.decided());
  w.points = {point("rk4", 1e-6, 1, 200), point("bdf2", 1e-6, 1, 400)};
  EXPECT_TRUE(level_winner(w, 1e-4, false).decided());  // an explicit winner: the implicit one's uncounted work only adds
}

}  // namespace
}  // namespace steplab
