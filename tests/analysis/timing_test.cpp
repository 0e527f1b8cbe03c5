// The timed runs' heap (analysis/kernel/timing.hpp): a block freed by one repeat is served to the
// next from pages already touched, so no repeat but the first pays the kernel's page faults,
// whatever the process allocated before.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cstdlib>
#include <cstring>

#include "analysis/kernel/timing.hpp"

namespace steplab {
namespace {

long minor_faults() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_minflt;
}

// One repeat's set-up: a block of `bytes`, touched page by page as a workspace is, then freed.
long faults_of_one_repeat(std::size_t bytes) {
  const long before = minor_faults();
  char* block = static_cast<char*>(std::malloc(bytes));
  std::memset(block, 1, bytes);
  volatile char keep = block[bytes - 1];
  (void)keep;
  std::free(block);
  return minor_faults() - before;
}

TEST(Timing, RepeatsRunOnPagesAlreadyTouched) {
  // 8 MiB, 2048 pages of 4 KiB: above glibc's default mmap threshold (128 KiB, raised as blocks are
  // freed up to 32 MiB), so without fixed thresholds the first such block is mapped fresh and
  // returned on free, and every repeat faults in all its pages again.
  constexpr std::size_t kBytes = 8 << 20;
  keep_heap_pages();
  faults_of_one_repeat(kBytes);  // the first repeat: the heap grows, its pages faulted in once
  // The next repeats reuse those pages: a fault or two where the heap's top moves, not 2048.
  for (int repeat = 0; repeat < 3; ++repeat) EXPECT_LT(faults_of_one_repeat(kBytes), 16) << "repeat " << repeat;
}

TEST(Timing, RepeatsUntilBothCountAndTimeAreMet) {
  int runs = 0;
  const auto times = repeated_timings([&] { ++runs; }, 5, 0.0);
  EXPECT_EQ(times.size(), 5u);
  EXPECT_EQ(runs, 5);
  for (double t : times) EXPECT_GE(t, 0.0);
}

}  // namespace
}  // namespace steplab
