// `steplab study dense-output`: each fixed-step method's output between steps (core/
// dense_output.hpp), its order beside its steps' (analysis/studies/dense_output.hpp). Its command,
// its parameters, its table on stdout and its JSON (steplab.dense_output/1) with --json.
#include "reports/studies/studies.hpp"

#include <cmath>
#include <cstdio>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/dense_output.hpp"
#include "reports/data/inputs.hpp"
#include "reports/data/output.hpp"
#include "reports/data/run_json.hpp"
#include "reports/data/study_command.hpp"

namespace steplab {
namespace {

Json order_json(const OrderFit& f) {
  if (!f.fitted) return {{"order", nullptr}, {"exact", f.exact}, {"note", f.note}};
  return {{"order", f.order}, {"order_bound", {finite_or_null(f.bound_lo), finite_or_null(f.bound_hi)}},
          {"dt_range", {f.dt_lo, f.dt_hi}}, {"local_orders", f.local_slopes}};
}

std::string order_text(const OrderFit& f) {
  if (f.exact) return "exact";
  if (!f.fitted) return "-";
  return fmt::format("{:.2f} [{:.2f}, {:.2f}]", f.order, f.bound_lo, f.bound_hi);
}

constexpr StudyParam<DenseOutputConfig> kDenseOutputParams[] = {
    {"t-end", "simulated time", kPositive, &DenseOutputConfig::t_end},
    {"dt-max", "largest step of the sweep", kPositive, &DenseOutputConfig::dt_max},
    {"dt-min", "smallest step of the sweep", kPositive, &DenseOutputConfig::dt_min},
    {"points", "steps in the sweep", {3, 100}, &DenseOutputConfig::points},
    {"outputs", "output times, evenly spaced over [0, t_end]", {2, 100'000}, &DenseOutputConfig::outputs},
};

}  // namespace

std::span<const StudyParam<DenseOutputConfig>> dense_output_params() { return kDenseOutputParams; }

Json dense_output_json(const DenseOutputResult& r) {
  const DenseOutputConfig& c = r.config;
  Json rows = Json::array(), fits = Json::array();
  for (const DenseOutputRow& w : r.rows)
    rows.push_back({{"method", std::string(method_info(w.method).name)}, {"dt", w.dt}, {"steps", w.steps}, {"status", to_string(w.status)},
                    {"error_steps", finite_or_null(w.error_steps)}, {"error_outputs", finite_or_null(w.error_outputs)},
                    {"floor", w.floor}});
  for (const DenseOutputFit& f : r.fits)
    fits.push_back({{"method", std::string(method_info(f.method).name)}, {"declared_order", f.declared}, {"output", f.quintic ? "quintic" : "cubic"},
                    {"predicted_output_order", f.predicted}, {"steps", order_json(f.steps)}, {"outputs", order_json(f.outputs)}});
  return {{"schema", schema::dense_output},
          {"scene", scene_name(c.scene)},
          {"params", scene_params_json(c.scene, c.params)},
          {"t_end", c.t_end},
          {"outputs", c.outputs},
          {"rows", rows},
          {"fits", fits}};
}

std::string dense_output_table(const DenseOutputResult& r) {
  const DenseOutputConfig& c = r.config;
  std::string out = fmt::format(
      "Output between steps on the {} to t = {:g}: the largest position error at the steps and at {} evenly spaced times "
      "inside them (cubic Hermite from x, v below order 3, quintic from x, v, a from 3 up), each error's order fitted over "
      "the dt sweep\n\n{:<18} {:>8} {:>8} {:>9} {:>22} {:>22}\n",
      scene_name(c.scene), c.t_end, c.outputs, "method", "declared", "output", "predicted", "order at steps", "order between steps");
  for (const DenseOutputFit& f : r.fits)
    out += fmt::format("{:<18} {:>8} {:>8} {:>9} {:>22} {:>22}\n", std::string(method_info(f.method).name), f.declared, f.quintic ? "quintic" : "cubic",
                       f.predicted, order_text(f.steps), order_text(f.outputs));
  return out + "\nOrders with their bounds (analysis/fits/order_fit.hpp); '-' where no asymptotic range was found.\n";
}

namespace {

bool has_exact(const SceneKernel& s) { return s.exact != nullptr && s.dim != Eigen::Dynamic; }

struct DenseOutputArgs : StudyArgs {};

CLI::App* add_dense_output(CLI::App* study, DenseOutputArgs& a) {
  CLI::App* cmd = study->add_subcommand("dense-output", "output between steps: each method's error inside its steps and its "
                                                        "order, beside the order at the steps");
  a.scene.scene = "spring";
  a.scene.add_to(cmd, has_exact);
  cmd->add_option("--methods", a.methods, "comma-separated methods (default every numerical method that runs on the scene)");
  add_params(cmd, dense_output_params(), a.params, DenseOutputConfig{});
  add_threads_option(cmd, a.threads);
  a.add_shard_and_json(cmd, schema::dense_output);
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
  return run_study(ctx, a, false, [&] { return dense_output_study(c); }, dense_output_table, dense_output_json);
}

}  // namespace

StudyCommand dense_output_command(CLI::App* study) { return study_command(study, add_dense_output, run_dense_output); }

}  // namespace steplab
