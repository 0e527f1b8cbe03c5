#include "analysis/studies/collision.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/kernel/shard.hpp"

namespace steplab {
namespace {

CollisionRun summary(std::size_t method, double dt, const AnyResult& r) {
  return {method, dt, r.status, r.failed_step, r.failed_t, r.energy_ratio_final, r.energy_ratio_max, 0, {}, {}};
}

RunSpec collision_spec(double dt, double t_end) {
  RunSpec spec;
  spec.dt = dt;
  spec.steps = steps_for(t_end, dt);
  spec.errors = false;
  return spec;
}

// The rebound scene: each time the mass leaves the ground, E/E0 and the apex of the flight that
// follows (the observer of analysis/kernel/kernel_impl.hpp), and the deepest penetration.
CollisionRun bounce_run(std::size_t method, std::size_t scene, const std::vector<double>& params, double dt, double t_end) {
  Observed o;
  o.max_bounces = kMaxRecordedBounces;
  const AnyResult r = pair_kernel(method, scene).run_observed(params, collision_spec(dt, t_end), o);
  CollisionRun out = summary(method, dt, r);
  out.max_penetration = o.max_penetration;
  out.bounces = std::move(o.bounces);
  return out;
}

// The contact body: the deepest penetration of its particles, and its path.
CollisionRun body_run(std::size_t method, std::size_t scene, const std::vector<double>& params, double dt, double t_end,
                      long long samples) {
  RunSpec spec = collision_spec(dt, t_end);
  spec.max_samples = samples;
  Observed o;
  AnyResult r = pair_kernel(method, scene).run_observed(params, spec, o);
  CollisionRun out = summary(method, dt, r);
  out.max_penetration = o.max_penetration;
  out.path = to_fixed<6>(std::move(r)).samples;
  return out;
}

}  // namespace

CollisionResult collision_study(const CollisionConfig& c) {
  CollisionResult out;
  out.config = c;
  const std::size_t nm = c.methods.size(), nd = c.dts.size(), nr = c.reference_dts.size();
  const std::size_t rk4 = *find_method("rk4");
  std::vector<CollisionRun> runs = study_map<CollisionRun>(nm * nd + nm + nr, c.workers, [&](std::size_t task) {
    if (task < nm * nd) return bounce_run(c.methods[task / nd], c.rebound_scene, c.rebound_params, c.dts[task % nd], c.t_end);
    if (task >= nm * nd + nm) return body_run(rk4, c.body_scene, c.body_params, c.reference_dts[task - nm * nd - nm], c.t_end, 2);
    const std::size_t m = c.methods[task - nm * nd];
    if (!applies(m, c.body_scene)) return CollisionRun{};
    return body_run(m, c.body_scene, c.body_params, c.triangle_dt, c.t_end, c.path_samples);
  });
  const auto at = [&](std::size_t i) { return std::make_move_iterator(runs.begin() + static_cast<std::ptrdiff_t>(i)); };
  out.triangle_reference.assign(at(nm * nd + nm), at(runs.size()));
  for (CollisionRun& r : out.triangle_reference) r.path.clear();
  out.triangle.assign(at(nm * nd), at(nm * nd + nm));
  runs.resize(nm * nd);
  out.bounce = std::move(runs);
  return out;
}

}  // namespace steplab
