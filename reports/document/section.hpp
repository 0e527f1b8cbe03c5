// A report section: one unit with its own studies (beyond the shared ones in ReportData), its
// findings, its data files, its figures and its Markdown. The report is the list of sections in
// reports/document/sections/sections.hpp; adding a section is one file in reports/document/sections/ plus one line
// there (and, if it draws a figure, its gnuplot script in reports/document/gnuplot/, which stays a plain
// script a reader can rerun on the report's data/).
#pragma once

#include <filesystem>
#include <functional>
#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

#include "reports/document/report.hpp"

namespace steplab {
class Ledger;
}

namespace steplab {

// The report's data/ folder.
class DataDir {
 public:
  explicit DataDir(std::filesystem::path dir) : dir_(std::move(dir)) {}
  void write(const std::string& file, const std::string& content) const;

 private:
  std::filesystem::path dir_;
};

// A panel of a figure: its title and the solvers it draws (method or peer names).
struct Panel {
  std::string title;
  std::vector<std::string> solvers;
};

// A figure a section draws: reports/document/gnuplot/<script>.gp, with gnuplot variables of its own
// (`name='value'; ...`) beside the ones every script gets (datadir, outfile, format, methods, ...),
// and its panels, given to the script as npanel, panel1 .. (the solvers, space-separated) and
// ptitle1 .. (the titles). A section gives a panel only solvers with data to draw: gnuplot stops
// on a plot with no point.
struct FigureSpec {
  std::string script;
  std::string vars;
  std::vector<Panel> panels;
};

// A panel per family of the report (kReportFamilies), each with its members among `methods` that
// `drawn` accepts (a method with data in this figure), by order. A family whose panel would draw
// only methods an earlier panel draws is left out: explicit Euler opens the Adams-Bashforth family
// as well, and alone there it would be drawn twice.
std::vector<Panel> family_panels(const std::vector<std::size_t>& methods,
                                 const std::function<bool(std::size_t)>& drawn = nullptr);

// What a section's Markdown may use: the shared data and findings, and the figure numbering.
// The report's figures are numbered in the order the sections list them (Section::figures), the
// order the Markdown must show them in: figure n is drawn into figures/fig<n>_<script>.<ext>.
class Page {
 public:
  Page(const ReportData& d, const Findings& f, std::string ext, std::vector<std::string> figures)
      : data(d), findings(f), ext_(std::move(ext)), order_(std::move(figures)) {}
  const ReportData& data;
  const Findings& findings;
  // Where the findings a section states are recorded (reports/document/claims.hpp): set while the
  // report's Markdown is rendered for data/claims.json, null otherwise.
  Ledger* ledger = nullptr;
  // The methods on springs on the sheet's spring (Report::springs), where the report measured them.
  const ReportData* springs = nullptr;
  const Findings* springs_findings = nullptr;
  // ![caption](figures/fig<n>_<script>.<ext>): numbered "Figure n:" in the Markdown; LaTeX numbers
  // the PDF's alike. std::logic_error if `script` is not the next figure of the report's order.
  std::string figure(const std::string& script, const std::string& caption);
  // Whether the report draws this figure, and its number (0: it does not): for a sentence that
  // points to a figure of another section, before or after.
  bool has(const std::string& script) const { return number(script) > 0; }
  int number(const std::string& script) const;
  int next_figure() const { return figure_ + 1; }

 private:
  std::string ext_;
  std::vector<std::string> order_;
  int figure_ = 0;
};

// figures/fig<n>_<script>: the file a figure is drawn into.
std::string figure_file(int number, const std::string& script);

// A section's `missing()` for the scenes it needs: "" if the config covers each of them, else
// "it needs `bounce` and `falling`, not among the chosen scenes".
std::string uncovered(const ReportConfig& c, std::initializer_list<std::size_t> scenes);
// The same for the shared studies in `studies` (ReportStudy bits): stability and work-precision
// need the spring, the collision study its two scenes, the scenes' figures one of the cannon ball
// and the spring, convergence one scene it converges on (ReportConfig::convergence_scenes).
std::string uncovered_for(const ReportConfig& c, unsigned studies);

class Section {
 public:
  virtual ~Section() = default;
  // Its name in the section list (sections.hpp): its data go to data/<id>/.
  std::string id;
  // The shared studies it reads (ReportStudy bits): the report runs those of its chosen sections.
  virtual unsigned needs() const { return 0; }
  // Why it cannot be made from the config's choice (a scene it needs is not covered), or "": the
  // report then shows one line in its place, "*Left out: <title> (<reason>).*", and runs nothing for it.
  // By default the scenes its shared studies need (uncovered_for); a section with studies of its
  // own says what they need.
  virtual std::string missing(const ReportConfig& c) const { return uncovered_for(c, needs()); }
  virtual std::string title() const = 0;
  virtual void study(const ReportData&) {}                                    // its own studies
  virtual void write_data(const ReportData&, const DataDir&) const {}         // its data files
  virtual std::vector<FigureSpec> figures(const ReportData&) const { return {}; }
  virtual std::string markdown(Page& page) const = 0;
};

// The sections by name, in the report's order (reports/document/sections/sections.cpp): those
// named in `chosen` (names from section_names()); the full report's (its default) and the hand-in's
// (`--sheet`) are two choices of them.
std::vector<std::unique_ptr<Section>> report_sections(const std::vector<std::string>& chosen);
std::vector<std::string> section_names();
std::vector<std::string> full_report_sections();


}  // namespace steplab
