// The report works for every choice of methods: small reports with every section, for each
// numerical method alone and for pairs across families (each family paired with each other, its
// members taken in turn so that every method is in a pair), made whole (figures by gnuplot, the
// PDF by pandoc). A figure must not fail because a chosen method has nothing to draw in it (a
// method that reaches no target, a family represented only by a method another panel draws).
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "cli_helpers.hpp"
#include "reports/document/report.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"
#include "small_report.hpp"

namespace steplab {
namespace {

// The report's families with their own members (explicit and implicit Euler once, in their
// Runge-Kutta families).
std::vector<std::vector<std::size_t>> families() {
  std::vector<std::vector<std::size_t>> out;
  for (Family f : kReportFamilies) {
    std::vector<std::size_t> own;
    for (std::size_t m : ode_methods())
      if (method_info(m).family == f) own.push_back(m);
    if (!own.empty()) out.push_back(own);
  }
  return out;
}

std::vector<std::vector<std::size_t>> choices() {
  std::vector<std::vector<std::size_t>> out;
  for (std::size_t m : ode_methods()) out.push_back({m});  // the methods on springs: the frames section's
  const auto fam = families();
  std::size_t turn = 0;
  for (std::size_t a = 0; a < fam.size(); ++a)
    for (std::size_t b = a + 1; b < fam.size(); ++b, ++turn)
      out.push_back({fam[a][turn % fam[a].size()], fam[b][(turn + 1) % fam[b].size()]});
  return out;
}

TEST(ReportSubsets, EveryMethodAloneAndPairsAcrossFamiliesMakeWholeReports) {
  const std::vector<std::vector<std::size_t>> sets = choices();
  std::set<std::size_t> covered;
  for (const auto& s : sets) covered.insert(s.begin(), s.end());
  ASSERT_EQ(covered.size(), ode_methods().size());  // every method but the exact flow and those on springs
  for (const auto& s : sets) {
    std::vector<std::string> names;
    for (std::size_t m : s) names.push_back(name(m));
    ReportConfig c = small_config();
    choose_methods(c, names, "methods");
    // Every section but the frame budget's two (the rope's and the cloth's), which (with the
    // summary's rows of the methods on springs they bring) measure their own methods whatever the
    // choice: the default report of ReportPages makes them; here they would be made twenty times over.
    c.sections = section_names();
    std::erase(c.sections, std::string("frames"));
    std::erase(c.sections, std::string("cloth"));
    TempDir dir;
    const std::string out = dir.path("report");
    SCOPED_TRACE(fmt::format("--methods {}", fmt::join(names, ",")));
    try {
      ASSERT_EQ(write_report(c, out, true), 0);
    } catch (const std::exception& e) {
      FAIL() << e.what();
    }
    // Every section's heading once.
    std::set<std::string> headings;
    for (const std::string& line : split_lines(slurp(out + "/report.md")))
      if (line.rfind("## ", 0) == 0) {
        EXPECT_TRUE(headings.insert(line).second) << line << " twice";
      }
    EXPECT_TRUE(std::filesystem::exists(out + "/report.pdf"));
    const Result claims = verify_claims(out);
    EXPECT_EQ(claims.status, 0) << claims.out << claims.err;
  }
}

}  // namespace
}  // namespace steplab
