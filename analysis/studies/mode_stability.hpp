// Stability of a scene that declares its modes (core/scene.hpp: modes(), e.g. the rope of N
// masses, the soft body): dt* predicted from its modes and measured by runs of the whole scene.
//
// Prediction. Where the scene is linear and its modes decouple (the rope: mass- and
// stiffness-proportional damping), every method of the table is invariant under the modal change
// of coordinates (equal masses: it is orthogonal, the same for x and v), so a step of the scene
// is independent steps of damped oscillators, mode j one of angular frequency omega_j and damping
// ratio zeta_j. dt* of the scene = min over the modes of each oscillator's predicted dt*, each
// from the method's own step matrix (analysis/studies/stability.hpp): no eigensolve of the 2N x 2N
// system. Undamped, every mode's dt* is C / omega_j for the method's constant C on the imaginary
// axis, so the scene's is C / omega_max. A scene that is not linear declares the modes of its
// linearisation (the soft body: its fastest), and the prediction is theirs.
// Measurement. Runs of the scene itself from its start, h scanned by doubling from
// 0.02 / omega_max until a run is unstable, the edge bisected to 1e-3 relative. A run is unstable
// when its state blows up (core/simulate.hpp) or E/E0 passes 1e4, and besides, by what the
// exact motion of the scene cannot do:
//   damped (every mode's zeta > 0): the exact energy only falls (dE/dt = -v^T C v), so a run
//       whose energy ends above its start is unstable. A bounded nonlinear force (a pendulum)
//       never blows up: an unstable method makes it swing wider or spin over the top with a
//       bounded energy, which this sees and "E/E0 past 1e4" would not;
//   undamped: its energy's ln E slope over the run is above the spring study's kStableRate
//       (analysis/studies/stability.hpp), where the run spans kRateRadians of its slowest mode
//       (where the work cap cuts it shorter, E/E0 past 1e4 alone decides). An oscillation of
//       amplitude A in ln E at frequency Omega biases the slope by about 12 A / (Omega T^2)
//       (stability.hpp): over omega_min T = 2000 radians, with Omega = 2 omega_min, that is
//       3e-6 A omega_min, below kStableRate for the oscillations a stable method leaves (A of
//       1e-3 .. 1e-1) where omega_min is of order 1 (the rope of 16 masses: 30 slow periods, where
//       5 000 fast steps spanned 3 and symplectic Euler's oscillation read as growth).
// Where the instability saturates (a pendulum just past dt*: its rest is unstable, the swing
// grows until the softer restoring force at large angles balances the damping, a limit cycle) a
// run whose limit cycle holds less energy than its start ends below it and counts as stable: the
// measured dt* is then the step whose limit cycle reaches the start's energy, above the
// linearisation's (docs/studies.md gives the pendulum's figures).
// How long a run must be to see a growth: a mode that the start barely
// excites grows from round-off (1e-16 of the state) and must pass the test's amplitude ratio
// 1e2, a growth of e^41 (kSeedGrowth). Just past dt* it grows slowly: explicit Euler on the
// chain at 0.00025 (25 % past its dt* 0.000200) by 0.06 % a step, so 60 000 steps saw no growth
// and measured dt* 61 % too large. So a run at h lasts kSeedGrowth / ln rho steps, rho the
// largest growth a step the modes predict at h (their step matrices' spectral radius), at least
// `steps` and at most kMaxThresholdWork / dim (then a step within ~0.5 % past dt* may still be
// missed: the mark in the table says so). The prediction sets only how long a run is; whether it
// grows is the run's.
#pragma once

#include <cstddef>
#include <vector>

#include "analysis/kernel/parallel.hpp"
#include "core/run_result.hpp"
#include "core/scene.hpp"

namespace steplab {

inline constexpr double kSeedGrowth = 45;           // ln(1e18) = 41.4, and a margin
inline constexpr double kRateRadians = 2000;        // an undamped run's span in its slowest mode's radians, for its slope
inline constexpr double kMaxThresholdWork = 1e7;     // steps x coordinates of one run, at most

struct ModeStabilityConfig {
  std::size_t scene = 0;       // a scene with modes (SceneKernel::modes)
  std::vector<double> params;  // its parameters, table order
  std::vector<std::size_t> methods;
  long long steps = 5'000;
  Workers workers;  // threads (0: all cores), progress, shard log
};

struct ModeThresholdRow {
  std::size_t method;
  double omega_max;     // the fastest mode's angular frequency
  double dt_theory;     // min over the modes of the predicted dt*
  int binding_mode;     // the mode j that sets it (1 .. N, slowest first; 0 if none limits it: dt* infinite)
  double dt_measured;
};

// The predicted dt* of the unit oscillator (omega 1) with damping 2 zeta: a linear mode of
// angular frequency omega and damping ratio zeta has dt* = this / omega.
double unit_oscillator_threshold(std::size_t method, double two_zeta);
// min over the modes of their dt*; `binding_mode` (if given) receives the mode j that sets it.
double modes_predicted_threshold(std::size_t method, const std::vector<Mode>& modes, int* binding_mode = nullptr);
// Whether every mode is damped (zeta > 0): the scene's exact energy then only falls.
bool damped(const std::vector<Mode>& modes);
// Whether a run from the scene's start is unstable by the rules above (its samples the first
// and the last state; its ln E slope fitted where the scene is undamped, and read where the run
// was long enough for it, rate_trusted).
bool unstable_run(const AnyResult& r, bool damped_scene, bool rate_trusted);
// The largest step at which runs of `steps` steps of the scene are stable (above); `omega_max`
// sets the scale of the search.
double measured_threshold(std::size_t method, std::size_t scene, const std::vector<double>& params, double omega_max,
                          long long steps);
std::vector<ModeThresholdRow> mode_threshold_study(const ModeStabilityConfig& c);
// The largest growth a step of h that the modes predict (1 or less: stable), and the steps a
// run at h takes to see it (at least `steps`).
double predicted_growth(std::size_t method, const std::vector<Mode>& modes, double h);
long long threshold_run_steps(std::size_t method, const std::vector<Mode>& modes, int dim, double h, long long steps);

}  // namespace steplab
