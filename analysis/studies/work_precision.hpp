// Work-precision: what each method pays for an error on each of its scenes (by default the
// one-frequency spring and the stiff chain, analysis/studies/defaults.hpp), and, on the first scene that
// declares a stiff limit (core/scene.hpp), where on the stiffness axis implicit methods start to pay.
//
// A point is one run to t_end: its largest position error against the exact solution at its steps
// (not the final one alone, which a lucky phase can make small), and its cost
// counted two ways: force evaluations (exact and repeatable: the run is made once more through a
// counting scene; its Jacobian evaluations, factorisations and solves counted beside), and run time, the minimum over repeated timings (at least
// kMinRepeats, and kMinSeconds in all), the integration alone, one run at a time. The minimum, not
// the median: a timing can only be slowed by the machine, never sped up, so the minimum is the
// estimate least disturbed by other load.
//
// Fixed-step methods run over a dt sweep; steplab's dopri5 (core/dopri5.hpp) and the peers users
// would pick instead (analysis/peers/peers.hpp), Boost.Odeint's controlled runge_kutta_dopri5 (the same
// tableau, odeint's own controller) and SUNDIALS CVODE with Adams-Moulton and with BDF (dense LU,
// the analytic Jacobian), over a tolerance sweep with rtol = atol = tol. Every solver is timed
// alike: the scene made outside the timed region, the solver's own set-up, run and clean-up inside.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/kernel/parallel.hpp"
#include "analysis/kernel/counts.hpp"
#include "analysis/studies/defaults.hpp"
#include "core/simulate.hpp"

namespace steplab {

// The adaptive solvers of the study on its fixed-size scenes: steplab's dopri5 first, then the
// peers built into this steplab (analysis/peers/peers.hpp, PeerScenes::FixedSize).
std::vector<std::string> adaptive_solvers();

struct WorkPoint {
  std::string method;    // a table method, or an adaptive solver: "dopri5", "odeint_dopri5", "cvode_bdf_dense", ...
  bool adaptive = false;
  double setting = 0;    // dt, or the tolerance of an adaptive method
  RunStatus status = RunStatus::Ok;
  double error = 0;      // largest position error at the steps; inf if diverged
  long long steps = 0, force_evaluations = 0, jacobian_evaluations = 0;
  long long rejected = 0, factorisations = 0, solves = 0, newton = 0;  // analysis/kernel/counts.hpp
  double seconds = -1;   // minimum of the timings; -1 without timing
  double spread = 1;     // its two timing passes' minima, larger over smaller (analysis/kernel/noise.hpp)
  Counts counts() const { return {steps, rejected, force_evaluations, jacobian_evaluations, factorisations, solves, newton}; }
};

template <class F> void encode_fields(WorkPoint& p, F&& f) {  // analysis/kernel/shard.hpp
  f(p.method), f(p.adaptive), f(p.setting), f(p.status), f(p.error), f(p.steps), f(p.force_evaluations);
  f(p.jacobian_evaluations), f(p.rejected), f(p.factorisations), f(p.solves), f(p.newton), f(p.seconds), f(p.spread);
}

// "Evaluations" in steplab are force evaluations F(x, v): the study's cost untimed. Jacobian
// evaluations, factorisations and linear solves are counted beside them (Counts), never added in.
struct Cheapest {
  double error_level;
  std::string by_time, by_forces;  // empty: no run reached the level
  double seconds = -1;
  long long forces = 0;            // force evaluations of the cheapest by them
  std::ptrdiff_t time_point = -1, forces_point = -1;  // those runs in SceneWork::points (their counts)
};

// On the stiff scene: where each explicit method's steps stop being stable, against the step its
// accuracy alone would allow for kLimitErrorLevel: the dt at which its error reaches that level
// on the scene's stiff limit (the chain's slow mode alone: the masses move as one on spring k1).
struct StableStep {
  std::string method;
  double largest_stable_dt;   // the largest dt of the scene's sweep that did not diverge
  double accuracy_dt;         // on the stiff limit, interpolated in the same dt sweep; -1: not reached
  double next_tried_dt;       // the sweep's next dt above largest_stable_dt (which diverged): the limit lies between; inf: none
};

struct SceneWork {
  std::size_t scene;
  std::vector<double> params;
  std::vector<WorkPoint> points;
  std::vector<Cheapest> cheapest;  // one per error level
};

struct StiffnessRow {
  double stiffness2, ratio;  // k2 and k2 / k1
  std::string best_explicit, best_implicit;
  double explicit_seconds = -1, implicit_seconds = -1;  // cheapest run with error <= crossover_error
  long long explicit_forces = 0, implicit_forces = 0;
};

struct WorkPrecisionConfig {
  std::vector<SweepScene> scenes{kWorkPrecisionScenes.begin(), kWorkPrecisionScenes.end()};
  std::vector<std::size_t> methods;  // fixed-step methods (indices into the table)
  std::vector<std::string> adaptive = adaptive_solvers();  // dopri5 and the peers run
  std::vector<double> tolerances{1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11};
  std::vector<double> error_levels{1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8};
  std::vector<double> stiffnesses{5, 5e1, 5e2, 5e3, 5e4, 5e5, 5e6};  // the stiff scene's stiffness (the chain's k2)
  double crossover_error = 1e-4;
  double t_end = 10, sweep_t_end = 2;  // the scenes; the stiffness sweep
  int points = 14;                     // dt sweep points per decade range below
  bool timing = true;
  Workers workers;  // threads (0: all cores), progress, shard log
};

inline constexpr int kMinRepeats = 5;
inline constexpr double kMinSeconds = 0.002;
inline constexpr double kLimitErrorLevel = 1e-4;

struct WorkPrecisionResult {
  WorkPrecisionConfig config;
  std::vector<SceneWork> scenes;       // config.scenes, in order
  std::ptrdiff_t stiff = -1;           // the scene (in `scenes`) with the stiff limit; -1: none
  std::vector<StableStep> limits;      // the stiff scene's explicit methods
  std::vector<StiffnessRow> stiffness; // empty: no scene with a stiff limit
  double crossover_ratio = -1;         // smallest k2/k1 from which on implicit is cheaper (timed: by more than kTieMargin); -1: never
};

WorkPrecisionResult work_precision_study(const WorkPrecisionConfig& config);

}  // namespace steplab
