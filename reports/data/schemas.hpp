// The schema every JSON document of steplab's opens with, "steplab.<kind>/<version>": one name
// per kind, read by the writers and by each command's --help. The version steps when a field
// changes its meaning or goes; docs/json.md says what changed. A study's schema is declared with
// its writers (reports/studies/studies.hpp); these are the others'.
#pragma once

#include <string_view>

namespace steplab::schema {

inline constexpr std::string_view run = "steplab.run/1";    // steplab run --json
inline constexpr std::string_view part = "steplab.part/1";  // --shard i/N, read by steplab merge

}  // namespace steplab::schema
