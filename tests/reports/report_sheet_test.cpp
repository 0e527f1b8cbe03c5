// The exercise's hand-in (`steplab report --sheet`) and a report on chosen scenes
// (ReportConfig::covered): the hand-in's numbers are the full report's, its sentences follow the
// data when the sheet's parameters change, and a section that needs a scene not chosen is left
// out with one line.
#include <gtest/gtest.h>

#include <algorithm>

#include <fmt/format.h>

#include <cmath>
#include <regex>
#include <string>
#include <vector>

#include "analysis/kernel/kernel.hpp"
#include "reports/data/inputs.hpp"
#include "reports/document/report.hpp"
#include "reports/document/section.hpp"
#include "small_report.hpp"
#include "cli_helpers.hpp"

namespace steplab {
namespace {

std::size_t scene(std::string_view name) { return *find_scene(name); }

// The hand-in with the small studies' settings (the sheet's own choice of methods, scenes, sections).
ReportConfig small_sheet() {
  const ReportConfig sheet = sheet_report_config();
  ReportConfig c = small_config();
  c.methods = sheet.methods;
  c.covered = sheet.covered;
  c.sections = sheet.sections;
  return c;
}

// The number printed after `key` in `md` (NaN if absent).
double number_after(const std::string& md, const std::string& key) {
  const std::size_t at = md.find(key);
  return at == std::string::npos ? NAN : std::stod(md.substr(at + key.size()));
}


TEST(ReportSheet, IsTheSheetsMethodsScenesAndSections) {
  const ReportConfig c = sheet_report_config();
  std::vector<std::string> names;
  for (std::size_t m : c.methods) names.push_back(std::string(method_info(m).name));
  EXPECT_EQ(names, (std::vector<std::string>{"explicit_euler", "symplectic_euler", "explicit_midpoint", "implicit_euler", "analytic"}));
  // the sheet's two scenes, its spring swinging in a plane (the long run's) and the slides' falling triangle
  std::vector<std::size_t> covered{scene("spring"), scene("cannonball"), scene("swing"), scene("falling")};
  std::sort(covered.begin(), covered.end());
  EXPECT_EQ(c.covered, covered);
  EXPECT_EQ(c.convergence_scenes(), (std::vector<std::size_t>{scene("spring"), scene("cannonball")}));
  const std::string md = markdown(small_sheet());
  EXPECT_EQ(md.find("Left out"), std::string::npos) << md;  // every section of the hand-in applies to its scenes
  for (const char* heading : {"## Answers", "## The exercise", "## Summary", "## Which methods are stable",
                              "## Is stability correlated with the order?", "## Is the energy kept?", "## The scenes", "## Convergence",
                              "## Over a long run", "## Collision", "The falling triangle", "## Reproduce"})
    EXPECT_NE(md.find(heading), std::string::npos) << heading;
  for (const char* absent : {"## Stability", "## What accuracy costs", "## As the system grows", "family by family",
                             "Bounces and penetration", "## Appendix"})
    EXPECT_EQ(md.find(absent), std::string::npos) << absent;
  // The hand-in opens with its answers and names the sheet's methods there.
  EXPECT_LT(md.find("## Answers"), md.find("## The exercise"));
  EXPECT_NE(md.find("The 2018 exercise sheet asks for `explicit_euler`, `symplectic_euler`, `explicit_midpoint` and "
                    "`implicit_euler`"), std::string::npos) << md;
}

// Each number of the hand-in is the full report's for the same method and scene: the same runs.
TEST(ReportSheet, NumbersAreTheFullReports) {
  ReportConfig all = small_config();
  all.sections = {"summary", "convergence", "scenes"};
  const Report full = build_report(all);
  const Report sheet = build_report(small_sheet());
  ASSERT_EQ(sheet.data.convergence.size(), 2u);
  for (const ConvergenceResult& r : sheet.data.convergence) {
    const ConvergenceResult& f = full.data.convergence_on(r.config.scene);
    for (std::size_t i = 0; i < r.config.methods.size(); ++i) {
      const std::size_t m = r.config.methods[i];
      std::size_t j = 0;
      while (f.config.methods[j] != m) ++j;
      EXPECT_EQ(r.fits[i].fit.order, f.fits[j].fit.order) << method_info(m).name;
      EXPECT_EQ(r.fits[i].fit.bound_lo, f.fits[j].fit.bound_lo) << method_info(m).name;
      for (std::size_t k = 0; k < r.dts.size(); ++k)
        EXPECT_EQ(r.records[i * r.dts.size() + k].error_final, f.records[j * f.dts.size() + k].error_final);
    }
  }
  for (std::size_t i = 0; i < sheet.findings.rows.size(); ++i) {
    const MethodFinding& a = sheet.findings.rows[i];
    std::size_t j = 0;
    while (full.findings.rows[j].method != a.method) ++j;
    const MethodFinding& b = full.findings.rows[j];
    EXPECT_EQ(a.dt_measured, b.dt_measured) << method_info(a.method).name;
    EXPECT_EQ(a.dt_undamped_measured, b.dt_undamped_measured) << method_info(a.method).name;
    EXPECT_EQ(a.stable_large_dt, b.stable_large_dt);
    EXPECT_EQ(a.energy_rate_large_dt, b.energy_rate_large_dt);
  }
}

// The constants of the sheet's equation (2) from the rest start, c1 = m g / k and
// c2 = -alpha c1 / beta, worked by hand for the parameters set here.
TEST(ReportSheet, ConstantsFollowTheParameters) {
  ReportConfig c = small_sheet();
  c.sections = {"sheet"};
  std::string md = markdown(c);
  EXPECT_NEAR(number_after(md, "**$c_1 = "), 1.962, 1e-12) << md;  // 1 * 9.81 / 5
  // alpha = -0.05, beta = sqrt(20 - 0.01) / 2 = 2.2355089...; c2 = 0.05 * 1.962 / beta
  EXPECT_NEAR(number_after(md, "**$c_2 = "), 0.0438826, 1e-7);
  EXPECT_LT(number_after(md, "the errors below are measured against (the scene's own, written for every damping regime) to within "), 1e-12);

  c.oscillator.params = {2, 8, 0.5, 5, 9.81};  // m, k, gamma, L, g
  md = markdown(c);
  EXPECT_NEAR(number_after(md, "**$c_1 = "), 2.4525, 1e-12) << md;  // 2 * 9.81 / 8
  // alpha = -0.125, beta = sqrt(64 - 0.25) / 4 = 1.9960899...; c2 = 0.125 * 2.4525 / beta = 0.1535801...
  EXPECT_NEAR(number_after(md, "**$c_2 = "), 0.15358, 1e-5);
  EXPECT_NE(md.find("(underdamped)"), std::string::npos);

  c.oscillator.params = {1, 5, 10, 5, 9.81};  // 4 k m = 20 < gamma^2 = 100
  md = markdown(c);
  EXPECT_NE(md.find("the cube is overdamped"), std::string::npos) << md;
  EXPECT_EQ(md.find("**$c_2 = "), std::string::npos);
}

// The second question's answer follows the measured dt*: undamped, explicit Euler and explicit
// midpoint are both unstable at every step (dt* = 0), so within their family dt* stays the same
// (the family table's words and rule: reports/document/findings.hpp, trend).
TEST(ReportSheet, OrderAnswerFollowsTheData) {
  ReportConfig c = small_sheet();
  c.sections = {"order"};
  std::string md = markdown(c);
  EXPECT_NE(md.find("**Not as a rule.**"), std::string::npos) << md;  // order 1: 0.02, 0.87, inf
  EXPECT_NE(md.find("in the explicit Runge-Kutta family dt* rises with the order (`explicit_euler` 0.02, `explicit_midpoint` 0.2649)"),
            std::string::npos) << md;

  c.oscillator.params[static_cast<std::size_t>(scene_kernel(c.oscillator.scene).damping_param)] = 0;
  md = markdown(c);
  EXPECT_NE(md.find("dt* stays the same with the order (`explicit_euler` 0, `explicit_midpoint` 0)"), std::string::npos) << md;

  choose_methods(c, {"explicit_euler", "explicit_midpoint"}, "methods");
  md = markdown(c);
  EXPECT_NE(md.find("No two of these methods share an order"), std::string::npos) << md;
  EXPECT_EQ(md.find("Not as a rule"), std::string::npos);
}

// The smallest text of a figure's PDF at print size, in points. pdftotext's line boxes of gnuplot's
// cairo text are 0.775 of the font size across the line (measured: 9 pt text 6.98 pt high, 8 pt
// 6.20); a rotated label's line is tall and narrow, so the box's smaller side is the across. Lines
// of two characters or more: a lone digit is narrower than it is high.
double smallest_text_pt(const std::string& pdf, const TempDir& dir) {
  const std::string out = dir.path("bbox.html");
  if (std::system(("pdftotext -bbox-layout '" + pdf + "' '" + out + "'").c_str()) != 0) return NAN;
  const std::string html = slurp(out);
  static const std::regex line(R"re(<line xMin="([\d.]+)" yMin="([\d.]+)" xMax="([\d.]+)" yMax="([\d.]+)">([\s\S]*?)</line>)re");
  static const std::regex word(R"re(>([^<]+)</word>)re");
  double smallest = INFINITY;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), line); it != std::sregex_iterator(); ++it) {
    const std::string words = (*it)[5];
    std::size_t chars = 0;
    for (auto w = std::sregex_iterator(words.begin(), words.end(), word); w != std::sregex_iterator(); ++w) chars += (*w)[1].length();
    if (chars < 2) continue;
    const double across = std::min(std::stod((*it)[3]) - std::stod((*it)[1]), std::stod((*it)[4]) - std::stod((*it)[2]));
    smallest = std::min(smallest, across / 0.775);
  }
  return smallest;
}

