#include "reports/data/inputs.hpp"

#include "core/simulate.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include <fmt/format.h>

namespace steplab {

std::string_view describe(Bound b) {
  switch (b) {
    case Bound::Positive: return "a finite number > 0";
    case Bound::NonNegative: return "a finite number >= 0";
    case Bound::Fraction: return "a number >= 0 and < 1";
    case Bound::Any: return "a finite number";
  }
  return "a number";
}

double check_number(std::string_view what, double value, Bound bound) {
  const bool ok = std::isfinite(value) && (bound != Bound::Positive || value > 0) &&
                  (bound != Bound::NonNegative || value >= 0) && (bound != Bound::Fraction || (value >= 0 && value < 1));
  if (!ok) throw UsageError(fmt::format("{} = {} is out of range; accepted: {}", what, value, describe(bound)));
  return value;
}

double parse_number(std::string_view what, std::string_view text, Bound bound) {
  double value = 0;
  const auto* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec == std::errc::invalid_argument || ptr != end)
    throw UsageError(fmt::format("{} '{}' is not a number; accepted: {}", what, text, describe(bound)));
  if (ec == std::errc::result_out_of_range || !std::isfinite(value))
    throw UsageError(fmt::format("{} '{}' is not finite; accepted: {}", what, text, describe(bound)));
  return check_number(what, value, bound);
}

long long parse_count(std::string_view what, std::string_view text, long long lo, long long hi) {
  long long value = 0;
  const auto* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || value < lo || value > hi)
    throw UsageError(fmt::format("{} '{}' is not accepted; accepted: a whole number from {} to {}", what, text, lo, hi));
  return value;
}

std::vector<std::string> split_list(std::string_view text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    std::string_view item = text.substr(start, comma - start);
    while (!item.empty() && std::isspace(static_cast<unsigned char>(item.front()))) item.remove_prefix(1);
    while (!item.empty() && std::isspace(static_cast<unsigned char>(item.back()))) item.remove_suffix(1);
    out.emplace_back(item);
    start = comma + 1;
  }
  return out;
}

namespace {

// Optimal string alignment distance: insertions, deletions, substitutions and swaps of two
// neighbours, one edit each (Damerau's typo model).
std::size_t typo_distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

}  // namespace

std::string did_you_mean(std::string_view typed, const std::vector<std::string>& candidates) {
  const std::string* best = nullptr;
  std::size_t best_distance = 3;  // at most two edits
  for (const std::string& c : candidates) {
    const std::size_t d = typo_distance(typed, c);
    if (d < best_distance && 2 * d < typed.size()) best = &c, best_distance = d;
  }
  return best ? fmt::format(" (did you mean '{}'?)", *best) : "";
}

long long step_count(double t_end, double dt) {
  const double ratio = t_end / dt;
  if (!(ratio <= static_cast<double>(max_steps)))
    throw UsageError(fmt::format("--t-end {} with --dt {} needs {:.3g} steps; accepted: at most {} steps", t_end, dt,
                                 ratio, max_steps));
  return steps_for(t_end, dt);
}

std::vector<double> number_list(std::string_view what, const std::string& text, Bound bound) {
  std::vector<double> out;
  for (const std::string& item : split_list(text)) out.push_back(parse_number(what, item, bound));
  return out;
}

void check_distinct(std::string_view what, const std::vector<double>& values) {
  for (std::size_t i = 0; i < values.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (values[i] == values[j])
        throw UsageError(fmt::format("{} names {} twice; accepted: each value once", what, values[i]));
}

void check_increasing(std::string_view what, const std::vector<double>& values) {
  for (std::size_t i = 1; i < values.size(); ++i)
    if (!(values[i] > values[i - 1]))
      throw UsageError(fmt::format("{} are not increasing ({} after {}); accepted: strictly increasing values", what, values[i],
                                   values[i - 1]));
}

}  // namespace steplab
