#include "reports/cli/input_checks.hpp"

#include <algorithm>
#include <utility>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "reports/data/inputs.hpp"

namespace steplab {

void check_repeats(const std::vector<std::string>& args) {
  std::vector<std::string> seen;
  for (const std::string& a : args) {
    if (a.rfind("--", 0) != 0 || a == "--") continue;
    const std::string name = a.substr(0, a.find('='));
    if (std::find(seen.begin(), seen.end(), name) != seen.end())
      throw UsageError(fmt::format("{} is given twice; accepted: each option once", name));
    seen.push_back(name);
  }
}

void check_no_empty_values(CLI::App& app) {
  CLI::App* at = &app;
  while (!at->get_subcommands().empty()) at = at->get_subcommands().front();
  for (const CLI::Option* o : at->get_options()) {
    if (o->count() == 0 || o->get_expected_max() == 0 || o->get_lnames().empty()) continue;
    for (const std::string& v : o->results())
      if (v.empty())
        throw UsageError(fmt::format("--{} is given an empty value; accepted: {} (or leave the option out for its default)",
                                     o->get_lnames()[0], o->get_type_name().empty() ? "a value" : o->get_type_name()));
  }
}

void check_unique_names() {
  for (const auto& [what, names] : {std::pair{"methods", method_name_list()}, std::pair{"scenes", scene_name_list()}})
    for (std::size_t i = 0; i < names.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (names[i] == names[j])
          throw UsageError(fmt::format("two {} are named '{}' (one is steplab's, or two of yours): give yours another `name`; "
                                       "accepted: one name each",
                                       what, names[i]));
}

}  // namespace steplab
