#include "analysis/kernel/kernel.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <utility>

namespace steplab {
namespace {

// The old command-line framework's names.
constexpr std::array<std::pair<std::string_view, std::string_view>, 3> kMethodAliases{{
    {"euler", "explicit_euler"},
    {"midpoint", "explicit_midpoint"},
    {"backwards_euler", "implicit_euler"},
}};

}  // namespace

bool applies(std::size_t m, std::size_t s) {
  const KernelTable& t = kernel_table();
  return m < t.methods.size() && s < t.scenes.size() && t.pairs[m * t.scenes.size() + s]->run != nullptr;
}

std::string why_not(std::size_t m, std::size_t s) {
  if (applies(m, s)) return {};
  const SceneKernel& scene = scene_kernel(s);
  if (method_info(m).exact_flow) return "needs a scene with an exact solution; " + std::string(scene.name) + " has none";
  if (method_info(m).on_springs) {
    std::string with;
    for (std::size_t i = 0; i < scene_count(); ++i)
      if (applies(m, i)) with += (with.empty() ? "" : ", ") + std::string(scene_name(i));
    return "works on a scene's springs (core/springs.hpp); " + std::string(scene.name) + " is not made of springs; accepted: " + with;
  }
  return std::string(method_info(m).implicit ? "is implicit" : "solves an implicit stage (its damped kick)") +
         " and needs the scene's Jacobians dF/dx and dF/dv; " + std::string(scene.name) +
         " declares no jacobians(x, v) (core/scene.hpp), so the explicit methods run on it";
}

const PairKernel& pair_kernel(std::size_t m, std::size_t s) {
  if (!applies(m, s))
    throw std::invalid_argument("method " + std::to_string(m) + " does not run on scene " + std::to_string(s));
  const KernelTable& t = kernel_table();
  return *t.pairs[m * t.scenes.size() + s];
}

std::optional<std::size_t> find_method(std::string_view name) {
  for (const auto& [alias, target] : kMethodAliases)
    if (name == alias) name = target;
  for (std::size_t i = 0; i < method_count(); ++i)
    if (method_info(i).name == name) return i;
  return std::nullopt;
}

std::optional<std::size_t> find_scene(std::string_view name) {
  for (std::size_t i = 0; i < scene_count(); ++i)
    if (scene_name(i) == name || (!scene_kernel(i).old_name.empty() && scene_kernel(i).old_name == name)) return i;
  return std::nullopt;
}

std::size_t scene_index(std::string_view name) {
  const auto s = find_scene(name);
  if (!s) throw std::logic_error("the kernel table has no scene " + std::string(name));
  return *s;
}

std::string method_names() {
  std::string out;
  for (std::size_t i = 0; i < method_count(); ++i) out += (out.empty() ? "" : ", ") + std::string(method_info(i).name);
  out += " (old names: ";
  for (std::size_t i = 0; i < kMethodAliases.size(); ++i) out += (i ? ", " : "") + std::string(kMethodAliases[i].first);
  return out + ")";
}

std::vector<AnyResult> run_all(const PairKernel& k, std::span<const BatchRun> runs, int width) {
  if (width == 0) width = best_width();
  if (!cpu_has_width(width))
    throw std::invalid_argument("a pack width is 1, 2, 4 (AVX2) or 8 (AVX-512) that this CPU has, not " + std::to_string(width));
  std::vector<AnyResult> out(runs.size());
  const bool samples = std::ranges::any_of(runs, [](const BatchRun& r) { return r.spec.max_samples > 0 || r.spec.outputs > 0; });
  if (width > 1 && k.run_batch && !samples) k.run_batch(runs, out.data(), width);
  else
    for (std::size_t i = 0; i < runs.size(); ++i) out[i] = k.run(runs[i].params, runs[i].spec);
  return out;
}

std::vector<std::string> method_name_list() {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < method_count(); ++i) out.emplace_back(method_info(i).name);
  for (const auto& [alias, target] : kMethodAliases) out.emplace_back(alias);
  return out;
}

std::vector<std::string> scene_name_list() {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < scene_count(); ++i) {
    out.emplace_back(scene_name(i));
    if (!scene_kernel(i).old_name.empty()) out.emplace_back(scene_kernel(i).old_name);
  }
  return out;
}

std::string scene_list() {
  return scene_list([](const SceneKernel&) { return true; });
}

std::string scene_list(bool (*offers)(const SceneKernel&)) {
  std::string out;
  for (std::size_t i = 0; i < scene_count(); ++i)
    if (offers(scene_kernel(i))) out += (out.empty() ? "" : ", ") + std::string(scene_name(i));
  return out;
}


}  // namespace steplab
