#include "reports/data/scene_args.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "reports/data/inputs.hpp"

namespace steplab {

std::vector<std::string> all_scene_parameters() {
  std::vector<std::string> out;
  for (std::size_t s = 0; s < scene_count(); ++s)
    for (const ParamSpec& p : scene_kernel(s).params)
      if (std::find(out.begin(), out.end(), p.name) == out.end()) out.emplace_back(p.name);
  return out;
}

std::string scene_parameters_help(bool (*accepts)(const SceneKernel&), bool sized) {
  std::string out = sized ? "Scene parameters (each a NUMBER; the stiffness NUMBER,..., the map's axis; the size is --sizes), by scene:\n"
                          : "Scene parameters (each a NUMBER), by scene:\n";
  for (std::size_t s = 0; s < scene_count(); ++s) {
    const SceneKernel& k = scene_kernel(s);
    if (accepts && !accepts(k)) continue;
    out += fmt::format("  {}:\n", scene_name(s));
    for (std::size_t i = 0; i < k.params.size(); ++i) {
      const ParamSpec& p = k.params[i];
      if (sized && static_cast<int>(i) == k.size_param) continue;
      const bool list = sized && static_cast<int>(i) == k.stiffness_param;
      out += fmt::format("    {:<28}{}{} (default {})\n", fmt::format("--{} {}", p.name, list ? "NUMBER,..." : "NUMBER"), p.help,
                         list ? ", a comma-separated list" : "", p.default_value);
    }
  }
  return out;
}

void SceneArgs::add_to(CLI::App* a, bool (*accepts)(const SceneKernel&), bool with_scene_option, bool sized_scene) {
  app = a;
  sized = sized_scene;
  const auto every = [](const SceneKernel&) { return true; };
  if (!accepts) accepts = every;
  if (with_scene_option) {
    std::string old_names;  // " (spring1d is the old name of spring)"
    for (std::size_t i = 0; i < scene_count(); ++i)
      if (const SceneKernel& k = scene_kernel(i); accepts(k) && !k.old_name.empty())
        old_names += fmt::format(" ({} is the old name of {})", k.old_name, k.name);
    a->add_option("--scene", scene, "scene: " + scene_list(accepts) + old_names)->capture_default_str();
  }
  // Listed once, by scene, in the footer; an empty group keeps them out of the merged option list.
  for (const std::string& name : all_scene_parameters()) a->add_option("--" + name, text[name])->group("");
  a->footer(scene_parameters_help(accepts, sized));
}

bool SceneArgs::given(std::string_view name) const {
  const auto it = text.find(name);
  if (it != text.end() && !it->second.empty()) return true;
  return app && app->count("--" + std::string(name)) > 0;  // given, but empty
}

std::size_t SceneArgs::scene_index() const {
  const auto index = find_scene(scene);
  if (!index)
    throw UsageError(fmt::format("--scene '{}' is unknown{}; accepted: {}", scene, did_you_mean(scene, scene_name_list()), scene_list()));
  return *index;
}

std::vector<double> SceneArgs::values(std::size_t index) const {
  const SceneKernel& s = scene_kernel(index);
  if (sized && s.size_param >= 0 && given(s.params[s.size_param].name))
    throw UsageError(fmt::format("--{} is not an option here: the study sets the {}'s size; accepted: --sizes WHOLE,...",
                                 s.params[s.size_param].name, s.name));
  for (const auto& [name, value] : text) {
    if (!given(name)) continue;
    if (!has_param(index, name)) {
      std::string list;
      for (const ParamSpec& p : s.params) list += (list.empty() ? "--" : ", --") + std::string(p.name);
      throw UsageError(fmt::format("--{} does not apply to scene {}; accepted: {}", name, s.name, list));
    }
  }
  std::vector<double> v;
  for (const ParamSpec& p : s.params) {
    const std::string option = "--" + std::string(p.name);
    if (given(p.name) && p.is_count) v.push_back(static_cast<double>(parse_count(option, text.at(std::string(p.name)), static_cast<long long>(p.min_count), static_cast<long long>(p.max_count))));
    else if (given(p.name)) v.push_back(parse_number(option, text.at(std::string(p.name)), p.bound));
    else if (auto f = old_defaults.find(p.name); f != old_defaults.end()) v.push_back(f->second);
    else v.push_back(p.default_value);
  }
  return v;
}

}  // namespace steplab
