// When does implicit pay: a scene of run-time size that declares its modes (core/scene.hpp:
// size_param, modes(); the rope of N masses, the soft body of n x n masses: N = n^2) refined over
// `sizes`, and stiffened over `stiffnesses` (its stiffness_param), every method and the peers in
// each cell (size, stiffness), at each target error.
//
// For each target, stiffness, solver and size:
//   the largest stable step dt*, predicted from the scene's modes (analysis/studies/mode_stability.hpp;
//     measured against runs there);
//   the step (dopri5 and the peers: the tolerance rtol = atol) at which the run reaches the
//     target error over the whole motion: the largest |x_i(t_k) - x_i*(t_k)| over the coordinates
//     and the frames t_k = k t_end / frames, k = 1 .. frames, against the exact solution (the
//     rope) or the reference solution (dopri5 at rtol 1e-13 with its dense output), so that the
//     same error per mass is asked at every N and a body that has settled by t_end is not
//     matched there alone. A fixed-step run interpolates each frame inside the step that holds it
//     (its output between steps, core/dense_output.hpp: a step need not divide the frame
//     interval; with steps_divide_frames, as an animation's, it does and gives each frame a state
//     of its own); dopri5 interpolates (its dense output), CVODE and ARKODE too (their normal
//     mode), RADAU5 by its collocation polynomial, Boost.Odeint steps to each frame. A target is absolute, or a fraction
//     of the body's extent at rest (the visual one: 1 % of its size). The search: secant in
//     log-log on error ~ C dt^p (p the method's order; for a tolerance p = 1), the largest step
//     tried whose error is at or below the target, from at most kSearchRuns runs.
//     A fixed-step method's search is capped at 0.95 dt*: it is told where its steps stop being
//     stable, from the exact modes, which no adaptive solver is told (ScalingRow::capped marks
//     the rows that stopped there).
//   that run's cost: its wall-clock time (the minimum of repeated runs, at least one and
//     timing_seconds in all, one at a time after the searches; for every solver alike the scene is made outside
//     the timed region, the solver's set-up, run (with its frames) and clean-up inside), its
//     counts (analysis/kernel/counts.hpp: steps, rejected steps, force and Jacobian evaluations,
//     factorisations, linear solves, Newton iterations); the cost of one step is their ratio.
// Then per series (target, stiffness, solver) the exponents p of cost ~ N^p, N the number of
// masses, for one step and for the whole run, and q of dt* ~ N^q (Exponent below); per (target,
// stiffness) the size from which an implicit method's whole run is cheaper than every explicit
// one's; and per cell the map's answer: the cheapest solver and its margin over the next
// (ScalingCell).
#pragma once

#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/kernel/parallel.hpp"
#include "analysis/kernel/counts.hpp"
#include "analysis/kernel/noise.hpp"
#include "analysis/studies/defaults.hpp"
#include "core/simulate.hpp"

