// Checks of a command line that the parser does not make, each refusing in one line (a
// UsageError, reports/data/inputs.hpp) before anything runs.
#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace steplab {

// An option given twice (--dt 0.01 --dt 0.02): which value would count is not for the parser to
// guess. Said before parsing, by name, where the parser would only count the values.
void check_repeats(const std::vector<std::string>& args);

// An option given with an empty value (--methods ""): refused, not read as if it were not given
// (which would run the defaults silently). After parsing, on the command that was parsed.
void check_no_empty_values(CLI::App& app);

// Two methods or two scenes of one name (a user's, built with steplab_add_executable, named as a
// built-in one is): a name would pick either.
void check_unique_names();

}  // namespace steplab
