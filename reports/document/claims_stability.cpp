// The claims about the spring's stability study (claims.hpp): which runs are stable, the
// thresholds measured against the predicted ones, how dt* moves along a family, Spearman's rho of
// order against dt*, the rates of the unstable runs and the map's cells, each over the rows of the
// stability document (data/stability/stability.json, or the methods on springs').
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "reports/studies/studies.hpp"
#include "reports/document/claims.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"

namespace steplab {

Json stability_document(const ReportData& d) { return stability_json(d.config.oscillator.params, d.thresholds, d.sweep, &d.map); }

namespace {

// The stability document of a source, made once per ledger.
const Json& stability_doc(Ledger& l, StabilitySource s) {
  return l.document(s.file, [&] { return stability_document(s.data); });
}

// `field` of the first row of the stability document's `table` that matches `where`, or none.
std::optional<Evidence> field_of(Ledger& l, StabilitySource s, const char* table, const Json& where, const char* field) {
  stability_doc(l, s);
  return find_row_field(l, s.file, fmt::format("/{}", table), where, field);
}

// The measured dt* of `method` at `damping` (its thresholds row), or none where the study has no such row.
std::optional<Evidence> measured_dt(Ledger& l, StabilitySource s, std::size_t method, double damping) {
  return field_of(l, s, "thresholds", {{"method", name(method)}, {"damping", damping}}, "dt_measured");
}

// Membership over the stability document's `table`: the rows whose fields equal `where`, of the
// numerical methods, whose `field` equals `equals`, are `set`.
void membership(Ledger& l, StabilitySource s, Claim c, const char* table, Json where, const char* field, Json equals,
                const std::vector<std::size_t>& set) {
  stability_doc(l, s);
  claim_members(l, std::move(c), s.file, fmt::format("/{}", table), std::move(where), "method", true,
                test_field(fmt::format("/{}", field), "==", std::move(equals)), method_names(set));
}

}  // namespace

std::vector<ShownStudy> shown_studies(const Page& page) {
  std::vector<ShownStudy> out{{{page.data, kStabilityDocument}, page.findings, ""}};
  if (page.springs) out.push_back({{*page.springs, kSpringsStabilityDocument}, *page.springs_findings, ".springs"});
  return out;
}

void claim_unstable_at(Ledger& l, StabilitySource s, std::string id, std::string section, std::string sentence, double dt,
                       double damping, const std::vector<std::size_t>& set) {
  membership(l, s, claim_text(std::move(id), std::move(section), std::move(sentence)), "sweep", {{"dt", dt}, {"damping", damping}},
             "stable", false, set);
}

void claim_unbounded_at(Ledger& l, StabilitySource s, std::string id, std::string section, std::string sentence,
                        double damping, const std::vector<std::size_t>& set) {
  membership(l, s, claim_text(std::move(id), std::move(section), std::move(sentence)), "thresholds", {{"damping", damping}},
             "dt_theory", "unbounded", set);
}

namespace {

// A method's measured and predicted dt* at `damping`, from its thresholds row.
std::pair<Evidence, Evidence> measured_and_predicted(Ledger& l, StabilitySource s, std::size_t m, double damping) {
  const Json where = {{"method", name(m)}, {"damping", damping}};
  const std::optional<Evidence> measured = field_of(l, s, "thresholds", where, "dt_measured"),
                                theory = field_of(l, s, "thresholds", where, "dt_theory");
  if (!measured || !theory) throw std::logic_error(name(m) + " has no thresholds row at that damping");
  return {*measured, *theory};
}

}  // namespace

void claim_thresholds_agree(Ledger& l, StabilitySource s, std::string id, std::string section, std::string sentence,
                            const std::vector<std::pair<std::size_t, double>>& cases, double relative, std::size_t agree) {
  std::vector<ClaimGroup> groups;
  for (const auto& [m, damping] : cases) {
    auto [measured, theory] = measured_and_predicted(l, s, m, damping);
    groups.push_back({"equality", {{"pairs", {{0, 1}}}, {"relative", relative}, {"absolute", 0}}, {std::move(measured), std::move(theory)}});
  }
  claim_count(l, claim_text(std::move(id), std::move(section), std::move(sentence)), std::move(groups), static_cast<int>(agree));
}

void claim_measured_as_predicted(Ledger& l, StabilitySource s, std::string id, std::string section, std::string sentence,
                                 const std::vector<std::size_t>& methods, double damping, double relative) {
  std::vector<std::pair<Evidence, Evidence>> pairs;
  for (std::size_t m : methods) pairs.push_back(measured_and_predicted(l, s, m, damping));
  claim_equal(l, claim_text(std::move(id), std::move(section), std::move(sentence)), pairs, relative, 0);
}

void claim_sweep(Ledger& l, StabilitySource s, std::string id, std::string section, std::string sentence, double dt,
                 double damping, const std::vector<std::size_t>& methods, const char* field, const char* op, double limit) {
  if (methods.empty()) return;
  Claim c{std::move(id), std::move(section), std::move(sentence), "threshold", {{"op", op}, {"limit", limit}}, {}};
  for (std::size_t m : methods) {
    const std::optional<Evidence> v = field_of(l, s, "sweep", {{"method", name(m)}, {"dt", dt}, {"damping", damping}}, field);
    if (!v) throw std::logic_error("claim_sweep: " + name(m) + " without its sweep row");
    c.evidence.push_back(*v);
  }
  l.add(std::move(c));
}

void claim_map_cells(Ledger& l, StabilitySource s, std::string id, std::string section, std::string sentence, std::size_t disagree) {
  stability_doc(l, s);
  std::vector<std::pair<Evidence, Evidence>> pairs;
  for (std::size_t m : s.data.map.methods)
    pairs.push_back({l.at(s.file, "/map/stable/" + name(m)), l.at(s.file, "/map/predicted/" + name(m))});
  claim_mismatch(l, claim_text(std::move(id), std::move(section), std::move(sentence)), pairs, disagree);
}

void claim_stability_extreme(Ledger& l, StabilitySource s, Claim c, const char* table, const std::vector<Json>& rows, std::size_t a,
                             const char* field, Extreme which, Digits d) {
  std::vector<Evidence> values;
  for (const Json& where : rows) {
    const std::optional<Evidence> v = field_of(l, s, table, where, field);
    if (!v) throw std::logic_error("claim_stability_extreme: no " + std::string(table) + " row " + where.dump());
    values.push_back(*v);
  }
  claim_extreme(l, std::move(c), std::move(values), a, which, d);
}

void claim_unstable_runs(Ledger& l, StabilitySource s, const std::string& section, const std::string& at, const std::string& sentence,
                         double dt, double damping, const std::vector<MethodRate>& runs, bool strong) {
  claim_rate(l, s, fmt::format("{}.weakly_unstable_{}", section, at), section, sentence, dt, damping, weakly(runs), "<", kWeakRate);
  claim_sweep(l, s, fmt::format("{}.weakly_unstable_{}.near_e0", section, at), section, sentence, dt, damping, weakly(runs),
              "energy_ratio_max", "<=", kBlownRatio);
  claim_sweep(l, s, fmt::format("{}.far_from_e0_{}", section, at), section, sentence, dt, damping, far_from_e0(runs), "energy_ratio_max",
              ">", kBlownRatio);
  if (strong)
    claim_rate(l, s, fmt::format("{}.strongly_unstable_{}", section, at), section, sentence, dt, damping, strongly(runs), ">=", kWeakRate);
}

void claim_family_trend(Ledger& l, StabilitySource s, std::string id, std::string section, std::string sentence,
                        const FamilyTrend& t, double damping) {
  Claim c{std::move(id), std::move(section), std::move(sentence), "trend", {}, {}};
  for (std::size_t m : t.members) {
    const std::optional<Evidence> dt = measured_dt(l, s, m, damping);
    if (!dt) return;  // not measured: no claim
    c.evidence.push_back(*dt);
  }
  c.rule = {{"along", method_names(t.members)}, {"relative", kSameThreshold}, {"trend", to_text(t.trend)}};
  l.add(std::move(c));
}

std::vector<StabilityPoint> spearman_points(StabilitySource s, const Findings& f) {
  std::vector<StabilityPoint> out;
  for (std::size_t m : methods_of(f, f.numerical)) out.push_back({s, m});
  return out;
}

void claim_spearman(Ledger& l, const std::vector<StabilityPoint>& points, double value, std::string id, std::string section,
                    std::string sentence, int decimals) {
  Claim c{std::move(id), std::move(section), std::move(sentence), "statistic", {}, {}};
  Json x = Json::array(), y = Json::array();
  for (const StabilityPoint& p : points) {
    const std::optional<Evidence> dt = measured_dt(l, p.source, p.method, p.source.data.config.damping());
    if (!dt) return;  // a point not measured: no claim
    x.push_back(c.evidence.size());
    c.evidence.push_back(l.order_of(p.method));
    y.push_back(c.evidence.size());
    c.evidence.push_back(*dt);
  }
  c.rule = {{"statistic", "spearman"}, {"x", std::move(x)},          {"y", std::move(y)},
            {"value", std::stod(fmt::format("{:.{}f}", value, decimals))},  // as printed
            {"decimals", decimals},    {"words", correlation_words(value)}};
  l.add(std::move(c));
}

}  // namespace steplab
