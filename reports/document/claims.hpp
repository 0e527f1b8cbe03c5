// The report's ledger of claims: data/claims.json (schema steplab.claims/1, docs/json.md). Each
// finding a section states is recorded with its rule and the values it rests on, each named by
// the data file and JSON pointer it sits at, so that a program that shares no code with the
// report (tools/verify_claims.py) re-evaluates it from the data alone. The ledger does not judge
// a claim: it records what the sentence says, the rule that would make it true, and where the
// evidence lies.
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/studies/long_time.hpp"
#include "reports/document/findings.hpp"

namespace steplab {

class Page;
using Json = nlohmann::ordered_json;

struct Evidence {
  std::string file;     // under data/; "claims.json" is the ledger itself (its methods table)
  std::string pointer;  // RFC 6901
  Json value;           // what the pointer finds there
  bool operator==(const Evidence&) const = default;
};

struct Claim {
  std::string id, section, sentence, kind;  // kind: membership, trend, statistic, threshold, comparison, equality, count, ratio, extreme, mismatch (docs/json.md)
  Json rule;
  std::vector<Evidence> evidence;
};

class Ledger {
 public:
  explicit Ledger(const std::vector<std::size_t>& methods) : methods_(methods) {}
  // The data document at `file` (a path under data/) that claims cite, made by `make` the first
  // time: the report writes it there unless a section already wrote the same document.
  const Json& document(const std::string& file, const std::function<Json()>& make);
  // The value at `pointer` in a cited document, as evidence.
  Evidence at(const std::string& file, const std::string& pointer) const;
  // A method's declared order, as evidence from the ledger's methods table.
  Evidence order_of(std::size_t method) const;
  void add(Claim c);  // std::logic_error for an id used twice
  // A sentence the report states as theory (a textbook result, a definition), not as a finding.
  void theory(std::string section, std::string sentence);
  Json json() const;  // schema, methods, theory, claims
  const std::map<std::string, Json>& documents() const { return documents_; }
  std::size_t size() const { return claims_.size(); }