namespace steplab {

inline constexpr int kSearchRuns = 10;

// A target error: `value` itself, or (of_extent) value times the body's extent at rest, the largest
// over its axes of max - min of its initial positions at the study's largest size.
struct ErrorTarget {
  double value = 1e-4;
  bool of_extent = false;
};

struct ScalingConfig {
  std::string scene{kDefaultSizedScene};  // a scene that scales(): of run-time size, with modes
  // the scene's parameters, table order (its size parameter replaced by each size, its stiffness
  // parameter by each stiffness)
  std::vector<double> params;
  std::vector<int> sizes{16, 64, 256, 1024};
  std::vector<double> stiffnesses;  // the scene's stiffness_param; empty: params' own (one)
  std::vector<ErrorTarget> targets{{1e-4, false}};
  int frames = 100;  // the error is the largest over the frames k t_end / frames, k = 1 .. frames
  bool steps_divide_frames = false;  // a fixed step divides the frame interval (else: output between steps)
  std::vector<std::size_t> methods;  // numerical methods of the table
  // steplab's dopri5 and the peers (analysis/peers/peers.hpp) that run on the scene: by default all
  // that are built (scaling_config)
  std::vector<std::string> adaptive;
  double t_end = 2;
  long long max_steps = 2'000'000;   // a search does not try steps that need more
  bool timing = true;
  double timing_seconds = 0.1;  // each timed row's runs take at least this long in all (the minimum kept)
  Workers workers;  // threads (0: all cores), progress, shard log
};

struct ScalingRow {
  std::string solver;    // a method's name, dopri5 or a peer's (analysis/peers/peers.hpp)
  int target = 0;        // its index in ScalingConfig::targets
  double stiffness = 0;  // the scene's stiffness parameter (NaN: the scene declares none)
  bool implicit = false;
  bool adaptive = false; // dt below is then the tolerance
  int n = 0;             // the size: the value of the scene's size parameter
  int masses = 0;        // N
  double dt_stable = 0;  // predicted dt* (inf: none; NaN for the adaptive solvers)
  double dt = 0;         // the step (tolerance) that reaches the target; NaN if none did
  bool capped = false;   // a fixed step at the search's cap, 0.95 dt* (told by the modes)
  double error = 0;      // its error (largest over the coordinates and the frames)
  long long steps = 0, forces = 0, jacobians = 0;
  long long rejected = 0, factorisations = 0, solves = 0, newton = 0;  // analysis/kernel/counts.hpp
  double seconds = 0;    // the whole run (0 without timing)
  double spread = 1;     // its two timing passes' minima, larger over smaller (analysis/kernel/noise.hpp)
  int runs = 0;          // runs the search took
  Counts counts() const { return {steps, rejected, forces, jacobians, factorisations, solves, newton}; }
  bool reached() const { return dt == dt; }
};

// An exponent p of y ~ N^p: least squares in log-log over the sizes where y is finite and > 0,
// with its 95 % interval (Student's t, n - 2 degrees of freedom: analysis/fits/fit.hpp), fitted only
// over at least kFitSizes sizes spanning at least kFitDecades decades of N (two sizes fit any
// exponent exactly; a narrow span measures the overheads' mix, not a power): else NaN, with the
// sizes and span it had. `early`: the sizes begin below the asymptotic regime, where a step's cost
// grows by less than N^kAsymptoticSlope from the smallest size to the next (a step touches every
// mass, so its work grows at least as N; flatter, fixed overheads still dominate).
inline constexpr int kFitSizes = 3;
inline constexpr double kFitDecades = 1.5;
inline constexpr double kAsymptoticSlope = 0.5;
struct Exponent {
  double value = std::numeric_limits<double>::quiet_NaN(), lo = value, hi = value;
  int sizes = 0;       // sizes with a value
  double decades = 0;  // log10(N_max / N_min) over them
  bool early = false;
  bool fitted() const { return !std::isnan(value); }
};
Exponent fit_exponent(std::span<const double> masses, std::span<const double> y);
// Whether a step's cost (NaN or <= 0 where unknown) grows by less than N^kAsymptoticSlope from
// the smallest size with one to the next.
bool begins_early(std::span<const double> masses, std::span<const double> step_cost);

struct ScalingFit {
  std::string solver;
  int target = 0;
  double stiffness = 0;
  Exponent step, run;  // cost of one step, of the whole run at the target error
  Exponent stable;     // dt* ~ N^q, where dt* is finite and > 0
};

// A cell of the map (one target, stiffness and size): the cheapest solver that reached the target
// and the next cheapest, with the margin next / cheapest; its rival, the cheapest solver of another
// group (solver_group, analysis/peers/peers.hpp), with the margin rival / cheapest that decides
// the cell (two members of one family within the noise are still that family's win); the
// cheapest implicit fixed-step method against the cheapest explicit one (fixed-step or adaptive) and against the cheapest adaptive
// implicit peer (CVODE, ARKODE's DIRK tables, RADAU5): their costs over its (> 1: the implicit method is cheaper). NaN where a side
// has none. `motion`: how far the body moves, the largest |x_i(t_k) - x_i(0)| of the exact (or
// reference) solution over the coordinates and frames; where the target error exceeds it, a run
// that stays at rest meets the target, and only stability separates the solvers.
struct ScalingCell {
  int n = 0, masses = 0;
  std::string cheapest, next, rival, best_implicit, best_explicit, best_implicit_peer;
  double margin = 0, rival_margin = 0, explicit_over_implicit = 0, implicit_peer_over_implicit = 0;
  double motion = 0;
};

// What one (target, stiffness) of the study found: its absolute error, the smallest size at which
// some implicit method's whole run is cheaper than every explicit method's (time, or force +
// Jacobian evaluations without timing), and which (0 if none), and a cell per size.
struct ScalingBlock {
  int target = 0;
  double error = 0, stiffness = 0;
  int crossover = 0;
  std::string crossover_method;
  std::vector<ScalingCell> cells;
};

struct ScalingResult {
  ScalingConfig config;
  std::vector<ScalingRow> rows;  // target-major, then stiffness, solver, size
  std::vector<ScalingFit> fits;  // one per series (target, stiffness, solver), in the rows' order
  std::vector<ScalingBlock> blocks;  // one per (target, stiffness), in the rows' order

