// The report's "Does the order hold when stiff?" (reports/document/sections/stiff_order.cpp): its
// sentences follow the measured orders and the theory, under changed methods and stiffnesses.
#include <gtest/gtest.h>

#include <string>

#include "reports/document/report.hpp"
#include "small_report.hpp"

namespace steplab {
namespace {


ReportConfig stiff_only() {
  ReportConfig c = small_config();
  c.sections = {"stiff_order"};
  return c;
}

bool has(const std::string& md, const std::string& s) { return md.find(s) != std::string::npos; }

// The default sweep (1e-2 .. 1e16): Radau IIA 5 and Gauss-Legendre 4 fall, BDF2 gains an order
// in the largest error (from its Gauss-Legendre start), BDF3 keeps 3 in both limits but strays
// between them (4.3 at stiffness 1e6), implicit Euler and midpoint keep theirs at every stiffness,
// the explicit methods have no stiff limit; no method differs from the theory. (Every class is
// re-derived from the fits under other settings in claims_test.cpp.)
TEST(ReportStiffOrder, TheDefaultSweepsVerdicts) {
  const std::string md = markdown(stiff_only());
  const auto line = [&](const std::string& key) {
    const std::size_t a = md.find(key);
    return a == std::string::npos ? std::string() : md.substr(a, md.find('\n', a) - a);
  };
  EXPECT_TRUE(has(line("- **Fall**"), "`radau_iia5` from 5.0")) << md;
  EXPECT_TRUE(has(line("- **Fall**"), "`gauss_legendre4` from 4.0")) << md;
  EXPECT_TRUE(has(line("- **Keep their order at every stiffness**"), "`implicit_euler`")) << md;
  EXPECT_TRUE(has(line("- **Keep their order at every stiffness**"), "`implicit_midpoint`")) << md;
  EXPECT_FALSE(has(line("- **Keep their order at every stiffness**"), "`bdf3`")) << md;
  EXPECT_TRUE(has(line("- **Keep their order in both limits but stray"), "`bdf3` (3 in both limits, 4.")) << md;
  EXPECT_TRUE(has(line("- **Gain**"), "`bdf2` from 2.0")) << md;
  EXPECT_TRUE(has(line("- **Gain**"), "from its `gauss_legendre4` start")) << md;
  EXPECT_TRUE(has(line("- **Not stable**"), "`rk4`")) << md;
  EXPECT_FALSE(has(md, "Differ from the theory")) << md;
  EXPECT_FALSE(has(md, "not reached")) << md;
}

// Stopped at stiffness 1e4 the stiff regime is never entered: the limit is said not reached,
// never claimed; with only explicit methods there is nothing but the unstable sentence.
TEST(ReportStiffOrder, SentencesUnderChangedStiffnessesAndMethods) {
  ReportConfig c = stiff_only();
  c.stiff_order.stiffnesses = {1e-2, 1, 1e2, 1e4};
  std::string md = markdown(c);
  EXPECT_TRUE(has(md, "The stiff limit is not reached at these steps for")) << md;
  EXPECT_FALSE(has(md, "**Fall**")) << md;

  choose_methods(c, {"rk4", "explicit_euler"}, "methods");
  md = markdown(c);
  EXPECT_TRUE(has(md, "- **Not stable** as h |lambda| grows: `explicit_euler` and `rk4`")) << md;
  EXPECT_FALSE(has(md, "**Keep their order")) << md;
}

// Without the target among the chosen scenes the section is one line.
TEST(ReportStiffOrder, LeftOutWithoutItsScene) {
  ReportConfig c = stiff_only();
  choose_scenes(c, {"spring"}, "scenes");
  const std::string md = markdown(c);
  EXPECT_TRUE(has(md, "*Left out: Does the order hold when stiff? (it needs `target`")) << md;
}

}  // namespace
}  // namespace steplab
