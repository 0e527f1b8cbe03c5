// `steplab study dense-output`: each fixed-step method's output between steps (core/
// dense_output.hpp), its order beside its steps' (analysis/studies/dense_output.hpp). Table on
// stdout, JSON (steplab.dense_output/1) with --json.
#include <cstdio>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/dense_output.hpp"
#include "reports/cli/commands.hpp"
#include "reports/cli/shards.hpp"
#include "reports/data/inputs.hpp"
#include "reports/data/output.hpp"
#include "reports/data/studies.hpp"

namespace steplab {
namespace {

bool has_exact(const SceneKernel& s) { return s.exact != nullptr && s.dim != Eigen::Dynamic; }

// `study dense-output`: the order of each method's output
// between steps beside its steps' (analysis/studies/dense_output.hpp).
struct DenseOutputArgs {
  SceneArgs scene;  // the spring by default
  std::string methods;
  std::map<std::string, std::string> params;  // as typed, by name (dense_output_params())
  std::string threads = "0";
  std::string shard;  // --shard i/N (reports/cli/shards.hpp)
  std::string json;
};

CLI::App* add_dense_output(CLI::App* study, DenseOutputArgs& a) {
  CLI::App* cmd = study->add_subcommand("dense-output", "output between steps: each method's error inside its steps and its "
                                                        "order, beside the order at the steps");
  a.scene.scene = "spring";
  a.scene.add_to(cmd, has_exact);
  cmd->add_option("--methods", a.methods, "comma-separated methods (default every numerical method that runs on the scene)");
  add_params(cmd, dense_output_params(), a.params, DenseOutputConfig{});
  add_threads_option(cmd, a.threads);
  add_shard_option(cmd, a.shard);
  cmd->add_option("--json", a.json, fmt::format("write JSON (schema {}) to this file", schema::dense_output));
  return cmd;
}

int run_dense_output(DenseOutputArgs& a, Context& ctx) {
  const std::size_t scene = a.scene.scene_index();
  if (!has_exact(scene_kernel(scene)))
    throw UsageError(fmt::format("--scene {} has no exact solution to measure against; accepted: {}", scene_name(scene),
                                 scene_list(has_exact)));
  DenseOutputConfig c;
  c.scene = scene;
  c.params = a.scene.values(scene);
  c.methods = a.methods.empty() ? dense_output_methods(scene, ode_methods()) : resolve_methods(a.methods, false, scene);
  read_params(dense_output_params(), a.params, c);
  check_sweep(c.dt_min, c.dt_max, c.t_end, option_names());
  c.workers = ctx.workers(resolve_thread_count(a.threads));
  return run_study(ctx, a.shard, a.json, false, [&] { return dense_output_study(c); },
                   [](const DenseOutputResult& r) { return dense_output_table(r); }, [](const DenseOutputResult& r) { return dense_output_json(r); });
}

}  // namespace

StudyCommand dense_output_command(CLI::App* study) { return study_command(study, add_dense_output, run_dense_output); }

}  // namespace steplab
