#include "analysis/defaults.hpp"

namespace steplab {

ScalingDefaults scaling_defaults(std::string_view scene) {
  // The soft body's grid side n gives n^2 masses, and its implicit steps pay a sparse LU each.
  if (scene == "softbody") return {{4, 8, 16}, 200'000};
  return {};
}

std::vector<int> report_sizes(std::string_view scene) {
  if (scene == "softbody") return {3, 6};  // n = 3, 6: 9 and 36 masses
  return {8, 32, 128};
}

}  // namespace steplab
