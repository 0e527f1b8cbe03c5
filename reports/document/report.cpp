// The report's frame (reports/document/report.hpp): the sections of reports/document/sections/ run
// and rendered in order into Markdown; write_report.cpp draws the figures, makes the atlas and the
// PDF, and swaps the output folder in atomically.
#include "reports/document/report.hpp"

#include <cctype>
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
#include "analysis/peers/peers.hpp"
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
  const auto it = std::find(shown_.begin(), shown_.end(), script);
  return it == shown_.end() ? 0 : static_cast<int>(it - shown_.begin()) + 1;
}

std::string Page::figure(const std::string& script, const std::string& caption) {
  if (collecting_) {  // the hand-out's first rendering: which figures it shows
    seen_.push_back(script);
    return {};
  }
  const std::size_t k = seen_.size();
  if (k >= shown_.size() || shown_[k] != script)
    throw std::logic_error("the report's Markdown shows " + script + " out of the order its sections list their figures");
  seen_.push_back(script);
  const auto file = std::find(files_.begin(), files_.end(), script);
  if (file == files_.end()) throw std::logic_error("the report draws no figure " + script);
  const std::string label = ext_ == "pdf" ? caption : fmt::format("Figure {}: {}", k + 1, caption);
  return fmt::format("![{}](figures/{}.{})\n\n", label, figure_file(static_cast<int>(file - files_.begin()) + 1, script), ext_);
}

// Pandoc's identifier of a heading (its manual, "Extension: auto_identifiers"): letters, digits,
// '_', '-' and '.' kept, spaces to hyphens, lower case, nothing before the first letter.
std::string Page::atlas_link(const std::string& title) {
  std::string id;
  for (char ch : title) {
    const unsigned char u = static_cast<unsigned char>(ch);
    if (std::isalnum(u) || ch == '_' || ch == '-' || ch == '.' || u >= 0x80) id += static_cast<char>(std::tolower(u));
    else if (ch == ' ' || ch == '\n') id += '-';
  }
  const auto first = std::find_if(id.begin(), id.end(), [](char ch) { return std::isalpha(static_cast<unsigned char>(ch)) || (ch & 0x80); });
  return "atlas.html#" + std::string(first, id.end());
}

std::string Section::brief_markdown(const std::string& title, const std::string& answer) {
  const std::string paragraph = without_final_newlines(answer);  // a paragraph of its own, however the answer ends
  return fmt::format("## {}\n\n{}The study, its tables and figures: [the atlas, {}]({}).\n\n", title,
                     paragraph.empty() ? "" : paragraph + "\n\n", title, Page::atlas_link(title));
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

std::vector<Panel> solver_panels(const std::vector<std::size_t>& methods, const std::vector<std::string>& adaptive,
                                 const std::function<bool(std::string_view)>& drawn) {
  Panel explicit_{"explicit Runge-Kutta and Adams-Bashforth", {}}, splitting{"symplectic splitting", {}},
      implicit_{"implicit methods", {}}, explicit_adaptive{"explicit adaptive solvers", {}},
      implicit_adaptive{"implicit adaptive solvers", {}};
  for (std::size_t m : methods)
    if (drawn(name(m)))
      (method_info(m).implicit ? implicit_ : method_info(m).family == Family::Splitting ? splitting : explicit_)
          .solvers.push_back(name(m));
  for (const std::string& a : adaptive) {
    const PeerInfo* p = find_peer(a);
    if (drawn(a)) (p && p->implicit ? implicit_adaptive : explicit_adaptive).solvers.push_back(a);
  }
  std::vector<Panel> out;
  for (Panel* p : {&explicit_, &splitting, &implicit_, &explicit_adaptive, &implicit_adaptive}) {
    // a group of more than six (a config's longer list) in panels of at most six, "(1 of 2)" ...
    const std::size_t n = p->solvers.size(), parts = (n + 5) / 6;
    for (std::size_t k = 0; k < parts; ++k) {
      Panel part{parts > 1 ? fmt::format("{} ({} of {})", p->title, k + 1, parts) : p->title, {}};
      for (std::size_t i = k * n / parts; i < (k + 1) * n / parts; ++i) part.solvers.push_back(p->solvers[i]);
      out.push_back(std::move(part));
    }
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
    for (const FigureSpec& f : s->figures(r.data)) out.push_back(f.key());
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

std::string report_markdown(const Report& r, const std::string& ext, const std::string& footer, Ledger* ledger, bool handout) {
  const ReportConfig& c = r.data.config;
  std::string md = c.hand_in() ? "# Time integration: the exercise's hand-in, measured by steplab\n\n"
                       : "# steplab report: how time integrators behave, family by family, on the course's scenes\n\n";
  if (c.covers(c.oscillator.scene)) md += fmt::format("The hanging spring: {}. ", params_text(c.oscillator.scene, c.oscillator.params));
  md += "Every number below was measured by the commands at the end of this report. data/claims.json lists the findings the "
        "text states with their rules and the values they rest on (tools/verify_claims.py re-checks them), and marks the "
        "sentences of theory.";
  handout = handout && !c.hand_in();
  if (handout)
    md += " This hand-out answers the sheet; the atlas beside it, [atlas.html](atlas.html), holds every study, table and figure.";
  md += "\n\n";
  const std::vector<std::string> files = figure_order(r);
  const auto sections = [&](Page& page) {
    std::string out;
    for (const auto& s : r.sections)
      if (!page.handout || s->handout == Handout::Whole) out += s->markdown(page);
      else if (s->handout == Handout::Brief) out += s->brief(page);
    return out;
  };
  const auto with = [&](Page& page) -> Page& {
    if (r.springs) page.springs = &*r.springs, page.springs_findings = &*r.springs_findings;
    return page;
  };
  if (!handout) {
    Page page(r.data, r.findings, ext, files);
    page.ledger = ledger;
    md += sections(with(page));
  } else {
    Page first(r.data, r.findings, ext, files, files);  // which figures the hand-out shows, in order
    first.collecting_ = true;
    sections(with(first));
    Page page(r.data, r.findings, ext, files, first.shown());
    page.ledger = ledger;
    md += sections(with(page));
  }
  return md + "---\n\n" + footer + "\n";
}

}  // namespace steplab
