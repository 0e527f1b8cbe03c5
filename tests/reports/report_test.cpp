// Tests of the report's configuration, its rank correlation, and "As the system grows" (its
// sentences follow the scaling studies' rows). The other sentence classes: claims_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <cmath>
#include <regex>
#include <set>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/peers/peers.hpp"
#include "analysis/studies/scaling.hpp"
#include "reports/data/inputs.hpp"
#include "reports/studies/studies.hpp"
#include "reports/document/figure_styles.hpp"
#include "reports/document/report.hpp"
#include "small_report.hpp"

namespace steplab {
namespace {

std::string line_starting(const std::string& md, const std::string& prefix) {
  const std::size_t a = md.find(prefix);
  return a == std::string::npos ? "" : md.substr(a, md.find('\n', a) - a);
}

TEST(Spearman, KnownValues) {
  EXPECT_DOUBLE_EQ(spearman({1, 2, 3, 4}, {10, 20, 30, 40}), 1.0);
  EXPECT_DOUBLE_EQ(spearman({1, 2, 3, 4}, {4, 3, 2, 1}), -1.0);
  // ties and infinities: ranks (1.5, 1.5, 3, 4) against (1, 2, 3.5, 3.5)
  const double rho = spearman({1, 1, 2, INFINITY}, {0.1, 0.2, INFINITY, INFINITY});
  // Pearson of the ranks about their mean 2.5: deviations (-1, -1, 0.5, 1.5) and (-1.5, -0.5, 1, 1);
  // products 1.5 + 0.5 + 0.5 + 1.5 = 4; sums of squares 4.5 and 4.5: rho = 4 / 4.5
  EXPECT_NEAR(rho, 4.0 / 4.5, 1e-12);
}

TEST(ReportConfigJson, DefaultsRoundTripAndOverrides) {
  const auto defaults = report_config_json(default_report_config());
  EXPECT_EQ(report_config_json(report_config_from_json(defaults)).dump(), defaults.dump());
  const ReportConfig c = report_config_from_json(nlohmann::ordered_json::parse(R"({"spring": {"damping": 0.3}, "threads": 1})"));
  EXPECT_DOUBLE_EQ(c.damping(), 0.3);
  EXPECT_EQ(c.threads, 1u);
  EXPECT_DOUBLE_EQ(c.oscillator.params[1], 5.0);  // the stiffness, as the rest, stays default
}

TEST(ReportConfigJson, RefusesBadConfigs) {
  for (const char* bad : {R"({"spring": {"stifness": 3}})", R"({"sprung": {}})", R"({"spring": {"damping": "a lot"}})",
                          R"({"spring": {"mass": 0}})", R"({"stability": {"sweep_dts": []}})", R"({"convergence": {"points": 2.5}})",
                          R"({"convergence": {"dt_min": 0.5, "dt_max": 0.1}})", R"([1, 2])", R"({"work_precision": {"timing": 1}})"}) {
    EXPECT_THROW(report_config_from_json(nlohmann::ordered_json::parse(bad)), UsageError) << bad;
  }
}

}  // namespace
}  // namespace steplab

