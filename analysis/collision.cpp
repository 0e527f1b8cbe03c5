#include "analysis/collision.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/shard.hpp"
#include "core/scenes.hpp"

namespace steplab {
namespace {

CollisionRun summary(std::size_t method, double dt, const auto& r) {
  return {method, dt, r.status, r.failed_step, r.failed_t, r.energy_ratio_final, r.energy_ratio_max, 0, {}, {}};
}

template <class M> CollisionRun bounce_run(const Bounce& s, std::size_t method, double dt, double t_end) {
  RunSpec spec;
  spec.dt = dt;
  spec.steps = steps_for(t_end, dt);
  spec.errors = false;
  std::vector<BounceEvent> bounces;
  bounces.reserve(kMaxRecordedBounces);  // before the loop: the observer never allocates
  double max_pen = 0, flight_max = 0;
  bool was_in_contact = false;
  const double e0 = s.energy(s.initial().x, s.initial().v);
  const auto observe = [&](long long, double t, const State<1>& y) {
    const bool in_contact = s.ground.touching(y.x[0]);
    max_pen = std::max(max_pen, s.ground.penetration(y.x[0]));
    if (was_in_contact && !in_contact && bounces.size() < kMaxRecordedBounces) {
      bounces.push_back({t, s.energy(y.x, y.v) / e0, std::numeric_limits<double>::quiet_NaN()});
      flight_max = y.x[0];
    }
    // the rebound height is known once the flight turns down (its apex); a flight cut off by
    // t_end, or by the next contact before the apex, leaves it NaN
    if (!in_contact && !bounces.empty() && std::isnan(bounces.back().rebound_height)) {
      flight_max = std::max(flight_max, y.x[0]);
      if (y.v[0] <= 0) bounces.back().rebound_height = flight_max;
    }
    was_in_contact = in_contact;
  };
  const RunResult<1> r = simulate<M>(s, spec, observe);
  CollisionRun out = summary(method, dt, r);
  out.max_penetration = max_pen;
  out.bounces = std::move(bounces);
  return out;
}

template <class M> CollisionRun triangle_run(const Falling& s, std::size_t method, double dt, double t_end, long long samples) {
  RunSpec spec;
  spec.dt = dt;
  spec.steps = steps_for(t_end, dt);
  spec.max_samples = samples;
  spec.errors = false;
  double max_pen = 0;
  const auto observe = [&](long long, double, const State<6>& y) {
    for (int i = 0; i < 3; ++i) max_pen = std::max(max_pen, s.ground.penetration(y.x[2 * i + 1]));
  };
  RunResult<6> r = simulate<M>(s, spec, observe);
  CollisionRun out = summary(method, dt, r);
  out.max_penetration = max_pen;
  out.path = std::move(r.samples);
  return out;
}

}  // namespace

CollisionResult collision_study(const CollisionConfig& c) {
  CollisionResult out;
  out.config = c;
  const Bounce bounce(c.bounce_params);
  const Falling falling(c.falling_params);
  const std::size_t nm = c.methods.size(), nd = c.dts.size();
  std::vector<CollisionRun> runs = study_map<CollisionRun>(nm * nd + nm, c.threads, [&](std::size_t task) {
    if (task < nm * nd) {
      const std::size_t m = c.methods[task / nd];
      return with_method(m, [&]<class M>() { return bounce_run<M>(bounce, m, c.dts[task % nd], c.t_end); });
    }
    const std::size_t m = c.methods[task - nm * nd];
    return with_method(m, [&]<class M>() -> CollisionRun {
      if constexpr (!applies<M, Falling>()) return {};
      else return triangle_run<M>(falling, m, c.triangle_dt, c.t_end, c.path_samples);
    });
  });
  out.triangle.assign(std::make_move_iterator(runs.begin() + static_cast<std::ptrdiff_t>(nm * nd)), std::make_move_iterator(runs.end()));
  runs.resize(nm * nd);
  out.bounce = std::move(runs);
  return out;
}

}  // namespace steplab
