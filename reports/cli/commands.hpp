// The commands behind the CLI. Each takes its parsed arguments, throws UsageError for bad input
// (before writing anything) and returns the exit status.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/kernel/parallel.hpp"
#include "analysis/peers/peers.hpp"
#include "analysis/kernel/shard.hpp"
#include "reports/cli/scene_args.hpp"
#include "reports/data/studies.hpp"

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

// A study's command: its subcommand of `steplab study` with its options (their values held by the
// command), and how it runs once parsed. Each study's own file gives its maker; the list of them
// is STEPLAB_STUDIES (reports/data/studies.hpp).
struct StudyCommand {
  CLI::App* app;
  std::function<int(Context&)> run;
};
// A study's command from its two parts: `add` adds the subcommand and its options to `study`,
// bound to arguments of type A that the command holds; `run` runs it on them once parsed.
template <class A>
StudyCommand study_command(CLI::App* study, CLI::App* (*add)(CLI::App*, A&), int (*run)(A&, Context&)) {
  auto args = std::make_shared<A>();
  CLI::App* app = add(study, *args);
  app->footer("Each column of its table: docs/studies.md, \"The tables, column by column\".\n\n" + app->get_footer());
  return {app, [args, run](Context& ctx) { return run(*args, ctx); }};
}
// Each study's command, `<name>_command`, for each name of the list of studies
// (reports/data/studies.hpp): reports/cli/<name>_command.cpp (convergence, damping and stability:
// reports/cli/study_commands.cpp).
#define STEPLAB_STUDY_COMMAND(name) StudyCommand name##_command(CLI::App* study);
STEPLAB_STUDIES(STEPLAB_STUDY_COMMAND)
#undef STEPLAB_STUDY_COMMAND
// The old framework's amplitude table (`-testcase amplitude`), the spring's.
int amplitude_command(const std::vector<double>& spring_params, double step, const Context& ctx);

}  // namespace steplab

namespace steplab {

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