// The whole hand-in, as a student makes it: at most 5 pages of PDF (the issue's bound; 5 with the
// sheet's defaults), its figures drawn.
// Every figure of the report in `folder` by the written figure rules (docs/design.md), read from
// what gnuplot drew (tests/figure_rules_check.py: panels, curves a panel and their styles, ticks,
// text size, each caption's computed sentence).
void expect_figure_rules(const TempDir& dir, const std::string& folder) {
  const std::string rules = std::string("python3 ") + STEPLAB_SOURCE_DIR + "/tests/figure_rules_check.py " + dir.path(folder) +
                            " > " + dir.path("rules.txt") + " 2>&1";
  EXPECT_EQ(std::system(rules.c_str()), 0) << slurp(dir.path("rules.txt"));
}

TEST(ReportSheet, HandInIsAtMostFivePages) {
  TempDir dir;
  const Result r = run_steplab("report --sheet --out " + dir.path("hand-in"));
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string info = dir.path("info.txt");
  ASSERT_EQ(std::system(("pdfinfo " + dir.path("hand-in/report.pdf") + " > " + info).c_str()), 0);
  const double pages = number_after(slurp(info), "Pages:");
  EXPECT_GE(pages, 3);
  EXPECT_LE(pages, 5);
  for (const char* figure : {"hand-in/figures/fig1_energy_sheet.pdf", "hand-in/figures/fig2_cannonball.pdf", "hand-in/figures/fig3_spring.pdf",
                             "hand-in/figures/fig4_convergence.pdf", "hand-in/figures/fig5_long_time.pdf",
                             "hand-in/figures/fig6_triangle.pdf"})
    EXPECT_TRUE(std::filesystem::exists(dir.path(figure))) << figure;
  EXPECT_NE(slurp(dir.path("hand-in/report.md")).find("## The exercise"), std::string::npos);
  const Result claims = verify_claims(dir.path("hand-in"));
  EXPECT_EQ(claims.status, 0) << claims.out << claims.err;
  for (const auto& e : std::filesystem::directory_iterator(dir.path("hand-in/figures")))
    if (e.path().extension() == ".pdf") {
      EXPECT_GE(smallest_text_pt(e.path().string(), dir), 7.95) << e.path();
    }
  expect_figure_rules(dir, "hand-in");
}

