// Wall-clock timings of a run, repeated one after another (no other run competing for the core):
// at least `repeats` of them and `seconds` in all. A study keeps the median or the minimum; when
// two timings are told apart: analysis/kernel/noise.hpp.
#pragma once

#include <chrono>
#include <cstddef>
#include <vector>

namespace steplab {

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