  std::size_t solvers() const { return config.methods.size() + config.adaptive.size(); }
  std::size_t series() const { return config.sizes.empty() ? 0 : rows.size() / config.sizes.size(); }
  // Series s's rows (s = block * solvers() + solver), one per size in order.
  std::span<const ScalingRow> rows_of(std::size_t s) const {
    return {rows.data() + s * config.sizes.size(), config.sizes.size()};
  }
};

// Whether the study runs on a scene: of run-time size (a size parameter) with modes.
struct SceneKernel;
bool scales(const SceneKernel& scene);
// The study's defaults on a scene: its default parameters; the sizes and step cap of
// analysis/studies/defaults.hpp (the rope at 16, 64, 256, 1024 masses with searches of up to 2 000 000
// steps, the soft body at n = 4, 8, 16 with up to 200 000); dopri5 and every peer built that runs
// on the scene.
ScalingConfig scaling_config(std::string_view scene);

ScalingResult scaling_study(const ScalingConfig& c);
// What the rows say (analysis/studies/scaling_answers.cpp), given the rows, the blocks' target, error and
// stiffness and their cells' size and motion: the fits, each block's crossover and its cells'
// cheapest solvers and margins.
void answer_rows(ScalingResult& r);

// The stiffnesses the study runs: config.stiffnesses, or the one in params (NaN where the scene
// declares no stiffness parameter).
std::vector<double> scaling_stiffnesses(const ScalingConfig& c);
// A target's absolute error on the study's scene.
double absolute_error(const ScalingConfig& c, const ErrorTarget& t, double stiffness);
// A block's target in words: "0.0001", or "1 % of the extent, 0.05".
std::string target_text(const ScalingConfig& c, const ScalingBlock& b);

// What a row's run cost: its seconds, or without timing its force evaluations times N (each
// touches every mass; the Jacobians, factorisations and solves counted beside, not added in).
double scaling_cost(const ScalingConfig& c, const ScalingRow& r);
// The cheapest (scaling_cost) reached run at size k of block b that `keep` accepts, the first of
// equals in solver order; null if none.
template <class Keep> const ScalingRow* cheapest_run(const ScalingResult& r, std::size_t b, std::size_t k, Keep keep) {
  const ScalingRow* best = nullptr;
  for (std::size_t s = 0; s < r.solvers(); ++s) {
    const ScalingRow& w = r.rows_of(b * r.solvers() + s)[k];
    if (w.reached() && keep(w) && (!best || scaling_cost(r.config, w) < scaling_cost(r.config, *best))) best = &w;
  }
  return best;
}
// At size k of block b, the cheapest (by run time) implicit and explicit runs of steplab's
// fixed-step and adaptive methods that reached the target (null: none): what the crossover
// compares (ScalingBlock::crossover).
struct CrossoverSides {
  const ScalingRow *implicit = nullptr, *explicit_ = nullptr;
};
CrossoverSides crossover_sides(const ScalingResult& r, std::size_t b, std::size_t k);
// The number of masses at size n (the scene's: n on the rope, n^2 on the soft body).
int scaling_masses(const ScalingConfig& c, int n);
// The adaptive solvers that run on the scene: dopri5 and the peers built for it.
std::vector<std::string> scaling_adaptive_solvers(std::string_view scene);

}  // namespace steplab
