// The commands behind the CLI. Each takes its parsed arguments, throws UsageError for bad input
// (before writing anything) and returns the exit status.
#pragma once

#include <string>

#include "reports/scene_args.hpp"

namespace steplab {

struct RunArgs {
  SceneArgs scene;
  std::string method = "explicit_euler";
  std::string dt = "0.01";
  std::string t_end = "10";
  std::string samples = "10001";
  std::string json;  // write JSON here instead of CSV on stdout
};

int run_command(RunArgs& args);

}  // namespace steplab
