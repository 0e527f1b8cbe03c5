// The commands behind the CLI. Each takes its parsed arguments, throws UsageError for bad input
// (before writing anything) and returns the exit status.
#pragma once

#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/kernel/parallel.hpp"
#include "analysis/peers/peers.hpp"
#include "analysis/kernel/shard.hpp"
#include "reports/cli/scene_args.hpp"

namespace steplab {

// What every command is given beside its own arguments, made by cli_main (reports/cli/cli.hpp);
// nothing of it is process-wide.
struct Context {
  std::vector<std::string> invocation;  // the command line as typed, for a shard's part to name
  bool dry_run = false;                 // check the input and stop, running nothing (the fuzzer)
  ProgressHook progress = nullptr;      // shown as a study's tasks finish
  WorkLog log;                          // a shard's results, or a merge's parts (analysis/kernel/shard.hpp)
  // A study's workers: `threads`, the progress, the log.
  Workers workers(unsigned threads) { return {threads, progress, &log}; }
  // Called by each command once its input is checked: true in a dry run (stop); otherwise
  // refuses an output path that cannot be written, before any work is done.
  bool stop_after_validation(const std::string& output_path) const;
};

// Parses `args` (argv[1..]) and runs the command they name in `ctx`; bad input is one line on
// stderr and exit status 2. cli_main calls it with the whole command line, `steplab merge` with
// the study it replays.
int dispatch(const std::vector<std::string>& args, Context& ctx);

// A method's settings as typed: the sweeps a step of XPBD and PBD, the CG iterations and
// tolerance of Baraff-Witkin (core/method.hpp, MethodSettings). For `run` and `study frames`
// (reports/cli/frames_command.cpp).
struct SettingsArgs {
  std::string sweeps, cg_iterations, cg_tolerance;  // empty: the defaults
  void add_to(CLI::App* app);
  // The settings, each checked; UsageError for a value out of range, or for a setting given that
  // none of `methods` takes (run's --method, a study's --methods).
  MethodSettings resolve(const std::vector<std::size_t>& methods) const;
};

struct RunArgs {
  SceneArgs scene;
  SettingsArgs settings;
  std::string method = "explicit_euler";
  std::string dt;  // empty: 0.01 (dopri5 refuses a --dt given)
  std::string rtol, atol;  // dopri5 only; empty: SciPy's defaults 1e-3 and 1e-6
  std::string t_end = "10";
  std::string samples;  // empty: default_samples (run_command.cpp)
  std::string error_every;  // empty: the steps / 100, at least 1 (run_command.cpp)
  std::string json;  // write JSON here instead of CSV on stdout
};

int run_command(RunArgs& args, Context& ctx);

}  // namespace steplab

namespace steplab {

struct ConvergenceArgs {
  SceneArgs scene;
  SettingsArgs settings;  // of the methods on springs, for every run of theirs
  std::string methods;  // comma-separated; empty: every numerical method
  std::map<std::string, std::string> params;  // as typed, by name (convergence_params(); t-end empty: the study's)
  std::string error = "final";
  std::string sweep;  // NAME=V1,V2,...: the study at each value of one scene parameter
  bool reference = false;
  std::string threads = "0";
  std::string lanes;  // the pack width: auto, 1, 2, 4 or 8 (add_lanes_option)
  std::string shard;  // i/N: write part i of N to --json (reports/cli/parts.hpp)
  bool timing = false;
  std::string json;
};

int convergence_command(ConvergenceArgs& args, Context& ctx);

// Shared by the commands.
std::size_t resolve_method(std::string_view name);
// The methods of a comma-separated list (empty: every one, the exact flow if `with_analytic`); on
// `scene`, every one that runs there, and a named one that cannot is refused (why_not).
std::vector<std::size_t> resolve_methods(const std::string& list, bool with_analytic,
                                         std::optional<std::size_t> scene = std::nullopt);
// --methods of a study with peers: the table's numerical methods and the adaptive solvers
// `available` on its scene (dopri5 and the peers, analysis/peers/peers.hpp). The adaptive ones named are
// run, or every available one where none is named (none with --no-peers). A peer not built into
// this steplab, or not running on `scene`, is a UsageError. `table`: the peers (a test's own).
struct Solvers {
  std::vector<std::size_t> methods;
  std::vector<std::string> adaptive;
};
Solvers resolve_solvers(const std::string& list, const std::vector<std::string>& available, std::string_view scene, bool no_peers,
                        std::span<const PeerInfo> table = peers());
unsigned resolve_thread_count(const std::string& text);
int resolve_lanes(const std::string& text);
// --lanes on a study command.
void add_lanes_option(CLI::App* app, std::string& lanes);
// --threads on a command (`help`: where a study times its runs one at a time, it says so).
void add_threads_option(CLI::App* app, std::string& threads, const std::string& help = "worker threads, 0 = all cores");

}  // namespace steplab