// The default report within its budget (docs/design.md, "A report section"): a hand-out of at most
// 10 pages, no figure text under 8 pt at print size (a figure is 16 cm wide, inserted unscaled);
// every figure drawn is in the atlas, the hand-out's are numbered 1, 2, ... as it shows them, and
// each of its links into the atlas names a heading there.
TEST(ReportPages, DefaultWithinItsBudget) {
  TempDir dir;
  const Result r = run_steplab("report --out " + dir.path("report"));
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_EQ(std::system(("pdfinfo " + dir.path("report/report.pdf") + " > " + dir.path("info.txt")).c_str()), 0);
  EXPECT_LE(number_after(slurp(dir.path("info.txt")), "Pages:"), 10);
  const std::string md = slurp(dir.path("report/report.md")), atlas = slurp(dir.path("report/atlas.html"));
  int figures = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.path("report/figures"))) {
    if (e.path().extension() != ".pdf") continue;
    ++figures;
    EXPECT_GE(smallest_text_pt(e.path().string(), dir), 7.95) << e.path();
    EXPECT_NE(atlas.find("figures/" + e.path().stem().string() + ".svg"), std::string::npos) << e.path();
  }
  EXPECT_GE(figures, 8);
  static const std::regex shown(R"re(!\[Figure (\d+): [^\]]*\]\(figures/(fig\d+_\w+)\.png\))re");
  int k = 0;
  for (auto it = std::sregex_iterator(md.begin(), md.end(), shown); it != std::sregex_iterator(); ++it) {
    EXPECT_EQ(std::stoi((*it)[1]), ++k);
    EXPECT_TRUE(std::filesystem::exists(dir.path("report/figures/" + (*it)[2].str() + ".png"))) << (*it)[2];
  }
  EXPECT_GE(k, 4);  // the regions, the sheet's energy, convergence and the triangle
  static const std::regex link(R"re(\]\(atlas\.html#([^)]+)\))re");
  int links = 0;
  for (auto it = std::sregex_iterator(md.begin(), md.end(), link); it != std::sregex_iterator(); ++it, ++links)
    EXPECT_NE(atlas.find("id=\"" + (*it)[1].str() + "\""), std::string::npos) << (*it)[1];
  EXPECT_GE(links, 5);  // one per brief section
  const Result claims = verify_claims(dir.path("report"));
  EXPECT_EQ(claims.status, 0) << claims.out << claims.err;
  // The atlas in a real browser (tests/atlas_browser_check.py): every image loads, no error, every
  // link resolves; its screenshot at 1280 px is left in build/ for a person to look at.
  const std::string shot = (std::filesystem::path(STEPLAB_EXE).parent_path() / "atlas.png").string();
  const std::string check = std::string("python3 ") + STEPLAB_SOURCE_DIR + "/tests/atlas_browser_check.py " + dir.path("report") + " " +
                            shot + " > " + dir.path("atlas.txt") + " 2>&1";
  EXPECT_EQ(std::system(check.c_str()), 0) << slurp(dir.path("atlas.txt"));
  expect_figure_rules(dir, "report");
}

