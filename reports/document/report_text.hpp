// Small text helpers the report's sections share: method names, numbers as the report prints
// them, lists of methods in a sentence, fitted orders, and data-file lines.
#pragma once

#include <algorithm>
#include <cstddef>
#include <ranges>
#include <string>
#include <utility>
#include <vector>

#include "analysis/studies/convergence.hpp"
#include "analysis/kernel/counts.hpp"
#include "core/method.hpp"
#include "reports/document/report.hpp"

namespace steplab {

std::string name(std::size_t method);                     // the method's table name
std::string dt_text(double x);                            // 4 significant digits, inf, or - for NaN
std::string table_dt(double x);                           // the same for a table: $\infty$ for inf
std::string num(double x);                                // full precision for data files; NaN if not finite
std::string order_text(std::size_t method);               // declared order, or "exact"
std::string fitted_text(const ConvergenceFit& fit);       // headline order and its bound
std::string and_list(const std::vector<std::string>& items);       // a, b and c
inline std::string without_final_newlines(const std::string& s) { return s.substr(0, s.find_last_not_of('\n') + 1); }
std::string method_list(const std::vector<std::size_t>& methods);  // `a`, `b` and `c`; "none"
std::vector<std::size_t> sheet_methods();                           // the sheet's four, in its order (not the exact flow)
std::string quoted_list(const std::vector<std::string>& names);    // `a`, `b` and `c` (a method's or a peer's)
std::string fits_table(const ConvergenceResult& r);       // the Markdown table of fitted orders (not the exact ones)
// "mass 1, stiffness 5, ..." in table order; `skip`: a parameter's index to leave out (-1: none).
std::string params_text(std::size_t scene, const std::vector<double>& values, int skip = -1);
// The characters of code a line of the PDF holds: 18 cm of text width (A4, 1.5 cm margins) in 10 pt
// Latin Modern Typewriter, 0.525 em a character, hold 97; a few kept spare.
inline constexpr std::size_t kCodeColumns = 88;
// The first row of `rows` with the least `key` among those `keep` accepts, and the first with the
// greatest (both null where it accepts none): a figure caption's extremes.
template <class Row, class Keep, class Key>
std::pair<const Row*, const Row*> least_and_most(const std::vector<Row>& rows, Keep keep, Key key) {
  auto kept = rows | std::views::filter(keep);
  const auto least = std::ranges::min_element(kept, {}, key), most = std::ranges::max_element(kept, {}, key);
  if (least == kept.end()) return {nullptr, nullptr};
  return {&*least, &*most};
}
std::string wrapped(const std::string& cmd);              // a shell command broken for the page, a long list after a comma
std::string words(const std::vector<double>& v);          // gnuplot word list: "a b c"
std::string join(const std::vector<double>& v);           // CLI list: "a,b,c"
// x to two significant digits as "{:.2g}" prints it, rounded down or up so that the printed value
// is a bound ("by 3e-06 or more", "to within 1.8e-15"); x itself where not finite and positive.
double two_digits(double x, bool up);
std::string join(const std::vector<int>& v);
std::string method_words(const std::vector<std::size_t>& methods);

// The families the report groups methods by, and a family's members among `methods` (its own
// and those that open it: explicit Euler for Adams-Bashforth, implicit Euler for BDF), by order.
inline constexpr Family kReportFamilies[] = {Family::ExplicitRungeKutta, Family::Splitting, Family::ImplicitRungeKutta,
                                             Family::AdamsBashforth, Family::Bdf};
std::vector<std::size_t> family_members(const std::vector<std::size_t>& methods, Family f);
bool family_order_less(std::size_t a, std::size_t b);  // by family, then order, then table position

}  // namespace steplab
