// The claims of the energy, long-time and stiff-order findings, of the work-precision study's
// cheapest runs and crossover and of the crossover map, and the documents they cite (claims.hpp):
// each restates, over the cited document's own fields, the rule findings.hpp and analysis/studies
// apply, so that the verifier re-derives each class or verdict.
#include <algorithm>
#include <limits>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/peers/peers.hpp"
#include "analysis/studies/order_reduction.hpp"
#include "reports/studies/studies.hpp"
#include "reports/document/claims.hpp"
#include "reports/document/figure_styles.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/sections/long_time.hpp"

namespace steplab {

Json energy_document(const ReportData& d) {
  Json j;
  j["schema"] = "steplab.energy/1";
  j["dt"] = d.config.large_dt, j["t_end"] = d.config.energy_t_end;
  j["bounded_growth"] = kBoundedGrowth, j["blown_ratio"] = kBlownRatio;
  j["rows"] = Json::array();
  for (const EnergyBehaviour& b : energy_behaviour(d))
    j["rows"].push_back({{"method", name(b.method)},
                         {"symplectic", method_info(b.method).symplectic},
                         {"diverged", b.ended >= 0},
                         {"lo", b.lo},
                         {"hi", b.hi},
                         {"first_half", b.first_half},
                         {"second_half", b.second_half},
                         {"final_ratio", b.final_ratio},
                         {"round_off", b.round_off},
                         {"kind", to_text(b.kind)}});
  return j;
}

namespace {

// energy_behaviour's classes (findings.cpp) over a row of energy/energy.json.
Json energy_test(EnergyKind k, double round_off) {
  const Json blows = test_any({test_field("/diverged", "==", true), test_field("/hi", ">", kBlownRatio)});
  const Json damped = test_field("/lo", "<", 1 / kBlownRatio);
  const Json bounded = test_any({test_scaled("/second_half", "<=", kBoundedGrowth, "/first_half"),
                                 test_field("/second_half", "<=", round_off)});
  switch (k) {
    case EnergyKind::Blows: return blows;
    case EnergyKind::Damped: return test_all({test_not(blows), damped});
    case EnergyKind::Bounded: return test_all({test_not(blows), test_not(damped), bounded});
    case EnergyKind::Grows: return test_all({test_not(blows), test_not(damped), test_not(bounded), test_field("/final_ratio", ">", 1)});
    case EnergyKind::Decays: break;
  }
  return test_all({test_not(blows), test_not(damped), test_not(bounded), test_not(test_field("/final_ratio", ">", 1))});
}

}  // namespace

void claim_energy(Ledger& l, const ReportData& d, std::string id, std::string section, std::string sentence, EnergyKind k,
                  const std::vector<std::size_t>& set, bool symplectic) {
  const Json& doc = l.document(kEnergyDocument, [&] { return energy_document(d); });
  if (doc.at("rows").empty()) return;
  const double round_off = doc.at("rows").at(0).at("round_off").get<double>();  // one run length: one level
  Json test = energy_test(k, round_off);
  if (symplectic) test = test_all({std::move(test), test_field("/symplectic", "==", true)});
  claim_members(l, claim_text(std::move(id), std::move(section), std::move(sentence)), kEnergyDocument, "/rows", Json::object(),
                "method", true, std::move(test), method_names(set));
}

void claim_sheet_step(Ledger& l, const ReportData& d, std::string id, std::string section, std::string sentence,
                      const std::vector<std::size_t>& set) {
  l.document(kStabilityDocument, [&] { return stability_document(d); });
  const Json& energy = l.document(kEnergyDocument, [&] { return energy_document(d); });
  if (energy.at("rows").empty()) return;
  const double round_off = energy.at("rows").at(0).at("round_off").get<double>();
  const auto stable_at = [&](double damping) {
    return Selection{kStabilityDocument, "/sweep", {{"dt", d.config.large_dt}, {"damping", damping}}, "method", true,
                     test_field("/stable", "==", true)};
  };
  claim_members_of_all(l, claim_text(std::move(id), std::move(section), std::move(sentence)),
                       {stable_at(0.0), stable_at(d.config.damping()),
                        {kEnergyDocument, "/rows", Json::object(), "method", true, energy_test(EnergyKind::Bounded, round_off)}},
                       method_names(set));
}

std::string cite_convergence(Ledger& l, const ConvergenceResult& r) {
  std::string file = fmt::format("convergence/convergence_{}.json", scene_name(r.config.scene));
  l.document(file, [&] { return convergence_json(r); });
  return file;
}

std::string cite_long_time(Ledger& l, const LongTimeResult& r, const std::string& folder) {
  std::string file = fmt::format("{}/long_time_{}.json", folder, scene_name(r.config.scene));
  l.document(file, [&] { return long_time_json(r); });
  return file;
}

void claim_long_time(Ledger& l, const LongTimeResult& r, const std::string& folder, std::string id, std::string section,
                     std::string sentence, EnergyVerdict v, const std::vector<std::size_t>& set) {
  const std::string file = cite_long_time(l, r, folder);
  // energy_verdict (analysis/studies/long_time.hpp) over a row: lost where the run ended or its
  // energy error reached kLostAt; else bounded (growth interval below 0.5, or within round-off),
  // drifting (above 0.5).
  const Json lost = test_any({test_field("/status", "!=", "ok"), test_not(test_field("/invariants/energy/error_at_end", "<", kLostAt))});
  Json test;
  if (v == EnergyVerdict::Lost) test = lost;
  else if (v == EnergyVerdict::Bounded)
    test = test_all({test_not(lost), test_any({test_field("/invariants/energy/growth/ci95/1", "<", 0.5),
                                               test_field("/invariants/energy/round_off", "==", true)})});
  else if (v == EnergyVerdict::Drifting)
    test = test_all({test_not(lost), test_field("/invariants/energy/round_off", "==", false),
                     test_not(test_field("/invariants/energy/growth/ci95/1", "<", 0.5)),
                     test_field("/invariants/energy/growth/ci95/0", ">", 0.5)});
  else return;
  claim_members(l, claim_text(std::move(id), std::move(section), std::move(sentence)), file, "/rows", Json::object(), "method", true,
                std::move(test), method_names(set));
}

void claim_long_time_sides(Ledger& l, const LongTimeResult& r, const LongTimeSides& s, const std::string& folder, const std::string& id,
                           const std::string& section, const std::string& sentence) {
  claim_long_time(l, r, folder, id + ".bounded", section, sentence, EnergyVerdict::Bounded, s.bounded);
  claim_long_time(l, r, folder, id + ".drifting", section, sentence, EnergyVerdict::Drifting, s.drifting);
  claim_long_time(l, r, folder, id + ".lost", section, sentence, EnergyVerdict::Lost, s.lost);
  if (s.not_by_order)  // "the bounded ones are the symplectic ones"
    claim_members(l, claim_text(id + ".symplectic", section, sentence), cite_long_time(l, r, folder), "/rows", Json::object(), "method",
                  true, test_field("/symplectic", "==", true), method_names(s.bounded));
}

Evidence work_point_at(Ledger& l, const ReportData& d, const SceneWork& w, const WorkPoint& p, const char* field) {
  l.document(kWorkDocument, [&] { return work_precision_json(d.work); });
  return l.at(kWorkDocument, fmt::format("/scenes/{}/points/{}/{}", &w - d.work.scenes.data(), &p - w.points.data(), field));
}

void claim_cheapest(Ledger& l, const ReportData& d, std::string id, std::string section, std::string sentence, const SceneWork& w,
                    double level, bool timed, const LevelWinner& win) {
  if (!win.point || !win.undecided.empty()) return;
  const auto at = [&](const WorkPoint* p, const char* field) { return work_point_at(l, d, w, *p, field); };
  const char* cost = point_cost_field(timed);
  std::vector<const WorkPoint*> others;  // the runner-up first, then every other solver's cheapest run
  std::vector<std::string> seen{win.point->method};
  for (const WorkPoint& p : w.points)
    if (std::find(seen.begin(), seen.end(), p.method) == seen.end()) {
      seen.push_back(p.method);
      if (const WorkPoint* q = cheapest_point(w, p.method, level, timed))
        others.insert(p.method == win.next ? others.begin() : others.end(), q);
    }
  std::vector<Evidence> costs;
  for (const WorkPoint* p : others) costs.push_back(at(p, cost));
  for (const WorkPoint* p : win.also)  // each further solver the tie names: within the margin
    claim_group(l, claim_text(fmt::format("{}.tie.{}", id, p->method), section, sentence),
                comparison_group(at(win.point, cost), {at(p, cost)}, "tie", timed ? kTieMargin : 1.0));
  claim_group(l, claim_text(std::move(id), std::move(section), std::move(sentence)),
              comparison_group(at(win.point, cost), std::move(costs), win.tie ? "tie" : "less", timed ? kTieMargin : 1.0));
}

void claim_crossover(Ledger& l, const ReportData& d, std::string id, std::string section, std::string sentence) {
  const WorkPrecisionResult& r = d.work;
  if (!d.config.timing || !(r.crossover_ratio > 0)) return;
  l.document(kWorkDocument, [&] { return work_precision_json(r); });
  std::vector<ClaimGroup> from, below;  // the rows from the crossover on; the one before it
  for (std::size_t i = 0; i < r.stiffness.size(); ++i) {
    const StiffnessRow& row = r.stiffness[i];
    const bool on = row.ratio >= r.crossover_ratio;
    if (!on && (i + 1 >= r.stiffness.size() || r.stiffness[i + 1].ratio < r.crossover_ratio)) continue;
    std::vector<Evidence> explicit_run;  // none where no explicit method reached the error
    if (!row.best_explicit.empty()) explicit_run.push_back(l.at(kWorkDocument, fmt::format("/stiffness_sweep/{}/explicit_seconds", i)));
    (on ? from : below)
        .push_back(comparison_group(l.at(kWorkDocument, fmt::format("/stiffness_sweep/{}/implicit_seconds", i)), std::move(explicit_run), "less",
                                    kTieMargin));
  }
  const int n = static_cast<int>(from.size());
  claim_count(l, claim_text(id + ".from", section, sentence), std::move(from), n);
  claim_count(l, claim_text(id + ".before", section, sentence), std::move(below), 0);
}

namespace {

// A limit of the stiff-order study holds (order_reduction.cpp): reached, its order within `tol`
// of the theory's and its bound containing the theory's.
Json limit_holds(const std::string& limit, const std::string& theory, double tol) {
  return test_all({test_field(limit + "/reached", "==", true), test_difference(limit + "/order", theory, "<=", tol),
                   test_scaled(limit + "/order_bound/0", "<=", 1, theory), test_scaled(theory, "<=", 1, limit + "/order_bound/1")});
}

// A fit between the limits strays from the declared order: beyond kStiffTolerance of it and its
// bound not containing it, where its steps do not reach past dt*.
Json strays() {
  return test_all({test_field("/past_stable", "==", false), test_difference("/order", "/declared_order", ">", kStiffTolerance),
                   test_any({test_scaled("/order_bound/0", ">", 1, "/declared_order"),
                             test_scaled("/declared_order", ">", 1, "/order_bound/1")})});
}

}  // namespace

void claim_stiff(Ledger& l, const ReportData& d, const std::string& id, const std::string& section, const std::string& sentence,
                 const std::vector<StiffClaim>& claims) {
  const std::string file = "stiff_order/stiff_order.json";
  l.document(file, [&] { return order_reduction_json(d.stiff_order); });
  const Json limits = test_all({limit_holds("/non_stiff", "/theory/classical", kNonStiffTolerance),
                                limit_holds("/stiff", "/theory/stiff", kStiffTolerance)});
  std::vector<std::string> keeps, falls, rises, unstable;
  for (const StiffClaim& c : claims) {
    if (c.verdict == StiffVerdict::Keeps || c.verdict == StiffVerdict::Strays) keeps.push_back(name(c.method));
    if (c.verdict == StiffVerdict::Falls) falls.push_back(name(c.method));
    if (c.verdict == StiffVerdict::Rises) rises.push_back(name(c.method));
    if (c.verdict == StiffVerdict::Unstable) unstable.push_back(name(c.method));
    if (c.verdict == StiffVerdict::Keeps || c.verdict == StiffVerdict::Strays)  // each fit between the limits
      claim_members(l, claim_text(fmt::format("{}.strays.{}", id, name(c.method)), section, sentence), file, "/fits",
                    {{"method", name(c.method)}}, "method", true, strays(),
                    c.verdict == StiffVerdict::Strays ? std::vector<std::string>{name(c.method)} : std::vector<std::string>{});
  }
  const auto members = [&](const char* what, Json test, const std::vector<std::string>& set) {
    claim_members(l, claim_text(fmt::format("{}.{}", id, what), section, sentence), file, "/methods", Json::object(), "method", true,
                  std::move(test), set);
  };
  members("keeps_in_both_limits", test_all({limits, test_difference("/theory/stiff", "/theory/classical", "<=", 0)}), keeps);
  members("falls", test_all({limits, test_scaled("/theory/stiff", "<", 1, "/theory/classical")}), falls);
  members("rises", test_all({limits, test_scaled("/theory/stiff", ">", 1, "/theory/classical")}), rises);
  members("no_stiff_limit", test_field("/theory/stiff", "==", nullptr), unstable);
}

}  // namespace steplab

