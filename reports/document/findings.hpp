// What the report's sentences state, as values computed from the data they are about: the
// sections render these, and tests/reports/claims_test.cpp recomputes each from the studies' own
// numbers under changed parameters. Every statistic, count and list of methods here is over the
// numerical methods: the exact flow is the reference the others are measured against.
#pragma once

#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/kernel/noise.hpp"
#include "core/method.hpp"
#include "reports/document/report.hpp"

namespace steplab {

// The methods of Findings rows (indices into f.rows: f.numerical, f.stable_large, ...).
std::vector<std::size_t> methods_of(const Findings& f, const std::vector<std::size_t>& rows);

// Whether a margin of one cost over another is a tie: below kTieMargin where the costs are times
// (analysis/kernel/noise.hpp), only at 1 where they are counts.
bool tied(double margin, bool timed);

// Whether two measured values are the same within `relative` of the larger: equal, or both finite
// and |a - b| <= relative max(|a|, |b|). Infinity is the same as infinity only, never as a number
// (|inf - x| <= relative inf would hold for any x); NaN is the same as nothing.
bool same_within(double a, double b, double relative);

// How dt* moves along a family's orders; two dt* within kSameThreshold of each other (relative:
// the threshold search's resolution, a few parts in 10^4) count as the same (same_within). An
// unbounded dt* (stable at every step) is above every finite one. NotMeasured: a member has no dt*.
enum class Trend { StaysInfinite, Rises, Falls, StaysTheSame, Mixed, NotMeasured };
inline constexpr double kSameThreshold = 1e-3;
std::string_view to_text(Trend t);
Trend trend(const std::vector<double>& dt);

// A family of the report with methods of at least two orders: its members by order and their
// measured dt* at one damping.
struct FamilyTrend {
  Family family;
  std::vector<std::size_t> members;
  std::vector<double> dt;
  Trend trend;
};
std::vector<FamilyTrend> family_trends(const ReportData& d, double damping);

// Spearman's rho in words: "weak positive", "strong negative", ...: |rho| < 0.3 weak, < 0.7 moderate.
std::string correlation_words(double rho);
// Whether rho over n points is evidence of a correlation, at the 5 % level: with none, rho
// sqrt(n - 1) is about standard normal, so |rho| must exceed 1.96 / sqrt(n - 1); from 1 up (n
// <= 4) no ranking of so few points is evidence either way. "within chance for 15 methods (beyond
// it from |rho| > 0.52)", "beyond chance at the 5 % level (|rho| > 0.52)", or "no evidence either way,
// since no ranking of 4 methods reaches the 5 % level".
double spearman_chance(std::size_t n);
std::string chance_words(double rho, std::size_t n);

// An unstable run whose energy grows slower than this per unit time, and whose E/E0 stays at most
// kBlownRatio (below), is weakly unstable: E doubles in more than ln 2 / kWeakRate = 690 time
// units, 69 times the sheet's 10 s, where a run shows no growth; the rate is stated beside it.
// (Stable is at most kStableRate, 1e-6.) A run whose energy jumped far from E0 and then grows
// slowly (PBD at a large step) is not weakly unstable: the rate says nothing of it.
inline constexpr double kWeakRate = 1e-3;
// A method with its measured energy growth rate (d ln E / dt) and its largest E/E0 at one of the sheet's tests.
struct MethodRate {
  std::size_t method;
  double rate, energy_max;
};
// The methods of `rows` with their rate at the sheet's large step (undamped: at its small step without damping).
std::vector<MethodRate> rates_of(const Findings& f, const std::vector<std::size_t>& rows, bool undamped);
// "`a`, and weakly (energy growing 6e-06 and 1.2e-05 per unit time) `b` and `c`": the methods,
// those below kWeakRate last with their rates.
std::string unstable_words(const std::vector<MethodRate>& runs);
std::vector<std::size_t> weakly(const std::vector<MethodRate>& runs);  // below kWeakRate, E/E0 at most kBlownRatio
// The others with a finite rate (a blown-up run has none): by their rate (at least kWeakRate), or
// by their energy (below kWeakRate, E/E0 beyond kBlownRatio).
std::vector<std::size_t> strongly(const std::vector<MethodRate>& runs);
std::vector<std::size_t> far_from_e0(const std::vector<MethodRate>& runs);

// The undamped spring over the long run (the energy figure): E/E0's range, the largest
// |E/E0 - 1| over the run's first and second halves, and what that says.
enum class EnergyKind {
  Bounded,  // its second half strays no further than its first (within kBoundedGrowth), or no further
            // than round-off alone reaches (kRoundOff u sqrt(steps): analysis/studies/long_time.hpp)
  Grows,    // strays further and further, above E0 at the end: a slow geometric growth (on the
            // linear spring, |R| > 1: unstable at this step, though not blown up in the run)
  Decays,   // strays further and further, below E0 at the end: the method's own damping
  Damped,   // E/E0 below 1 / kBlownRatio: the method's own damping has taken the motion out
  Blows     // diverged, or E/E0 beyond kBlownRatio
};
inline constexpr double kBoundedGrowth = 1.25, kBlownRatio = 10;
struct EnergyBehaviour {
  std::size_t method;
  double lo = 1, hi = 1;                    // min and max of E/E0 over the run
  double first_half = 0, second_half = 0;   // max |E/E0 - 1| over each half
  double final_ratio = 1;
  double round_off = 0;                     // round-off's level over the run: kRoundOff u sqrt(steps)
  EnergyKind kind = EnergyKind::Bounded;
  double ended = -1;                        // t where a diverged run ended; -1: it did not
};
// The numerical methods' runs of ReportData::energy (the stability study's figure runs).
std::vector<EnergyBehaviour> energy_behaviour(const ReportData& d);
std::string_view to_text(EnergyKind k);
inline constexpr EnergyKind kEnergyKinds[] = {EnergyKind::Bounded, EnergyKind::Grows, EnergyKind::Decays, EnergyKind::Damped, EnergyKind::Blows};
std::vector<std::size_t> methods_of_kind(const std::vector<EnergyBehaviour>& e, EnergyKind k);

// Does the order hold when stiff: each method's verdict on the stiffened scene.
enum class StiffVerdict {
  Keeps,       // p in both limits and at every fit between them
  Strays,      // p in both limits, but a fit between them strays (the transition, with its bounds)
  Falls,       // to the theory's lower stiff order
  Rises,       // to the theory's higher stiff order (a multistep method: its one-step start's)
  NotReached,  // the stiff limit not reached at these steps
  Differs,     // a limit does not hold
  Unstable     // no stiff limit: not stable as h |lambda| grows
};
struct StiffClaim {
  std::size_t method;
  StiffVerdict verdict;
  int p = 0, stiff = -1;
  double non_stiff_order = 0, stiff_order = 0;
  double keeps_to = 0, reduced_from = 0;  // MethodReduction's transition (NaN: not seen)
  // Strays: the fit farthest from p between the limits, its bound, stiffness and h |lambda|
  double stray_order = 0, stray_lo = 0, stray_hi = 0, stray_value = 0, stray_h_lambda = 0;
  std::string_view starter = {};  // a multistep method's one-step start
};
// An order is kept where it is within this of the theory's (the non-stiff limit's tolerance, 0.05:
// analysis/studies/order_reduction.hpp) or its bound contains it.
std::vector<StiffClaim> stiff_claims(const OrderReduction& r);

// What accuracy costs (the work-precision study): a run's cost, by run time or, untimed, by force
// evaluations ("evaluations" are force evaluations throughout; Jacobians and factorisations are
// counted beside them), and in words: "1.2 µs", "812 force evaluations".
double point_cost(const WorkPoint& p, bool timed);
// The field of work_precision.json's points that point_cost reads.
inline const char* point_cost_field(bool timed) { return timed ? "seconds" : "force_evaluations"; }
std::string cost_text(bool timed, double seconds, long long forces);
// The cheapest run of `solver` on the scene with its error at most `level`; null if none reaches it.
const WorkPoint* cheapest_point(const SceneWork& w, const std::string& solver, double level, bool timed);

// The cheapest solver at an error level, its margin over the next solver's cheapest run, whether
// that is a tie (kTieMargin), and whether its winning run is at the edge of its sweep (its largest
// step or loosest tolerance: a larger one, not tried, might be cheaper still).
// Untimed, an implicit winner is undecided against the cheapest explicit solver that reached the
// level (`undecided`): its force evaluations leave out its Jacobians, factorisations and solves, so
// fewer of them is no win over a method that does nothing else.
struct LevelWinner {
  const WorkPoint* point = nullptr;  // null: no run reached the level
  std::string next;                  // the runner-up solver ("" if none)
  double margin = INFINITY;          // the runner-up's cost over the winner's
  bool tie = false, at_edge = false;
  std::string undecided;             // the explicit solver it is not told from ("" if decided)
  // In a tie, the solvers beyond the runner-up whose cheapest run is as close to the winner's
  // (within the margin): a tie names them all.
  std::vector<const WorkPoint*> also;
  bool decided() const { return !tie && undecided.empty(); }
  std::vector<std::string> tied_with() const;  // in a tie, the runner-up and `also`, by name
};
LevelWinner level_winner(const SceneWork& w, double level, bool timed);
// "`rk4`", "a tie of `a` and `b`", or "`radau_iia5` or `adams_bashforth3` (undecided: force
// evaluations leave out the implicit one's solves)".
std::string winner_words(const LevelWinner& w);

// Whether a solver (a table method, dopri5 or a peer) solves for its step: an implicit method or
// peer, whose force evaluations leave out its Jacobians, factorisations and linear solves.
bool solves(const std::string& solver);

// A cell of the scaling map: no solver reached the target; the body moves less than the target
// there (a run at rest meets it: a win for no one); untimed, an implicit cheapest is undecided
// against an explicit solver (solves uncounted); a tie (tied()); or a clear win.
enum class CellVerdict { None, Still, Undecided, Tie, Win };
// The verdict is its group's: the margin over the cheapest run of another group (rival_margin),
// so two members of one family within the noise are that family's win.
CellVerdict cell_verdict(const ScalingCell& m, double error, bool timed);
// Whether the cell's cheapest is an implicit fixed-step method cheaper than every other kind of
// solver (explicit, adaptive, implicit peers) by its margin, timed (untimed, only where no other
// kind reached the target): "implicit pays" there, even where another implicit family ties it.
bool implicit_wins(const ScalingCell& m, bool timed);
// The map's cells at one target, by verdict: the clear wins by solver group (solver_group), the
// ties between groups and undecided ones, the ones at rest; and the moving cells an implicit
// fixed-step method wins clearly ("stiffness/N", implicit_wins), a tie between two implicit
// families among them.
struct MapTally {
  int cells = 0, ties = 0, still = 0;
  std::map<std::string, int> wins;
  std::vector<std::string> implicit;
};
MapTally map_tally(const ScalingResult& r, std::size_t target);

// On a scene at an error level: steplab's cheapest implicit fixed-step run against each CVODE
// set-up's cheapest (either may be null where it does not reach the level).
struct PeerComparison {
  double level;
  const WorkPoint* steplab;
  std::string peer;
  const WorkPoint* run;
};
std::vector<PeerComparison> implicit_against_peers(const WorkPrecisionResult& r, const SceneWork& w, double level, bool timed);

}  // namespace steplab
