// The timed runs' heap (analysis/kernel/timing.hpp): a block freed by one repeat is served to the
// next from pages already touched, so no repeat but the first pays the kernel's page faults,
// whatever the process allocated before.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cstdlib>
#include <cstring>
#include <vector>

#include "analysis/kernel/timing.hpp"

namespace steplab {
namespace {

long minor_faults() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_minflt;
}

// One repeat's set-up: a block of `bytes`, touched page by page as a workspace is, then freed.
void one_repeat(std::size_t bytes) {
  char* block = static_cast<char*>(std::malloc(bytes));
  std::memset(block, 1, bytes);
  volatile char keep = block[bytes - 1];
  (void)keep;
  std::free(block);
}

TEST(Timing, RepeatsRunOnPagesAlreadyTouched) {
  // 8 MiB, 2048 pages of 4 KiB: above glibc's default mmap threshold (128 KiB, raised as blocks are
  // freed, up to 32 MiB), so with glibc's own thresholds the first such block is mapped fresh and
  // returned on free, and the second comes from a heap grown anew: 2048 faults each.
  constexpr std::size_t kBytes = 8 << 20;
  std::vector<long> faults;  // each repeat's, reserved so that the timed runs allocate nothing else
  faults.reserve(4);
  repeated_timings(
      [&] {
        const long before = minor_faults();
        one_repeat(kBytes);
        faults.push_back(minor_faults() - before);
      },
      4, 0.0);
  ASSERT_EQ(faults.size(), 4u);
  // The first repeat grows the heap; the next reuse its pages: a fault or two where the heap's top
  // moves, not 2048.
  for (std::size_t repeat = 1; repeat < faults.size(); ++repeat) EXPECT_LT(faults[repeat], 16) << "repeat " << repeat;
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
