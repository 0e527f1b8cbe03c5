// `steplab study work-precision`: cost against error on the spring and the stiff chain, the
// cheapest method per error level, the chain's stability limits, the stiffness sweep and its
// crossover (analysis/studies/work_precision.hpp). Table on stdout, JSON (steplab.work_precision/2) with --json.
#include <cstdio>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "analysis/studies/work_precision.hpp"
#include "analysis/kernel/kernel.hpp"
#include "analysis/peers/peers.hpp"
#include "reports/cli/commands.hpp"
#include "reports/data/inputs.hpp"
#include "reports/data/output.hpp"
#include "reports/cli/shards.hpp"
#include "reports/data/run_json.hpp"
#include "reports/data/studies.hpp"

namespace steplab {

namespace {

struct WorkPrecisionArgs {
  std::string methods;  // empty: every numerical method
  std::map<std::string, std::string> params;  // as typed, by name (work_precision_params())
  std::string threads = "0";
  std::string lanes;  // the pack width: auto, 1, 2, 4 or 8 (add_lanes_option)
  std::string shard;  // i/N: write part i of N to --json (reports/cli/shards.hpp)
  bool no_timing = false;  // cost by evaluations only: reproducible byte for byte
  std::string json;
};

CLI::App* add_work_precision(CLI::App* study, WorkPrecisionArgs& a) {
  CLI::App* cmd = study->add_subcommand("work-precision", "cost against error on the spring and the stiff chain; "
                                                          "cheapest method per error level; stiffness crossover");
  cmd->add_option("--methods", a.methods,
                  fmt::format("comma-separated methods and adaptive solvers ({}; default every numerical method, and every "
                              "adaptive solver where the list names none)", fmt::join(peer_names(PeerScenes::FixedSize), ", ")));
  add_params(cmd, work_precision_params(), a.params, WorkPrecisionConfig{});
  add_threads_option(cmd, a.threads, "worker threads for the error runs (timings run one at a time)");
  add_lanes_option(cmd, a.lanes);
  add_shard_option(cmd, a.shard);
  cmd->add_flag("--no-timing", a.no_timing, "cost by force evaluations only (reproducible byte for byte)");
  cmd->add_option("--json", a.json, fmt::format("write JSON (schema {}) to this file", schema::work_precision));
  return cmd;
}

int run_work_precision(WorkPrecisionArgs& a, Context& ctx) {
  WorkPrecisionConfig c;
  Solvers solvers = resolve_solvers(a.methods, adaptive_solvers(), "spring and chain", false);
  c.methods = std::move(solvers.methods);
  c.adaptive = std::move(solvers.adaptive);
  read_params(work_precision_params(), a.params, c);
  c.workers = ctx.workers(resolve_thread_count(a.threads));
  resolve_lanes(a.lanes);  // checked; the work-precision runs go one at a time
  c.timing = !a.no_timing;
  return run_study(ctx, a.shard, a.json, c.timing, [&] { return work_precision_study(c); },
                   [](const WorkPrecisionResult& r) { return work_precision_table(r); }, [](const WorkPrecisionResult& r) { return work_precision_json(r); });
}

}  // namespace

StudyCommand work_precision_command(CLI::App* study) { return study_command(study, add_work_precision, run_work_precision); }

}  // namespace steplab
