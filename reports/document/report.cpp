// The report's frame (reports/document/report.hpp): the sections of reports/document/sections/ run
// and rendered in order into Markdown; write_report.cpp draws the figures, makes the atlas and the
// PDF, and swaps the output folder in atomically.
#include "reports/document/report.hpp"

#include <cmath>
#include <cstdio>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <vector>

#include <fmt/format.h>

#include "analysis/kernel/parallel.hpp"
#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/defaults.hpp"
#include "reports/document/claims.hpp"
#include "reports/document/figure_styles.hpp"
#include "reports/data/output.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"

namespace steplab {
namespace fs = std::filesystem;

void DataDir::write(const std::string& file, const std::string& content) const {
  std::ofstream out(dir_ / file, std::ios::binary);
  out << content;
  if (!out) throw std::runtime_error("cannot write " + (dir_ / file).string());
}

std::string figure_file(int number, const std::string& script) { return fmt::format("fig{}_{}", number, script); }

int Page::number(const std::string& script) const {
  const auto it = std::find(order_.begin(), order_.end(), script);
  return it == order_.end() ? 0 : static_cast<int>(it - order_.begin()) + 1;
}

std::string Page::figure(const std::string& script, const std::string& caption) {
  if (static_cast<std::size_t>(figure_) >= order_.size() || order_[static_cast<std::size_t>(figure_)] != script)
    throw std::logic_error("the report's Markdown shows " + script + " out of the order its sections list their figures");
  ++figure_;
  const std::string label = ext_ == "pdf" ? caption : fmt::format("Figure {}: {}", figure_, caption);
  return fmt::format("![{}](figures/{}.{})\n\n", label, figure_file(figure_, script), ext_);
}

std::vector<Panel> family_panels(const std::vector<std::size_t>& methods, const std::function<bool(std::size_t)>& drawn) {
  std::vector<Panel> out;
  std::vector<std::size_t> shown;
  for (Family f : kReportFamilies) {
    Panel p{std::string(to_string(f)), {}};
    bool adds = false;
    for (std::size_t m : family_members(methods, f)) {
      if (drawn && !drawn(m)) continue;
      p.solvers.push_back(name(m));
      adds |= std::find(shown.begin(), shown.end(), m) == shown.end();
      shown.push_back(m);
    }
    if (adds) out.push_back(std::move(p));
  }
  return out;
}

std::string uncovered(const ReportConfig& c, std::initializer_list<std::size_t> scenes) {
  std::vector<std::string> missing;
  for (std::size_t s : scenes)
    if (!c.covers(s)) missing.push_back(fmt::format("`{}`", scene_name(s)));
  if (missing.empty()) return {};
  return fmt::format("it needs {}, not among the chosen scenes", and_list(missing));
}

std::string uncovered_for(const ReportConfig& c, unsigned studies) {
  std::string why;
  if (studies & (kStabilityStudy | kWorkPrecisionStudy)) why = uncovered(c, {c.oscillator.scene});
  if (why.empty() && (studies & kStiffOrderStudy)) why = uncovered(c, {c.stiffened.scene});
  if (why.empty() && (studies & kCollisionStudy)) why = uncovered(c, {c.rebound.scene, c.body.scene});
  if (why.empty() && (studies & kSceneFigures) && !c.covers(c.oscillator.scene) && !c.covers(c.projectile.scene))
    why = uncovered(c, {c.projectile.scene, c.oscillator.scene});
  if (why.empty() && (studies & kLongTimeStudy)) {  // the swinging spring at least (the hand-in's); the orbit where covered
    const auto swing = find_scene(kLongTimeSheetScene);
    if (swing) why = uncovered(c, {*swing});
  }
  if (why.empty() && (studies & kConvergenceStudy) && c.convergence_scenes().empty())
    why = "none of the chosen scenes is one it converges on (a scene with an exact solution, or one of yours)";
  return why;
}

namespace {

// A section the config's choice leaves out (Section::missing): one line in its place.
class LeftOut : public Section {
 public:
  LeftOut(std::string title, std::string why) : title_(std::move(title)), why_(std::move(why)) {}
  std::string title() const override { return title_; }
  std::string markdown(Page&) const override { return fmt::format("*Left out: {} ({}).*\n\n", title_, why_); }

 private:
  std::string title_, why_;
};

}  // namespace

Report::Report() = default;
Report::Report(Report&&) noexcept = default;
Report::~Report() = default;

std::vector<std::string> figure_order(const Report& r) {
  std::vector<std::string> out;
  for (const auto& s : r.sections)
    for (const FigureSpec& f : s->figures(r.data)) out.push_back(f.script);
  return out;
}

Report build_report(const ReportConfig& config, ProgressHook progress) {
  Report r;
  for (std::unique_ptr<Section>& s : report_sections(config.sections)) {
    const std::string why = s->missing(config);
    if (!why.empty()) {
      std::unique_ptr<Section> left = std::make_unique<LeftOut>(s->title(), why);
      left->id = s->id;
      s = std::move(left);
    }
    r.sections.push_back(std::move(s));
  }
  unsigned studies = 0;
  for (const auto& s : r.sections) studies |= s->needs();
  r.data = run_report_studies(config, studies, progress);
  if ((studies & kFindings) == kFindings) {
    r.findings = compute_findings(r.data);
    if (config.has_section("frames")) {
      ReportConfig c = config;
      c.methods.clear();
      for (std::size_t m = 0; m < method_count(); ++m)
        if (method_info(m).on_springs && applies(m, c.oscillator.scene)) c.methods.push_back(m);
      c.covered = {c.oscillator.scene};
      if (!c.methods.empty()) {
        r.springs = run_report_studies(c, kFindings, progress);
        r.springs_findings = compute_findings(*r.springs);
      }
    }
  }
  for (const auto& s : r.sections) s->study(r.data);
  return r;
}

std::string report_markdown(const Report& r, const std::string& ext, const std::string& footer, Ledger* ledger) {
  std::string md = r.data.config.has_section("sheet")
                       ? "# Time integration: the exercise's hand-in, measured by steplab\n\n"
                       : "# steplab report: how time integrators behave, family by family, on the course's scenes\n\n";
  const ReportScene& spring = r.data.config.oscillator;
  if (r.data.config.covers(spring.scene)) md += fmt::format("The hanging spring: {}. ", params_text(spring.scene, spring.params));
  md += "Every number below was measured by the commands at the end of this report. data/claims.json lists the findings the "
        "text states with their rules and the values they rest on (tools/verify_claims.py re-checks them), and marks the "
        "sentences of theory.\n\n";
  Page page(r.data, r.findings, ext, figure_order(r));
  page.ledger = ledger;
  if (r.springs) page.springs = &*r.springs, page.springs_findings = &*r.springs_findings;
  for (const auto& s : r.sections) md += s->markdown(page);
  return md + "---\n\n" + footer + "\n";
}

}  // namespace steplab
