// Reading numbers and names from the command line and config files, with one clear message
// naming the input and what is accepted when they are wrong (UsageError -> exit status 2).
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/scene.hpp"

namespace steplab {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string_view describe(Bound b);  // "a finite number > 0", ...

// A finite number within the bound, or a UsageError naming `what` (e.g. "--dt").
double parse_number(std::string_view what, std::string_view text, Bound bound);
double check_number(std::string_view what, double value, Bound bound);

// A whole number in [lo, hi].
long long parse_count(std::string_view what, std::string_view text, long long lo, long long hi);

// Comma-separated list, e.g. "euler,rk4"; spaces around an item are dropped ("rk4, euler").
std::vector<std::string> split_list(std::string_view text);
// " (did you mean 'rk4'?)" where one of `candidates` is a typo away from `typed` (at most two
// edits, a swap of neighbours counting one, and fewer edits than half its letters); "" otherwise.
std::string did_you_mean(std::string_view typed, const std::vector<std::string>& candidates);
// Comma-separated numbers, each within the bound.
std::vector<double> number_list(std::string_view what, const std::string& text, Bound bound);
// A UsageError naming `what` ("--sweep stiffness values") unless each value exceeds the one before.
void check_increasing(std::string_view what, const std::vector<double>& values);
// A UsageError naming `what` ("--stiffness") and the value if a list names one twice.
void check_distinct(std::string_view what, const std::vector<double>& values);

// steps_for(t_end, dt) (core/simulate.hpp), or a UsageError if that is more than max_steps.
inline constexpr long long max_steps = 1'000'000'000;
long long step_count(double t_end, double dt);

}  // namespace steplab
