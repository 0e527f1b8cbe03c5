// Timings of a run, repeated one after another (no other run competing for the core): at least
// `repeats` of them and `seconds` in all. A study keeps the median or the minimum; when two
// timings are told apart: analysis/kernel/noise.hpp.
//
// One repeat's time is the smaller of two clocks around it: the wall clock, and the thread's CPU
// time (CLOCK_THREAD_CPUTIME_ID, read outside the wall clock's window). Alone on its core they
// agree but for the CPU clock's own cost, a system call of about a microsecond, so the wall time
// is the smaller and a run of microseconds is timed as before. Preempted by another process, the
// wall time counts the other's slices and the CPU time does not: a run longer than the
// scheduler's slice, which beside other load is never timed without a preemption, is still timed
// as its own work (docs/design.md, "Timing noise").
#pragma once

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <ctime>
#include <vector>

namespace steplab {

inline double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

template <class F> std::vector<double> repeated_timings(F&& run, std::size_t repeats, double seconds) {
  std::vector<double> times;
  double total = 0;
  while (times.size() < repeats || total < seconds) {
    const double cpu_start = thread_cpu_seconds();
    const auto start = std::chrono::steady_clock::now();
    run();
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    times.push_back(std::min(wall, thread_cpu_seconds() - cpu_start));
    total += times.back();
  }
  return times;
}

}  // namespace steplab
