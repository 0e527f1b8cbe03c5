#include "reports/document/claims.hpp"

#include <algorithm>
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

// The stability document of a source, made once per ledger.
const Json& stability_doc(Ledger& l, StabilitySource s) {
  return l.document(s.file, [&] { return stability_document(s.data); });
}

// Whether every field of `where` has its value in `row`.
bool matches(const Json& row, const Json& where) {
  for (const auto& [k, v] : where.items())
    if (row.at(k) != v) return false;
  return true;
}

// `field` of the first row of the stability document's `table` that matches `where`, or none.
std::optional<Evidence> field_of(Ledger& l, StabilitySource s, const char* table, const Json& where, const char* field) {
  const Json& rows = stability_doc(l, s).at(table);
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (matches(rows[i], where)) return l.at(s.file, fmt::format("/{}/{}/{}", table, i, field));
  return std::nullopt;
}

// The measured dt* of `method` at `damping` (its thresholds row), or none where the study has no such row.
std::optional<Evidence> measured_dt(Ledger& l, StabilitySource s, std::size_t method, double damping) {
  return field_of(l, s, "thresholds", {{"method", name(method)}, {"damping", damping}}, "dt_measured");
}

bool numerical(const std::string& method) {
  const auto m = find_method(method);
  return m && !method_info(*m).exact_flow;
}

// Membership over the stability document's `table`: the rows whose fields equal `where`, of the
// numerical methods, whose `field` equals `equals`, are `set`.
void membership(Ledger& l, StabilitySource s, Claim c, const char* table, Json where, const char* field, Json equals,
                const std::vector<std::size_t>& set) {
  const Json& rows = stability_doc(l, s).at(table);
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (numerical(rows[i].at("method").get<std::string>()) && matches(rows[i], where))
      c.evidence.push_back(l.at(s.file, fmt::format("/{}/{}/{}", table, i, field)));
  c.kind = "membership";
  c.rule = {{"file", s.file}, {"rows", fmt::format("/{}", table)}, {"where", std::move(where)}, {"key", "method"},
            {"over", "numerical"}, {"field", field}, {"equals", std::move(equals)}, {"set", names(set)}};
  l.add(std::move(c));
}

}  // namespace

void claim_unstable_at(Ledger& l, StabilitySource s, std::string id, std::string section, std::string sentence, double dt,
                       double damping, const std::vector<std::size_t>& set) {
  membership(l, s, {std::move(id), std::move(section), std::move(sentence), {}, {}, {}}, "sweep", {{"dt", dt}, {"damping", damping}},
             "stable", false, set);
}

void claim_unbounded_at(Ledger& l, StabilitySource s, std::string id, std::string section, std::string sentence,
                        double damping, const std::vector<std::size_t>& set) {
  membership(l, s, {std::move(id), std::move(section), std::move(sentence), {}, {}, {}}, "thresholds", {{"damping", damping}},
             "dt_theory", "unbounded", set);
}

void claim_rate(Ledger& l, StabilitySource s, std::string id, std::string section, std::string sentence, double dt,
                double damping, const std::vector<std::size_t>& methods, const char* op, double limit) {
  if (methods.empty()) return;
  Claim c{std::move(id), std::move(section), std::move(sentence), "threshold", {{"op", op}, {"limit", limit}}, {}};
  for (std::size_t m : methods) {
    const std::optional<Evidence> rate = field_of(l, s, "sweep", {{"method", name(m)}, {"dt", dt}, {"damping", damping}}, "rate_measured");
    if (!rate) throw std::logic_error("claim_rate: " + name(m) + " without its sweep row");
    c.evidence.push_back(*rate);
  }
  l.add(std::move(c));
}

void claim_cheapest(Ledger& l, const ReportData& d, std::string id, std::string section, std::string sentence, const SceneWork& w,
                    double level, bool timed, const LevelWinner& win) {
  if (!win.point || !win.undecided.empty()) return;
  l.document(kWorkDocument, [&] { return work_precision_json(d.work); });
  const std::size_t s = static_cast<std::size_t>(&w - d.work.scenes.data());
  const auto at = [&](const WorkPoint* p, const char* field) {
    return l.at(kWorkDocument, fmt::format("/scenes/{}/points/{}/{}", s, p - w.points.data(), field));
  };
  const char* cost = timed ? "seconds" : "force_evaluations";
  Claim c{std::move(id), std::move(section), std::move(sentence), "comparison", {}, {}};
  std::vector<const WorkPoint*> others;  // the runner-up first, then every other solver's cheapest run
  std::vector<std::string> seen{win.point->method};
  for (const WorkPoint& p : w.points)
    if (std::find(seen.begin(), seen.end(), p.method) == seen.end()) {
      seen.push_back(p.method);
      if (const WorkPoint* q = cheapest_point(w, p.method, level, timed))
        others.insert(p.method == win.next ? others.begin() : others.end(), q);
    }
  c.evidence.push_back(at(win.point, cost));
  Json ids = Json::array(), noise = Json::array();
  for (const WorkPoint* p : others) ids.push_back(c.evidence.size()), c.evidence.push_back(at(p, cost));
  if (timed && !others.empty()) {
    noise.push_back(c.evidence.size()), c.evidence.push_back(at(win.point, "seconds_spread"));
    noise.push_back(c.evidence.size()), c.evidence.push_back(at(others.front(), "seconds_spread"));
  }
  c.rule = {{"a", 0}, {"others", std::move(ids)}, {"relation", win.tie ? "tie" : "less"}, {"margin", timed ? kTieMargin : 1.0},
            {"noise", std::move(noise)}};
  l.add(std::move(c));
}

void claim_family_trend(Ledger& l, StabilitySource s, std::string id, std::string section, std::string sentence,
                        const FamilyTrend& t, double damping) {
  Claim c{std::move(id), std::move(section), std::move(sentence), "trend", {}, {}};
  for (std::size_t m : t.members) {
    const std::optional<Evidence> dt = measured_dt(l, s, m, damping);
    if (!dt) return;  // not measured: no claim
    c.evidence.push_back(*dt);
  }
  c.rule = {{"along", names(t.members)}, {"relative", kSameThreshold}, {"trend", to_text(t.trend)}};
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
