// The schema every JSON document of steplab's opens with, "steplab.<kind>/<version>": one name
// per kind, read by the writers and by each command's --help. The version steps when a field
// changes its meaning or goes; docs/json.md says what changed.
#pragma once

#include <string_view>

namespace steplab::schema {

inline constexpr std::string_view run = "steplab.run/1";                    // steplab run --json
inline constexpr std::string_view convergence = "steplab.convergence/2";    // study convergence
inline constexpr std::string_view convergence_sweep = "steplab.convergence_sweep/1";  // ... --sweep
// study stability and study damping on the spring: "unbounded" for a dt* of every step, "never"
// where a method is not stable again beyond dt* (version 1 wrote "inf" for both)
inline constexpr std::string_view stability = "steplab.stability/2";
// study stability on any other scene that declares its modes (version 1 was named after the rope)
inline constexpr std::string_view mode_stability = "steplab.mode_stability/1";
inline constexpr std::string_view collision = "steplab.collision/1";        // study collision
// study work-precision: the untimed cost is force evaluations, the Jacobians beside (version 1 added
// them in): by_forces, forces, explicit_forces, implicit_forces where it had *evaluations*
inline constexpr std::string_view work_precision = "steplab.work_precision/2";
// study scaling: "unbounded" for a stable step of every size (version 3 wrote "inf")
inline constexpr std::string_view scaling = "steplab.scaling/5";
inline constexpr std::string_view frames = "steplab.frames/1";              // study frames
inline constexpr std::string_view long_time = "steplab.long_time/1";        // study long-time
inline constexpr std::string_view dense_output = "steplab.dense_output/1";  // study dense-output
inline constexpr std::string_view part = "steplab.part/1";                  // --shard i/N, read by steplab merge

}  // namespace steplab::schema
