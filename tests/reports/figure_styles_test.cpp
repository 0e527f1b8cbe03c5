// The methods' figure styles (reports/document/figure_styles.cpp): each method its own, members of a family
// panel told apart without colour (grey-scale print, colour-blind readers), and the gnuplot side
// (styles.gp) run through gnuplot itself.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <set>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "cli_helpers.hpp"
#include "analysis/kernel/kernel.hpp"
#include "reports/document/figure_styles.hpp"
#include "reports/document/section.hpp"
#include "reports/document/report_text.hpp"

namespace steplab {
namespace {

std::vector<std::size_t> every_method() {
  std::vector<std::size_t> all;
  for (std::size_t m = 0; m < method_count(); ++m) all.push_back(m);
  return all;
}

// Every method its own colour, and its own pair of point and dash: any two methods drawn in one
// panel (a family's, the sheet's four, the explicit fixed-step ones) differ in colour and in point
// and dash, as the figure rules ask (docs/design.md; tests/figure_rules_check.py checks the drawn
// figures).
TEST(FigureStyles, EachMethodHasItsOwnColourAndItsOwnPointAndDash) {
  std::set<std::string> colours;
  std::set<std::pair<int, std::string>> marks;
  for (std::size_t m = 0; m < method_count(); ++m) {
    const MethodStyle s = method_style(m);
    EXPECT_TRUE(colours.insert(s.colour).second) << name(m) << " " << s.colour;
    EXPECT_TRUE(marks.insert({s.point, s.dash}).second) << name(m) << " " << s.point << " " << s.dash;
  }
}

// Within a panel (a family, with explicit and implicit Euler opening Adams-Bashforth and BDF) no two
// methods share a point type or a dash type, so the panel reads in grey scale.
TEST(FigureStyles, APanelsMethodsDifferInPointAndDash) {
  for (Family f : kReportFamilies) {
    std::set<int> points;
    std::set<std::string> dashes;
    const auto members = family_members(every_method(), f);
    EXPECT_LE(members.size(), 6u) << to_string(f);  // at most six curves a panel
    for (std::size_t m : members) {
      EXPECT_TRUE(points.insert(method_style(m).point).second) << name(m) << " in " << to_string(f);
      EXPECT_TRUE(dashes.insert(method_style(m).dash).second) << name(m) << " in " << to_string(f);
    }
  }
}

// The sheet's four methods, drawn in one panel: each its own point or dash (three are first order).
TEST(FigureStyles, TheSheetsMethodsDifferInPointOrDash) {
  std::set<std::pair<int, std::string>> marks;
  for (const char* m : {"explicit_euler", "symplectic_euler", "explicit_midpoint", "implicit_euler"}) {
    const MethodStyle s = method_style(*find_method(m));
    EXPECT_TRUE(marks.insert({s.point, s.dash}).second) << m;
  }
  // the same order, the same family: the open point and the hue's tint
  EXPECT_EQ(method_style(*find_method("baraff_witkin")).point, method_style(*find_method("implicit_euler")).point - 1);
  EXPECT_EQ(method_style(*find_method("baraff_witkin")).colour, "#80CFB9");  // (00, 9E, 73) halfway to white
}

// The family hues are Okabe-Ito's; the first member of a family carries the hue itself.
TEST(FigureStyles, FamilyHuesAreOkabeIto) {
  EXPECT_EQ(method_style(*find_method("explicit_euler")).colour, "#0072B2");
  EXPECT_EQ(method_style(*find_method("symplectic_euler")).colour, "#D55E00");
  EXPECT_EQ(method_style(*find_method("implicit_euler")).colour, "#009E73");
  EXPECT_EQ(method_style(*find_method("rk4")).colour, "#003755");  // 0.48 x (00, 72, B2)
}

// gnuplot reads styles.gp: mlt() finds each method's linetype; terminal() and kfont follow the
// format the report sets (8 pt keys in print).
TEST(FigureStyles, GnuplotReadsTheStyles) {
  TempDir dir;
  std::ofstream(dir.path("styles.gp")) << styles_gp();
  std::ofstream(dir.path("probe.gp")) << "load 'styles.gp'\n"
                                         "print mlt('explicit_euler'), mlt('rk4'), mlt('bdf3'), mlt('nosuch')\n"
                                         "print in_list('rk4', 'rk3 rk4'), in_list('rk', 'rk3 rk4')\n"
                                         "print terminal(330 * 2 + 60, 4.2 * 2 + 0.6), '|', kfont\n";
  for (const char* format : {"png", "svg", "pdf"}) {
    const std::string cmd = fmt::format("cd '{}' && gnuplot -e \"format='{}'\" probe.gp 2>{}", dir.root(), format, dir.path("out"));
    ASSERT_EQ(std::system(cmd.c_str()), 0) << slurp(dir.path("out"));
    const auto lines = split_lines(slurp(dir.path("out")));
    ASSERT_EQ(lines.size(), 3u) << slurp(dir.path("out"));
    EXPECT_EQ(lines[0], "1 6 14 0");
    EXPECT_EQ(lines[1], "1 0");
    EXPECT_EQ(lines[2], std::string(format) == "pdf"   ? "set terminal pdfcairo enhanced size 16cm,9.0cm font ',10' | ,8"
                        : std::string(format) == "svg" ? "set terminal svg enhanced size 1100,720 font ',12' background rgb 'white' | ,11"
                                                       : "set terminal pngcairo enhanced size 1100,720 font ',12' | ,11");
  }
}

std::vector<std::size_t> methods(std::initializer_list<std::string_view> names) {
  std::vector<std::size_t> out;
  for (std::string_view n : names) out.push_back(*find_method(n));
  return out;
}

// A panel per family, its members by order; a family that would only draw what an earlier panel
// draws is left out (explicit Euler alone under Adams-Bashforth), and a method without data is not
// drawn (a panel of none is no panel).
TEST(FigurePanels, AFamilyPanelDrawsSomethingNew) {
  const std::vector<Panel> all = family_panels(every_method());
  ASSERT_EQ(all.size(), 5u);
  EXPECT_EQ(all[4].title, "BDF");
  EXPECT_EQ(all[4].solvers, (std::vector<std::string>{"implicit_euler", "bdf2", "bdf3"}));
  const std::vector<Panel> sheet = family_panels(methods({"explicit_euler", "symplectic_euler", "explicit_midpoint", "implicit_euler"}));
  ASSERT_EQ(sheet.size(), 3u);
  EXPECT_EQ(sheet[0].solvers, (std::vector<std::string>{"explicit_euler", "explicit_midpoint"}));
  EXPECT_EQ(sheet[2].solvers, (std::vector<std::string>{"implicit_euler"}));
  const auto not_euler = [](std::size_t m) { return name(m) != "explicit_euler"; };
  const std::vector<Panel> some = family_panels(methods({"explicit_euler", "rk4", "adams_bashforth2"}), not_euler);
  ASSERT_EQ(some.size(), 2u);
  EXPECT_EQ(some[0].solvers, (std::vector<std::string>{"rk4"}));
  EXPECT_EQ(some[1].solvers, (std::vector<std::string>{"adams_bashforth2"}));
  EXPECT_TRUE(family_panels(methods({"explicit_euler"}), not_euler).empty());
}

}  // namespace
}  // namespace steplab
