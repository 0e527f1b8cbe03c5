#include "analysis/studies/dense_output.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/kernel/kernel.hpp"
#include "analysis/kernel/shard.hpp"
#include "analysis/studies/convergence.hpp"  // sweep_steps, roundoff_floor
#include "core/dense_output.hpp"

namespace steplab {

std::vector<std::size_t> dense_output_methods(std::size_t scene, const std::vector<std::size_t>& from) {
  std::vector<std::size_t> out;
  for (std::size_t m : from)
    if (in_ode_studies(m) && applies(m, scene)) out.push_back(m);
  return out;
}

DenseOutputResult dense_output_study(const DenseOutputConfig& c) {
  DenseOutputResult out{c, {}, {}};
  const SceneKernel& scene = scene_kernel(c.scene);
  const std::vector<double> dts = sweep_steps(c.t_end, c.dt_max, c.dt_min, c.points);
  std::vector<Eigen::VectorXd> exact;  // the positions at the outputs
  for (int k = 0; k < c.outputs; ++k)
    exact.push_back(scene.exact(c.params, k == c.outputs - 1 ? c.t_end : c.t_end * k / (c.outputs - 1)).x);
  double scale = 0;
  for (const Eigen::VectorXd& x : exact) scale = std::max(scale, x.cwiseAbs().maxCoeff());
  const std::size_t nd = dts.size();
  out.rows = study_map<DenseOutputRow>(c.methods.size() * nd, c.workers, [&](std::size_t job) {
    const std::size_t m = c.methods[job / nd];
    DenseOutputRow row{m, dts[job % nd]};
    RunSpec spec;
    spec.dt = row.dt;
    spec.steps = row.steps = steps_for(c.t_end, row.dt);
    spec.outputs = c.outputs;
    const AnyResult r = pair_kernel(m, c.scene).run(c.params, spec);
    row.status = r.status;
    row.error_steps = r.error_max;
    row.floor = roundoff_floor(scale, row.steps);
    if (r.status != RunStatus::Ok || std::ssize(r.samples) != c.outputs) {
      row.error_outputs = row.error_steps = INFINITY;
      return row;
    }
    for (std::size_t k = 0; k < exact.size(); ++k)
      row.error_outputs = std::max(row.error_outputs, (r.samples[k].x - exact[k]).norm());
    return row;
  });
  for (std::size_t i = 0; i < c.methods.size(); ++i) {
    const MethodInfo& info = method_info(c.methods[i]);
    DenseOutputFit f{c.methods[i], info.order, quintic_output(info.order), dense_output_order(info.order), {}, {}};
    std::vector<ErrorPoint> at_steps, at_outputs;
    for (std::size_t j = 0; j < nd; ++j) {
      const DenseOutputRow& r = out.rows[i * nd + j];
      const bool diverged = r.status != RunStatus::Ok;
      at_steps.push_back({r.dt, r.error_steps, r.floor, diverged});
      at_outputs.push_back({r.dt, r.error_outputs, r.floor, diverged});
    }
    f.steps = fit_order(at_steps);
    f.outputs = fit_order(at_outputs);
    out.fits.push_back(std::move(f));
  }
  return out;
}

}  // namespace steplab
