// A study's parameters, declared once: a table of StudyParam<Config> beside the study's command,
// as a scene's ParamSpec table declares the scene's. From the table come the command's options and
// their help (add_params), the one rule each value is checked by, whether it is typed on the
// command line (read_params) or given in a report's configuration (param_from_json). A rule between parameters (fit-from below periods) is the study's own
// check, called on the Config both ways.
#pragma once

#include <cmath>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "reports/data/inputs.hpp"

namespace steplab {

template <class C>
struct StudyParam {
  std::string_view name;  // the option --<name>; its key in a configuration file with '_' for '-'
  std::string_view help;  // the table adds the range accepted and the default
  double lo, hi;          // accepted, inclusive; an int field's values are whole numbers
  std::variant<double C::*, int C::*, std::vector<int> C::*> field;  // a list: comma-separated
};

// "1e5" for 100000, "0.002", "10": the shorter of the plain and the exponent form.
inline std::string short_number(double v) {
  const std::string plain = fmt::format("{}", v);
  std::string e = fmt::format("{:e}", v);  // 1.000000e+05
  const std::size_t at = e.find('e');
  std::string mantissa = e.substr(0, at), exponent = e.substr(at + 1);
  while (mantissa.find('.') != std::string::npos && (mantissa.back() == '0' || mantissa.back() == '.')) mantissa.pop_back();
  if (exponent[0] == '+') exponent.erase(0, 1);
  const bool negative = exponent[0] == '-';
  exponent.erase(0, negative ? 1 : 0);
  while (exponent.size() > 1 && exponent[0] == '0') exponent.erase(0, 1);
  const std::string compact = mantissa + "e" + (negative ? "-" : "") + exponent;
  return compact.size() + 2 <= plain.size() ? compact : plain;
}

// The rule: `value` (shown as `shown`, as typed or read) within [lo, hi], or one UsageError naming `where`.
template <class C>
void check_param(const StudyParam<C>& p, std::string_view where, double value, std::string_view shown) {
  if (!(value >= p.lo && value <= p.hi))
    throw UsageError(fmt::format("{} {} is out of range; accepted: {} .. {}", where, shown, short_number(p.lo), short_number(p.hi)));
}

// The command's options, each with its range and the default `c` holds (a list's default is the
// study's, said in its help); `text` receives what is typed, by name.
template <class C>
void add_params(CLI::App* cmd, std::span<const StudyParam<C>> table, std::map<std::string, std::string>& text, const C& c) {
  for (const StudyParam<C>& p : table) {
    std::string& t = text[std::string(p.name)];
    std::string help = fmt::format("{} ({} .. {})", p.help, short_number(p.lo), short_number(p.hi));
    if (const auto* d = std::get_if<double C::*>(&p.field)) t = short_number(c.**d);
    if (const auto* i = std::get_if<int C::*>(&p.field)) t = fmt::format("{}", c.**i);
    CLI::Option* o = cmd->add_option("--" + std::string(p.name), t, help);
    if (!t.empty()) o->capture_default_str();
  }
}

// The values typed into `c`, each checked by its rule.
template <class C>
void read_params(std::span<const StudyParam<C>> table, const std::map<std::string, std::string>& text, C& c) {
  for (const StudyParam<C>& p : table) {
    const std::string& t = text.at(std::string(p.name));
    if (t.empty()) continue;
    const std::string where = "--" + std::string(p.name);
    if (const auto* d = std::get_if<double C::*>(&p.field)) {
      c.**d = parse_number(where, t, Bound::Any);
      check_param(p, where, c.**d, t);
    } else if (const auto* i = std::get_if<int C::*>(&p.field)) {
      c.**i = static_cast<int>(parse_count(where, t, static_cast<long long>(p.lo), static_cast<long long>(p.hi)));
    } else {
      std::vector<int>& list = c.*std::get<std::vector<int> C::*>(p.field);
      list.clear();
      for (const std::string& item : split_list(t))
        list.push_back(static_cast<int>(parse_count(where, item, static_cast<long long>(p.lo), static_cast<long long>(p.hi))));
    }
  }
}

// The parameter `name` of the table from a configuration file's `value` (`where`: "config:
// long_time.periods"), checked by the same rule.
template <class C>
void param_from_json(std::span<const StudyParam<C>> table, std::string_view name, const nlohmann::ordered_json& value,
                     std::string_view where, C& c) {
  for (const StudyParam<C>& p : table) {
    if (p.name != name) continue;
    if (!value.is_number()) throw UsageError(fmt::format("{} is not a number; accepted: {} .. {}", where, short_number(p.lo), short_number(p.hi)));
    const double v = value.get<double>();
    check_param(p, where, v, short_number(v));
    if (const auto* d = std::get_if<double C::*>(&p.field)) c.**d = v;
    else if (const auto* i = std::get_if<int C::*>(&p.field)) {
      if (v != std::floor(v))
        throw UsageError(fmt::format("{} {} is not a whole number; accepted: {} .. {}", where, short_number(v), short_number(p.lo),
                                     short_number(p.hi)));
      c.**i = static_cast<int>(v);
    }
    return;
  }
}

}  // namespace steplab
