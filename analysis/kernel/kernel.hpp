// The kernel table: every method's and every scene's compiled code, reached at run time.
//
// A method's stepping code is a template over the scene (core/method.hpp); the run loop is a
// template over both (core/simulate.hpp). Each (method, scene) pair is instantiated once, in a
// translation unit CMake generates per method from core/registry.cmake (tools/kernels.cmake;
// Ceres Solver's generated schur_eliminator_*.cc are the model), and handed out here as a
// PairKernel of plain function pointers. The studies, `check`, `run`, the report, the benchmarks'
// study rows and the tests are ordinary code over this table: they cross it once per run, and
// the step loop behind each pointer is inlined as before.
//
// A scene is passed as its index and its parameter values in table order (core/scene.hpp); a
// result comes back as an AnyResult (core/simulate.hpp), the same numbers in vectors of run-time
// size. The table is the executable's own (kernel_table(), defined in a generated file): the
// `steplab` binary's holds the built-in methods and scenes, a tool made with
// steplab_add_executable() holds the user's beside them.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "analysis/kernel/counts.hpp"
#include "core/batch.hpp"
#include "core/dopri5.hpp"
#include "core/method.hpp"
#include "core/simulate.hpp"

namespace steplab {

using AnyState = State<Eigen::Dynamic>;
using AnyAdaptiveResult = AdaptiveResult<Eigen::Dynamic>;
using Params = std::span<const double>;  // a scene's parameter values, in its table's order

// dopri5's counts (core/dopri5.hpp) as every solver's (analysis/kernel/counts.hpp).
inline Counts counts_of(const AdaptiveStats& s) {
  Counts n;
  n.steps = s.accepted, n.rejected = s.rejected, n.forces = s.force_evaluations;
  return n;
}

struct BounceEvent {
  double t;               // time the mass left the ground
  double energy_ratio;    // E/E0 then
  double rebound_height;  // apex of the flight that follows (above the drop height 0: energy gained); NaN if cut off
};

// What an observed run records at every step (analysis/kernel/kernel_impl.hpp, Observer): the largest
// |x_i|; and on a scene with ground contact (core/scene.hpp, HasContact) the deepest penetration
// and, on a 1-D one, each time the mass leaves the ground with E/E0 and the apex that follows.
struct Observed {
  double max_abs_x = 0;
  double max_penetration = 0;
  std::size_t max_bounces = 0;       // bounces recorded at most (reserved before the run)
  std::vector<BounceEvent> bounces;
};

// A run that reads the invariants (core/invariants.hpp; analysis/studies/long_time.hpp):
// steps of dt up to the last of `at`, and at each of those step counts, for each invariant, the
// largest |I - I0| over the steps so far (every step is read: an oscillating error is caught at
// its peak), and the position error against the exact solution where the scene has one.
struct InvariantsRunSpec {
  double dt = 0.01;
  std::vector<long long> at;  // ascending step counts
  MethodSettings settings{};
};
struct InvariantsRun {
  RunStatus status = RunStatus::Ok;
  long long steps = 0;                        // steps completed with a finite state
  std::vector<double> invariant0, last;       // each invariant's value at the start and at the last step
  std::vector<std::vector<double>> largest;   // [invariant][k]: max |I - I0| up to step at[k]
  std::vector<double> position_error;         // [k]: |x - x_exact| at step at[k]; empty without an exact solution
};

// One method's code on one scene. A 1-D scene has the step-map entries too (the stability
// predictions and the local error difference or apply them), others have them null.
struct PairKernel {
  AnyResult (*run)(Params, const RunSpec&) = nullptr;
  // The run, counting what it asked of the scene and its Newton solves (analysis/kernel/counts.hpp).
  AnyResult (*run_counted)(Params, const RunSpec&, Counts&) = nullptr;    // scenes with an exact solution or of run-time size
  AnyResult (*run_observed)(Params, const RunSpec&, Observed&) = nullptr;  // fixed-size scenes with contact, and 1-D ones
  // Wall-clock times of the same run repeated (analysis/kernel/timing.hpp: at least `repeats`, `seconds`
  // in all), the scene made once before: the integration alone, what a user pays (the chain's
  // constructor, an eigen-decomposition, costs as much as a short run).
  std::vector<double> (*timings)(Params, const RunSpec&, std::size_t repeats, double seconds) = nullptr;
  // n steps of h from the initial state in place, starting again every `restart` steps (a
  // multistep method with a fresh memory), each state kept from being optimised away as
  // benchmark::DoNotOptimize keeps it: the per-step rows of `make bench` (bench/steps_bench.cpp).
  void (*time_steps)(Params, double h, long long n, int restart) = nullptr;
  // 1-D scenes. The step map flattened: x, v, then a multistep method's memory entries' x and v
  // (analysis/kernel/step_map.hpp), one step of h from z; the flattened memory of a run that has sat
  // at (x, v) forever.
  Eigen::VectorXd (*step_flat)(Params, const Eigen::VectorXd& z, double h) = nullptr;
  Eigen::VectorXd (*at_rest_flat)(Params, double x, double v) = nullptr;
  // One step of h from the exact state at t0, a multistep method remembering the exact past
  // (1-D scenes with an exact solution); y in: ignored, out: the state reached.
  StepStatus (*exact_step)(Params, double t0, double h, AnyState& y) = nullptr;
  // n steps of h from (x, v) with the method's own start-up, state k after step k + 1 in xs[k],
  // vs[k]; the first status that was not Ok (1-D scenes).
  StepStatus (*steps_from)(Params, double x, double v, double h, int n, double* xs, double* vs) = nullptr;
  // The runs, `width` (2, 4 or 8: cpu_has_width, core/batch.hpp) at a time in SIMD lanes, the
  // loop compiled for that width's instruction set; out[i] is what run() gives for runs[i], to
  // the bit. Where the method's step is written over the scalar and the scene is Packable (the
  // methods that core/batch.hpp's PackedStep admits); null elsewhere. Keeps
  // no samples (run_all gives runs that ask for them to run()).
  void (*run_batch)(std::span<const BatchRun> runs, AnyResult* out, int width) = nullptr;
  // Scenes with invariants (core/invariants.hpp): a run that reads them (InvariantsRunSpec above).
  InvariantsRun (*invariants_run)(Params, const InvariantsRunSpec&) = nullptr;
};

// One method, whatever the scene.
struct MethodKernel {
  MethodInfo info;
  int map_size;  // the flattened step map's length: 2 (x, v) plus 2 per memory entry
  // The step map of h = 1 on u'' = -k u - c u' (m = 1) applied to the unit vectors: the matrix
  // whose spectral radius is the method's amplification at h lambda = re + i im (regions.cpp).
  Eigen::MatrixXd (*test_matrix)(double k, double c);
  // Its Butcher tableau where it declares one (core/method.hpp): A row by row (s^2 entries) and
  // b (s entries); empty otherwise.
  std::span<const double> butcher_a{}, butcher_b{};
  // A multistep method's one-step start (its Starter, core/linear_multistep.hpp): that method's
  // name; empty for a one-step method.
  std::string_view starter{};
};

// A scene of run-time size made once and reached through the table (SceneKernel::made): what a
// solver outside the table (the peers, analysis/peers/sized_peers.cpp) asks of it. `scene` is the
// object SceneKernel::make made.
struct MadeSceneCode {
  Eigen::VectorXd (*force)(const void* scene, const Eigen::VectorXd& x, const Eigen::VectorXd& v);
  Jacobians<Eigen::Dynamic> (*jacobians)(const void* scene, const Eigen::VectorXd& x, const Eigen::VectorXd& v);
  const Eigen::VectorXd& (*inverse_mass)(const void* scene);
  State<Eigen::Dynamic> (*initial)(const void* scene);
};

// One scene, whatever the method.
// A mass-spring scene's springs at given states (core/springs.hpp): how many, and at each state
// the largest relative elongation C / L of a spring with a rest length (0 when none is stretched)
// and the scene's energy. For the frame-budget study (analysis/studies/frames.hpp).
struct SpringMeasures {
  int springs = 0;
  std::vector<double> stretch, energy;
};

struct SceneKernel {
  std::string_view name;
  std::string_view title;  // the scene in a few words, for a table's heading (its name if it gives none)
  std::string_view old_name;  // the name it had in the old framework, also accepted (empty: none)
  std::string_view equation;  // its equation of motion in one line, for the report (empty: not given)
  std::span<const ParamSpec> params;
  int dim;
  bool has_exact;
  bool driven = false;  // its force depends on t (core/scene.hpp, Driven)
  bool has_jacobians = true;  // dF/dx and dF/dv: the implicit methods and CVODE's Newton (HasJacobians)
  // What the scene offers the studies (core/scene.hpp), asked for instead of its name; a
  // parameter by its index in `params`, -1 where the scene declares none.
  int size_param = -1;       // the count that refines a scene of run-time size; -1: fixed size
  int coords_per_mass = 1;   // N masses = dim / coords_per_mass
  int jacobian_bandwidth = -1;  // -1: not declared banded
  int stiffness_param = -1, damping_param = -1;
  std::vector<Mode> (*modes)(Params) = nullptr;  // its linearisation's oscillators, slowest first
  // What it tends to as its stiffness grows: that scene's name and parameter values (null: none).
  std::string_view stiff_limit_scene{};
  std::vector<double> (*stiff_limit)(Params) = nullptr;
  // Scenes of run-time size: the scene made once and its code for solvers outside the table
  // (null on fixed-size scenes).
  std::shared_ptr<const void> (*make)(Params) = nullptr;
  const MadeSceneCode* made = nullptr;
  AnyState (*initial)(Params);
  AnyState (*exact)(Params, double t);  // null without an exact solution
  // The Euclidean norm of a vector of dim entries as the scene's fixed-size Vec computes it (Eigen
  // sums a fixed-size and a run-time-size vector in different orders: the last bits differ).
  double (*norm)(const Eigen::VectorXd&);
  AnyAdaptiveResult (*dopri5)(Params, const AdaptiveSpec&);
  // dopri5's run repeated and timed, the scene made once (PairKernel::timings).
  std::vector<double> (*dopri5_timings)(Params, const AdaptiveSpec&, std::size_t repeats, double seconds);
  SpringMeasures (*spring_measures)(Params, std::span<const AnyState>) = nullptr;  // mass-spring scenes only
  // Scenes with invariants (core/invariants.hpp): their names, and the period and extent the
  // long-time study measures in; empty and null elsewhere.
  std::span<const std::string_view> invariant_names{};
  double (*period)(Params) = nullptr;
  double (*extent)(Params) = nullptr;
};

struct KernelTable {
  std::span<const MethodKernel* const> methods;
  std::span<const SceneKernel* const> scenes;
  std::span<const PairKernel* const> pairs;  // [method][scene], method-major; null where the method does not apply
};

// The executable's table (a generated file: tools/kernels.cmake).
const KernelTable& kernel_table();

// --- The tables by index and by name -------------------------------------------------------

inline std::size_t method_count() { return kernel_table().methods.size(); }
inline const MethodKernel& method_kernel(std::size_t m) { return *kernel_table().methods[m]; }
inline const MethodInfo& method_info(std::size_t m) { return method_kernel(m).info; }
inline std::size_t scene_count() { return kernel_table().scenes.size(); }
inline const SceneKernel& scene_kernel(std::size_t s) { return *kernel_table().scenes[s]; }
inline std::string_view scene_name(std::size_t s) { return scene_kernel(s).name; }

// The runs of one pair, in order: in packs of `width` lanes (2, 4 or 8, as the CPU has them:
// cpu_has_width) where the pair has run_batch, one at a time where it has not or `width` is 1
// (the reference the packs are measured and tested against) or where a run asks for samples;
// 0: best_width(). The same numbers whatever the width. A width this CPU cannot step throws
// std::invalid_argument.
std::vector<AnyResult> run_all(const PairKernel& k, std::span<const BatchRun> runs, int width);

// Method m's code on scene s; throws std::invalid_argument where m does not apply (the exact
// flow on a scene without one, an implicit method on a scene without Jacobians): applies() tells
// first, and why_not says why in words ("needs ..."; empty where it applies).
const PairKernel& pair_kernel(std::size_t m, std::size_t s);
bool applies(std::size_t m, std::size_t s);
std::string why_not(std::size_t m, std::size_t s);

// The methods a study of the ODE takes when none are named: every numerical one but those on
// springs (XPBD, PBD, Baraff-Witkin), which the frame-budget study measures (study frames) and
// the others take by name.
inline bool in_ode_studies(std::size_t m) { return !method_info(m).exact_flow && !method_info(m).on_springs; }
inline std::vector<std::size_t> ode_methods() {
  std::vector<std::size_t> out;
  for (std::size_t m = 0; m < method_count(); ++m)
    if (in_ode_studies(m)) out.push_back(m);
  return out;
}

// Index of a method by its name or an old alias; of a scene by its name or its old name.
std::optional<std::size_t> find_method(std::string_view name);
std::optional<std::size_t> find_scene(std::string_view name);
// The scene's index; throws std::logic_error if the table has none of that name.
std::size_t scene_index(std::string_view name);
// "explicit_euler, symplectic_euler, ... (old names: euler, ...)" for error messages and --help;
// every name and old name a method is found by, and every scene's (for "did you mean").
std::string method_names();
std::vector<std::string> method_name_list();
std::vector<std::string> scene_name_list();
std::string scene_list();
// "rope, softbody": the scenes for which `offers` holds, for a message naming what is accepted.
std::string scene_list(bool (*offers)(const SceneKernel&));

// Whether the scene has a parameter of that name; its default values in table order.
inline bool has_param(std::size_t scene, std::string_view name) { return has_param(scene_kernel(scene).params, name); }
inline std::vector<double> default_param_values(std::size_t scene) { return default_values(scene_kernel(scene).params); }

}  // namespace steplab