namespace steplab {

namespace {

// A comparison group over one map cell's rows: the run of solver `a` against each reached run the
// cell sets against it (`against`: another group's, or another kind's), its cheapest at their head.
template <class Against>
ClaimGroup cell_group(Ledger& l, const std::string& file, const std::vector<std::size_t>& rows, const ScalingResult& r,
                      const std::string& a, Against against, const char* relation) {
  const auto at = [&](std::size_t i, const char* field) { return l.at(file, fmt::format("/rows/{}/{}", i, field)); };
  const auto ia = std::find_if(rows.begin(), rows.end(), [&](std::size_t i) { return r.rows[i].solver == a; });
  if (ia == rows.end()) throw std::logic_error("a map cell without its cheapest run: " + a);
  std::vector<std::size_t> others;
  for (std::size_t i : rows)
    if (i != *ia && against(r.rows[i])) others.push_back(i);
  const auto cost = [&](std::size_t i) { return scaling_cost(r.config, r.rows[i]); };
  std::stable_sort(others.begin(), others.end(), [&](std::size_t x, std::size_t y) { return cost(x) < cost(y); });
  std::vector<Evidence> seconds;
  for (std::size_t i : others) seconds.push_back(at(i, "seconds"));
  return comparison_group(at(*ia, "seconds"), std::move(seconds), relation, kTieMargin);
}

}  // namespace

void claim_map(Ledger& l, const ScalingResult& r, std::size_t target, const std::string& id, const std::string& section,
               const std::string& sentence, const MapTally& tally) {
  if (!r.config.timing) return;  // untimed, the verdicts rest on counts that leave out the solves: no claim
  const std::string file = "scaling/scaling_map.json";
  l.document(file, [&] { return scaling_json(r); });
  const std::size_t nk = r.blocks.size() / r.config.targets.size();
  std::vector<ClaimGroup> ties, wins, implicit, still;
  // Each group the sentence names (a clear win somewhere): in every cell where it reached the
  // target, its cheapest run against every other group's, so that the cells a group's count is over
  // do not depend on which group's run came first in a tie.
  std::map<std::string, std::vector<ClaimGroup>> by_group;
  for (const auto& [group, n] : tally.wins)
    if (n > 0) by_group[group];
  const auto outside = [](const std::string& group) { return [group](const ScalingRow& w) { return solver_group(w.solver) != group; }; };
  for (std::size_t k = 0; k < nk; ++k) {
    const std::size_t b = target * nk + k;
    const ScalingBlock& block = r.blocks[b];
    for (std::size_t n = 0; n < block.cells.size(); ++n) {
      const ScalingCell& m = block.cells[n];
      if (m.cheapest.empty()) continue;
      ClaimGroup rest{"threshold", {{"op", "<"}, {"limit", block.error}, {"items", {0}}},
                      {l.at(file, fmt::format("/blocks/{}/map/{}/motion", b, n))}};
      still.push_back(std::move(rest));
      if (m.motion < block.error) continue;  // at rest: no one's win or tie
      std::vector<std::size_t> rows;  // the cell's reached rows (JSON rows are ScalingResult::rows)
      for (std::size_t s = 0; s < r.solvers(); ++s) {
        const ScalingRow& w = r.rows_of(b * r.solvers() + s)[n];
        if (w.reached()) rows.push_back(static_cast<std::size_t>(&w - r.rows.data()));
      }
      const std::string group = solver_group(m.cheapest);
      ties.push_back(cell_group(l, file, rows, r, m.cheapest, outside(group), "tie"));
      wins.push_back(cell_group(l, file, rows, r, m.cheapest, outside(group), "less"));
      for (auto& [named, cells] : by_group)  // the named group's cheapest run in this cell, if it reached the target
        if (const ScalingRow* best = cheapest_run(r, b, n, [&](const ScalingRow& w) { return solver_group(w.solver) == named; }))
          cells.push_back(cell_group(l, file, rows, r, best->solver, outside(named), "less"));
      if (!m.best_implicit.empty())  // an implicit fixed-step method against every other kind of solver
        implicit.push_back(cell_group(l, file, rows, r, m.best_implicit, [](const ScalingRow& w) { return w.adaptive || !w.implicit; }, "less"));
    }
  }
  int won = 0;
  for (const auto& [group, n] : tally.wins) won += n;
  claim_count(l, claim_text(id + ".ties", section, sentence), std::move(ties), tally.ties);
  claim_count(l, claim_text(id + ".wins", section, sentence), std::move(wins), won);
  for (auto& [group, cells] : by_group)
    claim_count(l, claim_text(id + ".wins." + id_word(group), section, sentence), std::move(cells), tally.wins.at(group));
  claim_count(l, claim_text(id + ".implicit_wins", section, sentence), std::move(implicit), static_cast<int>(tally.implicit.size()));
  claim_count(l, claim_text(id + ".at_rest", section, sentence), std::move(still), tally.still);
}

void claim_scaling_crossover(Ledger& l, const ScalingResult& r, const std::string& file, const std::string& id,
                             const std::string& section, const std::string& sentence) {
  if (!r.config.timing) return;
  l.document(file, [&] { return scaling_json(r); });
  const ScalingBlock& block = r.blocks.front();
  std::vector<ClaimGroup> groups;
  for (std::size_t k = 0; k < r.config.sizes.size(); ++k) {
    const ScalingRow* imp = crossover_sides(r, 0, k).implicit;
    std::vector<std::size_t> rows;  // the cheapest implicit run, then every explicit one (JSON rows are ScalingResult::rows)
    for (std::size_t s = 0; s < r.config.methods.size(); ++s)
      if (const ScalingRow& w = r.rows_of(s)[k]; w.reached() && !w.implicit) rows.push_back(static_cast<std::size_t>(&w - r.rows.data()));
    if (imp) {
      rows.insert(rows.begin(), static_cast<std::size_t>(imp - r.rows.data()));
      groups.push_back(cell_group(l, file, rows, r, imp->solver, [](const ScalingRow&) { return true; }, "less"));
    }
    if (r.config.sizes[k] == block.crossover) break;
  }
  claim_count(l, claim_text(id, section, sentence), std::move(groups), block.crossover == 0 ? 0 : 1);
}

}  // namespace steplab
