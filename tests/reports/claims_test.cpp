// Every kind of sentence the report states, re-derived here from the data it is about, with this
// file's own arithmetic (not reports/document/findings.cpp's), under changed parameters: the
// report's claims are true for whatever the studies measure. A statistic, a count and a list never
// include the exact flow. The classes, each a function below:
//   1 which methods are stable (answers, hand-in)      9  the cheapest run per error level, ties, edges
//   2 never stable vs stable again, undamped           10 steplab's implicit methods against the implicit peers
//   3 stable at every step tried                       11 the stiffness crossover
//   4 the rank correlation of order and dt*            12 the bounce orders that are findings
//   5 each family's trend with the order               13 the scaling exponents that are findings
//   6 Dahlquist's barrier                              14 the crossover map's wins and ties
//   7 the energy over a long run                       15 the contact advice
//   8 the order when stiff (keeps, strays, falls, rises, unstable)
//   16 the exact methods on the cannon ball            17 measured dt* against predicted
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <regex>
#include <set>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/peers/peers.hpp"
#include "reports/studies/studies.hpp"
#include "reports/document/findings.hpp"
#include "claims.hpp"
#include "reports/document/report.hpp"
#include "small_report.hpp"

namespace steplab {
namespace {

using namespace claims;

// 1, 2, 3: the stable lists, from the damping sweep's runs and the thresholds; the answers' with
// the methods on springs (`springs`, measured on the same spring where the report has them). An
// unstable run whose energy grows slower than 1e-3 per unit time, and whose E/E0 stays at most 10,
// is named "weakly" unstable.
void stability_claims(const ReportData& d, const std::string& md, const ReportData* springs = nullptr) {
  const ReportConfig& c = d.config;
  Names unstable_large, unstable_undamped, always, never, again, weak_large, weak_undamped;
  for (const ReportData* data : {&d, springs}) {
    if (!data) continue;
    for (const SweepRow& r : data->sweep) {
      if (exact(r.method)) continue;
      if (r.dt == c.large_dt && r.damping == c.damping() && !r.run.stable()) {
        unstable_large.insert(nm(r.method));
        if (r.run.rate < 1e-3 && r.run.energy_ratio_max <= 10) weak_large.insert(nm(r.method));
      }
      if (r.dt == c.small_dt && r.damping == 0 && !r.run.stable()) {
        unstable_undamped.insert(nm(r.method));
        if (r.run.rate < 1e-3 && r.run.energy_ratio_max <= 10) weak_undamped.insert(nm(r.method));
      }
    }
    for (std::size_t m : data->methods)
      if (const ThresholdRow* t = threshold(*data, m, c.damping()); t && !exact(m) && std::isinf(t->dt_theory) && data != &d)
        always.insert(nm(m));
  }
  const auto zero = std::find(d.map.damping.begin(), d.map.damping.end(), 0.0);
  for (std::size_t m : d.methods) {
    if (exact(m)) continue;
    if (const ThresholdRow* t = threshold(d, m, c.damping()); t && std::isinf(t->dt_theory)) always.insert(nm(m));
    const ThresholdRow* t0 = threshold(d, m, 0);
    if (!t0 || t0->dt_theory != 0) continue;
    bool map_stable = false;
    const auto i = std::find(d.map.methods.begin(), d.map.methods.end(), m);
    if (i != d.map.methods.end() && zero != d.map.damping.end())
      for (bool cell : d.map.stable[static_cast<std::size_t>(i - d.map.methods.begin())][static_cast<std::size_t>(zero - d.map.damping.begin())])
        map_stable |= cell;
    (std::isinf(t0->again_theory) && std::isinf(t0->again_measured) && !map_stable ? never : again).insert(nm(m));
  }
  // the answer: "every method is stable but ..."; "without damping ... X are not"
  const std::string answer = line_with(md, "- **Which method is stable?**");
  ASSERT_FALSE(answer.empty()) << md;
  EXPECT_EQ(names(answer, "is stable but", "; without damping"), unstable_large) << answer;
  EXPECT_EQ(names(answer, "; without damping", "Stable at every step"), unstable_undamped) << answer;
  EXPECT_EQ(names(answer, "Stable at every step tried:", "."), always) << answer;
  const std::size_t split = answer.find("; without damping");
  EXPECT_EQ(names(answer.substr(0, split), "weakly"), weak_large) << answer;
  EXPECT_EQ(names(answer.substr(split), "weakly", " not:"), weak_undamped) << answer;
  // the hand-in's section, where chosen
  if (!c.has_section("stable")) return;
  if (const std::string never_line = line_with(md, "- Without damping no step is stable for"); !never.empty() || !never_line.empty()) {
    EXPECT_EQ(names(never_line, "for", ":"), never) << never_line;
  }
  if (const std::string again_line = line_with(md, "- Without damping no small step is stable for"); !again.empty() || !again_line.empty()) {
    EXPECT_EQ(names(again_line), again) << again_line;
    for (const std::string& m : again) {  // from where, as the thresholds say
      const ThresholdRow* t0 = threshold(d, *find_method(m), 0);
      const double from = std::isfinite(t0->again_measured) ? t0->again_measured : t0->again_theory;
      if (std::isfinite(from)) {
        EXPECT_NE(again_line.find(fmt::format("from dt = {:.4g}", from)), std::string::npos) << again_line;
      }
    }
  }
}

// Spearman's rho by hand: average ranks (ties share, +inf above every finite value), Pearson of them.
double rank_correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const auto ranks = [](const std::vector<double>& x) {
    std::vector<double> r(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      double below = 0, equal = 0;
      for (double y : x) below += y < x[i], equal += y == x[i];
      r[i] = below + (equal + 1) / 2;
    }
    return r;
  };
  const std::vector<double> ra = ranks(a), rb = ranks(b);
  const double n = static_cast<double>(a.size()), ma = (n + 1) / 2;
  double ab = 0, aa = 0, bb = 0;
  for (std::size_t i = 0; i < ra.size(); ++i) ab += (ra[i] - ma) * (rb[i] - ma), aa += (ra[i] - ma) * (ra[i] - ma), bb += (rb[i] - ma) * (rb[i] - ma);
  return ab / std::sqrt(aa * bb);
}

// 4: the correlation over the ODE methods, in the answers and the families section; in the
// answers also with the methods on springs that claim an order (PBD claims none).
void correlation_claim(const ReportData& d, const std::string& md, const ReportData* springs = nullptr) {
  std::vector<double> order, dt;
  for (std::size_t m : d.methods)
    if (!exact(m)) order.push_back(method_info(m).order), dt.push_back(threshold(d, m, d.config.damping())->dt_measured);
  if (order.size() < 3) return;
  const double rho = rank_correlation(order, dt);
  EXPECT_NE(md.find(fmt::format("over the {} ODE methods, Spearman's rank correlation between the order and dt* (damping {}) is "
                                "{:.2f}", order.size(), d.config.damping(), rho)),
            std::string::npos)
      << rho << "\n" << md;
  if (springs) {
    std::vector<double> all_order = order, all_dt = dt;
    for (std::size_t m : springs->methods)
      if (method_info(m).order > 0)
        all_order.push_back(method_info(m).order), all_dt.push_back(threshold(*springs, m, d.config.damping())->dt_measured);
    EXPECT_NE(md.find(fmt::format("with the {} methods on springs that claim an order, over {}, it is {:.2f}", all_order.size() - order.size(),
                                  all_order.size(), rank_correlation(all_order, all_dt))),
              std::string::npos) << md;
  }
  // Evidence at the 5 % level: under no correlation (and no ties) Spearman's rho has mean 0 and
  // variance exactly 1 / (n - 1), and is close to normal: evidence beyond 1.96 standard deviations.
  const double sd = 1 / std::sqrt(static_cast<double>(order.size()) - 1);
  const bool beyond = std::abs(rho) > 1.96 * sd;
  EXPECT_NE(md.find(beyond ? "beyond chance at the 5 % level" : fmt::format("within chance for {} methods", order.size())),
            std::string::npos) << rho << "\n" << md;
  if (d.config.has_section("families")) {
    EXPECT_NE(md.find(fmt::format("Pooled over the {} ODE methods, Spearman's rank correlation between order and measured dt* "
                                  "(damping {}) is **{:.2f}**", order.size(), d.config.damping(), rho)),
              std::string::npos) << md;
  }
}

// 5, 6: each family's trend at every damping; Dahlquist's methods.
void family_claims(const ReportData& d, const std::string& md) {
  std::vector<double> dampings;
  for (const ThresholdRow& r : d.thresholds)
    if (std::find(dampings.begin(), dampings.end(), r.damping) == dampings.end()) dampings.push_back(r.damping);
  std::sort(dampings.begin(), dampings.end());
  Names every_step;
  for (Family f : {Family::ExplicitRungeKutta, Family::Splitting, Family::ImplicitRungeKutta, Family::AdamsBashforth, Family::Bdf}) {
    std::vector<std::size_t> fam;
    for (std::size_t m : d.methods)
      if (method_info(m).family == f || method_info(m).first_of == f) fam.push_back(m);
    std::sort(fam.begin(), fam.end(), [](auto a, auto b) { return std::pair(method_info(a).order, a) < std::pair(method_info(b).order, b); });
    if (fam.size() < 2) continue;
    std::string row = fmt::format("| {} |", to_string(f));
    for (double g : dampings) {
      bool up = false, down = false, inf = true;
      for (std::size_t i = 0; i < fam.size(); ++i) {
        const double x = threshold(d, fam[i], g)->dt_measured;
        inf &= std::isinf(x);
        if (i == 0) continue;
        const double y = threshold(d, fam[i - 1], g)->dt_measured;
        // Stable at every step (infinity) against a finite dt* is a move, up or down; two finite dt*
        // within the threshold search's resolution (1e-3 of the larger, in logarithms) are no move.
        if (std::isinf(x) != std::isinf(y)) {
          up |= std::isinf(x), down |= std::isinf(y);
          continue;
        }
        if (std::isinf(x) || (x > 0 && y > 0 && std::abs(std::log(x / y)) < 1e-3) || (x == 0 && y == 0)) continue;
        up |= x > y, down |= x < y;
      }
      // Theory (Dahlquist): implicit Euler and BDF2 are A-stable, BDF3 is not, so where BDF3's dt*
      // is finite the family falls, whatever its value.
      if (f == Family::Bdf && std::isinf(threshold(d, fam.front(), g)->dt_measured) && std::isfinite(threshold(d, fam.back(), g)->dt_measured)) {
        EXPECT_TRUE(down && !up) << "BDF at damping " << g;
      }
      row += fmt::format(" {} |", inf ? "stays unbounded" : up && !down ? "rises" : down && !up ? "falls" : !up && !down ? "stays the same"
                                                                                                       : "does not move one way");
    }
    EXPECT_NE(md.find(row + "\n"), std::string::npos) << row << "\n" << md;
    if (f == Family::AdamsBashforth || f == Family::Bdf)
      for (std::size_t m : fam) {
        bool all = true;
        for (double g : dampings) all &= std::isinf(threshold(d, m, g)->dt_measured);
        if (all) every_step.insert(nm(m));
      }
  }
  const std::string dahlquist = line_with(md, "Dahlquist's second barrier");
  if (!dahlquist.empty()) {
    EXPECT_EQ(names(dahlquist, "at every damping tried:", "; with a stability region"), every_step) << dahlquist;
  }
}

// The comparison every trend rests on, against values whose answer is known: infinity is the same
// as infinity only, never as a number, and NaN is the same as nothing.
TEST(Trend, InfinityIsNeverTheSameAsANumber) {
  EXPECT_FALSE(same_within(INFINITY, 0.2183, kSameThreshold));
  EXPECT_FALSE(same_within(0, INFINITY, kSameThreshold));
  EXPECT_TRUE(same_within(INFINITY, INFINITY, kSameThreshold));
  EXPECT_FALSE(same_within(NAN, NAN, kSameThreshold));
  EXPECT_TRUE(same_within(1.0, 1.0009, kSameThreshold));
  EXPECT_FALSE(same_within(1.0, 1.0011, kSameThreshold));
  // BDF at damping 0 and 0.1: implicit Euler and BDF2 unbounded, BDF3 0 or 0.2183.
  EXPECT_EQ(trend({INFINITY, INFINITY, 0.0}), Trend::Falls);
  EXPECT_EQ(trend({INFINITY, INFINITY, 0.2183}), Trend::Falls);
  EXPECT_EQ(trend({0.2, INFINITY}), Trend::Rises);
  EXPECT_EQ(trend({INFINITY, INFINITY}), Trend::StaysInfinite);
  EXPECT_EQ(trend({0.2, 0.20001, 0.2}), Trend::StaysTheSame);
  EXPECT_EQ(trend({0.2, INFINITY, 0.1}), Trend::Mixed);
  EXPECT_EQ(trend({0.2, NAN}), Trend::NotMeasured);
}

// 7: the energy over the long undamped run, classified here from its samples.
void energy_claims(const ReportData& d, const std::string& md) {
  Names bounded, grows, decays, damped, blown;
  for (std::size_t i = 0; i < d.methods.size(); ++i) {
    const RunResult<1>& r = d.energy[i];
    if (exact(d.methods[i]) || r.samples.empty()) continue;
    const double e0 = r.samples.front().energy, half = r.samples.back().t / 2;
    double lo = 1, hi = 1, first = 0, second = 0;
    for (const auto& s : r.samples) {
      const double q = s.energy / e0;
      lo = std::min(lo, q), hi = std::max(hi, q);
      (s.t <= half ? first : second) = std::max(s.t <= half ? first : second, std::abs(q - 1));
    }
    const std::string n = nm(d.methods[i]);
    // bounded also where the second half strays no further than round-off reaches: 30 roundings
    // of 2^-53 a step, walking at random over the run's steps
    const double round_off = 30 * std::ldexp(1.0, -53) * std::sqrt(r.samples.back().t / d.config.large_dt);
    (r.status != RunStatus::Ok || hi > 10 ? blown
     : lo < 0.1                            ? damped
     : second <= 1.25 * first || second <= round_off ? bounded
     : r.samples.back().energy > e0                  ? grows
                                                     : decays)
        .insert(n);
  }
  const std::string answer = line_with(md, "- **Is the energy kept?**");
  ASSERT_FALSE(answer.empty()) << md;
  const auto part = [&](const char* from) {
    return names_until(answer, from, {"it grows slowly", "it decays slowly", "the method damps it out", "it blows up for", ";", "(figure"});
  };
  EXPECT_EQ(part("stays bounded for"), bounded) << answer;
  EXPECT_EQ(part("(unstable at this step) for"), grows) << answer;
  EXPECT_EQ(part("(the method's own damping) for"), decays) << answer;
  EXPECT_EQ(part("damps it out for"), damped) << answer;
  EXPECT_EQ(part("it blows up for"), blown) << answer;
  if (d.config.has_section("energy")) {
    EXPECT_EQ(names(line_with(md, "- **Bounded**")), bounded);
    EXPECT_EQ(names(line_with(md, "- **Grows**")), grows);
    EXPECT_EQ(names(line_with(md, "- **Decays**")), decays);
    EXPECT_EQ(names(line_with(md, "- **Damped out**")), damped);
    EXPECT_EQ(names(line_with(md, "- **Blows up**")), blown);
  }
}

// 8: the order when stiff, from the sweep's fits and each method's theory: keeps (p in both limits
// and every fit between them within 0.15 of p or its bound holding p), strays (kept in both
// limits, a fit between them not), falls and rises (both limits hold, the stiff order below or
// above p), unstable (no stiff limit).
void stiff_claims_follow(const ReportData& d, const std::string& md) {
  const OrderReduction& r = d.stiff_order;
  Names keep, strays, falls, rises, unstable;
  for (std::size_t m = 0; m < r.methods.size(); ++m) {
    const MethodReduction& mr = r.methods[m];
    const std::string n = nm(mr.method);
    if (mr.theory.stiff < 0) {
      unstable.insert(n);
      continue;
    }
    if (!mr.stiff.reached || !mr.stiff.fitted || !mr.stiff.holds || !mr.non_stiff.holds) continue;
    if (mr.theory.stiff < mr.theory.classical) falls.insert(n);
    else if (mr.theory.stiff > mr.theory.classical) rises.insert(n);
    else {
      bool all = true;
      for (std::size_t v = 0; v < r.sweep.values.size(); ++v) {
        const OrderFit& f = r.sweep.studies[v].fits[m].fit;
        if (f.fitted && !mr.past_stable[v])
          all &= std::abs(f.order - mr.theory.classical) <= 0.15 || (f.bound_lo <= mr.theory.classical && mr.theory.classical <= f.bound_hi);
      }
      (all ? keep : strays).insert(n);
    }
  }
  EXPECT_EQ(names(line_with(md, "- **Keep their order at every stiffness**")), keep) << md;
  EXPECT_EQ(names_until(line_with(md, "- **Keep their order in both limits but stray"), "stray between them", {"The transition"}), strays);
  EXPECT_EQ(names_until(line_with(md, "- **Fall**"), "stiff order:", {"\n"}), falls);
  EXPECT_EQ(names_until(line_with(md, "- **Gain**"), "largest error:", {"The method's own"}),
            [&] {  // each with its start named too
              Names with_start = rises;
              for (const std::string& n : rises)
                if (!method_kernel(*find_method(n)).starter.empty()) with_start.insert(std::string(method_kernel(*find_method(n)).starter));
              return with_start;
            }());
  EXPECT_EQ(names_until(line_with(md, "- **Not stable**"), "grows:", {": orders"}), unstable);
}

// 16: the cannon ball's exact methods (to round-off), the others with their orders.
void cannonball_claim(const ReportData& d, const std::string& md) {
  Names exact_ones, others;
  for (const ConvergenceFit& f : d.convergence_on(d.config.projectile.scene).fits)
    if (!exact(f.method)) (f.fit.exact ? exact_ones : others).insert(nm(f.method));
  const std::string line = line_with(md, "Cannon ball: exact to round-off for");
  EXPECT_EQ(names_until(line, "for", {"; the other"}), exact_ones) << line;
  EXPECT_EQ(names_until(line, "; the other", {"\n"}), others) << line;
}

// 17: the measured dt* within 1 % of the prediction, counted.
void detail_claim(const ReportData& d, const std::string& md) {
  std::size_t agree = 0, rows = 0;
  for (const ThresholdRow& r : d.thresholds) {
    if (exact(r.method)) continue;
    ++rows;
    agree += r.dt_theory == r.dt_measured || std::abs(r.dt_measured / r.dt_theory - 1) <= 0.01;
  }
  EXPECT_NE(md.find(fmt::format("within 1 % of the prediction in {} of these {} cases", agree, rows)), std::string::npos);
}

void claims_follow_data(const ReportConfig& c) {
  const Made m = make(c);
  const ReportData& d = m.report.data;
  using Claim = void (*)(const ReportData&, const std::string&);
  const ReportData* springs = m.report.springs ? &*m.report.springs : nullptr;
  stability_claims(d, m.md, springs);
  correlation_claim(d, m.md, springs);
  for (const Claim claim : {family_claims, energy_claims, stiff_claims_follow, cost_claims,
                            peer_claims, crossover_claim, bounce_claims, cannonball_claim, detail_claim, contact_claim})
    claim(d, m.md);
}

TEST(Claims, FollowTheDataWithDefaults) { claims_follow_data(small_config()); }

TEST(Claims, FollowTheDataWithoutDamping) {
  ReportConfig c = small_config();
  param(c.oscillator, "damping") = 0;  // explicit Euler, midpoint, AB2 and BDF3 unstable at every small step
  claims_follow_data(c);
}

TEST(Claims, FollowTheDataWithAStiffSpringAndALargeStep) {
  ReportConfig c = small_config();
  param(c.oscillator, "stiffness") = 50;  // omega = 7.1
  c.large_dt = 0.3;                       // beyond symplectic Euler's 2/omega = 0.28
  c.stiff_order.stiffnesses = {1e-2, 1, 1e2, 1e4};  // the stiff limit not reached
  claims_follow_data(c);
}

TEST(Claims, FollowTheDataOnAFewMethods) {
  ReportConfig c = small_config();
  choose_methods(c, {"explicit_euler", "symplectic_euler", "rk4", "implicit_midpoint", "bdf3", "analytic"}, "methods");
  claims_follow_data(c);
}

// The exact flow is in no statistic: the hand-in's four methods give the correlation of its own
// table (explicit Euler 1 / 0.02, symplectic Euler 1 / 0.8746, implicit Euler 1 / inf, explicit
// midpoint 2 / 0.2649): -1/sqrt(15) = -0.26, where counting the exact flow (order and dt* both
// infinite) made it 0.29.
TEST(Claims, TheHandInsCorrelationLeavesTheExactFlowOut) {
  ReportConfig c = small_config();
  const ReportConfig sheet = sheet_report_config();
  c.methods = sheet.methods;
  c.covered = sheet.covered;
  c.sections = sheet.sections;
  const Made m = make(c);
  EXPECT_EQ(m.report.findings.spearman_n, 4u);
  EXPECT_NEAR(m.report.findings.spearman, -1 / std::sqrt(15.0), 1e-12);
  EXPECT_NE(m.md.find("Spearman's rank correlation between order and dt* is -0.26"), std::string::npos) << m.md;
  // Four methods: |rho| is at most 1, below 1.96 / sqrt(3) = 1.13, so no ranking of them is
  // evidence either way, whatever the data.
  EXPECT_NE(m.md.find("no evidence either way, since no ranking of 4 methods reaches the 5 % level"), std::string::npos) << m.md;
  stability_claims(m.report.data, m.md);
  energy_claims(m.report.data, m.md);
}

}  // namespace
}  // namespace steplab
