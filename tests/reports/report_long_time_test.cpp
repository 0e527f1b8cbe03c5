// "Stable for how long?" (reports/document/sections/long_time.cpp) and its answer at the report's
// top: each sentence re-derived here from the long-time runs the report made (bounded: the
// energy error's growth interval below 0.5 or at round-off, the orbit kept; drifting: above 0.5),
// under two settings.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "reports/studies/studies.hpp"
#include "reports/document/report.hpp"
#include "small_report.hpp"

namespace steplab {
namespace {

// The text between `from` and the next `to` in s (empty if `from` is missing).
std::string between(const std::string& s, const std::string& from, const std::string& to) {
  const std::size_t a = s.find(from);
  if (a == std::string::npos) return {};
  return s.substr(a, s.find(to, a + from.size()) - a);
}

std::string expect_long_time_follows_data(const ReportConfig& c) {
  const Report report = build_report(c);
  const std::string all = report_markdown(report, "png", "");
  const std::string section = between(all, "## Stable for how long?", "\n## ");
  EXPECT_FALSE(section.empty()) << all;
  const LongTimeResult& orbit = report.data.long_time_orbit;
  EXPECT_EQ(orbit.config.periods, c.long_time_periods);
  EXPECT_EQ(orbit.rows.size(), c.methods.size());
  const std::string kepler = between(section, "**Kepler's orbit.**", "\n"), answer = between(all, "**Stable for how long?**", "\n");
  const std::string bounded_part = between(kepler, "Bounded energy error", "Drifting"), drifting_part = between(kepler, "Drifting", ". ");
  for (const LongTimeRow& row : orbit.rows) {
    const std::string name = fmt::format("`{}`", method_info(row.method).name);
    const bool kept = row.status == RunStatus::Ok && row.error[0].back() < 0.1;
    const bool is_bounded = kept && ((row.growth[0].fitted && row.growth[0].hi < 0.5) || row.round_off[0]);
    const bool is_drifting = kept && !is_bounded && row.growth[0].fitted && row.growth[0].lo > 0.5;
    EXPECT_EQ(bounded_part.find(name) != std::string::npos, is_bounded) << name << "\n" << kepler;
    EXPECT_EQ(drifting_part.find(name) != std::string::npos, is_drifting) << name << "\n" << kepler;
    EXPECT_EQ(between(answer, "stays bounded with", "and drifts").find(name) != std::string::npos, is_bounded) << name << "\n" << answer;
    // its table row: the energy error's growth with its interval, and the phase's
    const std::string table_row = between(section, fmt::format("| {} |", name), "\n");
    // a run that stopped says how, in the table as in the text: its energy beyond bound, or Newton
    const char* stopped = row.status == RunStatus::Diverged ? "blew up at" : "Newton gave up at";
    // and a run whose energy error reached 0.1 (the orbit lost) no exponent beside it, which would read as bounded
    const std::string energy = row.status != RunStatus::Ok ? stopped : kept ? growth_text(row.growth[0]) : "| lost |";
    EXPECT_NE(table_row.find(energy), std::string::npos) << table_row;
    EXPECT_NE(table_row.find(growth_text(row.position_growth)), std::string::npos) << table_row;
  }
  return section;
}

TEST(ReportLongTime, FollowsTheDataUnderChangedParameters) {
  ReportConfig c = small_config();
  choose_methods(c, {"explicit_euler", "symplectic_euler", "velocity_verlet", "rk4", "yoshida4", "radau_iia5"}, "test");
  choose_sections(c, {"answers", "long_time"}, "test");
  const std::string a = expect_long_time_follows_data(c);
  c.long_time_periods = 1000;
  const std::string b = expect_long_time_follows_data(c);
  EXPECT_NE(a, b);
}

// The hand-in's paragraph: the sheet's four methods on the swinging spring, each named on its side.
TEST(ReportLongTime, HandInNamesEachMethodOnItsSide) {
  ReportConfig c = sheet_report_config();
  c.long_time_periods = 1000;  // explicit Euler blows up after 512
  choose_sections(c, {"long_run"}, "test");
  const Report report = build_report(c);
  const std::string md = report_markdown(report, "png", "");
  const LongTimeResult& swing = report.data.long_time_swing;
  ASSERT_EQ(swing.rows.size(), 4u);  // not the exact flow: the swing has none
  EXPECT_TRUE(report.data.long_time_orbit.rows.empty());  // the orbit is not the hand-in's
  for (const LongTimeRow& row : swing.rows) EXPECT_NE(md.find(fmt::format("`{}`", method_info(row.method).name)), std::string::npos);
  EXPECT_NE(md.find("Bounded energy error (growth exponent's interval below 0.5): `symplectic_euler`"), std::string::npos) << md;
  EXPECT_NE(md.find("`explicit_euler` (blew up after"), std::string::npos) << md;
}

}  // namespace
}  // namespace steplab
