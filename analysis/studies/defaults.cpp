#include "analysis/studies/defaults.hpp"

namespace steplab {

ScalingDefaults scaling_defaults(std::string_view scene) {
  // The soft body's grid side n gives n^2 masses, and its implicit steps pay a sparse solve each.
  // The report's n = 3, 6: 9 and 36 masses.
  if (scene == "softbody") return {{4, 8, 16}, 200'000, {3, 6}};
  return {};
}

}  // namespace steplab
