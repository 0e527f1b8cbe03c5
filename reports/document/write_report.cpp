// Writing a report to its folder: the studies' data, each figure drawn by its gnuplot script (PNG,
// SVG, PDF), report.md, the atlas and the PDF made by pandoc, all in a staging folder swapped in
// whole at the end (report.cpp builds the report and its Markdown).
#include "reports/document/report.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/utsname.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "analysis/kernel/parallel.hpp"
#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/defaults.hpp"
#include "reports/document/claims.hpp"
#include "reports/document/figure_styles.hpp"
#include "reports/document/gnuplot_scripts.hpp"
#include "reports/data/output.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"

namespace steplab {
namespace fs = std::filesystem;

namespace {

// The panels as gnuplot variables: npanel, panel1 .., ptitle1 ..
std::string panel_vars(const std::vector<Panel>& panels) {
  std::string out = fmt::format("npanel={}; ", panels.size());
  for (std::size_t i = 0; i < panels.size(); ++i)
    out += fmt::format("panel{}='{}'; ptitle{}='{}'; ", i + 1, fmt::join(panels[i].solvers, " "), i + 1, panels[i].title);
  return out;
}



// Runs `sh -c cmd` with its output (stdout and stderr) written to `log`, and returns its exit
// status. Not std::system: that ignores SIGINT in the caller while the child runs, and an
// interrupt must not be lost.
int run_tool(const std::string& cmd, const fs::path& log = "/dev/null") {
  posix_spawn_file_actions_t io;
  posix_spawn_file_actions_init(&io);
  posix_spawn_file_actions_addopen(&io, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&io, STDOUT_FILENO, STDERR_FILENO);
  const std::string full = cmd;
  const char* argv[] = {"/bin/sh", "-c", full.c_str(), nullptr};
  pid_t pid = 0;
  const int err = posix_spawn(&pid, "/bin/sh", &io, nullptr, const_cast<char* const*>(argv), environ);
  posix_spawn_file_actions_destroy(&io);
  if (err != 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (stop_requested) throw Interrupted();
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// What a tool said when it failed: the lines of its log that name an error (gnuplot's "line N:"
// and its caret line, LaTeX's "!" lines), or else its last lines; at most eight, indented.
std::string tool_errors(const fs::path& log) {
  std::ifstream in(log);
  std::vector<std::string> all, errors;
  for (std::string line; std::getline(in, line);) {
    if (line.empty()) continue;
    all.push_back(line);
    if (line.find("line ") != std::string::npos || line.rfind("!", 0) == 0 || line.find("rror") != std::string::npos ||
        line.find('^') != std::string::npos)
      errors.push_back(line);
  }
  const std::vector<std::string>& pick = errors.empty() ? all : errors;
  std::string out;
  for (std::size_t i = pick.size() > 8 ? pick.size() - 8 : 0; i < pick.size(); ++i) out += "\n    " + pick[i];
  return out.empty() ? "\n    (it printed nothing)" : out;
}

// A tool that failed while the report was made: the folder it ran in is kept for a look.
struct ToolFailed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Staging folders left by a run that was killed (SIGKILL cannot be handled): removed when the
// process that made them is gone.
void remove_stale_staging(const fs::path& out) {
  const std::string prefix = fmt::format(".{}.staging-", out.filename().string());
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(out.parent_path(), ec)) {
    const std::string n = entry.path().filename().string();
    if (n.rfind(prefix, 0) != 0) continue;
    const pid_t pid = static_cast<pid_t>(std::atol(n.c_str() + prefix.size()));
    if (pid > 0 && kill(pid, 0) != 0 && errno == ESRCH) fs::remove_all(entry.path(), ec);
  }
}

extern "C" void on_interrupt(int) { stop_requested = true; }

std::string machine_footer() {
  std::string cpu = "unknown CPU";
  std::ifstream info("/proc/cpuinfo");
  for (std::string line; std::getline(info, line);)
    if (line.rfind("model name", 0) == 0) {
      cpu = line.substr(line.find(':') + 2);
      break;
    }
  utsname u{};
  uname(&u);
  const std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  return fmt::format("steplab {} · {} ({} cores) · {} {} · compiler {} · {}", STEPLAB_VERSION, cpu, sysconf(_SC_NPROCESSORS_ONLN),
                     u.sysname, u.release, __VERSION__, date);
}

// What decides whether a report is up to date: the configuration and this very binary.
std::string stamp_for(const ReportConfig& c) {
  char exe[4096] = {};
  const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
  struct stat bin {};
  if (n > 0) stat(exe, &bin);
  return fmt::format("{}\nbinary {} {} {}\n", report_config_json(c).dump(), STEPLAB_VERSION, bin.st_size,
                     static_cast<long long>(bin.st_mtime));
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// pandoc in the staging folder, making `made` from `input` (then removed) with `options`; where
// it fails, ToolFailed, the folder kept for a look.
void run_pandoc(const fs::path& staging, const fs::path& out, const char* input, const char* made, const std::string& options,
                bool keep_input = false) {
  if (run_tool(fmt::format("cd '{}' && pandoc {} -o {} {}", staging.string(), input, made, options), staging / "pandoc.log") != 0)
    throw ToolFailed(fmt::format("pandoc could not make {}:{}\nits input and log are kept in {} (the next report into {} removes "
                                 "them)", made, tool_errors(staging / "pandoc.log"), staging.string(), out.string()));
  if (!keep_input) fs::remove(staging / input);
  fs::remove(staging / "pandoc.log");
}

// The atlas: the whole report as one web page, atlas.html, its figures as SVG beside their
// sections, its formulas as MathML and a table of contents linking each section; it names no file
// outside the report's folder and no network address, so it opens offline. Its Markdown,
// atlas.md, stays beside it (as report.md beside the hand-out's PDF).
void write_atlas(const std::string& markdown, const fs::path& staging, const fs::path& out) {
  write_atomic((staging / "atlas.md").string(), markdown);
  write_atomic((staging / "atlas-style.html").string(),
               "<style>\nbody { max-width: 1180px; font-size: 16px; }\nimg { max-width: 100%; height: auto; }\n"
               "table { font-size: 14px; display: block; overflow-x: auto; }\ncode { white-space: pre-wrap; }\n</style>\n");
  run_pandoc(staging, out, "atlas.md", "atlas.html",
             "--standalone --toc --toc-depth=2 --mathml -H atlas-style.html --metadata pagetitle='steplab atlas'", true);
  fs::remove(staging / "atlas-style.html");
}

}  // namespace

int write_report(const ReportConfig& c, const std::string& out_dir, bool force, ProgressHook progress) {
  // SIGINT and SIGTERM stop the work at the next task or tool; the staging folder is removed
  // and the previous report stays as it was. Installed first, so an early Ctrl-C exits 130 too.
  struct sigaction sa {};
  sa.sa_handler = on_interrupt;
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
  const fs::path out = fs::absolute(out_dir);
  const std::string stamp = stamp_for(c);
  if (!force && fs::exists(out / "data" / "stamp") && slurp(out / "data" / "stamp") == stamp && fs::exists(out / "report.pdf")) {
    std::fprintf(stderr, "steplab: %s is up to date (same configuration, same binary); --force redoes it\n", out.c_str());
    return 0;
  }
  remove_stale_staging(out);
  if (run_tool("command -v gnuplot") != 0 || run_tool("command -v pandoc") != 0 || run_tool("command -v pdflatex") != 0)
    throw std::runtime_error("the report needs gnuplot, pandoc and pdflatex; run: tools/install-deps report");

  const fs::path staging = out.parent_path() / fmt::format(".{}.staging-{}", out.filename().string(), getpid());
  fs::remove_all(staging);
  fs::create_directories(staging / "data");
  fs::create_directories(staging / "figures");
  try {
    const auto t0 = std::chrono::steady_clock::now();
    const Report report = build_report(c, progress);
    const ReportData& d = report.data;
    if (stop_requested) throw Interrupted();
    const double study_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    const DataDir data(staging / "data");
    data.write("config.json", report_config_json(c).dump(1) + "\n");
    for (const auto& s : report.sections) {  // each section's data in a folder of its own
      fs::create_directories(staging / "data" / s->id);
      s->write_data(d, DataDir(staging / "data" / s->id));
      if (fs::is_empty(staging / "data" / s->id)) fs::remove(staging / "data" / s->id);
    }

    // Figures: each script three times, PNG for the Markdown, SVG for the atlas and PDF (vector) for
    // the PDF, by one gnuplot process (a fresh session for each: `reset session` alone in its -e,
    // as gnuplot reads nothing after it on the line); the figures spread over the config's threads.
    const std::string all = method_words(d.methods), numeric = method_words(d.collision.config.methods);
    DataDir(staging / "figures").write("styles.gp", styles_gp());  // loaded by every script
    struct Drawing {
      std::string script, cmd;
    };
    std::vector<Drawing> drawings;
    int number = 0;
    for (const auto& s : report.sections)
      for (const FigureSpec& fig : s->figures(d)) {
        const std::string file = figure_file(++number, fig.key());
        const auto gp = std::find_if(gnuplot_scripts.begin(), gnuplot_scripts.end(), [&](const GnuplotScript& g) { return g.name == fig.script; });
        if (gp == gnuplot_scripts.end()) throw std::logic_error("no gnuplot script " + fig.script);
        DataDir(staging / "figures").write(fig.script + ".gp", std::string(gp->text));
        // What every format shares, after its own outfile and format.
        const std::string vars = fmt::format("methods='{}'; numeric='{}'; springdts='{}'; largedt='{}'; {}{}", all, numeric,
                                             words(c.spring_figure_dts), c.large_dt, panel_vars(fig.panels), fig.vars);
        std::string cmd = "gnuplot", fresh;
        for (const char* fmt_name : {"png", "svg", "pdf"}) {
          cmd += fmt::format("{} -e \"datadir='../data/{}'; outfile='{}.{}'; format='{}'; {}\" '{}.gp'", fresh, s->id, file, fmt_name,
                             fmt_name, vars, fig.script);
          fresh = " -e 'reset session'";
        }
        drawings.push_back({fig.script, cmd});
      }
    // figures/redraw.sh: each figure's command, to redraw it after editing its script
    std::string redraw = "#!/bin/sh\n# Redraws every figure from data/ (run it in figures/ after editing a script).\nset -e\n";
    for (const Drawing& g : drawings) redraw += g.cmd + "\n";
    DataDir(staging / "figures").write("redraw.sh", redraw);
    parallel_for(drawings.size(), Workers{d.workers.threads}, [&](std::size_t i) {
      const Drawing& g = drawings[i];
      const fs::path log = staging / "figures" / fmt::format("{}.{}.log", g.script, i);
      if (run_tool(fmt::format("cd '{}' && {}", (staging / "figures").string(), g.cmd), log) != 0)
        throw ToolFailed(fmt::format("gnuplot failed on {}.gp:{}\nthe script, its data and gnuplot's log are kept in "
                                     "{} (the next report into {} removes them)",
                                     g.script, tool_errors(log), (staging / "figures").string(), out.string()));
      fs::remove(log);
    });
    const std::string footer = machine_footer() + fmt::format(" · studies {:.1f} s", study_seconds);
    std::vector<std::size_t> cited = d.methods;  // the methods the claims may name, with their declared order
    if (report.springs) cited.insert(cited.end(), report.springs->methods.begin(), report.springs->methods.end());
    Ledger ledger(cited);
    // The atlas states every finding; the hand-out some of them again (kept once) and, in its brief
    // sections, none the atlas does not.
    const std::string atlas = report_markdown(report, "svg", footer, &ledger);
    write_atomic((staging / "report.md").string(), report_markdown(report, "png", footer, &ledger, true));
    // The claims, and each data document they cite that no section wrote (the same document:
    // the claims' and the section's come from one function).
    for (const auto& [file, doc] : ledger.documents())
      if (!fs::exists(staging / "data" / file)) {
        fs::create_directories((staging / "data" / file).parent_path());
        data.write(file, doc.dump(1) + "\n");
      }
    data.write("claims.json", ledger.json().dump(1) + "\n");
    write_atlas(atlas, staging, out);
    write_atomic((staging / "report-pdf.md").string(), report_markdown(report, "pdf", footer, nullptr, true));
    // Each figure in the section that cites it: no float passes the next section's heading (a
    // \FloatBarrier, placeins', before each; the sections are LaTeX's subsections under the title),
    // and no heading ends a page (five lines kept below it, needspace);
    // a figure may fill up to 90 % of a text page, so that a large one sits among the text rather
    // than alone on a half-empty float page.
    run_pandoc(staging, out, "report-pdf.md", "report.pdf",
               "--pdf-engine=pdflatex -V papersize=a4 -V geometry:margin=1.5cm -V fontsize=10pt -V colorlinks=true "
               "-V 'header-includes=\\usepackage{float}\\floatplacement{figure}{!htbp}\\usepackage{placeins}\\usepackage{needspace}"
               "\\let\\plainsubsection\\subsection"
               "\\renewcommand{\\subsection}{\\FloatBarrier\\needspace{5\\baselineskip}\\plainsubsection}"
               "\\renewcommand{\\topfraction}{0.9}\\renewcommand{\\bottomfraction}{0.9}\\renewcommand{\\textfraction}{0.07}"
               "\\renewcommand{\\floatpagefraction}{0.85}'");
    data.write("stamp", stamp);
    write_atomic((staging / kReportMarker).string(), report_marker(staging.string()));
    if (stop_requested) throw Interrupted();
  } catch (const ToolFailed&) {
    throw;  // the staging folder kept: the message names it
  } catch (...) {
    fs::remove_all(staging);
    throw;
  }
  // Swap the new report in: one atomic exchange of the two folders, then the old one goes.
  if (fs::exists(out)) {
    if (renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, out.c_str(), RENAME_EXCHANGE) != 0) {
      fs::remove_all(staging);
      throw std::runtime_error(fmt::format("cannot replace {}", out.string()));
    }
    fs::remove_all(staging);
  } else {
    fs::rename(staging, out);
  }
  std::printf("wrote %s: report.pdf, report.md (the hand-out), atlas.html, atlas.md (every study), figures/, data/\n", out.c_str());
  return 0;
}

}  // namespace steplab
