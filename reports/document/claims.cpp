#include "reports/document/claims.hpp"

#include <algorithm>
#include <cctype>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
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

namespace {

// Whether every field of `where` has its value in `row` (a field the row lacks: no).
bool matches(const Json& row, const Json& where) {
  for (const auto& [k, v] : where.items())
    if (!row.contains(k) || row[k] != v) return false;
  return true;
}

bool numerical(const std::string& method) {
  const auto m = find_method(method);
  return m && !method_info(*m).exact_flow;
}

}  // namespace

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

ClaimGroup comparison_group(Evidence a, std::vector<Evidence> others, const char* relation, double margin) {
  ClaimGroup g{"comparison", {}, {std::move(a)}};
  Json ids = Json::array();
  for (Evidence& e : others) ids.push_back(g.evidence.size()), g.evidence.push_back(std::move(e));
  g.rule = {{"a", 0}, {"others", std::move(ids)}, {"relation", relation}, {"margin", margin}, {"noise", Json::array()}};
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

std::optional<Evidence> find_row_field(const Ledger& l, const std::string& file, const std::string& rows, const Json& where,
                                       const std::string& field) {
  const Json& table = l.documents().at(file).at(Json::json_pointer(rows));
  for (std::size_t i = 0; i < table.size(); ++i)
    if (matches(table[i], where)) return l.at(file, fmt::format("{}/{}/{}", rows, i, field));
  return std::nullopt;
}

Evidence row_field(const Ledger& l, const std::string& file, const std::string& rows, const Json& where, const std::string& field) {
  if (std::optional<Evidence> e = find_row_field(l, file, rows, where, field)) return *e;
  throw std::logic_error("row_field: no row of " + file + rows + " matches " + where.dump());
}

}  // namespace steplab
