#include "reports/document/claims.hpp"

#include <cctype>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "reports/data/studies.hpp"
#include "reports/document/report_text.hpp"

namespace steplab {

const Json& Ledger::document(const std::string& file, const std::function<Json()>& make) {
  auto it = documents_.find(file);
  if (it == documents_.end()) it = documents_.emplace(file, make()).first;
  return it->second;
}

Evidence Ledger::at(const std::string& file, const std::string& pointer) const {
  return {file, pointer, documents_.at(file).at(Json::json_pointer(pointer))};
}

Evidence Ledger::order_of(std::size_t method) const {
  for (std::size_t k = 0; k < methods_.size(); ++k)
    if (methods_[k] == method) return {"claims.json", fmt::format("/methods/{}/order", k), method_info(method).order};
  throw std::logic_error("order_of: " + name(method) + " is not among the report's methods");
}

void Ledger::add(Claim c) {
  for (const Claim& o : claims_)
    if (o.id == c.id) throw std::logic_error("claim id used twice: " + c.id);
  claims_.push_back(std::move(c));
}

Json Ledger::json() const {
  Json j;
  j["schema"] = "steplab.claims/1";
  j["methods"] = Json::array();
  for (std::size_t m : methods_) {
    const MethodInfo& i = method_info(m);
    j["methods"].push_back({{"name", i.name}, {"family", to_string(i.family)}, {"order", i.order}, {"symplectic", i.symplectic},
                            {"exact_flow", i.exact_flow}});
  }
  j["claims"] = Json::array();
  for (const Claim& c : claims_) {
    Json e = Json::array();
    for (const Evidence& x : c.evidence) e.push_back({{"file", x.file}, {"pointer", x.pointer}, {"value", x.value}});
    j["claims"].push_back({{"id", c.id}, {"section", c.section}, {"sentence", c.sentence}, {"kind", c.kind}, {"rule", c.rule},
                           {"evidence", std::move(e)}});
  }
  return j;
}

std::string id_word(std::string_view words) {
  std::string out(words);
  for (char& ch : out) ch = ch == ' ' ? '_' : static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return out;
}

Json stability_document(const ReportData& d) { return stability_json(d.config.oscillator.params, d.thresholds, d.sweep, &d.map); }

namespace {

Json names(const std::vector<std::size_t>& methods) {
  Json out = Json::array();
  for (std::size_t m : methods) out.push_back(name(m));
  return out;
}

// The stability document the claims about stability cite, made once per ledger.
const Json& stability_doc(Ledger& l, const ReportData& d) {
  return l.document(kStabilityDocument, [&] { return stability_document(d); });
}

// Whether every field of `where` has its value in `row`.
bool matches(const Json& row, const Json& where) {
  for (const auto& [k, v] : where.items())
    if (row.at(k) != v) return false;
  return true;
}

// The measured dt* of `method` at `damping` (its thresholds row), or none where the study has no such row.
std::optional<Evidence> measured_dt(Ledger& l, const ReportData& d, std::size_t method, double damping) {
  const Json& rows = stability_doc(l, d).at("thresholds");
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (matches(rows[i], {{"method", name(method)}, {"damping", damping}}))
      return l.at(kStabilityDocument, fmt::format("/thresholds/{}/dt_measured", i));
  return std::nullopt;
}

bool numerical(const std::string& method) {
  const auto m = find_method(method);
  return m && !method_info(*m).exact_flow;
}

// Membership over the stability document's `table`: the rows whose fields equal `where`, of the
// numerical methods, whose `field` equals `equals`, are `set`.
void membership(Ledger& l, const ReportData& d, Claim c, const char* table, Json where, const char* field, Json equals,
                const std::vector<std::size_t>& set) {
  const Json& rows = stability_doc(l, d).at(table);
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (numerical(rows[i].at("method").get<std::string>()) && matches(rows[i], where))
      c.evidence.push_back(l.at(kStabilityDocument, fmt::format("/{}/{}/{}", table, i, field)));
  c.kind = "membership";
  c.rule = {{"file", kStabilityDocument}, {"rows", fmt::format("/{}", table)}, {"where", std::move(where)}, {"key", "method"},
            {"over", "numerical"}, {"field", field}, {"equals", std::move(equals)}, {"set", names(set)}};
  l.add(std::move(c));
}

}  // namespace

void claim_unstable_at(Ledger& l, const ReportData& d, std::string id, std::string section, std::string sentence, double dt,
                       double damping, const std::vector<std::size_t>& set) {
  membership(l, d, {std::move(id), std::move(section), std::move(sentence), {}, {}, {}}, "sweep", {{"dt", dt}, {"damping", damping}},
             "stable", false, set);
}

void claim_unbounded_at(Ledger& l, const ReportData& d, std::string id, std::string section, std::string sentence,
                        double damping, const std::vector<std::size_t>& set) {
  membership(l, d, {std::move(id), std::move(section), std::move(sentence), {}, {}, {}}, "thresholds", {{"damping", damping}},
             "dt_theory", "unbounded", set);
}

void claim_family_trend(Ledger& l, const ReportData& d, std::string id, std::string section, std::string sentence,
                        const FamilyTrend& t, double damping) {
  Claim c{std::move(id), std::move(section), std::move(sentence), "trend", {}, {}};
  for (std::size_t m : t.members) {
    const std::optional<Evidence> dt = measured_dt(l, d, m, damping);
    if (!dt) return;  // not measured: no claim
    c.evidence.push_back(*dt);
  }
  c.rule = {{"along", names(t.members)}, {"relative", kSameThreshold}, {"trend", to_text(t.trend)}};
  l.add(std::move(c));
}

void claim_spearman(Ledger& l, const ReportData& d, const Findings& f, std::string id, std::string section, std::string sentence,
                    int decimals) {
  Claim c{std::move(id), std::move(section), std::move(sentence), "statistic", {}, {}};
  Json x = Json::array(), y = Json::array();
  for (std::size_t m : methods_of(f, f.numerical)) {
    const std::optional<Evidence> dt = measured_dt(l, d, m, d.config.damping());
    if (!dt) return;  // a point not measured: no claim
    x.push_back(c.evidence.size());
    c.evidence.push_back(l.order_of(m));
    y.push_back(c.evidence.size());
    c.evidence.push_back(*dt);
  }
  c.rule = {{"statistic", "spearman"}, {"x", std::move(x)},          {"y", std::move(y)},
            {"value", std::stod(fmt::format("{:.{}f}", f.spearman, decimals))},  // as printed
            {"decimals", decimals},    {"words", correlation_words(f.spearman)}};
  l.add(std::move(c));
}

}  // namespace steplab
