// `steplab run`: one method on one scene; CSV (t, x..., v..., energy) on stdout or JSON to a file.
#include <algorithm>
#include <cstdio>

#include <fmt/format.h>

#include "core/dopri5.hpp"
#include "analysis/kernel/kernel.hpp"
#include "reports/cli/commands.hpp"
#include "reports/data/inputs.hpp"
#include "reports/data/output.hpp"
#include "reports/data/run_json.hpp"

namespace steplab {
namespace {

// The state's D coordinates: x (D = 1) or x0, x1, ...
std::string csv(const AnyResult& r) {
  const auto D = r.final.x.size();
  std::string out = "t";
  for (Eigen::Index i = 0; i < D; ++i) out += D == 1 ? ",x" : fmt::format(",x{}", i);
  for (Eigen::Index i = 0; i < D; ++i) out += D == 1 ? ",v" : fmt::format(",v{}", i);
  out += ",energy\n";
  for (const auto& s : r.samples) {
    out += fmt::format("{}", s.t);
    for (Eigen::Index i = 0; i < D; ++i) out += fmt::format(",{}", s.x[i]);
    for (Eigen::Index i = 0; i < D; ++i) out += fmt::format(",{}", s.v[i]);
    out += fmt::format(",{}\n", s.energy);
  }
  return out;
}


// --samples: as given, or 10001 rows where they hold at most 10^6 numbers (t, x, v and the energy
// each), fewer on a large scene, down to the first and the last state (a rope of 1000 masses: 499
// rows, 10 MB of CSV, where 10001 were 390 MB; of 100 000 masses: 4 rows, 20 MB). A row count
// that makes more than 100 MB of CSV is said on stderr.
long long samples_for(const std::string& given, const SceneKernel& scene, Params params) {
  const long long columns = 2 * static_cast<long long>(scene.initial(params).x.size()) + 2;
  const long long rows = given.empty() ? std::clamp(1'000'000 / columns, 2LL, 10'001LL) : parse_count("--samples", given, 2, 100'000'000);
  if (const double mb = 20e-6 * static_cast<double>(rows * columns); mb > 100)
    fmt::print(stderr, "steplab: up to {} rows of {} columns: about {:.0f} MB of CSV (--samples sets fewer)\n", rows, columns, mb);
  return rows;
}

// --rtol and --atol (empty: the defaults), checked.
Tolerance read_tolerance(const std::string& rtol, const std::string& atol) {
  Tolerance t;
  if (!rtol.empty()) t.rtol = parse_number("--rtol", rtol, Bound::Positive);
  if (t.rtol < 1e-13 || t.rtol > 1)
    throw UsageError(fmt::format("--rtol {} is out of range; accepted: 1e-13 .. 1 (below, round-off decides the steps)", rtol));
  if (!atol.empty()) t.atol = parse_number("--atol", atol, Bound::Positive);
  return t;
}

// dopri5's counts: "adaptive": {accepted_steps, rejected_steps, force_evaluations, h_min, h_max}.
Json adaptive_json(const AdaptiveStats& s) {
  return {{"accepted_steps", s.accepted},
          {"rejected_steps", s.rejected},
          {"force_evaluations", s.force_evaluations},
          {"h_min", s.accepted > 0 ? Json(s.h_min) : Json(nullptr)},
          {"h_max", s.accepted > 0 ? Json(s.h_max) : Json(nullptr)}};
}

// The adaptive Dormand-Prince: a tolerance instead of a step; its steps in the JSON.
int run_dopri5(RunArgs& a, const Context& ctx) {
  const std::size_t scene = a.scene.scene_index();
  if (!a.dt.empty()) throw UsageError("--dt does not apply to dopri5, which chooses its own steps; give --rtol and --atol");
  if (!a.settings.sweeps.empty() || !a.settings.cg_iterations.empty() || !a.settings.cg_tolerance.empty())
    throw UsageError("--sweeps, --cg-iterations and --cg-tolerance apply to the methods on springs; dopri5 takes none");
  const std::vector<double> params = a.scene.values(scene);
  AdaptiveSpec spec;
  spec.tol = read_tolerance(a.rtol, a.atol);
  spec.t_end = parse_number("--t-end", a.t_end, Bound::NonNegative);
  spec.max_samples = samples_for(a.samples, scene_kernel(scene), params);
  if (ctx.stop_after_validation(a.json)) return 0;
  const SceneKernel& s = scene_kernel(scene);
  const AnyAdaptiveResult r = s.dopri5(params, spec);
  if (a.json.empty()) {
    std::fputs(csv(r.run).c_str(), stdout);
  } else {
    Json p = params_json(s.params, params);
    p["rtol"] = spec.tol.rtol;
    p["atol"] = spec.tol.atol;
    p["t_end"] = spec.t_end;
    Json j = run_json(s.name, "dopri5", std::move(p), r.run);
    j["adaptive"] = adaptive_json(r.stats);
    write_atomic(a.json, j.dump(1) + "\n");
  }
  if (r.run.status != RunStatus::Ok)
    fmt::print(stderr, "steplab: dopri5 {} at t = {}: the step size fell below round-off\n", to_string(r.run.status),
               r.run.failed_t);
  return 0;
}

}  // namespace

int run_command(RunArgs& a, Context& ctx) {
  if (a.method == "dopri5") return run_dopri5(a, ctx);
  if (!a.rtol.empty() || !a.atol.empty())
    throw UsageError(fmt::format("--rtol and --atol apply to the adaptive dopri5 only; --method {} takes --dt", a.method));
  const std::size_t scene = a.scene.scene_index();
  const std::size_t method = resolve_method(a.method);
  if (!applies(method, scene)) throw UsageError(fmt::format("--method {} {}", a.method, why_not(method, scene)));
  const std::vector<double> params = a.scene.values(scene);
  RunSpec spec;
  spec.settings = a.settings.resolve({method});
  spec.dt = a.dt.empty() ? 0.01 : parse_number("--dt", a.dt, Bound::Positive);
  const double t_end = parse_number("--t-end", a.t_end, Bound::NonNegative);
  spec.steps = step_count(t_end, spec.dt);
  spec.max_samples = samples_for(a.samples, scene_kernel(scene), params);
  // The CSV has no errors, so a run for it reads none; the JSON's are read every step, or on the
  // rope every --error-every steps (each read costs a sine transform: at 4096 masses about 14
  // steps of RK4), by default at about 100 evenly spaced steps and the last.
  spec.errors = !a.json.empty();
  spec.error_stride = a.error_every.empty() ? std::max(1LL, (spec.steps + 99) / 100)
                                            : parse_count("--error-every", a.error_every, 1, 1'000'000'000'000);
  if (ctx.stop_after_validation(a.json)) return 0;
  // A step that does not divide the time: the run takes whole steps, so it ends after t_end.
  if (const double end = static_cast<double>(spec.steps) * spec.dt; std::abs(end - t_end) > 1e-9 * std::max(t_end, spec.dt))
    fmt::print(stderr, "steplab: --t-end {} is not a whole number of steps of --dt {}: the run takes {} step{} and ends at t = {}\n",
               t_end, spec.dt, spec.steps, spec.steps == 1 ? "" : "s", end);

  const SceneKernel& s = scene_kernel(scene);
  const std::string_view name = method_info(method).name;
  // For the JSON, counted where the table counts (scenes with an exact solution or of run-time
  // size): the same run, its force and Jacobian evaluations and Newton solves added up beside it.
  // The CSV has no counts, so that run is not counted (the counters cost RK4 on the spring about
  // 4 % of its step).
  const PairKernel& k = pair_kernel(method, scene);
  const bool counted = k.run_counted && !a.json.empty();
  Counts counts;
  const AnyResult r = counted ? k.run_counted(params, spec, counts) : k.run(params, spec);
  if (a.json.empty()) {
    std::fputs(csv(r).c_str(), stdout);
  } else {
    Json p = params_json(s.params, params);
    p["dt"] = spec.dt;
    p["t_end"] = t_end;
    p.update(settings_json(method_info(method), spec.settings));
    Json j = run_json(s.name, name, std::move(p), r);
    j["counts"] = counted ? counts_json(counts) : Json(nullptr);
    write_atomic(a.json, j.dump(1) + "\n");
  }
  if (r.status != RunStatus::Ok)
    fmt::print(stderr, "steplab: {} {} at step {} (t = {:.6g})\n", name, to_string(r.status), r.failed_step, r.failed_t);
  return 0;
}

}  // namespace steplab