namespace steplab {
namespace {

// "As the system grows": its exponents and sentences follow the scaling studies the report ran
// (re-derived here from their rows): an exponent shown only where it is a finding (fitted, its
// interval at most +-0.5), the crossover, and the map's clear wins and ties (a margin below 1.2 a
// tie; untimed here, so only an exact equality), under two settings.
std::string expect_scaling_follows_data(const ReportConfig& c) {
  const Report report = build_report(c);
  const std::string all = report_markdown(report, "png", "");
  const std::size_t at = all.find("## As the system grows");
  EXPECT_NE(at, std::string::npos);
  const std::string md = all.substr(at, all.find("\n## ", at + 1) - at);
  const ReportData& d = report.data;
  EXPECT_EQ(d.scaling.size(), 2u);  // the rope and the soft body
  for (const ScalingResult& r : d.scaling) {
    // the study ran at the configuration's sizes (its text is checked against the study below)
    for (const ReportSizes& s : c.scaling)
      if (scene_name(s.scene) == r.config.scene) {
        EXPECT_EQ(r.config.sizes, s.sizes) << r.config.scene;
      }
    const std::string part = md.substr(md.find(std::string(scene_kernel(*find_scene(r.config.scene)).title)));
    const std::size_t table = part.substr(0, part.find("\n**")).find("| solver | cost ~ N^p^");  // its exponents' table, if any
    const std::string exponents = table == std::string::npos ? "" : part.substr(table, part.find("\n\n", table) - table);
    // the solvers without a finding are named before "at these sizes", where others have one
    const std::size_t either = part.find("\nFor `");
    const std::string named = either == std::string::npos ? "" : part.substr(either, part.find(" no exponent is a finding", either) - either);
    for (const ScalingFit& f : r.fits) {
      const auto finding = [](const Exponent& e) { return e.fitted() && e.hi - e.lo <= 1; };
      const std::string row = line_starting(exponents, "| `" + f.solver + "` |");
      if (!finding(f.step) && !finding(f.run) && !finding(f.stable)) {
        EXPECT_TRUE(row.empty()) << row;
        if (!exponents.empty()) {
          EXPECT_NE(named.find("`" + f.solver + "`"), std::string::npos) << f.solver << "\n" << part;
        }
        continue;
      }
      EXPECT_NE(row.find("| " + (finding(f.run) ? exponent_text(f.run) : std::string("-")) + " |"), std::string::npos) << row;
    }
    const ScalingBlock& b = r.blocks.front();
    EXPECT_NE(part.find(!r.config.timing ? std::string("Untimed, where implicit pays is not read")
                        : b.crossover == 0 ? std::string("At none of these sizes is an implicit method")
                                           : fmt::format("From N = {} on (of these sizes), `{}`", scaling_masses(r.config, b.crossover),
                                                         b.crossover_method)),
              std::string::npos) << part;
  }
  EXPECT_TRUE(d.scaling_map.has_value());
  const ScalingResult& map = *d.scaling_map;
  EXPECT_EQ(map.config.targets.front().value, c.scaling_error);  // the map's first target is the configured error
  const std::size_t nk = map.blocks.size() / map.config.targets.size();
  for (std::size_t t = 0; t < map.config.targets.size(); ++t) {
    std::map<std::string, int> wins;
    int ties = 0, implicit = 0;
    // A solver whose force evaluations leave out its solves: an implicit method or peer.
    const auto solves = [](const std::string& s) {
      const auto m = find_method(s);
      return m ? method_info(*m).implicit : find_peer(s) && find_peer(s)->implicit;
    };
    EXPECT_FALSE(map.config.timing);  // the counts below are the untimed rules
    for (std::size_t k = 0; k < nk; ++k)
      for (const ScalingCell& cell : map.blocks[t * nk + k].cells) {
        if (cell.cheapest.empty() || cell.motion < map.blocks[t * nk + k].error) continue;  // none, or a body at rest: no one's
        // untimed: the cheapest ties the cheapest of another group only when their counts are equal,
        // and an implicit cheapest is undecided against an explicit one; "implicit pays" only where
        // no other kind of solver reached the target
        if (cell.rival_margin == 1 || (solves(cell.cheapest) && !cell.best_explicit.empty())) ++ties;
        else ++wins[solver_group(cell.cheapest)];
        implicit += cell.cheapest == cell.best_implicit && cell.best_explicit.empty() && cell.best_implicit_peer.empty();
      }
    const std::string line = line_starting(md, fmt::format("- At error {}, of", target_text(map.config, map.blocks[t * nk])));
    EXPECT_FALSE(line.empty()) << t << md;
    for (const auto& [group, n] : wins) EXPECT_NE(line.find(fmt::format("{} {}", group, n)), std::string::npos) << line;
    if (ties) {
      EXPECT_NE(line.find(fmt::format("; {} tie", ties)), std::string::npos) << line;
    }
    EXPECT_NE(line.find(implicit == 0 ? std::string("No implicit fixed-step method is clearly the cheapest anywhere")
                                      : fmt::format("An implicit fixed-step method is clearly the cheapest in {} ", implicit)),
              std::string::npos) << line;
  }
  return md;
}

TEST(ReportScaling, FollowsTheDataUnderChangedParameters) {
  ReportConfig c = small_config();
  const std::string a = expect_scaling_follows_data(c);
  sizes_of(c, "rope") = {4, 16, 128};  // 1.5 decades: the exponents fitted
  sizes_of(c, "softbody") = {3, 4};
  c.scaling_error = 1e-3;
  c.scaling_stiffening = {1, 30, 1000};
  const std::string b = expect_scaling_follows_data(c);
  // The section's words changed with the data: the exponents fitted only over 1.5 decades of N.
  EXPECT_EQ(a.find("| solver | cost ~ N^p^"), std::string::npos) << a;
  EXPECT_NE(b.find("| solver | cost ~ N^p^"), std::string::npos) << b;
}

}  // namespace
}  // namespace steplab
