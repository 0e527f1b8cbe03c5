// Wall-clock timings of a run, repeated one after another (no other run competing for the core):
// at least `repeats` of them and `seconds` in all. A study keeps the median or the minimum.
#pragma once

#include <chrono>
#include <cstddef>
#include <vector>

namespace steplab {

// A margin of one solver's cost over another's below this is within the noise of timing runs this
// short (the minimum of repeats moves by up to 10-20 % from one report to the next on a 2-core
// machine): a tie, not a win. Exact counts (an untimed study) tie only when equal.
inline constexpr double kTieMargin = 1.2;

template <class F> std::vector<double> repeated_timings(F&& run, std::size_t repeats, double seconds) {
  std::vector<double> times;
  double total = 0;
  while (times.size() < repeats || total < seconds) {
    const auto start = std::chrono::steady_clock::now();
    run();
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    total += times.back();
  }
  return times;
}

}  // namespace steplab
