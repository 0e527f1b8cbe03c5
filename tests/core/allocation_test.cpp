// No heap allocation in a stepping loop: counts calls of the global operator new while whole
// runs of every method on every scene execute, through the kernel table (analysis/kernel.hpp).
// A run allocates the same whatever its number of steps: its sample buffer, reserved before the
// loop, and the result it hands back.
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <new>

#include "analysis/kernel.hpp"

namespace {
std::atomic<long> g_allocations{0};
std::atomic<long> g_mallocs{0};
}

// Every malloc of code linked statically (steplab's libraries, Eigen's vectors of run-time size,
// which allocate with std::malloc, not operator new): the link wraps it (tests/CMakeLists.txt).
extern "C" void* __real_malloc(std::size_t n);
extern "C" void* __wrap_malloc(std::size_t n) {
  ++g_mallocs;
  return __real_malloc(n);
}

// The replacement pairs malloc with free throughout; GCC's -Wmismatched-new-delete cannot see
// that operator new below is the one in use and warns on the deletes.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = __real_malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
// The nothrow form too (std::stable_sort's temporary buffer uses it): left to the sanitizer's
// own operator new, its blocks would come back to the free() below as a mismatch.
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  ++g_allocations;
  return __real_malloc(n ? n : 1);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
#pragma GCC diagnostic pop

namespace steplab {
namespace {

// Allocations of one run through the kernel table: the run itself (its sample buffer, reserved
// before the loop) and the result handed back (AnyResult: the final state's two vectors and one
// per sample).
long allocations_in_run(std::size_t m, std::size_t s, long long steps, long long samples, int kind) {
  RunSpec spec;
  spec.dt = 0.001;
  spec.steps = steps;
  spec.max_samples = samples;
  spec.energy_rate = true;
  const std::vector<double> p = default_param_values(s);
  Counts counts;
  Observed observed;
  observed.max_bounces = 16;
  const long before = g_allocations.load();
  const AnyResult r = kind == 0 ? pair_kernel(m, s).run(p, spec)
                      : kind == 1 ? pair_kernel(m, s).run_counted(p, spec, counts)
                                  : pair_kernel(m, s).run_observed(p, spec, observed);
  const long used = g_allocations.load() - before;
  EXPECT_EQ(r.steps, steps);
  return used;
}

// Every method on every scene, plain, counted and observed: the count does not grow with the
// steps (none in a step); without samples it is the result's two vectors (and the observed run's
// bounce buffer, reserved before the loop).
TEST(Allocation, NoneInAnyStepOfAnyMethodOnAnyScene) {
  for (std::size_t s = 0; s < scene_count(); ++s)
    for (std::size_t m = 0; m < method_count(); ++m) {
      if (!applies(m, s) || scene_kernel(s).dim == Eigen::Dynamic) continue;  // those: below
      for (int kind = 0; kind < 3; ++kind) {
        if ((kind == 1 && !pair_kernel(m, s).run_counted) || (kind == 2 && !pair_kernel(m, s).run_observed)) continue;
        const std::string what = std::string(scene_name(s)) + " " + std::string(method_info(m).name) + " kind " + std::to_string(kind);
        EXPECT_LE(allocations_in_run(m, s, 2000, 0, kind), kind == 2 ? 3 : 2) << what;
        EXPECT_EQ(allocations_in_run(m, s, 200, 0, kind), allocations_in_run(m, s, 4000, 0, kind)) << what;
        EXPECT_EQ(allocations_in_run(m, s, 200, 50, kind), allocations_in_run(m, s, 4000, 50, kind)) << what;
      }
    }
}

// A scene of run-time size (the rope) allocates in its steps: Eigen's vectors of run-time size,
// the sparse Jacobians, the sparse factorisation. What is asked: a count per step that does not
// grow with the size. Every method, 100 steps and 200 steps of ropes of 4 and of 256 masses;
// operator new and malloc both counted (each counted once: operator new above takes the real malloc).
long allocations_per_sized_run(std::size_t m, std::size_t s, double size, double dt, long long steps) {
  RunSpec spec;
  spec.dt = dt;
  spec.steps = steps;
  std::vector<double> p = default_param_values(s);
  p[0] = size;
  const long before = g_allocations.load() + g_mallocs.load();
  const AnyResult r = pair_kernel(m, s).run(p, spec);
  EXPECT_EQ(r.steps, steps);
  return g_allocations.load() + g_mallocs.load() - before;
}

// The allocations of `steps` more steps: a run of 2 x steps less a run of `steps` (what a run
// makes once, its Newton workspace among it, cancels), each after a short run of the same size
// (what is made once per size and process, as the rope's FFTW plans, is made by then).
long allocations_of_steps(std::size_t m, std::size_t s, double size, double dt, long long steps) {
  allocations_per_sized_run(m, s, size, dt, 10);
  const long longer = allocations_per_sized_run(m, s, size, dt, 2 * steps);
  allocations_per_sized_run(m, s, size, dt, 10);
  return longer - allocations_per_sized_run(m, s, size, dt, steps);
}

// The allocations of `steps` more steps at three sizes holding `masses` (printed, a step each): equal.
void expect_per_step_counts(const std::string& what, const char* masses, const std::array<long, 3>& n, long long steps) {
  const double k = static_cast<double>(steps);
  std::printf("%-18s allocations a step at %s masses: %.2f %.2f %.2f\n", what.c_str(), masses, n[0] / k, n[1] / k, n[2] / k);
  EXPECT_EQ(n[0], n[1]) << what;
  EXPECT_EQ(n[0], n[2]) << what;
}

TEST(Allocation, PerStepCountOnTheRopeDoesNotGrowWithItsSize) {
  const std::size_t s = *find_scene("rope");
  const auto per_step = [&](std::size_t m, double masses) {
    // dt: omega_max h < 0.2 (omega_max ~ 4.5 N here): every method stable
    return allocations_of_steps(m, s, masses, 0.04 / masses, 100);
  };
  // Newton's kept matrices and vectors live in the run's workspace (core/sparse.hpp), made in its
  // first steps: what a step allocates is the scene's own vectors (its force values, and the
  // exact solution tracked), the same at every size. Measured: explicit Euler 11, implicit Euler
  // 12, Radau IIA 15, RK4 24 a step at 4, 256 and 2048 masses.
  for (std::size_t m = 0; m < method_count(); ++m)
    expect_per_step_counts(std::string(method_info(m).name), "4, 256, 2048", {per_step(m, 4), per_step(m, 256), per_step(m, 2048)},
                           100);
}

// The soft body likewise, at 3 x 3, 6 x 6 and 12 x 12 masses (dt 1e-4: every method stable, the
// body in free fall), 50 steps' difference: the same count at every size. Its implicit methods'
// unsymmetric matrices are factorised and solved by KLU, which solves in place. Measured: explicit
// Euler 4, implicit Euler 5, Radau IIA 8, RK4 17 a step (one a force evaluation).
TEST(Allocation, PerStepCountOnTheSoftBodyDoesNotGrowWithItsSize) {
  const std::size_t s = *find_scene("softbody");
  const auto per_step = [&](std::size_t m, double n) { return allocations_of_steps(m, s, n, 1e-4, 50); };
  for (std::size_t m = 0; m < method_count(); ++m) {
    if (!applies(m, s)) continue;
    expect_per_step_counts(std::string(method_info(m).name), "9, 36, 144", {per_step(m, 3), per_step(m, 6), per_step(m, 12)}, 50);
  }
}

}  // namespace
}  // namespace steplab
