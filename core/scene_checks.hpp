// STEPLAB_SCENE: what a scene file ends with, and what it checks of the scene at compile time.
// Included at the end of core/scene.hpp.
//
// The optional members (jacobians, modes, the long-time study's invariants) are found by their
// signatures: a member declared with another one would be silently left out, and the implicit
// methods refused, no dt* predicted or no long-time study run, with no word why. So a scene that
// names such a member at all, whatever its type, must declare it as the studies read it; the
// check's message names the member and the signature expected (docs/scenes.md, "Every member").
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <string_view>
#include <type_traits>
#include <vector>

namespace steplab {

// Whether a scene names a member `m` at all, of any type: a class derived from the scene and from
// one with a member `m` finds that name in two bases, an ambiguous lookup, exactly where the scene
// has one. (A final class cannot be derived from: it is taken to name none.)
#define STEPLAB_MEMBER_PROBE(m)                                                         \
  struct Probe_##m##_Base {                                                             \
    int m;                                                                              \
  };                                                                                    \
  template <class S> struct Probe_##m : S, Probe_##m##_Base {};                         \
  template <class S> concept Names_##m = !std::is_final_v<S> && !requires { &Probe_##m<S>::m; };
namespace member_probe {
STEPLAB_MEMBER_PROBE(jacobians)
STEPLAB_MEMBER_PROBE(modes)
STEPLAB_MEMBER_PROBE(invariant_names)
STEPLAB_MEMBER_PROBE(invariants)
STEPLAB_MEMBER_PROBE(period)
STEPLAB_MEMBER_PROBE(extent)
}  // namespace member_probe
#undef STEPLAB_MEMBER_PROBE

// The long-time study's members (core/invariants.hpp), each as that study reads it.
template <class S>
concept InvariantNamesAsRead = requires {
  { S::invariant_names.size() } -> std::convertible_to<std::size_t>;
  { S::invariant_names[0] } -> std::convertible_to<std::string_view>;
};
template <class S>
concept InvariantsAsRead = InvariantNamesAsRead<S> && requires(const S& s, const Vec<S::dim>& x, const Vec<S::dim>& v) {
  { s.invariants(x, v) } -> std::convertible_to<std::array<double, S::invariant_names.size()>>;
};
template <class S> concept PeriodAsRead = requires(const S& s) { { s.period() } -> std::convertible_to<double>; };
template <class S> concept ExtentAsRead = requires(const S& s) { { s.extent() } -> std::convertible_to<double>; };

// Each optional member the scene names is declared as it is read; -> which one is not.
template <class S> constexpr bool jacobians_as_read() { return !member_probe::Names_jacobians<S> || HasJacobians<S>; }
template <class S> constexpr bool modes_as_read() { return !member_probe::Names_modes<S> || HasModes<S>; }
template <class S> constexpr bool invariant_names_as_read() {
  return !member_probe::Names_invariant_names<S> || InvariantNamesAsRead<S>;
}
template <class S> constexpr bool invariants_as_read() { return !member_probe::Names_invariants<S> || InvariantsAsRead<S>; }
template <class S> constexpr bool period_as_read() { return !member_probe::Names_period<S> || PeriodAsRead<S>; }
template <class S> constexpr bool extent_as_read() { return !member_probe::Names_extent<S> || ExtentAsRead<S>; }
// The long-time study needs all four or none.
template <class S> constexpr bool invariants_complete() {
  using namespace member_probe;
  constexpr int named = Names_invariant_names<S> + Names_invariants<S> + Names_period<S> + Names_extent<S>;
  return named == 0 || named == 4;
}

// Every declared name is a parameter, and a size parameter is a count of a scene of run-time size.
template <Scene S> constexpr bool declarations_hold() {
  if constexpr (requires { S::size_param; })
    if (size_param_index<S>() < 0 || !S::params[size_param_index<S>()].is_count || S::dim != Eigen::Dynamic) return false;
  if constexpr (requires { S::stiffness_param; })
    if (stiffness_param_index<S>() < 0) return false;
  if constexpr (requires { S::damping_param; })
    if (damping_param_index<S>() < 0) return false;
  if constexpr (requires { S::stiff_limit_scene; })
    if (!HasStiffLimit<S> || stiffness_param_index<S>() < 0) return false;
  return coords_per_mass<S>() >= 1;
}

}  // namespace steplab

// A scene file ends with STEPLAB_SCENE(<its type>);, outside any namespace (tools/kernels.cmake).
// Code that takes long to compile and need not be inlined (the chain's long-double
// eigen-decomposition) goes at the end of the file inside #ifdef STEPLAB_SCENE_SOURCE: the scene's
// generated translation unit defines it, so that code is compiled once, not in every method's file.
// Each check its own static_assert, so that the compiler's first error names the member.
#define STEPLAB_SCENE(...)                                                                                            \
  static_assert(::steplab::Scene<__VA_ARGS__>, "STEPLAB_SCENE: the type is not a Scene (core/scene.hpp)");            \
  static_assert(::steplab::declarations_hold<__VA_ARGS__>(),                                                           \
                "STEPLAB_SCENE: a declared size_param, stiffness_param or damping_param names no parameter of the scene, " \
                "or size_param is not a count of a scene of run-time size (core/scene.hpp)");                           \
  static_assert(::steplab::jacobians_as_read<__VA_ARGS__>(),                                                           \
                "STEPLAB_SCENE: `jacobians` is not `steplab::Jacobians<dim> jacobians(const steplab::Vec<dim>& x, "    \
                "const steplab::Vec<dim>& v) const` (a driven scene: `(double t, x, v)`; docs/scenes.md)");            \
  static_assert(::steplab::modes_as_read<__VA_ARGS__>(),                                                               \
                "STEPLAB_SCENE: `modes` is not `std::vector<steplab::Mode> modes() const` (docs/scenes.md)");          \
  static_assert(::steplab::invariant_names_as_read<__VA_ARGS__>(),                                                     \
                "STEPLAB_SCENE: `invariant_names` is not `static constexpr std::array<std::string_view, N> "           \
                "invariant_names` (docs/scenes.md)");                                                                  \
  static_assert(::steplab::invariants_as_read<__VA_ARGS__>(),                                                          \
                "STEPLAB_SCENE: `invariants` is not `std::array<double, N> invariants(const steplab::Vec<dim>& x, "    \
                "const steplab::Vec<dim>& v) const`, N the number of invariant_names (docs/scenes.md)");               \
  static_assert(::steplab::period_as_read<__VA_ARGS__>(),                                                              \
                "STEPLAB_SCENE: `period` is not `double period() const` (docs/scenes.md)");                            \
  static_assert(::steplab::extent_as_read<__VA_ARGS__>(),                                                              \
                "STEPLAB_SCENE: `extent` is not `double extent() const` (docs/scenes.md)");                            \
  static_assert(::steplab::invariants_complete<__VA_ARGS__>(),                                                         \
                "STEPLAB_SCENE: the long-time study reads invariant_names, invariants(x, v), period() and extent() "   \
                "together: a scene declares all four or none (docs/scenes.md)")
