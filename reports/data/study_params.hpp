// A study's parameters, declared once: a table of StudyParam<Config> beside the study's writers,
// as a scene's ParamSpec table declares the scene's. From the table come the command's options,
// their help and value kind (add_params), the one rule each value is checked by, whether it is
// typed on the command line (read_params) or given in a report's configuration (params_from_json),
// and the configuration's keys with their defaults (params_json). A rule between parameters
// (dt-min below dt-max, fit-from below periods) is the study's own check, called on the Config
// both ways with a ParamNamer that says how the value arrived.
#pragma once

#include <cmath>
#include <functional>
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

// The values a parameter accepts: lo .. hi inclusive, or above lo where lo_open (a step, a time:
// > 0). An int field's values are whole numbers.
struct Range {
  double lo, hi;
  bool lo_open = false;
};
inline constexpr Range kPositive{0, INFINITY, true};
inline constexpr Range kNonNegative{0, INFINITY};

template <class C>
struct StudyParam {
  std::string_view name;  // the option --<name>; its key in a configuration file with '_' for '-'
  std::string_view help;  // the table adds the range accepted and the default
  Range range;
  // A list is comma-separated on the command line, an array in a configuration file.
  std::variant<double C::*, int C::*, long long C::*, std::vector<int> C::*, std::vector<double> C::*> field;
  // Where the study chooses the default itself (it depends on other input): that choice in words,
  // and the option starts empty.
  std::string_view default_help = {};
  std::string_view key = {};  // its configuration key where that is not the name's (stability's sweep_dts: --dts)
};

// Which rows a command offers, where two commands share a table (`study damping`, `study stability`).
using ParamFilter = bool (*)(std::string_view name);

inline std::string option_name(std::string_view name) { return fmt::format("--{}", name); }
inline std::string config_key(std::string_view name) {
  std::string key(name);
  for (char& ch : key) ch = ch == '-' ? '_' : ch;
  return key;
}
template <class C>
std::string config_key(const StudyParam<C>& p) { return p.key.empty() ? config_key(p.name) : std::string(p.key); }

// How a rule names a parameter: "--dt-min" typed, "convergence.dt_min" in a configuration, whose
// messages begin with its origin, "config: ".
struct ParamNamer {
  std::string origin;
  std::function<std::string(std::string_view)> name = option_name;
  std::string operator()(std::string_view param) const { return name(param); }
};
inline ParamNamer option_names() { return {}; }
inline ParamNamer config_names(const std::string& section) {
  return {"config: ", [section](std::string_view param) { return fmt::format("{}.{}", section, config_key(param)); }};
}

// "1e5" for 100000, "0.002", "10": the shorter of the plain and the exponent form, either read
// back as `v` exactly.
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
  return compact.size() + 2 <= plain.size() && std::stod(compact) == v ? compact : plain;
}

// "1 .. 1e7", "> 0", ">= 0".
inline std::string range_text(const Range& r) {
  if (std::isinf(r.hi)) return fmt::format("{} {}", r.lo_open ? ">" : ">=", short_number(r.lo));
  return fmt::format("{}{} .. {}", r.lo_open ? "above " : "", short_number(r.lo), short_number(r.hi));
}

// The rule: `value` (shown as `shown`, as typed or read) within the range, or one UsageError naming `where`.
template <class C>
void check_param(const StudyParam<C>& p, std::string_view where, double value, std::string_view shown) {
  const bool above = p.range.lo_open ? value > p.range.lo : value >= p.range.lo;
  if (!(above && value <= p.range.hi && std::isfinite(value)))
    throw UsageError(fmt::format("{} {} is out of range; accepted: {}", where, shown, range_text(p.range)));
}

// A whole number for an int field (`shown` as typed or read), checked by the rule (whose range
// an int field's holds).
template <class C>
long long whole_param(const StudyParam<C>& p, std::string_view where, std::string_view shown, double value) {
  if (value != std::floor(value))
    throw UsageError(fmt::format("{} {} is not a whole number; accepted: {}", where, shown, range_text(p.range)));
  check_param(p, where, value, shown);
  return static_cast<long long>(value);
}

// The command's options (the rows `keep` keeps), each with its value kind, its range and the
// default `c` holds (a list's default is its values); `text` receives what is typed, by name.
template <class C>
void add_params(CLI::App* cmd, std::span<const StudyParam<C>> table, std::map<std::string, std::string>& text, const C& c,
                ParamFilter keep = nullptr) {
  for (const StudyParam<C>& p : table) {
    if (keep && !keep(p.name)) continue;
    std::string& t = text[std::string(p.name)];
    std::string help = fmt::format("{} ({})", p.help, range_text(p.range)), kind = "NUMBER";
    if (std::holds_alternative<int C::*>(p.field) || std::holds_alternative<long long C::*>(p.field)) kind = "WHOLE";
    if (std::holds_alternative<std::vector<double> C::*>(p.field)) kind = "NUMBER,...";
    if (std::holds_alternative<std::vector<int> C::*>(p.field)) kind = "WHOLE,...";
    if (!p.default_help.empty()) help += fmt::format(" (default {})", p.default_help);
    else if (const auto* d = std::get_if<double C::*>(&p.field)) t = short_number(c.**d);
    else if (const auto* i = std::get_if<int C::*>(&p.field)) t = fmt::format("{}", c.**i);
    else if (const auto* n = std::get_if<long long C::*>(&p.field)) t = fmt::format("{}", c.**n);
    else if (const auto* l = std::get_if<std::vector<double> C::*>(&p.field))
      for (double v : c.**l) t += fmt::format("{}{}", t.empty() ? "" : ",", short_number(v));
    else
      for (int v : c.*std::get<std::vector<int> C::*>(p.field)) t += fmt::format("{}{}", t.empty() ? "" : ",", v);
    CLI::Option* o = cmd->add_option(option_name(p.name), t, help)->type_name(kind);
    if (!t.empty()) o->capture_default_str();
  }
}

