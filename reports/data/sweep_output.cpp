// Order against a parameter (analysis/convergence.hpp, ConvergenceSweep): its JSON and its table.
#include <cmath>

#include <fmt/format.h>

#include "analysis/kernel.hpp"
#include "reports/data/study_output.hpp"

namespace steplab {
namespace {

Json number_or_null(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

std::string_view param_name(const ConvergenceSweep& s) {
  return scene_kernel(s.studies.front().config.scene).params[s.param].name;
}

// "2.000" for a fitted order, "exact" at round-off, "-" where none could be fitted.
std::string order_cell(const ConvergenceFit& f) {
  if (f.fit.exact) return "exact";
  return f.fit.fitted ? fmt::format("{:.3f}", f.fit.order) : "-";
}

}  // namespace

Json convergence_sweep_json(const ConvergenceSweep& s) {
  Json j;
  j["schema"] = "steplab.convergence_sweep/1";
  j["scene"] = scene_name(s.studies.front().config.scene);
  j["param"] = param_name(s);
  j["values"] = s.values;
  Json fits = Json::array();  // one per (method, value): the order read against the parameter
  for (std::size_t v = 0; v < s.studies.size(); ++v)
    for (const ConvergenceFit& f : s.studies[v].fits) {
      Json e;
      e["method"] = method_info(f.method).name;
      e["value"] = s.values[v];
      e["exact"] = f.fit.exact;
      e["order"] = f.fit.fitted ? number_or_null(f.fit.order) : Json(nullptr);
      e["order_bound"] = f.fit.fitted ? Json{number_or_null(f.fit.bound_lo), number_or_null(f.fit.bound_hi)} : Json(nullptr);
      e["dt_range"] = f.fit.fitted ? Json{f.fit.dt_lo, f.fit.dt_hi} : Json(nullptr);
      e["note"] = f.fit.note;
      fits.push_back(std::move(e));
    }
  j["fits"] = std::move(fits);
  j["studies"] = Json::array();
  for (const ConvergenceResult& r : s.studies) j["studies"].push_back(convergence_json(r));
  return j;
}

std::string convergence_sweep_table(const ConvergenceSweep& s) {
  const ConvergenceResult& first = s.studies.front();
  const ConvergenceConfig& c = first.config;
  std::string out = fmt::format("Order against {} on {}: t_end {}, {} steps from {:.3g} to {:.3g}; fitted order of the {} "
                                "position error\n\n",
                                param_name(s), scene_name(c.scene), c.t_end, first.dts.size(), first.dts.front(),
                                first.dts.back(), to_string(c.fit_error));
  out += fmt::format("{:<18} {:>8}", "method", "declared");
  for (double v : s.values) out += fmt::format(" {:>9.3g}", v);
  out += "\n";
  for (std::size_t m = 0; m < first.fits.size(); ++m) {
    const MethodInfo& info = method_info(first.fits[m].method);
    out += fmt::format("{:<18} {:>8}", info.name, info.exact_flow ? "exact" : std::to_string(info.order));
    for (const ConvergenceResult& r : s.studies) out += fmt::format(" {:>9}", order_cell(r.fits[m]));
    out += "\n";
  }
  return out;
}

}  // namespace steplab
