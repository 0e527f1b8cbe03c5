// The defaults that name scenes: the one table in analysis/ and reports/ where a scene is named.
// Everything else asks a scene what it offers (core/scene.hpp, SceneKernel), so a new scene joins
// every study that applies without a line here; a line here only changes where a command starts.
#pragma once

#include <string_view>
#include <vector>

namespace steplab {

// The scene `steplab run` and the studies of one small scene start from (--scene's default).
inline constexpr std::string_view kDefaultScene = "spring";
// The scene `study scaling` starts from: one of run-time size.
inline constexpr std::string_view kDefaultSizedScene = "rope";

// The sizes `study scaling` refines a scene to, and the most steps a search may try.
struct ScalingDefaults {
  std::vector<int> sizes{16, 64, 256, 1024};
  long long max_steps = 2'000'000;
};
ScalingDefaults scaling_defaults(std::string_view scene);

}  // namespace steplab
