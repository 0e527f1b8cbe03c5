// A report of chosen methods and sections (ReportConfig::methods, ::sections): the numbers of a
// chosen method are the full report's, whatever it is chosen with; the sections not chosen are
// not written and the studies only they need do not run.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <string>
#include <vector>

#include "analysis/kernel/kernel.hpp"
#include "reports/data/inputs.hpp"
#include "reports/document/report.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"
#include "cli_helpers.hpp"
#include "small_report.hpp"

namespace steplab {
namespace {

ReportConfig chosen(const std::vector<std::string>& methods, const std::vector<std::string>& sections) {
  ReportConfig c = small_config();
  choose_methods(c, methods, "methods");
  choose_sections(c, sections, "sections");
  return c;
}

std::size_t method(std::string_view name) { return *find_method(name); }

std::size_t position(const ReportData& d, std::size_t m) {
  for (std::size_t i = 0; i < d.methods.size(); ++i)
    if (d.methods[i] == m) return i;
  throw std::logic_error("method not in the report");
}

// Method m's numbers in two reports: its fitted orders on every scene, its thresholds, its
// findings. Equal to the bit: the same runs, whichever methods run beside them.
void expect_same_numbers(const ReportData& a, const Findings& fa, const ReportData& b, const Findings& fb, std::size_t m) {
  const std::string n(method_info(m).name);
  const std::size_t i = position(a, m), j = position(b, m);
  ASSERT_EQ(a.convergence.size(), b.convergence.size());
  for (std::size_t s = 0; s < a.convergence.size(); ++s) {
    const OrderFit &x = a.convergence[s].fits[i].fit, &y = b.convergence[s].fits[j].fit;
    EXPECT_EQ(x.order, y.order) << n;
    EXPECT_EQ(x.bound_lo, y.bound_lo) << n;
    EXPECT_EQ(x.bound_hi, y.bound_hi) << n;
    EXPECT_EQ(x.local_slopes, y.local_slopes) << n;
  }
  for (const double damping : a.config.stability.threshold_dampings) {
    const ThresholdRow* ra = find_threshold(a, m, damping);
    const ThresholdRow* rb = find_threshold(b, m, damping);
    ASSERT_TRUE(ra && rb) << n << " at damping " << damping;
    EXPECT_EQ(ra->dt_measured, rb->dt_measured) << n;
    EXPECT_EQ(ra->dt_theory, rb->dt_theory) << n;
  }
  EXPECT_EQ(fa.rows[i].stable_large_dt, fb.rows[j].stable_large_dt) << n;
  EXPECT_EQ(fa.rows[i].stable_undamped, fb.rows[j].stable_undamped) << n;
  EXPECT_EQ(fa.rows[i].energy_rate_large_dt, fb.rows[j].energy_rate_large_dt) << n;
}

TEST(ReportChoice, AChosenMethodHasTheFullReportsNumbers) {
  ReportConfig all = small_config();
  all.sections = {"summary", "convergence"};  // every method; the findings' studies
  const Report full = build_report(all);
  const Report sheet = build_report(chosen({"explicit_euler", "symplectic_euler", "explicit_midpoint", "implicit_euler", "analytic"},
                                           {"summary", "convergence"}));
  const Report other = build_report(chosen({"rk4", "implicit_euler", "bdf2"}, {"summary", "convergence"}));
  for (const char* m : {"explicit_euler", "symplectic_euler", "explicit_midpoint", "implicit_euler", "analytic"})
    expect_same_numbers(sheet.data, sheet.findings, full.data, full.findings, method(m));
  for (const char* m : {"rk4", "implicit_euler", "bdf2"}) expect_same_numbers(other.data, other.findings, full.data, full.findings, method(m));
  EXPECT_EQ(sheet.findings.rows.size(), 5u);
}

TEST(ReportChoice, OnlyTheChosenSectionsAndMethodsAreWritten) {
  const Report r = build_report(chosen({"rk4", "explicit_euler"}, {"reproduce", "convergence"}));
  EXPECT_EQ(r.data.studies, unsigned{kConvergenceStudy});  // no stability, collision, work-precision or figure runs
  EXPECT_TRUE(r.data.thresholds.empty());
  EXPECT_TRUE(r.data.collision.bounce.empty());
  EXPECT_TRUE(r.data.cannon.empty());
  const std::string md = report_markdown(r, "png", "");
  EXPECT_NE(md.find("## Convergence"), std::string::npos);
  EXPECT_LT(md.find("## Convergence"), md.find("## Reproduce"));  // the report's order, not the list's
  for (const char* absent : {"## Summary", "## Stability", "## Cost", "## Collision", "## As the system grows"})
    EXPECT_EQ(md.find(absent), std::string::npos) << absent;
  for (std::size_t m = 0; m < method_count(); ++m) {  // every other method's name, as the report quotes one
    const std::string quoted = fmt::format("`{}`", method_info(m).name);
    const bool in = m == method("rk4") || m == method("explicit_euler");
    EXPECT_EQ(md.find(quoted) != std::string::npos, in) << quoted;
  }
  EXPECT_NE(md.find("study convergence --scene spring"), std::string::npos);
  EXPECT_NE(md.find("M=explicit_euler,rk4\n"), std::string::npos);  // the commands reproduce this report's methods
  EXPECT_NE(md.find("--methods $M"), std::string::npos);
  EXPECT_EQ(md.find("study collision"), std::string::npos);
}

// The Reproduce section names a long method list once, as M=... broken over lines with a
// backslash: the shell reads back the list whole, as printed.
TEST(ReportChoice, ReproducesItsMethodListThroughTheShell) {
  std::vector<std::string> names;
  for (std::size_t m = 0; m < method_count(); ++m)
    if (!method_info(m).on_springs) names.emplace_back(method_info(m).name);
  ReportConfig c = small_config();
  choose_methods(c, names, "methods");
  c.sections = {"reproduce"};
  const std::string md = markdown(c);
  // N (without the exact flow) first, then M as $N and the exact flow where it is last; or M, N:
  // the lines from the first assignment to the first that neither assigns nor continues one.
  const std::size_t from = std::min(md.find("\nM="), md.find("\nN=")) + 1;
  ASSERT_NE(from, 0u) << md;
  std::size_t to = from;
  for (std::size_t nl; (nl = md.find('\n', to)) != std::string::npos; to = nl + 1) {
    const std::string line = md.substr(to, nl - to), before = to > from ? md.substr(0, to - 1) : std::string();
    if (line.rfind("M=", 0) != 0 && line.rfind("N=", 0) != 0 && (before.empty() || before.back() != '\\')) break;
  }
  const std::string assignment = md.substr(from, to - from);
  EXPECT_NE(assignment.find("\\\n"), std::string::npos) << assignment;  // broken for the page
  for (std::size_t at = 0, nl; (nl = assignment.find('\n', at)) != std::string::npos; at = nl + 1)
    EXPECT_LE(nl - at, kCodeColumns + 1) << assignment;  // the code a line of the PDF holds, and the backslash
  const Result r = run_shell("bash -c '" + assignment + "printf %s \"$M\"'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, fmt::format("{}", fmt::join(names, ","))) << assignment;
}

// A Reproduce command whose list is longer than a line (the stiffness sweep's) is broken after a
// comma inside the word: every line fits the page, and the shell reads the words back as written.
TEST(ReportChoice, ALongListInACommandIsBrokenWhereTheShellJoinsIt) {
  std::string list;
  for (int k = 0; k < 30; ++k) list += fmt::format("{}1e+{}", k ? "," : "", k);
  const std::string cmd = "build/steplab study convergence --scene target --points 9 --sweep stiffness=" + list + " --methods $N";
  const std::string out = wrapped(cmd);
  std::size_t lines = 0;
  for (std::size_t at = 0, nl; (nl = out.find('\n', at)) != std::string::npos; at = nl + 1, ++lines)
    EXPECT_LE(nl - at, kCodeColumns + 1) << out;  // the code a line of the PDF holds, and the backslash
  EXPECT_GE(lines, 3u) << out;
  const Result r = run_shell("N=x; printf '%s ' " + out.substr(0, out.size() - 1));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "build/steplab study convergence --scene target --points 9 --sweep stiffness=" + list + " --methods x ") << out;
}

TEST(ReportChoice, AFamilyWithOneChosenMethodClaimsNoTrend) {
  const Report r = build_report(chosen({"rk4", "symplectic_euler", "velocity_verlet"}, {"families"}));
  const std::string md = report_markdown(r, "png", "");
  EXPECT_NE(md.find("No trend is read where the report has one method of a family: explicit Runge-Kutta (`rk4`)"), std::string::npos)
      << md;
  EXPECT_NE(md.find("| symplectic splitting |"), std::string::npos) << md;  // a row of the trend table
  EXPECT_EQ(md.find("| explicit Runge-Kutta |"), std::string::npos) << md;
}

TEST(ReportChoice, ACrossoverNeedsBothKinds) {  // no explicit method chosen: no claim that implicit pays
  ReportConfig c = chosen({"implicit_euler", "bdf2"}, {"scaling"});
  c.scaling_t_end = 0.5;
  const std::string md = report_markdown(build_report(c), "png", "");
  EXPECT_NE(md.find("This report has no explicit fixed-step method here, so where implicit pays is not read."), std::string::npos)
      << md;
  EXPECT_EQ(md.find("cheaper than every explicit"), std::string::npos);
  EXPECT_EQ(md.find("At none of these sizes"), std::string::npos);
}

TEST(ReportChoice, NamesInTheReportsOrderAndRefused) {
  ReportConfig c = small_config();
  choose_sections(c, {"reproduce", "summary"}, "sections");
  EXPECT_EQ(c.sections, (std::vector<std::string>{"summary", "reproduce"}));
  choose_methods(c, {"rk4", "euler"}, "methods");  // an old name, and the table's order
  EXPECT_EQ(c.methods, (std::vector<std::size_t>{method("explicit_euler"), method("rk4")}));
  EXPECT_EQ(default_report_config().sections, full_report_sections());
  EXPECT_EQ(default_report_config().covered, default_report_config().own_scenes());
  EXPECT_EQ(default_report_config().methods.size(), ode_methods().size() + 1);  // and the exact flow
  for (const std::vector<std::string>& bad :
       std::vector<std::vector<std::string>>{{}, {"rk4", "rk4"}, {"heun"}, {"analytic"}, {"xpbd"}, {"rk4", "baraff_witkin"}})
    EXPECT_THROW(choose_methods(c, bad, "methods"), UsageError);
  EXPECT_THROW(choose_sections(c, {"appendix"}, "sections"), UsageError);
  const ReportConfig back = report_config_from_json(report_config_json(chosen({"rk4"}, {"summary"})));
  EXPECT_EQ(back.methods, std::vector<std::size_t>{method("rk4")});
  EXPECT_EQ(back.sections, std::vector<std::string>{"summary"});
}

}  // namespace
}  // namespace steplab