namespace steplab {

// `study damping` and `study stability` share these (the spring only).
struct StabilityArgs {
  SceneArgs scene;
  std::string methods;
  std::string dts = "0.01,0.05,0.2";         // damping sweep
  std::string dampings;                      // damping sweep; empty: 0 .. 2 x critical (21) + 0.1
  std::string threshold_dampings = "0,0.1,1,4";
  std::string map_dt_points = "64", map_damping_points = "64", map_dt_min = "0.01", map_dt_max = "10";
  std::string threads = "0";
  std::string lanes;  // the pack width: auto, 1, 2, 4 or 8 (add_lanes_option)
  std::string shard;  // i/N: write part i of N to --json (reports/cli/parts.hpp)
  std::string json;
};

int damping_command(StabilityArgs& args, Context& ctx);
int stability_command(StabilityArgs& args, Context& ctx);
void add_stability_options(CLI::App* app, StabilityArgs& args, bool sweep, bool map);
int amplitude_command(const std::vector<double>& spring_params, double step, const Context& ctx);

}  // namespace steplab

namespace steplab {

struct CollisionArgs {
  SceneArgs scene;  // parameters shared by the bounce and the triangle (ground, mass, gravity)
  std::string methods;
  std::map<std::string, std::string> params;  // as typed, by name (collision_params())
  std::string threads = "0";
  std::string shard;
  std::string json;
};

int collision_command(CollisionArgs& args, Context& ctx);

// `study frames` (reports/cli/frames_command.cpp): a mass-spring scene at a frame rate, each
// method at substeps x sweeps (or CG iterations) = budget (analysis/studies/frames.hpp).
struct FramesArgs {
  SceneArgs scene;  // add_frames_command makes the rope the default, with the study's 32 masses and stiffness 5000
  std::string methods;  // empty: analysis/studies/defaults.hpp, kFramesMethods
  std::map<std::string, std::string> params;  // as typed, by name (frames_params())
  std::string threads = "0";
  bool no_timing = false, no_orders = false;
  std::string shard;  // --shard i/N (reports/cli/parts.hpp)
  std::string json;
};
CLI::App* add_frames_command(CLI::App* study, FramesArgs& args);
int frames_command(FramesArgs& args, Context& ctx);

// `study long-time` (reports/cli/long_time_command.cpp): a scene with invariants over many
// periods, each invariant's error and its growth exponent (analysis/studies/long_time.hpp).
struct LongTimeArgs {
  SceneArgs scene;  // add_long_time_command makes Kepler's orbit the default
  SettingsArgs settings;
  std::string methods;  // empty: every ODE method that runs on the scene
  std::map<std::string, std::string> params;  // as typed, by name (long_time_params())
  std::string threads = "0";
  std::string shard;  // --shard i/N (reports/cli/parts.hpp)
  std::string json;
};
CLI::App* add_long_time_command(CLI::App* study, LongTimeArgs& args);
int long_time_command(LongTimeArgs& args, Context& ctx);

// `study dense-output` (reports/cli/dense_output_command.cpp): the order of each method's output
// between steps beside its steps' (analysis/studies/dense_output.hpp).
struct DenseOutputArgs {
  SceneArgs scene;  // the spring by default
  std::string methods;
  std::map<std::string, std::string> params;  // as typed, by name (dense_output_params())
  std::string threads = "0";
  std::string shard;  // --shard i/N (reports/cli/parts.hpp)
  std::string json;
};
CLI::App* add_dense_output_command(CLI::App* study, DenseOutputArgs& args);
int dense_output_command(DenseOutputArgs& args, Context& ctx);

// `study scaling` (reports/cli/scaling_command.cpp): cost against the number of masses of the rope or the soft body.
struct ScalingArgs {
  SceneArgs scene;  // the scene's parameters (--masses, --grid replaced by each size); add_scaling_command makes rope the default
  std::string methods;
  std::string sizes;  // empty: the scene's default sizes (scaling_command.cpp)
  std::string error = "1e-4,1%";  // targets: absolute, or N% of the body's extent
  std::string t_end = "2";
  std::string frames = "100";
  bool steps_divide_frames = false;
  std::string max_steps;  // empty: the scene's default (scaling_command.cpp)
  std::string threads = "0";
  bool no_timing = false;
  bool no_peers = false;
  std::string shard;
  std::string json;
};

CLI::App* add_scaling_command(CLI::App* study, ScalingArgs& args);
int scaling_command(ScalingArgs& args, Context& ctx);

struct WorkPrecisionArgs {
  std::string methods;  // empty: every numerical method
  std::map<std::string, std::string> params;  // as typed, by name (work_precision_params())
  std::string threads = "0";
  std::string lanes;  // the pack width: auto, 1, 2, 4 or 8 (add_lanes_option)
  std::string shard;  // i/N: write part i of N to --json (reports/cli/parts.hpp)
  bool no_timing = false;  // cost by evaluations only: reproducible byte for byte
  std::string json;
};

CLI::App* add_work_precision_command(CLI::App* study, WorkPrecisionArgs& args);
int work_precision_command(WorkPrecisionArgs& args, Context& ctx);

}  // namespace steplab

namespace steplab {

struct ReportArgs {
  std::string out = "report";
  std::string config;
  std::string methods, scenes, sections;  // comma-separated; over the config's
  bool methods_given = false, scenes_given = false, sections_given = false;  // even as "" (refused: an empty list)
  bool sheet = false;  // the exercise's hand-in (sheet_report_config) as the base
  bool force = false;
  bool print_config = false;
};

int report_command(ReportArgs& args, Context& ctx);

}  // namespace steplab

namespace steplab {

struct CheckArgs {
  std::string method;
  std::string threads = "0";
};

int check_command(CheckArgs& args, Context& ctx);

}  // namespace steplab