TEST(ReportScenes, ASectionThatNeedsASceneNotChosenIsLeftOutWithOneLine) {
  ReportConfig c = small_config();
  choose_scenes(c, {"cannonball"}, "scenes");
  const Report r = build_report(c);
  EXPECT_EQ(r.data.studies, unsigned{kConvergenceStudy});  // no stability, collision, cost or growth runs
  const std::string md = report_markdown(r, "png", "");
  for (const char* line : {"*Left out: Summary (it needs `spring`, not among the chosen scenes).*",
                           "*Left out: Stability in detail (it needs `spring`, not among the chosen scenes).*",
                           "*Left out: Collision (it needs `bounce` and `falling`, not among the chosen scenes).*",
                           "*Left out: As the system grows (none of the chosen scenes is of run-time size).*"})
    EXPECT_NE(md.find(line), std::string::npos) << line << "\n" << md;
  EXPECT_NE(md.find("fig1_convergence"), std::string::npos);  // the scenes section is the hand-in's: not chosen here
  EXPECT_EQ(md.find("_spring."), std::string::npos);
  ASSERT_EQ(r.data.convergence.size(), 1u);
  EXPECT_EQ(r.data.convergence[0].config.scene, scene("cannonball"));
  EXPECT_NE(md.find("Error against dt on Cannon ball"), std::string::npos);
  EXPECT_EQ(md.find("The hanging spring:"), std::string::npos);
}

// A scene that is not one of the report's own (the chain is the cost section's contrast only):
// chosen, it gets a convergence study against its exact solution.
TEST(ReportScenes, AnotherSceneGetsItsConvergenceStudy) {
  ReportConfig c = small_config();
  choose_methods(c, {"rk4", "implicit_euler", "analytic"}, "methods");
  choose_scenes(c, {"chain"}, "scenes");
  choose_sections(c, {"convergence", "cost"}, "sections");
  const Report r = build_report(c);
  ASSERT_EQ(r.data.convergence.size(), 1u);
  const ConvergenceResult& chain = r.data.convergence[0];
  EXPECT_EQ(chain.config.scene, scene("chain"));
  EXPECT_FALSE(chain.uses_reference);
  const std::string md = report_markdown(r, "png", "");
  EXPECT_NE(md.find("*Left out: What accuracy costs (it needs `spring`"), std::string::npos) << md;
  EXPECT_NE(md.find(std::string(scene_kernel(scene("chain")).title) + ":"), std::string::npos) << md;  // its table
}

TEST(ReportScenes, RefusedChoices) {
  ReportConfig c = small_config();
  EXPECT_THROW(choose_scenes(c, {"nosuch"}, "scenes"), UsageError);
  EXPECT_THROW(choose_scenes(c, {}, "scenes"), UsageError);
  EXPECT_THROW(choose_scenes(c, {"spring", "spring"}, "scenes"), UsageError);
  choose_scenes(c, {"falling"}, "scenes");  // no exact solution: the exact flow runs on none of the chosen scenes
  choose_methods(c, {"rk4", "analytic"}, "methods");
  EXPECT_THROW(check_choice(c, "methods"), UsageError);
  choose_methods(c, {"rk4"}, "methods");
  EXPECT_NO_THROW(check_choice(c, "methods"));
  const ReportConfig back = report_config_from_json(report_config_json(sheet_report_config()));
  EXPECT_EQ(back.covered, sheet_report_config().covered);
  EXPECT_EQ(back.sections, sheet_report_config().sections);
}

}  // namespace
}  // namespace steplab
