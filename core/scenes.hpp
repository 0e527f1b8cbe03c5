// THE scene table. Adding a scene: write core/scenes/<name>.hpp (see core/scene.hpp for what a
// scene gives) and list it in `Scenes`. No integrator changes.
#pragma once

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "core/dispatch.hpp"

#include "core/scenes/bounce.hpp"
#include "core/scenes/cannonball.hpp"
#include "core/scenes/chain.hpp"
#include "core/scenes/falling.hpp"
#include "core/scenes/spring.hpp"

namespace steplab {

using Scenes = std::tuple<Cannonball, Spring, Falling, Bounce, Chain>;

inline constexpr std::size_t scene_count = std::tuple_size_v<Scenes>;

inline constexpr std::array<std::string_view, scene_count> scene_names = []<std::size_t... I>(std::index_sequence<I...>) {
  return std::array<std::string_view, scene_count>{std::tuple_element_t<I, Scenes>::name...};
}(std::make_index_sequence<scene_count>{});

inline std::optional<std::size_t> find_scene(std::string_view name) {
  if (name == "spring1d") name = "spring";  // the old framework's test case name
  for (std::size_t i = 0; i < scene_count; ++i)
    if (scene_names[i] == name) return i;
  return std::nullopt;
}

inline std::string scene_list() {
  std::string out;
  for (auto n : scene_names) out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

// Calls f.template operator()<S>() with the scene type at `index`.
template <class F> decltype(auto) with_scene(std::size_t index, F&& f) { return visit_type<Scenes>(index, f); }

}  // namespace steplab
