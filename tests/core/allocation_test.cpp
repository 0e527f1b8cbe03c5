// No heap allocation in a stepping loop: counts calls of the global operator new while whole
// runs of every method on every scene execute. Without samples a run allocates nothing at all;
// with samples it allocates once (the reserved buffer), however many steps it takes.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "core/lanes.hpp"
#include "core/methods.hpp"
#include "core/scenes.hpp"
#include "core/simulate.hpp"

namespace {
std::atomic<long> g_allocations{0};
}

// The replacement pairs malloc with free throughout; GCC's -Wmismatched-new-delete cannot see
// that operator new below is the one in use and warns on the deletes.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
// The nothrow form too (std::stable_sort's temporary buffer uses it): left to the sanitizer's
// own operator new, its blocks would come back to the free() below as a mismatch.
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  ++g_allocations;
  return std::malloc(n ? n : 1);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
#pragma GCC diagnostic pop

namespace steplab {
namespace {

template <class M, class S> long allocations_in_run(long long steps, long long samples) {
  const S scene = make_default_scene<S>();
  RunSpec spec;
  spec.dt = 0.001;
  spec.steps = steps;
  spec.max_samples = samples;
  spec.energy_rate = true;
  const long before = g_allocations.load();
  const auto r = simulate<M>(scene, spec);
  const long used = g_allocations.load() - before;
  EXPECT_EQ(r.steps, steps);
  return used;
}

// Runs in lanes (core/lanes.hpp): the lanes are allocated once, before stepping, so 9 runs of
// 4000 steps through 4 lanes allocate what 9 runs of 200 steps do.
template <class M, class S> long allocations_in_lanes(long long steps) {
  const S scene = make_default_scene<S>();
  RunSpec spec;
  spec.dt = 0.001;
  spec.steps = steps;
  spec.energy_rate = true;
  long long taken = 0;
  const long before = g_allocations.load();
  simulate_lanes<M, S>(
      9, 4, [&](std::size_t) { return std::pair(scene, spec); },
      [&](std::size_t, const RunResult<S::dim>& r, const S&) { taken += r.steps; });
  const long used = g_allocations.load() - before;
  EXPECT_EQ(taken, 9 * steps);
  return used;
}

TEST(Allocation, LanesAllocateOnlyBeforeStepping) {
  [&]<std::size_t... J>(std::index_sequence<J...>) {
    (([&]<class M>() {
       EXPECT_EQ((allocations_in_lanes<M, Spring>(200)), (allocations_in_lanes<M, Spring>(4000))) << M::info.name;
       EXPECT_LE((allocations_in_lanes<M, Spring>(200)), 1) << M::info.name;
     }.template operator()<std::tuple_element_t<J, Methods>>()),
     ...);
  }(std::make_index_sequence<method_count>{});
}

TEST(Allocation, NoneInAnyStepOfAnyMethodOnAnyScene) {
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (([&]<class S>() {
       [&]<std::size_t... J>(std::index_sequence<J...>) {
         (([&]<class M>() {
            if constexpr (applies<M, S>()) {
              EXPECT_EQ((allocations_in_run<M, S>(2000, 0)), 0) << S::name << " " << M::info.name;
              EXPECT_EQ((allocations_in_run<M, S>(200, 50)), (allocations_in_run<M, S>(4000, 50)))
                  << S::name << " " << M::info.name;
            }
          }.template operator()<std::tuple_element_t<J, Methods>>()),
          ...);
       }(std::make_index_sequence<method_count>{});
     }.template operator()<std::tuple_element_t<I, Scenes>>()),
     ...);
  }(std::make_index_sequence<scene_count>{});
}

}  // namespace
}  // namespace steplab
