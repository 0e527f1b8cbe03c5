// Stability of the rope of N masses (core/scenes/rope.hpp): dt* predicted from its modes and
// measured by runs of the whole rope.
//
// Prediction. The rope is linear and its modes decouple (mass- and stiffness-proportional
// damping), and every method of the table is invariant under the modal change of coordinates
// (equal masses: it is orthogonal, the same for x and v), so a step of the rope is N independent
// steps of damped oscillators: mode j is the spring of mass m, stiffness k lambda_j and damping
// c + d lambda_j. dt* of the rope = min over the modes of each oscillator's predicted dt*, each
// from the method's own step matrix on that spring (analysis/stability.hpp): no eigensolve of the
// 2N x 2N system. Undamped, every mode's dt* is C / omega_j for the method's constant C on the
// imaginary axis, so the rope's is C / omega_max.
// Measurement. Runs of the rope itself from its rest start, h scanned by doubling from
// 0.02 / omega_max until a run diverges, the edge bisected to 1e-3 relative. A run diverges when
// E/E0 passes 1e4 or a state is not finite (the unstable mode grows from round-off: e^44 over
// the run, which `steps` steps reach once the step is ~0.5 % past dt*). Stability here is the
// verdict "no growth past 1e4 in `steps` steps", not the ln E slope of the spring's study: the
// rope's energy sits in slow modes whose slope says nothing of the fastest.
#pragma once

#include <cstddef>
#include <vector>

#include "analysis/parallel.hpp"

namespace steplab {

struct Rope;  // core/scenes/rope.hpp

struct RopeStabilityConfig {
  std::vector<double> params;  // Rope parameters, table order
  std::vector<std::size_t> methods;
  long long steps = 5'000;
  Workers workers;  // threads (0: all cores), progress, shard log
};

struct RopeThresholdRow {
  std::size_t method;
  double omega_max;     // the fastest mode's angular frequency
  double dt_theory;     // min over the modes of the predicted dt*
  int binding_mode;     // the mode j that sets it (1 .. N; 0 if no mode limits it: dt* infinite)
  double dt_measured;
};

// The predicted dt* of the unit oscillator (mass 1, stiffness 1: omega 1) with damping 2 zeta:
// a linear mode of angular frequency omega and damping ratio zeta has dt* = this / omega.
double unit_oscillator_threshold(std::size_t method, double two_zeta);
double rope_predicted_threshold(std::size_t method, const Rope& r, int* binding_mode = nullptr);
double rope_measured_threshold(std::size_t method, const std::vector<double>& params, long long steps);
std::vector<RopeThresholdRow> rope_threshold_study(const RopeStabilityConfig& c);

}  // namespace steplab
