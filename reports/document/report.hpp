// `steplab report`: runs every study, draws the figures with gnuplot (reports/*.gp), writes
// report.md (figures linked relatively), report.pdf (pandoc + LaTeX), and the data of every
// study, into one folder.
//
// Every sentence that states a finding is generated from the numbers: Findings holds what the
// shared data say (which methods are stable where, dt* per method), each section computes what
// its own sentences need, and the text is rendered from that, so other parameters give other,
// still true, sentences. The sections are listed in reports/document/sections/sections.hpp.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "analysis/collision.hpp"
#include "analysis/convergence.hpp"
#include "analysis/stability.hpp"
#include "analysis/work_precision.hpp"
#include "reports/document/report_config.hpp"

namespace steplab {

// The shared studies (ReportData's fields), as bits: what a section needs (Section::needs) and
// what ran. kFindings: the convergence and stability studies Findings are computed from.
enum ReportStudy : unsigned {
  kConvergenceStudy = 1,  // convergence: every report scene with an exact solution
  kStabilityStudy = 2,    // thresholds, sweep, map, and the stability figures' runs
  kCollisionStudy = 4,
  kWorkPrecisionStudy = 8,
  kSceneFigures = 16,  // cannon, spring
  kFindings = kConvergenceStudy | kStabilityStudy,
};

struct ReportData {
  ReportConfig config;
  Workers workers;  // the config's threads, the command's progress
  unsigned studies = 0;  // ReportStudy bits: which shared studies ran (the fields of the others stay empty)
  std::vector<std::size_t> methods;  // the config's methods, in the table's order (the exact flow if chosen)
  std::vector<std::size_t> numerical_methods() const;  // `methods` but the exact flow
  std::vector<ConvergenceResult> convergence;  // each of the config's scenes with an exact solution, in order
  const ConvergenceResult& convergence_on(std::size_t scene) const;  // std::out_of_range if not studied
  std::vector<ThresholdRow> thresholds;
  std::vector<SweepRow> sweep;
  StabilityMap map;
  CollisionResult collision;
  WorkPrecisionResult work;  // spring and chain, with the peers; the stiffness sweep
  // figure data
  std::vector<RunResult<2>> cannon;               // [method]: the projectile's path
  std::vector<std::vector<RunResult<1>>> spring;  // [figure dt][method]
  std::vector<RunResult<1>> energy;               // [method]: gamma = 0 at the large step
  std::vector<double> curve_damping;              // predicted rate against damping, at the large step
  std::vector<std::vector<double>> curve_rate;    // [method][damping]
};

// The shared studies in `studies` (ReportStudy bits), on the config's methods.
ReportData run_report_studies(const ReportConfig& config, unsigned studies, ProgressHook progress = nullptr);

struct MethodFinding {
  std::size_t method;
  const ConvergenceFit* fit;  // on the oscillator (the spring)
  bool stable_large_dt;       // at config.large_dt with the spring's damping
  bool stable_undamped;       // at config.small_dt with damping 0
  double dt_theory, dt_measured;  // at the spring's damping
  double growth_large_dt;     // measured d ln E / dt at config.large_dt
  double again_measured;      // stable again from here (at the spring's damping; inf: never)
  double dt_undamped_theory, dt_undamped_measured;  // at damping 0
};

struct Findings {
  std::vector<MethodFinding> rows;
  double spearman = 0;                  // rank correlation of declared order and measured dt*, pooled
  std::vector<std::size_t> stable_large, unstable_large, stable_undamped, unstable_undamped;
  std::vector<std::size_t> never_stable_undamped, always_stable;  // predicted dt* = 0 at gamma = 0 / inf
};

Findings compute_findings(const ReportData& d);

// The threshold row of a method at a damping (nullptr if the study did not run that pair).
const ThresholdRow* find_threshold(const ReportData& d, std::size_t method, double damping);

// Ranks 1..n with ties sharing their average rank (+inf ranks above every finite value), and
// Spearman's rho: the correlation of two such rankings.
std::vector<double> average_ranks(const std::vector<double>& x);
double spearman(const std::vector<double>& a, const std::vector<double>& b);

class Section;

// The report: the config's sections (reports/document/section.hpp), the shared studies they need,
// their findings (if those studies ran), and the sections' own studies run.
struct Report {
  ReportData data;
  Findings findings;
  std::vector<std::unique_ptr<Section>> sections;
  Report();
  Report(Report&&) noexcept;
  ~Report();
};

Report build_report(const ReportConfig& config, ProgressHook progress = nullptr);

std::string report_markdown(const Report& r, const std::string& figure_ext, const std::string& footer);

// The whole report into `out_dir`, atomically: built in a staging folder beside it and swapped
// in at the end, so an interrupted run leaves the previous report as it was. Skips all work if
// `out_dir` already holds a report made from the same configuration by the same binary.
// `progress`: shown as the studies run. Returns the exit status.
int write_report(const ReportConfig& config, const std::string& out_dir, bool force, ProgressHook progress = nullptr);

}  // namespace steplab
