// JSON of one run (schema "steplab.run/1"). The field names are an interface: notebooks and
// scripts rely on them, and docs/json.md lists them.
#pragma once

#include <cmath>
#include <span>
#include <string_view>

#include <nlohmann/json.hpp>

#include "analysis/kernel/counts.hpp"
#include "core/simulate.hpp"
#include "reports/data/schemas.hpp"

namespace steplab {

using Json = nlohmann::ordered_json;

template <int D> Json vec_json(const Vec<D>& v) {
  Json a = Json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) a.push_back(v[i]);
  return a;
}

// A parameter's JSON key: its CLI name with '-' -> '_' ("rest-length" -> "rest_length").
inline std::string param_key(const ParamSpec& p) {
  std::string key(p.name);
  std::replace(key.begin(), key.end(), '-', '_');
  return key;
}

// A scene's parameters {key: value} from its table (SceneKernel::params) and values in that order.
inline Json params_json(std::span<const ParamSpec> spec, std::span<const double> values) {
  Json p = Json::object();
  for (std::size_t i = 0; i < spec.size(); ++i) p[param_key(spec[i])] = values[i];
  return p;
}

// A run's counts (analysis/kernel/counts.hpp) by their JSON names, the same in every document.
inline Json counts_json(const Counts& n) {
  return {{"steps", n.steps},           {"rejected_steps", n.rejected},  {"force_evaluations", n.forces},
          {"jacobian_evaluations", n.jacobians}, {"factorisations", n.factorisations}, {"linear_solves", n.solves},
          {"newton_iterations", n.newton}};
}

// A number, or null where it is not finite (a run that blew up).
inline Json finite_or_null(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

// The settings a method reads (core/method.hpp: takes_sweeps, takes_cg) by their JSON names; {}
// for a method without any.
inline Json settings_json(const MethodInfo& m, const MethodSettings& s) {
  Json j = Json::object();
  if (takes_sweeps(m)) j["sweeps"] = s.sweeps;
  if (takes_cg(m)) j["cg_iterations"] = s.cg_iterations, j["cg_tolerance"] = s.cg_tolerance;
  return j;
}

template <int D>
Json run_json(std::string_view scene, std::string_view method, Json params, const RunResult<D>& r) {
  Json j;
  j["schema"] = schema::run;
  j["scene"] = scene;
  j["method"] = method;
  j["params"] = std::move(params);
  j["status"] = to_string(r.status);
  j["diverged_at"] = r.status == RunStatus::Ok ? Json(nullptr) : Json{{"step", r.failed_step}, {"t", r.failed_t}};
  j["steps"] = r.steps;
  j["final"] = {{"t", r.t_final}, {"x", vec_json<D>(r.final.x)}, {"v", vec_json<D>(r.final.v)}};
  j["error"] = r.has_exact ? Json{{"final", r.error_final}, {"max", r.error_max}, {"rms", r.error_rms},
                                  {"velocity_final", r.error_v_final}, {"reads", r.error_reads}}
                           : Json(nullptr);
  j["energy_ratio"] = {{"final", r.energy_ratio_final}, {"max", r.energy_ratio_max}};
  Json samples = Json::array();
  for (const auto& s : r.samples)
    samples.push_back({{"t", s.t}, {"x", vec_json<D>(s.x)}, {"v", vec_json<D>(s.v)}, {"energy", s.energy}});
  j["samples"] = std::move(samples);
  return j;
}

}  // namespace steplab
