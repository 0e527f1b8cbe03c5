#include "reports/document/report_text.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/defaults.hpp"

namespace steplab {

std::string name(std::size_t m) { return std::string(method_info(m).name); }
std::string dt_text(double x) { return std::isinf(x) ? "inf" : std::isnan(x) ? "-" : fmt::format("{:.4g}", x); }
std::string table_dt(double x) { return std::isinf(x) ? "$\\infty$" : dt_text(x); }
std::string num(double x) { return std::isfinite(x) ? fmt::format("{}", x) : "NaN"; }

std::string order_text(std::size_t m) {
  const MethodInfo& info = method_info(m);
  return info.exact_flow ? "exact" : !info.converges ? "none" : std::to_string(info.order);
}

std::string fitted_text(const ConvergenceFit& fit) {
  if (fit.fit.exact) return "exact (round-off)";
  if (!fit.fit.fitted) return "-";
  // what the fit cannot vouch for, said beside it (analysis/fits/order_fit.hpp, step 7)
  const std::string few = fit.fit.few_points ? fmt::format(" ({} points: the plain slope)", fit.fit.line.n) : "";
  const std::string rough = fit.fit.non_monotone ? " (errors not monotone: no order)" : "";
  const std::string wide = fit.fit.wide && !fit.fit.non_monotone ? " (bound too wide: no finding)" : "";
  return fmt::format("{:.3f} [{:.3f}, {:.3f}]{}{}{}", fit.fit.order, fit.fit.bound_lo, fit.fit.bound_hi, few, rough, wide);
}

std::string and_list(const std::vector<std::string>& items) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) out += i + 1 == items.size() ? " and " : ", ";
    out += items[i];
  }
  return out;
}

std::string quoted_list(const std::vector<std::string>& names) {
  std::vector<std::string> quoted;
  for (const std::string& n : names) quoted.push_back(fmt::format("`{}`", n));
  return and_list(quoted);
}

std::string method_list(const std::vector<std::size_t>& methods) {
  if (methods.empty()) return "none";
  std::vector<std::string> names;
  for (std::size_t m : methods) names.push_back(name(m));
  return quoted_list(names);
}

std::string fits_table(const ConvergenceResult& r) {
  std::string out = "| method | declared | fitted order [bound] | points | dt range |\n"
                    "|------------------|-----:|-----------------------|-----:|-------------------|\n";
  for (const ConvergenceFit& f : r.fits) {
    if (method_info(f.method).exact_flow || f.fit.exact) continue;  // the reference; the exact ones named in a sentence
    const std::string n(method_info(f.method).name);
    if (!f.fit.fitted) out += fmt::format("| `{}` | {} | - ({}) | - | - |\n", n, order_text(f.method), f.fit.note);
    else
      out += fmt::format("| `{}` | {} | {} | {} | {:.3g} – {:.3g} |\n", n, order_text(f.method), fitted_text(f), f.fit.line.n,
                         f.fit.dt_lo, f.fit.dt_hi);
  }
  return out;
}

std::string params_text(std::size_t scene, const std::vector<double>& v, int skip) {
  const std::span<const ParamSpec> params = scene_kernel(scene).params;
  std::string out;
  for (std::size_t i = 0; i < params.size(); ++i)
    if (static_cast<int>(i) != skip) out += fmt::format("{}{} {}", out.empty() ? "" : ", ", params[i].name, v[i]);
  return out;
}

std::vector<std::size_t> sheet_methods() {
  std::vector<std::size_t> out;
  for (std::string_view n : kSheetMethods)
    if (const auto m = find_method(n); m && !method_info(*m).exact_flow) out.push_back(*m);
  return out;
}

std::string wrapped(const std::string& cmd) {
  std::string out, line;
  std::size_t start = 0;
  while (start < cmd.size()) {
    std::size_t next = cmd.find(" --", start + 1);
    if (next == std::string::npos) next = cmd.size();
    std::string piece = cmd.substr(start, next - start);
    if (line.find_first_not_of(' ') != std::string::npos && line.size() + piece.size() > kCodeColumns) {
      out += line + " \\\n";
      line = "   ";  // the continuation's indent
    }
    // A piece longer than a line (a long list) is broken after a comma: the shell removes a
    // backslash-newline inside a word, so the list reads back whole.
    for (std::size_t cut; line.size() + piece.size() > kCodeColumns &&
                          (cut = piece.rfind(',', kCodeColumns - line.size() - 2)) != std::string::npos && cut > 0;) {
      out += line + piece.substr(0, cut + 1) + "\\\n";
      line.clear();
      piece.erase(0, cut + 1);
    }
    line += piece;
    start = next;
  }
  return out + line + "\n";
}

std::string words(const std::vector<double>& v) {
  std::string out;
  for (double x : v) out += fmt::format("{}{}", out.empty() ? "" : " ", x);
  return out;
}

std::string join(const std::vector<double>& v) {
  std::string out;
  for (double x : v) out += fmt::format("{}{}", out.empty() ? "" : ",", x);
  return out;
}

double two_digits(double x, bool up) {
  if (!std::isfinite(x) || x <= 0) return x;
  const double unit = std::pow(10.0, std::floor(std::log10(x)) - 1);
  const auto printed = [](double v) { return std::stod(fmt::format("{:.2g}", v)); };
  const double b = printed((up ? std::ceil(x / unit) : std::floor(x / unit)) * unit);
  return up ? (b < x ? printed(b + unit) : b) : (b > x ? printed(b - unit) : b);  // the rounding of the product
}

std::string join(const std::vector<int>& v) { return join(std::vector<double>(v.begin(), v.end())); }

std::string method_words(const std::vector<std::size_t>& methods) {
  std::string out;
  for (std::size_t m : methods) {
    if (!out.empty()) out += ' ';
    out += name(m);
  }
  return out;
}

std::vector<std::size_t> family_members(const std::vector<std::size_t>& methods, Family f) {
  std::vector<std::size_t> out;
  for (std::size_t m : methods)
    if (method_info(m).family == f || method_info(m).first_of == f) out.push_back(m);
  std::sort(out.begin(), out.end(), [](std::size_t a, std::size_t b) {
    return std::pair(method_info(a).order, a) < std::pair(method_info(b).order, b);
  });
  return out;
}

bool family_order_less(std::size_t a, std::size_t b) {
  const MethodInfo &x = method_info(a), &y = method_info(b);
  return std::tuple(x.family, x.order, a) < std::tuple(y.family, y.order, b);
}

}  // namespace steplab
