// Frame-budget study: "substeps or sweeps, XPBD or large steps, at what cost a frame?". A
// mass-spring scene (core/springs.hpp; by default the rope of 32 masses at total stiffness 5000,
// analysis/studies/defaults.hpp) shown at a frame rate (60 a second) for t_end seconds. Each
// set-up is a method with its substeps a frame (the step h = 1 / (fps substeps)) and its
// settings (XPBD's and PBD's sweeps a substep, Baraff-Witkin's CG iterations); the ODE methods at
// their substeps alone. Per set-up, what a simulation engineer looks at:
//   error     the largest position error over the frames and the coordinates, against the exact
//             motion (or, on a scene without one, RK4 at reference_substeps a frame, checked
//             against RK4 at half as many: their largest difference is the reference's agreement)
//   stretch   over the frames, the largest relative elongation C / L of a spring less the
//             reference's at that frame (how much more the material gives than it should)
//   energy    lost per second against the reference: (E_ref(T) - E(T)) / T (numerical damping)
//   stable    the run ended with a finite state (RunStatus Ok) and has not flown apart: its error
//             is at most 10 times the span of the reference's motion (frames.cpp, kFlownApart)
//   cost      seconds a frame (the median of repeated runs, as every study times) and the work
//             counted: steps, force evaluations, constraint projections (steps x sweeps x springs),
//             CG iterations; and `spring visits` a frame, the work in one machine-independent unit:
//             a projection visits one spring, a force evaluation or a CG product all of them.
// The equal-cost grid: substeps x sweeps (or CG iterations) = budget for each divisor of it. Per
// family the front of error against cost a frame (seconds when timed, spring visits otherwise): the
// set-ups no other of the family dominates, i.e. is more accurate at no more cost on every cost
// the study has (spring visits; and seconds, where timed, within the timing's noise, so that of
// set-ups of equal work the more accurate is on the front, not the one that timed faster). And each method on springs' measured order in h on the same scene
// (substeps doubled at fixed settings): XPBD with one sweep and carried to convergence, PBD,
// Baraff-Witkin with its CG converged.
#pragma once

#include <vector>

#include "analysis/kernel/kernel.hpp"
#include "analysis/kernel/parallel.hpp"

namespace steplab {

struct FrameSetup {
  std::size_t method;
  int substeps = 1;
  MethodSettings settings{};
};

struct FrameRun {
  FrameSetup setup;
  RunStatus status = RunStatus::Ok;
  bool stable = false;
  double error = 0;           // largest over frames and coordinates
  double stretch = 0;         // largest over frames of (max C / L) - the reference's
  double energy_lost = 0;     // per second, against the reference
  Counts counts;              // over the whole run
  long long projections = 0;  // steps x sweeps x springs (the methods that sweep)
  double spring_visits = 0;   // a frame
  double seconds = 0;         // a frame; 0 when not timed
};

struct FrameOrder {
  FrameSetup setup;            // its settings; substeps below
  std::vector<int> substeps;   // doubling
  std::vector<double> errors;  // at each
  double order = 0;            // least-squares slope of log error against log h
};

struct FramesConfig {
  std::size_t scene = 0;
  std::vector<double> params;  // table order
  double fps = 60, t_end = 2;
  int budget = 30;                  // substeps x sweeps of the equal-cost grid
  std::vector<std::size_t> methods; // set-ups of these (default_frame_methods)
  int reference_substeps = 1000;    // RK4's, where the scene has no exact motion (at least 2)
  bool timing = true;
  double min_seconds = 0.05;        // of timed runs a set-up
  bool orders = true;               // the order rows
  Workers workers;
};

struct FamilyFront {
  Family family;
  std::vector<std::size_t> runs;  // indices into FramesResult::runs, cheapest first
};

// `motion`: how far the body moves, the largest |x_i(t_k) - x_i(0)| of the reference over the
// coordinates and frames. An error not below it is met by a run that stays at rest: no set-up is
// the cheapest to reach it (as a map cell at rest, analysis/studies/scaling.hpp).
// `reference_agreement`: on a scene without exact motion, the largest difference over the frames
// and coordinates between the reference and RK4 at half its substeps (m; NaN with the exact motion,
// or where the coarser run blew up): how far the errors below it can be trusted.
// `span`: the widest, over the axes, of the box the reference's positions fill over the frames (m);
// a run whose error passes 10 times it has flown apart (unstable, FrameRun::stable).
struct FramesResult {
  FramesConfig config;
  int springs = 0;
  double motion = 0;
  double span = 0;
  double extent = 0;  // the body's size at rest: the widest over the axes of its start's box (m)
  double reference_agreement = 0;
  std::vector<AnyState> reference;  // its frames (the exact motion's, or RK4's)
  std::vector<FrameRun> runs;
  std::vector<FamilyFront> fronts;
  std::vector<FrameOrder> orders;
};

// The default configuration: the rope of 32 masses at total stiffness 5000, XPBD, PBD,
// Baraff-Witkin, symplectic Euler, implicit Euler and RK4.
FramesConfig default_frames_config();
// The set-ups of `methods` at `budget`: for each divisor s of it, s substeps of budget / s sweeps
// (XPBD, PBD), or of at most budget / s CG iterations (Baraff-Witkin); an ODE method at s substeps.
std::vector<FrameSetup> frame_setups(const std::vector<std::size_t>& methods, int budget);
FramesResult frames_study(const FramesConfig& config);
// The report's cloth at a frame budget: the cloth of its defaults (16 a side) for
// kClothFramesSeconds (analysis/studies/defaults.hpp), the default methods, no order rows (at
// 128 to 1024 substeps a frame with 50 sweeps, they would cost thousands of times the budget's runs).
FramesConfig cloth_frames_config();
// The positions and velocities at each frame of set-up s's run (FramesResult::reference has the
// reference's): for a picture of the motion.
std::vector<AnyState> frame_states(const FramesConfig& c, const FrameSetup& s);

// The cost the fronts and the cheapest set-ups are drawn against: the spring visits a frame, a
// stated operation count of every kind of work (a projection visits one spring; a force
// evaluation, a Jacobian, a factorisation or a linear solve all of them, each a pass over the
// rope's tridiagonal system), the same on every machine. The time a frame is measured beside it,
// but a verdict on it would flip with the machine's load (two set-ups 0.6 % apart in time, XPBD
// and PBD, swapped places between two reports).
double frame_cost(const FrameRun& r);

}  // namespace steplab
