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
#include <optional>
#include <string>
#include <vector>

#include "analysis/studies/collision.hpp"
#include "analysis/studies/convergence.hpp"
#include "analysis/studies/order_reduction.hpp"
#include "analysis/studies/scaling.hpp"
#include "analysis/studies/long_time.hpp"
#include "analysis/studies/stability.hpp"
#include "analysis/studies/work_precision.hpp"
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
  kStiffOrderStudy = 32,  // does the order hold when stiff: the stiffened scene's sweep
  kScalingStudy = 64,     // as the system grows: every covered scene of run-time size, and the first one's map
  kLongTimeStudy = 128,   // stable for how long: the orbit and the swinging spring, where covered
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
  OrderReduction stiff_order;  // the stiffened scene's order against its stiffness
  // Each covered scene of config.scaling refined (the report's error, its first stiffness), and the
  // first one that declares a stiffness, stiffened as well at the map's sizes (both targets).
  std::vector<ScalingResult> scaling;
  std::optional<ScalingResult> scaling_map;
  // Stable for how long (analysis/studies/long_time.hpp): Kepler's orbit and the swinging spring
  // (analysis/studies/defaults.hpp), each where covered, config.long_time_periods long; empty rows
  // where not run.
  LongTimeResult long_time_orbit, long_time_swing;
  // figure data
  std::vector<RunResult<2>> cannon;               // [method]: the projectile's path
  std::vector<std::vector<RunResult<1>>> spring;  // [figure dt][method]
  std::vector<RunResult<1>> energy;               // [method]: gamma = 0 at the large step
  std::vector<RunResult<1>> energy_damped;        // [method]: the spring's damping at the large step
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
  double energy_rate_large_dt;     // measured d ln E / dt at config.large_dt
  double energy_rate_undamped;     // measured d ln E / dt at config.small_dt, damping 0
  double again_measured;      // stable again from here (at the spring's damping; inf: never)
  double dt_undamped_theory, dt_undamped_measured;  // at damping 0
  // At damping 0, where the method is stable again beyond dt* (predicted / measured; inf: at no
  // step the threshold search tried), and whether any step of the stability map is stable there.
  double again_undamped_theory, again_undamped_measured;
  bool map_stable_undamped;
  double energy_max_large_dt = NAN, energy_max_undamped = NAN;  // the largest E/E0 of those two runs
};

// What the shared studies say, every statistic and every list over the numerical methods only:
// the exact flow is the reference the others are measured against, not one of them.
struct Findings {
  std::vector<MethodFinding> rows;  // every method of the report, the exact flow's row included (the tables')
  std::vector<std::size_t> numerical;   // the rows of the numerical methods
  // Spearman's rank correlation of the declared order and the measured dt* at the spring's
  // damping, over the numerical methods (spearman_n of them); NaN for fewer than 2.
  double spearman = 0;
  std::size_t spearman_n = 0;
  std::vector<std::size_t> stable_large, unstable_large, stable_undamped, unstable_undamped;  // rows, numerical
  // Undamped, unstable at every small step (predicted dt* = 0): all of them; of those, the ones
  // stable at no step at all (neither the threshold search nor the map found one); the others are
  // stable again from again_undamped_*.
  std::vector<std::size_t> unstable_small_undamped, never_stable_undamped;
  std::vector<std::size_t> always_stable;  // dt* unbounded at the spring's damping: stable at every step tried
};

Findings compute_findings(const ReportData& d);

// The threshold row of a method at a damping (nullptr if the study did not run that pair).
const ThresholdRow* find_threshold(const ReportData& d, std::size_t method, double damping);
// The stability sweep's run of a method at (dt, damping) (nullptr if the sweep did not run it).
const SweepRow* find_sweep(const ReportData& d, std::size_t method, double dt, double damping);

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
  // The methods on springs (MethodInfo::on_springs) measured on the sheet's spring by the findings'
  // studies, run for them alone where the report has its frame-budget section: the summary table
  // shows them beside the others and the answers count them.
  std::optional<ReportData> springs;
  std::optional<Findings> springs_findings;
  std::vector<std::unique_ptr<Section>> sections;
  Report();
  Report(Report&&) noexcept;
  ~Report();
};

Report build_report(const ReportConfig& config, ProgressHook progress = nullptr);
// The report's figures (their scripts) in the order its sections list them: figure n is the n-th.
std::vector<std::string> figure_order(const Report& r);

class Ledger;
// The report's Markdown, every section whole (the atlas's), or with `handout` each as the hand-out
// shows it (sections.hpp); with `ledger`, the findings its sections state are recorded there.
std::string report_markdown(const Report& r, const std::string& figure_ext, const std::string& footer, Ledger* ledger = nullptr,
                            bool handout = false);

// The whole report into `out_dir`, atomically: built in a staging folder beside it and swapped
// in at the end, so an interrupted run leaves the previous report as it was. Skips all work if
// `out_dir` already holds a report made from the same configuration by the same binary.
// `progress`: shown as the studies run. Returns the exit status.
int write_report(const ReportConfig& config, const std::string& out_dir, bool force, ProgressHook progress = nullptr);

}  // namespace steplab
