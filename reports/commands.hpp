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

namespace steplab {

struct ConvergenceArgs {
  SceneArgs scene;
  std::string methods;  // comma-separated; empty: every numerical method
  std::string dt_max = "0.1", dt_min = "1e-4", points = "16", t_end = "10";
  std::string error = "final";
  std::string threads = "0";
  std::string json;
};

int convergence_command(ConvergenceArgs& args);

// Shared by the commands.
std::size_t resolve_method(std::string_view name);
std::vector<std::size_t> resolve_methods(const std::string& list, bool with_analytic);
unsigned resolve_thread_count(const std::string& text);

}  // namespace steplab
