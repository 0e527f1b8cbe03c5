// `steplab merge PART.json... --json OUT`: the parts a study wrote with `--shard i/N`
// (reports/data/study_command.hpp) put together. merge checks that the parts belong together (the
// same command line, the same N, each shard once, the same task lists), then runs the command
// with every task's result taken from the parts instead of computed: the study's fits and
// summaries follow from the same results as in one process, and its JSON is the same byte for
// byte.
#pragma once

#include <string>
#include <vector>

#include "reports/cli/commands.hpp"

namespace steplab {

struct MergeArgs {
  std::vector<std::string> parts;
  std::string json;
};
void add_merge_command(CLI::App& app, MergeArgs& args);
int merge_command(MergeArgs& args, Context& ctx);

}  // namespace steplab