// The values typed into `c`, each checked by its rule (an option left empty, or not offered,
// keeps `c`'s value).
template <class C>
void read_params(std::span<const StudyParam<C>> table, const std::map<std::string, std::string>& text, C& c) {
  for (const StudyParam<C>& p : table) {
    const auto typed = text.find(std::string(p.name));
    if (typed == text.end() || typed->second.empty()) continue;
    const std::string& t = typed->second;
    const std::string where = option_name(p.name);
    const auto one = [&](const std::string& item) {
      const double v = parse_number(where, item, Bound::Any);
      check_param(p, where, v, item);
      return v;
    };
    const auto whole = [&](const std::string& item) { return whole_param(p, where, item, parse_number(where, item, Bound::Any)); };
    if (const auto* d = std::get_if<double C::*>(&p.field)) c.**d = one(t);
    else if (const auto* i = std::get_if<int C::*>(&p.field)) c.**i = static_cast<int>(whole(t));
    else if (const auto* n = std::get_if<long long C::*>(&p.field)) c.**n = whole(t);
    else if (const auto* l = std::get_if<std::vector<double> C::*>(&p.field)) {
      (c.**l).clear();
      for (const std::string& item : split_list(t)) (c.**l).push_back(one(item));
    } else {
      std::vector<int>& list = c.*std::get<std::vector<int> C::*>(p.field);
      list.clear();
      for (const std::string& item : split_list(t)) list.push_back(static_cast<int>(whole(item)));
    }
  }
}

// The configuration's object of these parameters, keyed by config_key, with `c`'s values.
template <class C>
nlohmann::ordered_json params_json(std::span<const StudyParam<C>> table, const C& c) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const StudyParam<C>& p : table)
    std::visit([&](auto field) { j[config_key(p)] = c.*field; }, p.field);
  return j;
}

// The parameters of the table found in the configuration object `j` (section `section`: its keys
// are named "config: section.key"), each checked by the same rule as typed. A list must be a
// non-empty array.
template <class C>
void params_from_json(std::span<const StudyParam<C>> table, const nlohmann::ordered_json& j, const std::string& section, C& c) {
  for (const StudyParam<C>& p : table) {
    const std::string key = config_key(p);
    if (!j.contains(key)) continue;
    const nlohmann::ordered_json& value = j[key];
    const std::string where = fmt::format("config: {}.{}", section, key);
    const auto one = [&](const nlohmann::ordered_json& x) {
      if (!x.is_number()) throw UsageError(fmt::format("{} is not a number; accepted: {}", where, range_text(p.range)));
      const double v = x.get<double>();
      check_param(p, where, v, short_number(v));
      return v;
    };
    const bool list = std::holds_alternative<std::vector<double> C::*>(p.field) || std::holds_alternative<std::vector<int> C::*>(p.field);
    if (list && (!value.is_array() || value.empty()))
      throw UsageError(fmt::format("{} is not a non-empty array; accepted: numbers {}", where, range_text(p.range)));
    const auto whole = [&](const nlohmann::ordered_json& x) {
      const double v = one(x);
      return whole_param(p, where, short_number(v), v);
    };
    if (const auto* d = std::get_if<double C::*>(&p.field)) c.**d = one(value);
    else if (const auto* i = std::get_if<int C::*>(&p.field)) c.**i = static_cast<int>(whole(value));
    else if (const auto* n = std::get_if<long long C::*>(&p.field)) c.**n = whole(value);
    else if (const auto* l = std::get_if<std::vector<double> C::*>(&p.field)) {
      (c.**l).clear();
      for (const auto& x : value) (c.**l).push_back(one(x));
    } else {
      std::vector<int>& out = c.*std::get<std::vector<int> C::*>(p.field);
      out.clear();
      for (const auto& x : value) out.push_back(static_cast<int>(whole(x)));
    }
  }
}

// The one rule of a step sweep: 0 < dt-min < dt-max <= t-end, and at most max_steps steps of
// dt-min over t-end (the parameters named "dt-min", "dt-max", "t-end" by `name`).
inline void check_sweep(double dt_min, double dt_max, double t_end, const ParamNamer& name) {
  if (!(dt_min < dt_max))
    throw UsageError(fmt::format("{}{} {} is not below {} {}; accepted: dt-min < dt-max", name.origin, name("dt-min"),
                                 short_number(dt_min), name("dt-max"), short_number(dt_max)));
  if (!(dt_max <= t_end))
    throw UsageError(fmt::format("{}{} {} is longer than {} {}; accepted: dt-max <= t-end", name.origin, name("dt-max"),
                                 short_number(dt_max), name("t-end"), short_number(t_end)));
  step_count(t_end, dt_min);
}

}  // namespace steplab
