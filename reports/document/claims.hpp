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
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "reports/document/findings.hpp"

namespace steplab {

using Json = nlohmann::ordered_json;

struct Evidence {
  std::string file;     // under data/; "claims.json" is the ledger itself (its methods table)
  std::string pointer;  // RFC 6901
  Json value;           // what the pointer finds there
};

struct Claim {
  std::string id, section, sentence, kind;  // kind: membership, trend, statistic, threshold, comparison (docs/json.md)
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
  Json json() const;  // schema, methods, claims
  const std::map<std::string, Json>& documents() const { return documents_; }
  std::size_t size() const { return claims_.size(); }

 private:
  std::vector<std::size_t> methods_;
  std::map<std::string, Json> documents_;
  std::vector<Claim> claims_;
};

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

// "The methods in `set` are exactly those of the stability study's sweep at (dt, damping) whose
// run is unstable": a membership claim over the source's numerical methods.
void claim_unstable_at(Ledger& l, StabilitySource s, std::string id, std::string section, std::string sentence, double dt,
                       double damping, const std::vector<std::size_t>& set);
// "The methods in `set` are exactly those whose predicted dt* at `damping` is unbounded".
void claim_unbounded_at(Ledger& l, StabilitySource s, std::string id, std::string section, std::string sentence,
                        double damping, const std::vector<std::size_t>& set);
// "The runs of `methods` at (dt, damping) grow their energy at a rate `op` `limit`" (op "<", "<=",
// ">" or ">="): a threshold claim on each one's measured rate (the weakly unstable ones: below
// kWeakRate); none for no method.
void claim_rate(Ledger& l, StabilitySource s, std::string id, std::string section, std::string sentence, double dt,
                double damping, const std::vector<std::size_t>& methods, const char* op, double limit);
// The work-precision study as the report writes it, data/cost/work_precision.json.
inline constexpr const char* kWorkDocument = "cost/work_precision.json";
// "The cheapest run to error `level` on scene `w` is `win`'s, by its margin or tied with the
// runner-up": a comparison claim over each solver's cheapest run at the level (by run time, with
// the two runs' timing spreads as the noise, or untimed by force evaluations); none where no run
// reached the level or the winner is undecided.
void claim_cheapest(Ledger& l, const ReportData& d, std::string id, std::string section, std::string sentence, const SceneWork& w,
                    double level, bool timed, const LevelWinner& win);
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

}  // namespace steplab
