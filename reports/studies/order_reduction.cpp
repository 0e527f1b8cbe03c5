// `steplab study convergence --sweep`: order against stiffness (analysis/studies/order_reduction.hpp),
// its JSON (steplab.convergence_sweep/1) and its table.
#include "reports/studies/studies.hpp"

#include <cmath>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "reports/data/run_json.hpp"

namespace steplab {
namespace {

std::string_view param_name(const ConvergenceSweep& s) {
  return scene_kernel(s.studies.front().config.scene).params[s.param].name;
}

// "2.000" for a fitted order, "exact" at round-off, "-" where none could be fitted.
std::string order_cell(const ConvergenceFit& f) {
  if (f.fit.exact) return "exact";
  return f.fit.fitted ? fmt::format("{:.3f}", f.fit.order) : "-";
}

Json theory_json(const StiffTheory& t) {
  Json j;
  j["classical"] = t.classical;
  j["stiff"] = t.stiff >= 0 ? Json(t.stiff) : Json(nullptr);
  j["stage_order"] = t.stage_order >= 0 ? Json(t.stage_order) : Json(nullptr);
  j["r_infinity"] = t.stage_order >= 0 ? Json(t.r_infinity) : Json(nullptr);
  j["stiffly_accurate"] = t.stiffly_accurate;
  j["long_run"] = t.long_run;  // C of R(inf) = 1, else 0
  j["rule"] = t.rule;
  return j;
}

Json limit_json(const LimitCheck& c) {
  Json j;
  j["reached"] = c.reached;
  j["order"] = c.fitted ? Json(c.order) : Json(nullptr);
  j["order_bound"] = c.fitted ? Json{c.bound_lo, c.bound_hi} : Json(nullptr);
  j["holds"] = c.holds;
  return j;
}

// "holds (2.00)", "fails (3.41)", "not reached (3.63)", "no fit", "-".
std::string limit_cell(const LimitCheck& c, bool has_theory) {
  const std::string word = limit_word(c, has_theory);
  return has_theory && c.fitted ? fmt::format("{} ({:.2f})", word, c.order) : word;
}

std::string transition_cell(const MethodReduction& m) {
  if (m.theory.stiff < 0 || m.theory.stiff == m.theory.classical) return "-";
  const auto x = [](double v) { return std::isnan(v) ? std::string("?") : fmt::format("{:.2g}", v); };
  return fmt::format("{} .. {}", x(m.keeps_to), x(m.reduced_from));
}

}  // namespace

std::string limit_word(const LimitCheck& c, bool has_theory) {
  if (!has_theory) return "-";
  if (!c.fitted) return "no fit";
  if (!c.reached) return "not reached";
  return c.holds ? "holds" : "fails";
}

Json order_reduction_json(const OrderReduction& r) {
  const ConvergenceSweep& s = r.sweep;
  Json j;
  j["schema"] = schema::convergence_sweep;
  j["scene"] = scene_name(s.studies.front().config.scene);
  j["param"] = param_name(s);
  j["values"] = s.values;
  j["driven"] = r.driven;  // false: an autonomous scene, the stiff limit not checked (analysis/studies/order_reduction.hpp)
  j["stiff_rate"] = r.rates;  // |lambda| of the stiffest mode's slower eigenvalue, per value
  j["tolerance"] = {{"non_stiff", kNonStiffTolerance}, {"stiff", kStiffTolerance}};
  Json methods = Json::array();
  for (const MethodReduction& m : r.methods) {
    Json e;
    e["method"] = method_info(m.method).name;
    e["theory"] = theory_json(m.theory);
    e["non_stiff"] = limit_json(m.non_stiff);
    e["stiff"] = m.theory.stiff >= 0 && r.driven ? limit_json(m.stiff) : Json(nullptr);
    e["order_kept_to_h_lambda"] = finite_or_null(m.keeps_to);
    e["stiff_order_from_h_lambda"] = finite_or_null(m.reduced_from);
    methods.push_back(std::move(e));
  }
  j["methods"] = std::move(methods);
  Json fits = Json::array();  // one per (method, value): the order read against the parameter
  for (std::size_t v = 0; v < s.studies.size(); ++v)
    for (std::size_t m = 0; m < s.studies[v].fits.size(); ++m) {
      const ConvergenceFit& f = s.studies[v].fits[m];
      Json e;
      e["method"] = method_info(f.method).name;
      e["declared_order"] = method_info(f.method).order;
      e["value"] = s.values[v];
      e["exact"] = f.fit.exact;
      e["order"] = f.fit.fitted ? finite_or_null(f.fit.order) : Json(nullptr);
      e["order_bound"] = f.fit.fitted ? Json{finite_or_null(f.fit.bound_lo), finite_or_null(f.fit.bound_hi)} : Json(nullptr);
      e["dt_range"] = f.fit.fitted ? Json{f.fit.dt_lo, f.fit.dt_hi} : Json(nullptr);
      e["h_lambda"] = finite_or_null(r.methods[m].h_lambda[v]);
      e["past_stable"] = static_cast<bool>(r.methods[m].past_stable[v]);
      e["note"] = f.fit.note;
      fits.push_back(std::move(e));
    }
  j["fits"] = std::move(fits);
  j["studies"] = Json::array();
  for (const ConvergenceResult& c : s.studies) j["studies"].push_back(convergence_json(c));
  return j;
}

std::string order_reduction_table(const OrderReduction& r) {
  const ConvergenceSweep& s = r.sweep;
  const ConvergenceResult& first = s.studies.front();
  const ConvergenceConfig& c = first.config;
  std::string out = fmt::format("Order against {} on {}: t_end {}, {} steps from {:.3g} to {:.3g}; fitted order of the {} "
                                "position error\n\n",
                                param_name(s), scene_name(c.scene), c.t_end, first.dts.size(), first.dts.front(),
                                first.dts.back(), to_string(c.fit_error));
  out += fmt::format("{:<18} {:>6} {:>6}", param_name(s), "", "");
  for (double v : s.values) out += fmt::format(" {:>9.3g}", v);
  out += fmt::format("\n{:<18} {:>6} {:>6}", "|lambda|", "", "");
  for (double v : r.rates) out += fmt::format(" {:>9.3g}", v);
  out += fmt::format("\n{:<18} {:>6} {:>6}\n", "method", "p", "stiff");
  for (std::size_t m = 0; m < r.methods.size(); ++m) {
    const MethodReduction& mr = r.methods[m];
    const MethodInfo& info = method_info(mr.method);
    out += fmt::format("{:<18} {:>6} {:>6}", info.name, info.exact_flow ? "exact" : std::to_string(info.order),
                       mr.theory.stiff >= 0 && !info.exact_flow && r.driven ? std::to_string(mr.theory.stiff) : "-");
    for (const ConvergenceResult& st : s.studies) out += fmt::format(" {:>9}", order_cell(st.fits[m]));
    out += "\n";
  }
  out += fmt::format("\np: the classical order; stiff: the theory's order as h|lambda| grows (analysis/studies/order_reduction.hpp). "
                     "A limit holds when the order at the first (last) value is within {} ({}) of the theory and its bound "
                     "contains it, in that limit's regime (h|lambda_max| <= {} at the largest step; h|lambda| >= {} at the "
                     "smallest). The transition: the order kept up to h|lambda| = a, the stiff order from b (at the fit's "
                     "middle step).\n\n",
                     kNonStiffTolerance, kStiffTolerance, kNonStiffRegime, kStiffRegime);
  if (!r.driven)
    out += fmt::format("{} is autonomous: no forcing is sampled at the stages' times, so the theory's stiff limit does not "
                       "apply. Its slow modes converge at p; the fast mode the start excites adds an error that does not "
                       "shrink with h while h|lambda| > 1, so where it dominates the fitted order falls towards 0 (a "
                       "plateau, not a lower order).\n\n",
                       scene_name(c.scene));
  out += fmt::format("{:<18} {:>22} {:>22} {:>14}  {}\n", "method", "non-stiff limit", "stiff limit", "a .. b", "rule");
  for (const MethodReduction& mr : r.methods) {
    if (method_info(mr.method).exact_flow) continue;
    out += fmt::format("{:<18} {:>22} {:>22} {:>14}  {}\n", method_info(mr.method).name, limit_cell(mr.non_stiff, true),
                       limit_cell(mr.stiff, mr.theory.stiff >= 0 && r.driven), r.driven ? transition_cell(mr) : "-", mr.theory.rule);
  }
  return out;
}

}  // namespace steplab
