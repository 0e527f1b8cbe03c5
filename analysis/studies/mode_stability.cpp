#include "analysis/studies/mode_stability.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

#include <Eigen/Eigenvalues>

#include "analysis/kernel/kernel.hpp"
#include "analysis/kernel/shard.hpp"
#include "analysis/studies/stability.hpp"
#include "core/scenes/spring.hpp"

namespace steplab {

// Each mode on the unit spring (mass 1, stiffness 1: omega 1) with damping 2 zeta_j, zeta_j =
// (c + d lambda_j) / (2 m omega_j): a method's step on a linear oscillator depends on omega h
// and zeta alone, so mode j's dt* is the unit spring's divided by omega_j. (On the mode's own
// spring, mass 1/N and stiffness K N lambda_j, the differenced step matrix loses the digits the
// threshold needs once omega passes ~100: forces of 1e6 against perturbations of 1e-1.)
// Modes of equal zeta (all of them undamped) share one computation.
double unit_oscillator_threshold(std::size_t method, double two_zeta) {
  std::vector<double> unit = default_param_values<Spring>();
  unit[param_index(Spring::params, "mass")] = 1, unit[stiffness_param_index<Spring>()] = 1, unit[damping_param_index<Spring>()] = 0;
  return predicted_stable_set(method, linear_spring(unit, two_zeta), false).dt_star;
}

double modes_predicted_threshold(std::size_t method, const std::vector<Mode>& modes, int* binding_mode) {
  std::map<double, double> unit_dt;  // 2 zeta -> the unit spring's dt*
  double best = std::numeric_limits<double>::infinity();
  int binding = 0;
  for (int j = static_cast<int>(modes.size()); j >= 1; --j) {  // the fastest first: ties go to it
    const auto [w, two_zeta] = modes[j - 1];
    auto it = unit_dt.find(two_zeta);
    if (it == unit_dt.end()) it = unit_dt.emplace(two_zeta, unit_oscillator_threshold(method, two_zeta)).first;
    const double dt = it->second / w;
    if (dt < best) best = dt, binding = j;
  }
  if (binding_mode) *binding_mode = std::isinf(best) ? 0 : binding;
  return best;
}

// The largest growth per step the modes' linearisation predicts at step h: the spectral radius
// of the method's step matrix on each mode (omega h and 2 zeta omega h on the unit oscillator).
double predicted_growth(std::size_t method, const std::vector<Mode>& modes, double h) {
  const MethodKernel& k = method_kernel(method);
  double rho = 0;
  std::map<std::pair<double, double>, double> seen;
  for (const Mode& mode : modes) {
    const double wh = mode.omega * h;
    auto [it, fresh] = seen.emplace(std::pair{wh, mode.two_zeta}, 0.0);
    if (fresh) it->second = k.test_matrix(wh * wh, mode.two_zeta * wh).eigenvalues().cwiseAbs().maxCoeff();
    rho = std::max(rho, it->second);
  }
  return rho;
}

long long threshold_run_steps(std::size_t method, const std::vector<Mode>& modes, int dim, double h, long long steps) {
  if (modes.empty()) return steps;
  const double rho = predicted_growth(method, modes, h);
  if (!(rho > 1)) return steps;
  const double needed = std::ceil(kSeedGrowth / std::log(rho));
  const double most = std::max(static_cast<double>(steps), kMaxThresholdWork / std::max(dim, 1));
  return static_cast<long long>(std::clamp(needed, static_cast<double>(steps), most));
}

bool damped(const std::vector<Mode>& modes) {
  return !modes.empty() && std::all_of(modes.begin(), modes.end(), [](const Mode& m) { return m.two_zeta > 0; });
}

bool unstable_run(const AnyResult& r, bool damped_scene, bool rate_trusted) {
  if (r.status != RunStatus::Ok) return true;  // E/E0 past 1e4, a blow-up, a Newton that gave up
  if (damped_scene) return r.samples.back().energy > r.samples.front().energy;
  return rate_trusted && r.energy_rate > kStableRate;
}

double measured_threshold(std::size_t method, std::size_t scene, const std::vector<double>& params, double omega_max,
                          long long steps) {
  const PairKernel& k = pair_kernel(method, scene);
  const SceneKernel& sk = scene_kernel(scene);
  const std::vector<Mode> modes = sk.modes ? sk.modes(params) : std::vector<Mode>{};
  const int dim = static_cast<int>(sk.initial(params).x.size());
  const bool damped_scene = damped(modes);
  double omega_min = omega_max;
  for (const Mode& m : modes) omega_min = std::min(omega_min, m.omega);
  RunSpec spec;
  spec.errors = false;
  spec.stop_above = 1e4;
  spec.max_samples = 2;                  // the start's energy and the end's
  spec.energy_rate = !damped_scene;      // the ln E slope of an undamped scene
  return stable_set(kMeasureMinWh / omega_max, kMaxWh / omega_max, 2, 1e-3,
                    [&](double h) {
                      spec.dt = h;
                      // undamped: long enough for the ln E slope to be the trend's (kRateRadians)
                      const double rate_steps = damped_scene ? 0 : std::ceil(kRateRadians / (omega_min * h));
                      const double cap = kMaxThresholdWork / std::max(dim, 1);
                      spec.steps = threshold_run_steps(method, modes, dim, h, std::max<long long>(steps, static_cast<long long>(std::min(rate_steps, cap))));
                      return unstable_run(k.run(params, spec), damped_scene, static_cast<double>(spec.steps) >= rate_steps);
                    },
                    false)
      .dt_star;
}

std::vector<ModeThresholdRow> mode_threshold_study(const ModeStabilityConfig& c) {
  const std::vector<Mode> modes = scene_kernel(c.scene).modes(c.params);
  double omega_max = 0;
  for (const Mode& mode : modes) omega_max = std::max(omega_max, mode.omega);
  return study_map<ModeThresholdRow>(c.methods.size(), c.workers, [&](std::size_t i) {
    const std::size_t m = c.methods[i];
    ModeThresholdRow row{m, omega_max, 0, 0, 0};
    row.dt_theory = modes_predicted_threshold(m, modes, &row.binding_mode);
    row.dt_measured = measured_threshold(m, c.scene, c.params, omega_max, c.steps);
    return row;
  }, implicit_first(c.methods));
}

}  // namespace steplab
