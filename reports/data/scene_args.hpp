// The scene and its parameters as given on the command line (--scene, --mass, --stiffness, ...),
// shared by `run` and every study. A parameter is an option only once, whatever scenes have it.
#pragma once

#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "analysis/studies/defaults.hpp"
#include "analysis/kernel/kernel.hpp"

namespace steplab {

struct SceneArgs {
  std::string scene = std::string(kDefaultScene);
  std::map<std::string, std::string, std::less<>> text;   // parameter -> value as typed
  std::map<std::string, double, std::less<>> old_defaults;  // the old framework's defaults, in place of the scene's
  CLI::App* app = nullptr;

  // Adds --scene (unless the command has its scenes fixed), one option per parameter name of any
  // scene, and their help by scene: of the scenes the command `accepts` (null: every one).
  // `sized` (study scaling): a scene's size parameter is not an option (the command's --sizes
  // sets it; given, it is refused), and its stiffness parameter takes a LIST.
  void add_to(CLI::App* a, bool (*accepts)(const SceneKernel&) = nullptr, bool with_scene_option = true, bool sized = false);
  void set(std::string_view name, std::string value) { text[std::string(name)] = std::move(value); }
  bool given(std::string_view name) const;

  bool sized = false;  // add_to's
  std::size_t scene_index() const;  // UsageError for an unknown scene
  // The scene's parameter values in its table order. UsageError for a value out of bounds, or a
  // parameter given that the scene does not have.
  std::vector<double> values(std::size_t scene_index) const;
};

// Every parameter name that some scene has, in first-seen order.
std::vector<std::string> all_scene_parameters();
// The parameters of the scenes `accepts` takes (null: every one) for --help, grouped by scene,
// each with its meaning and default.
std::string scene_parameters_help(bool (*accepts)(const SceneKernel&) = nullptr, bool sized = false);

}  // namespace steplab
