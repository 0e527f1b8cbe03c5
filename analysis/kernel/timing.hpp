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
//
// A run's set-up allocates inside the timed region (an implicit method's matrices and
// factorisations, a peer's memory) and its clean-up frees it. glibc serves a block above its mmap
// threshold with fresh pages, each faulted in on first touch, and raises that threshold as such
// blocks are freed; so whether a repeat paid for its pages depended on what the process had
// allocated before (radau_iia5 on the rope at N = 128: 0.43 to 0.57 ms a run in a process that
// ran steplab's methods alone, 0.20 ms in one that had run the peers first). keep_heap_pages()
// fixes both thresholds (which also stops glibc moving them): a block up to 32 MiB comes from the
// heap, and freed pages stay there, so every repeat but the first runs on pages already touched,
// in every process alike.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <ctime>
#include <malloc.h>
#include <vector>

namespace steplab {

inline double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

inline void keep_heap_pages() {
  static const bool kept = mallopt(M_MMAP_THRESHOLD, 32 << 20) == 1 && mallopt(M_TRIM_THRESHOLD, 1 << 30) == 1;
  (void)kept;
}

template <class F> std::vector<double> repeated_timings(F&& run, std::size_t repeats, double seconds) {
  keep_heap_pages();
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
