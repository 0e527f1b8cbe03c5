// What the claims tests share: reading names and lines out of the report's markdown, making a
// report, and the classes of claims that tests/reports/claims_cost_test.cpp re-derives.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <initializer_list>
#include <regex>
#include <set>
#include <string>

#include "analysis/kernel/kernel.hpp"
#include "reports/document/report.hpp"

namespace steplab::claims {

using Names = std::set<std::string>;

inline std::string nm(std::size_t m) { return std::string(method_info(m).name); }
inline bool exact(std::size_t m) { return method_info(m).exact_flow; }

inline double& param(ReportScene& s, std::string_view name) {
  return s.params[static_cast<std::size_t>(param_index(scene_kernel(s.scene).params, name))];
}

// The line of `md` that contains `key` (from the line's start), "" if none.
inline std::string line_with(const std::string& md, const std::string& key) {
  const std::size_t a = md.find(key);
  if (a == std::string::npos) return "";
  const std::size_t start = md.rfind('\n', a) == std::string::npos ? 0 : md.rfind('\n', a) + 1;
  return md.substr(start, md.find('\n', a) - start);
}

// The backticked names of `text` between `from` and `to` (to the end if `to` is empty or absent).
inline Names names(const std::string& text, const std::string& from = "", const std::string& to = "") {
  const std::size_t a = from.empty() ? 0 : text.find(from);
  if (a == std::string::npos) return {};
  const std::size_t b = to.empty() ? std::string::npos : text.find(to, a + from.size());
  const std::string part = text.substr(a, b == std::string::npos ? std::string::npos : b - a);
  Names out;
  static const std::regex name("`([a-z_0-9]+)`");
  for (auto it = std::sregex_iterator(part.begin(), part.end(), name); it != std::sregex_iterator(); ++it) out.insert((*it)[1]);
  return out;
}

// The names after `from` up to the nearest of `ends` (or the end).
inline Names names_until(const std::string& text, const std::string& from, std::initializer_list<const char*> ends) {
  const std::size_t a = text.find(from);
  if (a == std::string::npos) return {};
  std::size_t b = std::string::npos;
  for (const char* e : ends) b = std::min(b, text.find(e, a + from.size()));
  return names(text.substr(a, b == std::string::npos ? std::string::npos : b - a));
}

inline const ThresholdRow* threshold(const ReportData& d, std::size_t m, double damping) {
  for (const ThresholdRow& r : d.thresholds)
    if (r.method == m && r.damping == damping) return &r;
  return nullptr;
}

struct Made {
  Report report;
  std::string md;
};
inline Made make(const ReportConfig& c) {
  Made out{build_report(c), ""};
  out.md = report_markdown(out.report, "png", "");
  return out;
}

// 9 .. 12, 15 (claims_cost_test.cpp): the cost section's, the collision section's and the advice's.
void cost_claims(const ReportData& d, const std::string& md);
void peer_claims(const ReportData& d, const std::string& md);
void crossover_claim(const ReportData& d, const std::string& md);
void bounce_claims(const ReportData& d, const std::string& md);
void contact_claim(const ReportData& d, const std::string& md);

}  // namespace steplab::claims
