// `--shard i/N` on every study, and `steplab merge PART.json... --json OUT`.
//
// A shard runs the i-th of N equal parts of each of the study's task lists (analysis/kernel/shard.hpp)
// and writes them as a part (schema steplab.part/1):
//   {"schema", "command": the study's command line without --shard, --json, --threads and
//    --lanes, "shard": [i, N], "calls": [{"tasks": n, "results": {"<task>": "<hex bytes>", ...}}]}
// merge checks that the parts belong together (the same command line, the same N, each shard
// once, the same task lists), then runs the command with every task's result taken from the
// parts instead of computed: the study's fits and summaries follow from the same results as in
// one process, and its JSON is the same byte for byte.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "reports/cli/commands.hpp"
#include "reports/data/output.hpp"

namespace steplab {

// --shard on a study command.
void add_shard_option(CLI::App* app, std::string& shard);

// Starts shard mode if `shard` ("i/N") is given: refuses it without --json (the part goes there)
// or where the study times its runs (`timed`: times from different machines do not compare).
void begin_shard(Context& ctx, const std::string& shard, const std::string& json, bool timed);

// In shard mode: writes the part to `json`, says so on stdout, and returns true (the command
// then writes nothing else). Otherwise false.
bool finish_shard(const Context& ctx, const std::string& json);

// What every study command does once its input is checked: its shard begun (if `shard` names
// one), nothing run in a dry run, the study run, and then its part written (a shard) or its
// table on stdout and its JSON to `json` (if named). `timed`: the study times its runs.
template <class Study, class Table, class ToJson>
int run_study(Context& ctx, const std::string& shard, const std::string& json, bool timed, Study&& study, Table&& table,
              ToJson&& to_json) {
  begin_shard(ctx, shard, json, timed);
  if (ctx.stop_after_validation(json)) return 0;
  const auto r = study();
  if (finish_shard(ctx, json)) return 0;
  std::fputs(table(r).c_str(), stdout);
  if (!json.empty()) write_atomic(json, to_json(r).dump(1) + "\n");
  return 0;
}

struct MergeArgs {
  std::vector<std::string> parts;
  std::string json;
};
void add_merge_command(CLI::App& app, MergeArgs& args);
int merge_command(MergeArgs& args, Context& ctx);

}  // namespace steplab
