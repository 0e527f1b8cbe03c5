// What every study's command shares (each study's own is in reports/studies/<name>.cpp): the
// context it runs in, its options that are not parameters (--methods, --threads, --lanes,
// --shard, the method settings), their checks, and the tail every command runs once its input is
// checked (run_study).
//
// A shard runs the i-th of N equal parts of each of the study's task lists (analysis/kernel/shard.hpp)
// and writes them as a part (schema steplab.part/1):
//   {"schema", "command": the study's command line without --shard, --json, --threads and
//    --lanes, "shard": [i, N], "calls": [{"tasks": n, "results": {"<task>": "<hex bytes>", ...}}]}
// `steplab merge` (reports/cli/shards.hpp) puts the parts together.
#pragma once

#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/kernel/parallel.hpp"
#include "analysis/kernel/shard.hpp"
#include "analysis/peers/peers.hpp"
#include "reports/data/output.hpp"
#include "reports/data/scene_args.hpp"

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

// A method's settings as typed: the sweeps a step of XPBD and PBD, the CG iterations and
// tolerance of Baraff-Witkin (core/method.hpp, MethodSettings). For `run` and `study frames`.
struct SettingsArgs {
  std::string sweeps, cg_iterations, cg_tolerance;  // empty: the defaults
  void add_to(CLI::App* app);
  // The settings, each checked; UsageError for a value out of range, or for a setting given that
  // none of `methods` takes (run's --method, a study's --methods).
  MethodSettings resolve(const std::vector<std::size_t>& methods) const;
};

// What every study's command holds as typed, beside its own arguments; checked when it runs.
struct StudyArgs {
  SceneArgs scene;  // the scene and its parameters (a study of fixed scenes: their parameters alone)
  std::string methods;  // comma-separated; empty: the study's own choice
  std::map<std::string, std::string> params;  // as typed, by name (the study's StudyParam table)
  std::string threads = "0";
  std::string lanes;  // the pack width: auto, 1, 2, 4 or 8 (add_lanes_option), where the study packs runs
  std::string shard;  // i/N: write part i of N to --json
  std::string json;
  // Its last two options: --shard, and --json to write the study's JSON (schema `schema`).
  void add_shard_and_json(CLI::App* cmd, std::string_view schema);
};

// A study's command: its subcommand of `steplab study` with its options (their values held by the
// command), and how it runs once parsed. The list of them is STEPLAB_STUDIES
// (reports/studies/studies.hpp).
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

// --shard on a study command.
void add_shard_option(CLI::App* app, std::string& shard);
// Starts shard mode if `shard` ("i/N") is given: refuses it without --json (the part goes there)
// or where the study times its runs (`timed`: times from different machines do not compare).
void begin_shard(Context& ctx, const std::string& shard, const std::string& json, bool timed);
// In shard mode: writes the part to `json`, says so on stdout, and returns true (the command
// then writes nothing else). Otherwise false.
bool finish_shard(const Context& ctx, const std::string& json);
// The most parts a study is split into.
inline constexpr long long kMaxShards = 1'000'000;

// What every study command does once its input is checked: its shard begun (if `a.shard` names
// one), nothing run in a dry run, the study run, and then its part written (a shard) or its
// table on stdout and its JSON to `a.json` (if named). `timed`: the study times its runs.
template <class Study, class Table, class ToJson>
int run_study(Context& ctx, const StudyArgs& a, bool timed, Study&& study, Table&& table, ToJson&& to_json) {
  begin_shard(ctx, a.shard, a.json, timed);
  if (ctx.stop_after_validation(a.json)) return 0;
  const auto r = study();
  if (finish_shard(ctx, a.json)) return 0;
  std::fputs(table(r).c_str(), stdout);
  if (!a.json.empty()) write_atomic(a.json, to_json(r).dump(1) + "\n");
  return 0;
}

}  // namespace steplab
