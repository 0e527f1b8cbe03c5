#include "reports/document/claims.hpp"

#include <algorithm>
#include <cctype>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "reports/data/studies.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"

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
    if (o.id == c.id) {
      // The hand-out states again what the atlas states: the same finding, kept once (in the
      // atlas's words, which may point to a figure the hand-out leaves out).
      if (o.kind == c.kind && o.rule == c.rule && o.evidence == c.evidence) return;
      throw std::logic_error("claim id used twice: " + c.id);
    }
  claims_.push_back(std::move(c));
}

void Ledger::theory(std::string section, std::string sentence) {
  const std::pair<std::string, std::string> t(std::move(section), std::move(sentence));
  if (std::find(theory_.begin(), theory_.end(), t) == theory_.end()) theory_.push_back(t);
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
  j["theory"] = Json::array();
  for (const auto& [section, sentence] : theory_) j["theory"].push_back({{"section", section}, {"sentence", sentence}});
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

void claim_extreme_rate(Ledger& l, StabilitySource s, std::string id, std::string section, std::string sentence,
                        const std::vector<const SweepRow*>& rows, const SweepRow* extreme, Extreme which, Digits d) {
  std::vector<Evidence> values;
  std::size_t a = rows.size();
  for (const SweepRow* r : rows) {
    if (r == extreme) a = values.size();
    const auto rate = field_of(l, s, "sweep", {{"method", name(r->method)}, {"dt", r->dt}, {"damping", r->damping}}, "rate_measured");
    if (!rate) throw std::logic_error("claim_extreme_rate: " + name(r->method) + " without its sweep row");
    values.push_back(*rate);
  }
  claim_extreme(l, claim_text(std::move(id), std::move(section), std::move(sentence)), std::move(values), a, which, d);
}

void claim_least_threshold(Ledger& l, StabilitySource s, std::string id, std::string section, std::string sentence,
                           const std::vector<std::size_t>& methods, std::size_t least, double damping, const char* field, Digits d) {
  std::vector<Evidence> values;
  std::size_t a = methods.size();
  for (std::size_t m : methods) {
    const auto v = field_of(l, s, "thresholds", {{"method", name(m)}, {"damping", damping}}, field);
    if (!v) throw std::logic_error("claim_least_threshold: " + name(m) + " without its thresholds row");
    if (m == least) a = values.size();
    values.push_back(*v);
  }
  claim_extreme(l, claim_text(std::move(id), std::move(section), std::move(sentence)), std::move(values), a, Extreme::Least, d);
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

Json test_field(std::string pointer, const char* op, Json value) {
  return {{"field", std::move(pointer)}, {"op", op}, {"value", std::move(value)}};
}
Json test_difference(std::string p1, std::string p2, const char* op, double value) {
  return {{"difference", {std::move(p1), std::move(p2)}}, {"op", op}, {"value", value}};
}
Json test_scaled(std::string p1, const char* op, double times, std::string p2) {
  return {{"scaled", {std::move(p1), std::move(p2)}}, {"op", op}, {"times", times}};
}
Json test_all(std::vector<Json> tests) { return {{"all", Json(std::move(tests))}}; }
Json test_any(std::vector<Json> tests) { return {{"any", Json(std::move(tests))}}; }
Json test_not(Json test) { return {{"not", std::move(test)}}; }

namespace {

// Every row pointer a test reads (its fields, differences and scaled pairs, in any nesting).
void pointers_of(const Json& test, std::vector<std::string>& out) {
  if (test.contains("field")) out.push_back(test.at("field").get<std::string>());
  for (const char* pair : {"difference", "scaled"})
    if (test.contains(pair))
      for (const Json& p : test.at(pair)) out.push_back(p.get<std::string>());
  for (const char* list : {"all", "any"})
    if (test.contains(list))
      for (const Json& t : test.at(list)) pointers_of(t, out);
  if (test.contains("not")) pointers_of(test.at("not"), out);
}

}  // namespace

std::vector<std::string> method_names(const std::vector<std::size_t>& methods) {
  std::vector<std::string> out;
  for (std::size_t m : methods) out.push_back(name(m));
  return out;
}

void claim_members(Ledger& l, Claim c, const std::string& file, const std::string& rows, Json where, const char* key,
                   bool numerical_only, Json test, const std::vector<std::string>& set) {
  claim_members_of_all(l, std::move(c), {{file, rows, std::move(where), key, numerical_only, std::move(test)}}, set);
}

void claim_members_of_all(Ledger& l, Claim c, const std::vector<Selection>& selections, const std::vector<std::string>& set) {
  Json rules = Json::array();
  for (const Selection& s : selections) {
    std::vector<std::string> fields;
    pointers_of(s.test, fields);
    std::sort(fields.begin(), fields.end());
    fields.erase(std::unique(fields.begin(), fields.end()), fields.end());
    const Json& table = l.at(s.file, s.rows).value;
    for (std::size_t i = 0; i < table.size(); ++i) {
      const Json& row = table[i];
      if (!matches(row, s.where) || (s.numerical && !numerical(row.at(s.key).get<std::string>()))) continue;
      for (const std::string& f : fields)
        if (row.contains(Json::json_pointer(f))) {
          Evidence e = l.at(s.file, fmt::format("{}/{}{}", s.rows, i, f));
          const auto same = [&](const Evidence& o) { return o.file == e.file && o.pointer == e.pointer; };
          if (std::none_of(c.evidence.begin(), c.evidence.end(), same)) c.evidence.push_back(std::move(e));  // shared items once
        }
    }
    rules.push_back({{"file", s.file}, {"rows", s.rows}, {"where", s.where}, {"key", s.key},
                     {"over", s.numerical ? "numerical" : "all"}, {"test", s.test}});
  }
  c.kind = "membership";
  c.rule = rules.at(0);
  c.rule["set"] = set;
  if (rules.size() > 1) c.rule["and"] = Json(rules.begin() + 1, rules.end());
  l.add(std::move(c));
}

void claim_equal(Ledger& l, Claim c, const std::vector<std::pair<Evidence, Evidence>>& pairs, double relative, double absolute) {
  if (pairs.empty()) return;
  Json ij = Json::array();
  for (const auto& [a, b] : pairs) {
    ij.push_back({c.evidence.size(), c.evidence.size() + 1});
    c.evidence.push_back(a), c.evidence.push_back(b);
  }
  c.kind = "equality";
  c.rule = {{"pairs", std::move(ij)}, {"relative", relative}, {"absolute", absolute}};
  l.add(std::move(c));
}

namespace {

// A group's rule with its evidence indices moved up by `base` (the evidence before it).
Json shifted(Json rule, const std::string& kind, std::size_t base) {
  const auto up = [&](Json& i) { i = i.get<std::size_t>() + base; };
  if (kind == "equality")
    for (Json& p : rule.at("pairs")) up(p[0]), up(p[1]);
  if (kind == "threshold")
    for (Json& i : rule.at("items")) up(i);
  if (kind == "comparison") {
    up(rule.at("a"));
    for (const char* list : {"others", "noise"})
      for (Json& i : rule.at(list)) up(i);
  }
  return rule;
}

}  // namespace

ClaimGroup comparison_group(Evidence a, std::vector<Evidence> others, std::vector<Evidence> noise, const char* relation, double margin) {
  ClaimGroup g{"comparison", {}, {std::move(a)}};
  Json ids = Json::array(), noise_ids = Json::array();
  for (Evidence& e : others) ids.push_back(g.evidence.size()), g.evidence.push_back(std::move(e));
  for (Evidence& e : noise) noise_ids.push_back(g.evidence.size()), g.evidence.push_back(std::move(e));
  g.rule = {{"a", 0}, {"others", std::move(ids)}, {"relation", relation}, {"margin", margin}, {"noise", std::move(noise_ids)}};
  return g;
}

void claim_group(Ledger& l, Claim c, ClaimGroup g) {
  c.kind = std::move(g.kind), c.rule = std::move(g.rule), c.evidence = std::move(g.evidence);
  l.add(std::move(c));
}

void claim_count(Ledger& l, Claim c, std::vector<ClaimGroup> groups, int count) {
  if (groups.empty()) return;
  Json rules = Json::array();
  for (ClaimGroup& g : groups) {
    rules.push_back({{"kind", g.kind}, {"rule", shifted(std::move(g.rule), g.kind, c.evidence.size())}});
    for (Evidence& e : g.evidence) c.evidence.push_back(std::move(e));
  }
  c.kind = "count";
  c.rule = {{"groups", std::move(rules)}, {"count", count}};
  l.add(std::move(c));
}

std::string printed(double x, Digits d) { return d.significant ? fmt::format("{:.{}g}", x, d.n) : fmt::format("{:.{}f}", x, d.n); }

void claim_ratios(Ledger& l, Claim c, const std::vector<Ratio>& ratios, double least, double greatest, Digits d) {
  if (ratios.empty()) return;
  Json terms = Json::array();
  for (const Ratio& r : ratios) {
    Json over = Json::array(), under = Json::array();
    for (const Evidence& e : r.over) over.push_back(c.evidence.size()), c.evidence.push_back(e);
    for (const Evidence& e : r.under) under.push_back(c.evidence.size()), c.evidence.push_back(e);
    terms.push_back({{"over", std::move(over)}, {"under", std::move(under)}});
  }
  c.kind = "ratio";
  c.rule = {{"ratios", std::move(terms)}, {"least", printed(least, d)}, {"greatest", printed(greatest, d)},
            {"digits", {{d.significant ? "significant" : "decimals", d.n}}}};
  l.add(std::move(c));
}

void claim_extreme(Ledger& l, Claim c, std::vector<Evidence> values, std::size_t a, Extreme which, std::optional<Digits> d) {
  if (a >= values.size()) throw std::logic_error("claim_extreme: " + c.id + " without its value");
  Json others = Json::array();
  for (std::size_t k = 0; k < values.size(); ++k)
    if (k != a) others.push_back(k);
  c.kind = "extreme";
  c.rule = {{"a", a}, {"others", std::move(others)}, {"which", which == Extreme::Least ? "least" : "greatest"}};
  if (d) c.rule["printed"] = printed(values[a].value.get<double>(), *d), c.rule["digits"] = {{d->significant ? "significant" : "decimals", d->n}};
  c.evidence = std::move(values);
  l.add(std::move(c));
}

void claim_greatest_fall(Ledger& l, Claim c, const std::vector<std::pair<Evidence, Evidence>>& pairs, std::size_t a) {
  if (a >= pairs.size()) throw std::logic_error("claim_greatest_fall: " + c.id + " without its pair");
  Json others = Json::array();
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    if (k != a) others.push_back({2 * k, 2 * k + 1});
    c.evidence.push_back(pairs[k].first), c.evidence.push_back(pairs[k].second);
  }
  c.kind = "extreme";
  c.rule = {{"a", {2 * a, 2 * a + 1}}, {"others", std::move(others)}, {"which", "greatest"}};
  l.add(std::move(c));
}

void claim_mismatch(Ledger& l, Claim c, const std::vector<std::pair<Evidence, Evidence>>& pairs, std::size_t count) {
  if (pairs.empty()) return;
  Json ids = Json::array();
  for (const auto& [a, b] : pairs) ids.push_back({c.evidence.size(), c.evidence.size() + 1}), c.evidence.push_back(a), c.evidence.push_back(b);
  c.kind = "mismatch";
  c.rule = {{"pairs", std::move(ids)}, {"count", count}};
  l.add(std::move(c));
}

void claim_range(Ledger& l, const std::string& id, const std::string& section, const std::string& sentence, const Kept& k,
                 std::optional<Digits> d) {
  claim_extreme(l, claim_text(id + ".least", section, sentence), k.values, k.least, Extreme::Least, d);
  claim_extreme(l, claim_text(id + ".greatest", section, sentence), k.values, k.most, Extreme::Greatest, d);
}

Evidence row_field(const Ledger& l, const std::string& file, const std::string& rows, const Json& where, const std::string& field) {
  const Json& table = l.documents().at(file).at(Json::json_pointer(rows));
  for (std::size_t i = 0; i < table.size(); ++i) {
    bool all = true;
    for (const auto& [k, v] : where.items()) all = all && table[i].contains(k) && table[i][k] == v;
    if (all) return l.at(file, fmt::format("{}/{}/{}", rows, i, field));
  }
  throw std::logic_error("row_field: no row of " + file + rows + " matches " + where.dump());
}

}  // namespace steplab
