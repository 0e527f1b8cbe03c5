// THE method table. Adding an integrator: write core/methods/<name>.hpp (a struct with `info`
// and `step`, see core/method.hpp; a multistep method also keeps a memory, see core/stepper.hpp)
// and list it in `Methods` below. Nothing else changes:
// the CLI, the studies, the tests over every method and the report all iterate this list.
// Then `steplab check --method <name>` measures what its `info` claims (analysis/check.hpp).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>

#include "core/dispatch.hpp"

#include "core/methods/adams_bashforth2.hpp"
#include "core/methods/adams_bashforth3.hpp"
#include "core/methods/analytic.hpp"
#include "core/methods/bdf2.hpp"
#include "core/methods/bdf3.hpp"
#include "core/methods/explicit_euler.hpp"
#include "core/methods/explicit_midpoint.hpp"
#include "core/methods/implicit_euler.hpp"
#include "core/methods/gauss_legendre4.hpp"
#include "core/methods/implicit_midpoint.hpp"
#include "core/methods/radau_iia5.hpp"
#include "core/methods/rk3.hpp"
#include "core/methods/rk4.hpp"
#include "core/methods/symplectic_euler.hpp"
#include "core/methods/velocity_verlet.hpp"
#include "core/methods/yoshida4.hpp"

namespace steplab {

using Methods = std::tuple<ExplicitEuler, SymplecticEuler, ExplicitMidpoint, ImplicitEuler,  // the sheet's four
                           VelocityVerlet, Rk4, ImplicitMidpoint,                            // order vs stability
                           Rk3, Yoshida4, GaussLegendre4,                                    // families: one-step
                           AdamsBashforth2, AdamsBashforth3, Bdf2, Bdf3,                     // families: multistep
                           RadauIIA5,                                                        // stiff systems
                           Analytic>;

inline constexpr std::size_t method_count = std::tuple_size_v<Methods>;

// The old command-line framework's names.
inline constexpr std::array<std::pair<std::string_view, std::string_view>, 3> method_aliases{{
    {"euler", "explicit_euler"},
    {"midpoint", "explicit_midpoint"},
    {"backwards_euler", "implicit_euler"},
}};

inline constexpr std::array<MethodInfo, method_count> method_infos = []<std::size_t... I>(std::index_sequence<I...>) {
  return std::array<MethodInfo, method_count>{std::tuple_element_t<I, Methods>::info...};
}(std::make_index_sequence<method_count>{});

// Index of a method by its name or an old alias.
inline std::optional<std::size_t> find_method(std::string_view name) {
  for (const auto& [alias, target] : method_aliases)
    if (name == alias) name = target;
  for (std::size_t i = 0; i < method_count; ++i)
    if (method_infos[i].name == name) return i;
  return std::nullopt;
}

// "explicit_euler, symplectic_euler, ... (aliases: euler, ...)" for error messages and --help.
inline std::string method_names() {
  std::string out;
  for (const auto& info : method_infos) out += (out.empty() ? "" : ", ") + std::string(info.name);
  out += " (old names: ";
  for (std::size_t i = 0; i < method_aliases.size(); ++i)
    out += (i ? ", " : "") + std::string(method_aliases[i].first);
  return out + ")";
}

// Whether method M can run on scene S (the exact flow needs a scene that has one).
template <class M, class S> constexpr bool applies() {
  if constexpr (M::info.exact_flow) return HasExact<S>;
  else return true;
}

// Calls f.template operator()<M>() with the method at `index`: the one dispatch point from a
// runtime name to compiled code.
template <class F> decltype(auto) with_method(std::size_t index, F&& f) { return visit_type<Methods>(index, f); }

}  // namespace steplab
