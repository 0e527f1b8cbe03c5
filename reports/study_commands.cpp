// `steplab study ...`: reads and checks the arguments, runs the study, prints its table and
// writes its JSON.
#include <cstdio>

#include <fmt/format.h>

#include "analysis/convergence.hpp"
#include "core/scenes.hpp"
#include "reports/commands.hpp"
#include "reports/inputs.hpp"
#include "reports/output.hpp"
#include "reports/study_output.hpp"

namespace steplab {

std::vector<std::size_t> resolve_methods(const std::string& list, bool with_analytic) {
  std::vector<std::size_t> out;
  if (list.empty()) {
    for (std::size_t i = 0; i < method_count; ++i)
      if (with_analytic || !method_infos[i].exact_flow) out.push_back(i);
    return out;
  }
  for (const std::string& name : split_list(list)) {
    const std::size_t m = resolve_method(name);
    if (std::find(out.begin(), out.end(), m) != out.end())
      throw UsageError(fmt::format("--methods names '{}' twice; accepted: each method once", name));
    out.push_back(m);
  }
  return out;
}

unsigned resolve_thread_count(const std::string& text) {
  return static_cast<unsigned>(parse_count("--threads", text, 0, 1024));
}

int convergence_command(ConvergenceArgs& a) {
  ConvergenceConfig c;
  c.scene = a.scene.scene_index();
  const bool has_exact = with_scene(c.scene, [&]<class S>() { return HasExact<S>; });
  if (!has_exact)
    throw UsageError(fmt::format("--scene {} has no exact solution to converge to; accepted: the scenes with one", a.scene.scene));
  c.params = a.scene.values(c.scene);
  c.methods = resolve_methods(a.methods, false);
  c.t_end = parse_number("--t-end", a.t_end, Bound::Positive);
  c.dt_max = parse_number("--dt-max", a.dt_max, Bound::Positive);
  c.dt_min = parse_number("--dt-min", a.dt_min, Bound::Positive);
  if (c.dt_min >= c.dt_max)
    throw UsageError(fmt::format("--dt-min {} is not below --dt-max {}; accepted: dt-min < dt-max", c.dt_min, c.dt_max));
  if (c.dt_max > c.t_end)
    throw UsageError(fmt::format("--dt-max {} is longer than --t-end {}; accepted: dt-max <= t-end", c.dt_max, c.t_end));
  c.points = static_cast<int>(parse_count("--points", a.points, 3, 1000));
  step_count(c.t_end, c.dt_min);  // refuses more than 10^9 steps
  if (a.error == "final") c.fit_error = ErrorKind::Final;
  else if (a.error == "max") c.fit_error = ErrorKind::Max;
  else if (a.error == "rms") c.fit_error = ErrorKind::Rms;
  else throw UsageError(fmt::format("--error '{}' is unknown; accepted: final, max, rms", a.error));
  c.threads = resolve_thread_count(a.threads);
  if (sweep_steps(c.t_end, c.dt_max, c.dt_min, c.points).size() < 3)
    throw UsageError("--dt-max, --dt-min and --t-end leave fewer than 3 distinct steps; accepted: a wider range");
  if (!a.json.empty()) check_writable(a.json);

  const ConvergenceResult r = convergence_study(c);
  std::fputs(convergence_table(r).c_str(), stdout);
  if (!a.json.empty()) write_atomic(a.json, convergence_json(r).dump(1) + "\n");
  return 0;
}

}  // namespace steplab