 private:
  std::vector<std::size_t> methods_;
  std::map<std::string, Json> documents_;
  std::vector<Claim> claims_;
  std::vector<std::pair<std::string, std::string>> theory_;
};

// A claim's words, before its kind, rule and evidence.
inline Claim claim_text(std::string id, std::string section, std::string sentence) {
  return {std::move(id), std::move(section), std::move(sentence), {}, {}, {}};
}

// Tests on one row of a table (docs/json.md, "A report's claims"), their pointers relative to the
// row: `field` op value ("==", "!=", "<", "<=", ">", ">="); |x1 - x2| op value; x1 op times x2.
Json test_field(std::string pointer, const char* op, Json value);
Json test_difference(std::string p1, std::string p2, const char* op, double value);
Json test_scaled(std::string p1, const char* op, double times, std::string p2);
Json test_all(std::vector<Json> tests);
Json test_any(std::vector<Json> tests);
Json test_not(Json test);

// "`set` is exactly the rows of `rows` in the cited document `file` that match `where`, of the
// numerical methods (`numerical`) or all, and meet `test`": a membership claim, its evidence every
// value the test reads in those rows. The rows' `key` names them ("method", "solver").
void claim_members(Ledger& l, Claim c, const std::string& file, const std::string& rows, Json where, const char* key,
                   bool numerical, Json test, const std::vector<std::string>& set);
// One selection of a membership claim: the rows of `rows` in the cited document `file` that match
// `where`, of the numerical methods (`numerical`) or all, and meet `test`, named by `key`.
struct Selection {
  std::string file, rows;
  Json where;
  const char* key;
  bool numerical;
  Json test;
};
// "`set` is exactly the rows every one of `selections` selects" (their intersection by key).
void claim_members_of_all(Ledger& l, Claim c, const std::vector<Selection>& selections, const std::vector<std::string>& set);
std::vector<std::string> method_names(const std::vector<std::size_t>& methods);

// "Each pair is equal within max(absolute, relative max(|a|, |b|))" (infinity equal to infinity only).
void claim_equal(Ledger& l, Claim c, const std::vector<std::pair<Evidence, Evidence>>& pairs, double relative, double absolute);

// One group of a count claim: a rule of kind equality, comparison or threshold over its own evidence.
struct ClaimGroup {
  std::string kind;
  Json rule;  // its indices into `evidence`
  std::vector<Evidence> evidence;
};
// "`count` of these hold": the groups' evidence appended, their indices shifted to the claim's.
void claim_count(Ledger& l, Claim c, std::vector<ClaimGroup> groups, int count);
// A comparison of `a` against `others` (the one it ties with or beats by its margin first); as a
// group, or a claim of its own. Its rule's `noise` list (docs/json.md) is empty: the timings'
// spreads are recorded but decide nothing (analysis/kernel/noise.hpp).
ClaimGroup comparison_group(Evidence a, std::vector<Evidence> others, const char* relation, double margin);
void claim_group(Ledger& l, Claim c, ClaimGroup g);

// The digits a ratio is printed with: `n` after the point (fmt's {:.nf}), or `n` significant ones
// ({:.ng}); `printed` writes it so.
struct Digits {
  bool significant;
  int n;
};
std::string printed(double x, Digits d);
// One ratio of evidence: the product of the `over` values over the product of the `under` ones.
struct Ratio {
  std::vector<Evidence> over, under;
};
// "These ratios lie from `least` to `greatest`", each printed with `d` as the sentence prints it: a
// ratio claim, the verifier recomputing each from its evidence. claim_ratio: one ratio, `value`.
void claim_ratios(Ledger& l, Claim c, const std::vector<Ratio>& ratios, double least, double greatest, Digits d);
inline void claim_ratio(Ledger& l, Claim c, Ratio r, double value, Digits d) { claim_ratios(l, std::move(c), {std::move(r)}, value, value, d); }

// "`values[a]` is the least (the greatest) of `values`", and where `d` is given, printed as the
// sentence prints it (printed(value, *d)): an extreme claim, what a figure's caption says of its
// curves. "n cells of these pairs of tables differ": a mismatch claim, each evidence a whole array.
enum class Extreme { Least, Greatest };
void claim_extreme(Ledger& l, Claim c, std::vector<Evidence> values, std::size_t a, Extreme which, std::optional<Digits> d = {});
// "The fall from `first` to `second` of pairs[a] is the greatest of the pairs'": an extreme claim
// over differences (a figure's furthest fall).
void claim_greatest_fall(Ledger& l, Claim c, const std::vector<std::pair<Evidence, Evidence>>& pairs, std::size_t a);
void claim_mismatch(Ledger& l, Claim c, const std::vector<std::pair<Evidence, Evidence>>& pairs, std::size_t count);
// The evidence of each row of `rows` that `keep` holds (`at(row, its index in rows)`), and where
// the rows `least` and `most` sit among them: what claim_extreme and claim_range take.
struct Kept {
  std::vector<Evidence> values;
  std::size_t least = 0, most = 0;
};
template <class Row, class Keep, class At>
Kept kept_evidence(const std::vector<Row>& rows, Keep&& keep, const std::type_identity_t<Row>* least, const std::type_identity_t<Row>* most, At&& at) {
  Kept out;
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (keep(rows[i])) {
      if (&rows[i] == least) out.least = out.values.size();
      if (&rows[i] == most) out.most = out.values.size();
      out.values.push_back(at(rows[i], i));
    }
  return out;
}
// The rows `keep` holds whose `key` prints with `d` as `x`'s does, x first: the rows a sentence
// names with the extreme x, since to its digits they tie with it (none where x is null).
template <class Row, class Keep, class Key>
std::vector<const Row*> printed_ties(const std::vector<Row>& rows, Keep&& keep, Key&& key, const std::type_identity_t<Row>* x, Digits d) {
  if (!x) return {};
  std::vector<const Row*> out{x};
  for (const Row& r : rows)
    if (&r != x && keep(r) && printed(key(r), d) == printed(key(*x), d)) out.push_back(&r);
  return out;
}
// The least and the greatest of the kept values as a sentence states them: two extreme claims,
// `id`.least and `id`.greatest.
void claim_range(Ledger& l, const std::string& id, const std::string& section, const std::string& sentence, const Kept& k,
                 std::optional<Digits> d = {});
// `field` of the first row of the array at `rows` in the cited document `file` whose fields equal
// `where`'s, as evidence: none where there is none (row_field: std::logic_error).
std::optional<Evidence> find_row_field(const Ledger& l, const std::string& file, const std::string& rows, const Json& where,
                                       const std::string& field);
Evidence row_field(const Ledger& l, const std::string& file, const std::string& rows, const Json& where, const std::string& field);

// Words as part of a claim's id: "explicit Runge-Kutta" -> "explicit_runge-kutta".
std::string id_word(std::string_view words);

// The spring's stability study as the report writes it, data/stability/stability.json (the
// stability section's, and the claims' about stability wherever the section is left out); the
// methods on springs' (Report::springs) at data/summary/springs_stability.json.
inline constexpr const char* kStabilityDocument = "stability/stability.json";
inline constexpr const char* kSpringsStabilityDocument = "summary/springs_stability.json";
Json stability_document(const ReportData& d);

// A stability study a claim reads: the data and the file its document is written to.
struct StabilitySource {
  const ReportData& data;
  const char* file = kStabilityDocument;
};

// The stability studies a page shows: the report's, and the methods on springs' where the report
// measured them (the summary table shows both), each with its findings and the suffix of its
// claims' ids ("" and ".springs").
struct ShownStudy {
  StabilitySource study;
  const Findings& f;
  const char* id;
};
std::vector<ShownStudy> shown_studies(const Page& page);

// "The methods in `set` are exactly those of the stability study's sweep at (dt, damping) whose
// run is unstable": a membership claim over the source's numerical methods.
void claim_unstable_at(Ledger& l, StabilitySource s, std::string id, std::string section, std::string sentence, double dt,
                       double damping, const std::vector<std::size_t>& set);
// "The measured dt* is within `relative` of the predicted one in `agree` of these cases" (method,
// damping): a count claim over their thresholds rows (same_within: infinity only as infinity).
void claim_thresholds_agree(Ledger& l, StabilitySource s, std::string id, std::string section, std::string sentence,
                            const std::vector<std::pair<std::size_t, double>>& cases, double relative, std::size_t agree);
// "Each of `methods` has its measured dt* at `damping` within `relative` of the predicted one": an
// equality claim over their thresholds rows.
void claim_measured_as_predicted(Ledger& l, StabilitySource s, std::string id, std::string section, std::string sentence,
                                 const std::vector<std::size_t>& methods, double damping, double relative);
// "The methods in `set` are exactly those whose predicted dt* at `damping` is unbounded".
void claim_unbounded_at(Ledger& l, StabilitySource s, std::string id, std::string section, std::string sentence,
                        double damping, const std::vector<std::size_t>& set);
// "The runs of `methods` at (dt, damping) grow their energy at a rate `op` `limit`" (op "<", "<=",
// ">" or ">="): a threshold claim on each one's measured rate (the weakly unstable ones: below
// kWeakRate); none for no method.
// claim_sweep: the same of another `field` of their sweep rows (energy_ratio_max).
void claim_sweep(Ledger& l, StabilitySource s, std::string id, std::string section, std::string sentence, double dt,
                 double damping, const std::vector<std::size_t>& methods, const char* field, const char* op, double limit);
inline void claim_rate(Ledger& l, StabilitySource s, std::string id, std::string section, std::string sentence, double dt,
                       double damping, const std::vector<std::size_t>& methods, const char* op, double limit) {
  claim_sweep(l, s, std::move(id), std::move(section), std::move(sentence), dt, damping, methods, "rate_measured", op, limit);
}
// "`disagree` of the stability map's cells disagree with the step map's prediction": a mismatch
// claim over each method's two tables of map/stable and map/predicted.
void claim_map_cells(Ledger& l, StabilitySource s, std::string id, std::string section, std::string sentence, std::size_t disagree);
// "Row `a` of these rows of the stability document's `table` (thresholds, sweep; each named by its
// fields) has the least (greatest) `field`, printed with `d`": an extreme claim.
void claim_stability_extreme(Ledger& l, StabilitySource s, Claim c, const char* table, const std::vector<Json>& rows, std::size_t a,
                             const char* field, Extreme which, Digits d);
// The unstable runs at (dt, damping) by how they grow (findings.hpp): the weak ones' rates below
// kWeakRate and their E/E0 at most kBlownRatio (`section`.weakly_unstable_`at`, and its .near_e0),
// the ones far from E0 (`section`.far_from_e0_`at`) and, where `strong`, the others' rates
// (`section`.strongly_unstable_`at`).
void claim_unstable_runs(Ledger& l, StabilitySource s, const std::string& section, const std::string& at, const std::string& sentence,
                         double dt, double damping, const std::vector<MethodRate>& runs, bool strong);
// The work-precision study as the report writes it, data/cost/work_precision.json.
inline constexpr const char* kWorkDocument = "cost/work_precision.json";
// A field of a work point (`p` of scene `w`) in the cited work-precision document, as evidence.
Evidence work_point_at(Ledger& l, const ReportData& d, const SceneWork& w, const WorkPoint& p, const char* field);
// "The cheapest run to error `level` on scene `w` is `win`'s, by its margin or tied with the
// runner-up": a comparison claim over each solver's cheapest run at the level (by run time, or
// untimed by force evaluations); none where no run
// reached the level or the winner is undecided.
void claim_cheapest(Ledger& l, const ReportData& d, std::string id, std::string section, std::string sentence, const SceneWork& w,
                    double level, bool timed, const LevelWinner& win);
// "From stiffness ratio r on an implicit method is cheaper than every explicit one by more than
// kTieMargin" (the work-precision study's crossover, timed only): a count claim that every row of
// the stiffness sweep from r on has its best implicit run that much cheaper, and one that the row
// before r has not.
void claim_crossover(Ledger& l, const ReportData& d, std::string id, std::string section, std::string sentence);
// How the measured dt* at `damping` moves along a family's orders (a trend claim); none where a
// member has no threshold row.
void claim_family_trend(Ledger& l, StabilitySource s, std::string id, std::string section, std::string sentence,
                        const FamilyTrend& t, double damping);
// Spearman's rho between the declared order and the measured dt* at the spring's damping, over
// `points` (a method of a source each), as printed (`value` with `decimals` decimals, in words);
// none where a point has no threshold row.
struct StabilityPoint {
  StabilitySource source;
  std::size_t method;
};
void claim_spearman(Ledger& l, const std::vector<StabilityPoint>& points, double value, std::string id, std::string section,
                    std::string sentence, int decimals);
// The numerical methods of findings `f` as Spearman's points of source `s`.
std::vector<StabilityPoint> spearman_points(StabilitySource s, const Findings& f);

// The undamped spring's long run as the claims cite it: data/energy/energy.json, a row per
// numerical method with energy_behaviour's values (findings.hpp) and its class.
inline constexpr const char* kEnergyDocument = "energy/energy.json";
inline constexpr const char* kCollisionDocument = "collision/collision.json";  // the collision study's
Json energy_document(const ReportData& d);
// "`set` is the methods whose run is of kind `k`" (and symplectic, where `symplectic`).
void claim_energy(Ledger& l, const ReportData& d, std::string id, std::string section, std::string sentence, EnergyKind k,
                  const std::vector<std::size_t>& set, bool symplectic = false);
// "`set` is the methods stable at the sheet's step (config.large_dt) with and without the spring's
// damping, in the stability sweep, whose undamped run at that step keeps its energy bounded".
void claim_sheet_step(Ledger& l, const ReportData& d, std::string id, std::string section, std::string sentence,
                      const std::vector<std::size_t>& set);
// A convergence study's document, cited: data/convergence/convergence_<scene>.json, its name returned.
std::string cite_convergence(Ledger& l, const ConvergenceResult& r);
// The long-time study's document of `r`'s scene in a section's folder, cited:
// data/<folder>/long_time_<scene>.json, its name returned.
std::string cite_long_time(Ledger& l, const LongTimeResult& r, const std::string& folder);
// "`set` is the methods whose energy error over the long run is `v`" (energy_verdict, Bounded,
// Drifting or Lost at kLostAt).
void claim_long_time(Ledger& l, const LongTimeResult& r, const std::string& folder, std::string id, std::string section,
                     std::string sentence, EnergyVerdict v, const std::vector<std::size_t>& set);
// The run's sides (sections/long_time.hpp) as `id`.bounded, .drifting, .lost and, where the bounded
// ones are the symplectic ones whatever the order, .symplectic.
struct LongTimeSides;
void claim_long_time_sides(Ledger& l, const LongTimeResult& r, const LongTimeSides& s, const std::string& folder, const std::string& id,
                           const std::string& section, const std::string& sentence);
// The stiff-order verdicts (stiff_claims): which methods keep their order in both limits, fall,
// rise or have no stiff limit, over the study's methods table, and for each that keeps it in both
// limits, whether a fit between them strays.
void claim_stiff(Ledger& l, const ReportData& d, const std::string& id, const std::string& section, const std::string& sentence,
                 const std::vector<StiffClaim>& claims);

// The crossover map's tally at target `target` (map_tally, timed only): how many cells are ties,
// clear wins, clear wins of an implicit fixed-step method, and at rest, each a count claim over the
// cells' runs in data/scaling/scaling_map.json.
void claim_map(Ledger& l, const ScalingResult& r, std::size_t target, const std::string& id, const std::string& section,
               const std::string& sentence, const MapTally& tally);

// The scaling study's crossover (answer_crossover, timed only) at its first block, in the cited
// document `file`: at each size up to the crossover's (every size where there is none), the cheapest
// implicit fixed-step run against every explicit one's (steplab's methods), a comparison by
// kTieMargin; a count claim that 1 of them holds (the crossover's) or none.
void claim_scaling_crossover(Ledger& l, const ScalingResult& r, const std::string& file, const std::string& id,
                             const std::string& section, const std::string& sentence);

}  // namespace steplab
