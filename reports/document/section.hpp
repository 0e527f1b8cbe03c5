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
#include <string_view>
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
  std::string name = {};  // a second figure of one script: its own name (fig<n>_<name>), else the script's
  const std::string& key() const { return name.empty() ? script : name; }
};

// A panel per family of the report (kReportFamilies), each with its members among `methods` that
// `drawn` accepts (a method with data in this figure), by order. A family whose panel would draw
// only methods an earlier panel draws is left out: explicit Euler opens the Adams-Bashforth family
// as well, and alone there it would be drawn twice.
std::vector<Panel> family_panels(const std::vector<std::size_t>& methods,
                                 const std::function<bool(std::size_t)>& drawn = nullptr);
// Panels of at most six curves over fixed-step methods and adaptive solvers, those `drawn`
// accepts: the explicit Runge-Kutta and Adams-Bashforth methods, the symplectic splittings, the
// implicit methods, the explicit adaptive solvers, the implicit ones (a group of more than six
// split in order).
std::vector<Panel> solver_panels(const std::vector<std::size_t>& methods, const std::vector<std::string>& adaptive,
                                 const std::function<bool(std::string_view)>& drawn);

// What a section's Markdown may use: the shared data and findings, and the figure numbering.
// The report draws every figure its sections list (Section::figures), numbered in that order:
// figure n goes to figures/fig<n>_<script>.<ext>. The Markdown shows them in that order too,
// numbered as shown: the atlas shows every one, the hand-out (`handout`) only those of its
// sections, so its numbers are its own (`shown`, found by a first rendering).
class Page {
 public:
  Page(const ReportData& d, const Findings& f, std::string ext, std::vector<std::string> figures)
      : data(d), findings(f), ext_(std::move(ext)), files_(figures), shown_(std::move(figures)) {}
  Page(const ReportData& d, const Findings& f, std::string ext, std::vector<std::string> figures, std::vector<std::string> shown)
      : data(d), findings(f), handout(true), ext_(std::move(ext)), files_(std::move(figures)), shown_(std::move(shown)) {}
  const ReportData& data;
  const Findings& findings;
  // The hand-out (report.pdf and report.md): a section shows its figures for the sheet's methods,
  // and leaves the rest to the atlas.
  const bool handout = false;
  // Where the findings a section states are recorded (reports/document/claims.hpp): set while the
  // report's Markdown is rendered for data/claims.json, null otherwise.
  Ledger* ledger = nullptr;
  // The methods on springs on the sheet's spring (Report::springs), where the report measured them.
  const ReportData* springs = nullptr;
  const Findings* springs_findings = nullptr;
  // ![caption](figures/fig<n>_<script>.<ext>): numbered "Figure k:" in the Markdown (k its place
  // among those shown); LaTeX numbers the PDF's alike. std::logic_error if `script` is not the
  // next figure of the order shown.
  std::string figure(const std::string& script, const std::string& caption);
  // Whether this Markdown shows the figure, and its number (0: it does not): for a sentence that
  // points to a figure of another section, before or after.
  bool has(const std::string& script) const { return number(script) > 0; }
  int number(const std::string& script) const;
  // The figures shown so far, in order.
  const std::vector<std::string>& shown() const { return seen_; }
  // The atlas's address of a section, for the hand-out's links: atlas.html#<its title's anchor>.
  static std::string atlas_link(const std::string& title);

 private:
  std::string ext_;
  std::vector<std::string> files_, shown_, seen_;
  bool collecting_ = false;
  friend std::string report_markdown(const Report&, const std::string&, const std::string&, Ledger*, bool);
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

// How the hand-out shows a section of the full report (sections.hpp): whole, brief (its answer
// and a link to the atlas), or not at all (the atlas alone has it).
enum class Handout { Whole, Brief, Atlas };

class Section {
 public:
  virtual ~Section() = default;
  // Its name in the section list (sections.hpp): its data go to data/<id>/.
  std::string id;
  Handout handout = Handout::Whole;
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
  // The hand-out's brief version: its heading, its answer (by default none) and a link to it in the atlas.
  virtual std::string brief(Page&) const { return brief_markdown(title(), {}); }

 protected:
  // "## <title>\n\n<answer>The study, its tables and figures: the atlas, <title>."
  static std::string brief_markdown(const std::string& title, const std::string& answer);
};

// The sections by name, in the report's order (reports/document/sections/sections.cpp): those
// named in `chosen` (names from section_names()); the full report's (its default) and the hand-in's
// (`--sheet`) are two choices of them.
std::vector<std::unique_ptr<Section>> report_sections(const std::vector<std::string>& chosen);
std::vector<std::string> section_names();
std::vector<std::string> full_report_sections();


}  // namespace steplab
