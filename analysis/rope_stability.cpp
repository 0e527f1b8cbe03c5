#include "analysis/rope_stability.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <map>

#include "analysis/kernel.hpp"
#include "analysis/shard.hpp"
#include "analysis/stability.hpp"
#include "core/scenes/rope.hpp"
#include "core/scenes/spring.hpp"

namespace steplab {

// Each mode on the unit spring (mass 1, stiffness 1: omega 1) with damping 2 zeta_j, zeta_j =
// (c + d lambda_j) / (2 m omega_j): a method's step on a linear oscillator depends on omega h
// and zeta alone, so mode j's dt* is the unit spring's divided by omega_j. (On the mode's own
// spring, mass 1/N and stiffness K N lambda_j, the differenced step matrix loses the digits the
// threshold needs once omega passes ~100: forces of 1e6 against perturbations of 1e-1.)
// Modes of equal zeta (all of them undamped) share one computation.
double unit_oscillator_threshold(std::size_t method, double two_zeta) {
  const std::vector<double> unit{1.0, 1.0, 0.0, 5.0, 9.81};  // Spring::params: mass, stiffness, damping, rest-length, gravity
  return predicted_stable_set(method, linear_spring(unit, two_zeta), false).dt_star;
}

double rope_predicted_threshold(std::size_t method, const Rope& r, int* binding_mode) {
  std::map<double, double> unit_dt;  // 2 zeta -> the unit spring's dt*
  double best = std::numeric_limits<double>::infinity();
  int binding = 0;
  for (int j = r.n; j >= 1; --j) {  // the fastest first: ties go to it
    const double w = r.omega(j), two_zeta = (r.c + r.d * r.lambda[j - 1]) / (r.m * w);
    auto it = unit_dt.find(two_zeta);
    if (it == unit_dt.end()) it = unit_dt.emplace(two_zeta, unit_oscillator_threshold(method, two_zeta)).first;
    const double dt = it->second / w;
    if (dt < best) best = dt, binding = j;
  }
  if (binding_mode) *binding_mode = std::isinf(best) ? 0 : binding;
  return best;
}

double rope_measured_threshold(std::size_t method, const std::vector<double>& params, long long steps) {
  const std::size_t scene = scene_index(Rope::name);
  const Rope r(params);
  const double w = r.omega(r.n);
  const PairKernel& k = pair_kernel(method, scene);
  RunSpec spec;
  spec.steps = steps;
  spec.errors = false;
  spec.stop_above = 1e4;
  return stable_set(kMeasureMinWh / w, kMaxWh / w, 2, 1e-3,
                    [&](double h) {
                      spec.dt = h;
                      return k.run(params, spec).status != RunStatus::Ok;
                    },
                    false)
      .dt_star;
}

std::vector<RopeThresholdRow> rope_threshold_study(const RopeStabilityConfig& c) {
  const Rope r(c.params);
  return study_map<RopeThresholdRow>(c.methods.size(), c.workers, [&](std::size_t i) {
    const std::size_t m = c.methods[i];
    RopeThresholdRow row{m, r.omega(r.n), 0, 0, 0};
    row.dt_theory = rope_predicted_threshold(m, r, &row.binding_mode);
    row.dt_measured = rope_measured_threshold(m, c.params, c.steps);
    return row;
  }, implicit_first(c.methods));
}

}  // namespace steplab
