// Collision study: how each method handles the penalty ground, on two scenes (by default the
// bounce and the falling triangle, analysis/studies/defaults.hpp):
//  - the rebound scene (its motion known exactly; the undamped bounce): per method and dt, the
//    energy ratio E/E0 after each bounce (when the mass leaves the ground), the rebound height of
//    the flight that follows, the deepest penetration, and blow-up;
//  - the contact body (several particles; the falling triangle): per method at one dt, energy
//    ratio, deepest penetration, blow-up, and a decimated path of its particles (three in the
//    plane: six coordinates) for the report's figure.
#pragma once

#include <vector>

#include "analysis/kernel/parallel.hpp"
#include "analysis/studies/defaults.hpp"
#include "analysis/kernel/kernel.hpp"

namespace steplab {

struct CollisionRun {
  std::size_t method;
  double dt;
  RunStatus status;
  long long failed_step;
  double failed_t;
  double energy_ratio_final, energy_ratio_max;
  double max_penetration;
  std::vector<BounceEvent> bounces;   // rebound scene only
  std::vector<Sample<6>> path;        // contact body only
};

template <class F> void encode_fields(CollisionRun& r, F&& f) {  // analysis/kernel/shard.hpp
  f(r.method), f(r.dt), f(r.status), f(r.failed_step), f(r.failed_t), f(r.energy_ratio_final), f(r.energy_ratio_max);
  f(r.max_penetration), f(r.bounces), f(r.path);
}

struct CollisionConfig {
  std::size_t rebound_scene = scene_index(kReboundScene), body_scene = scene_index(kContactBodyScene);
  std::vector<double> rebound_params, body_params;  // table order
  std::vector<std::size_t> methods;
  std::vector<double> dts{0.001, 0.002, 0.004};
  double t_end = 10;
  double triangle_dt = 0.001;
  long long path_samples = 1001;
  // The contact body has no exact motion: its reference is RK4 at these steps, coarse to fine (the
  // last is the reference, the first its check: how far apart their E/E0 at t_end lie). The
  // contact's kink keeps RK4 from its order, so two steps, not an extrapolation: on the falling
  // triangle E/E0 ends at 0.64955 and 0.64948.
  std::vector<double> reference_dts{5e-5, 2e-5};
  Workers workers;  // threads (0: all cores), progress, shard log
};

struct CollisionResult {
  CollisionConfig config;
  std::vector<CollisionRun> bounce;    // the rebound scene: method-major, dt-minor
  std::vector<CollisionRun> triangle;  // the contact body: one per method
  std::vector<CollisionRun> triangle_reference;  // RK4 at each reference_dts, without its path
};

inline constexpr std::size_t kMaxRecordedBounces = 4096;

CollisionResult collision_study(const CollisionConfig& config);

}  // namespace steplab
