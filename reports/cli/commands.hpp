// The commands that are not studies (a study's command is in reports/studies/<name>.cpp). Each
// takes its parsed arguments, throws UsageError for bad input (before writing anything) and
// returns the exit status.
#pragma once

#include <string>
#include <vector>

#include "reports/data/study_command.hpp"

namespace steplab {

// Parses `args` (argv[1..]) and runs the command they name in `ctx`; bad input is one line on
// stderr and exit status 2. cli_main calls it with the whole command line, `steplab merge` with
// the study it replays.
int dispatch(const std::vector<std::string>& args, Context& ctx);

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

struct CheckArgs {
  std::string method;
  std::string threads = "0";
};

int check_command(CheckArgs& args, Context& ctx);

}  // namespace steplab
