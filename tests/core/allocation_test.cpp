// No heap allocation in a stepping loop: counts calls of the global operator new while whole
// runs of every method on every scene execute, through the kernel table (analysis/kernel/kernel.hpp).
// A run allocates the same whatever its number of steps: its sample buffer, reserved before the
// loop, and the result it hands back.
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <new>

#include "analysis/kernel/kernel.hpp"
#include "core/methods/xpbd.hpp"
#include "core/scenes/cloth.hpp"
#include "core/scenes/rope.hpp"
#include "core/scenes/softbody.hpp"
#include "core/simulate.hpp"

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
  // every step taken, or a blow-up that ended the run (explicit Euler on the chain at this step:
  // its fast mode grows 4 % a step and passes the blow-up bound, core/simulate.hpp, at step 497)
  if (r.status == RunStatus::Ok) EXPECT_EQ(r.steps, steps);
  else EXPECT_EQ(r.status, RunStatus::Diverged);
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

// A scene of run-time size allocates in a run's first step only: the run owns a scratch pool for
// a step's temporaries and a Newton workspace (core/scratch.hpp, core/sparse.hpp), the scenes
// write their forces and Jacobians into them, the rope's exact motion is stepped mode by mode in
// vectors made once. Every method, plain and counted, on ropes and soft bodies of 64 and 4096
// masses: operator new and malloc both counted (each once: operator new above takes the real malloc).

// The allocations a run of `steps` steps makes, run(steps).
long allocations_of(const std::function<void(long long)>& run, long long steps) {
  const long before = g_allocations.load() + g_mallocs.load();
  run(steps);
  return g_allocations.load() + g_mallocs.load() - before;
}

// The allocations of `steps` more steps: a run of 2 x steps less a run of `steps` (what a run
// makes once, its workspace among it, cancels), each after a short run of the same size (what is
// made once per size and process, as the rope's FFTW plans, is made by then).
long allocations_of_steps(const std::function<void(long long)>& run, long long steps) {
  allocations_of(run, 10);
  const long longer = allocations_of(run, 2 * steps);
  allocations_of(run, 10);
  return longer - allocations_of(run, steps);
}

// Method m on scene s of the given size through the kernel table, plain or counted.
long allocations_of_steps(std::size_t m, std::size_t s, double size, double dt, long long steps, bool counted) {
  std::vector<double> p = default_param_values(s);
  p[0] = size;
  return allocations_of_steps(
      [&](long long n) {
        RunSpec spec;
        spec.dt = dt, spec.steps = n;
        Counts counts;
        const AnyResult r = counted ? pair_kernel(m, s).run_counted(p, spec, counts) : pair_kernel(m, s).run(p, spec);
        EXPECT_EQ(r.steps, n);
      },
      steps);
}

void expect_none_in_steps(const char* scene, std::array<double, 2> sizes, const std::function<double(double)>& dt) {
  const std::size_t s = *find_scene(scene);
  for (std::size_t m = 0; m < method_count(); ++m) {
    if (!applies(m, s)) continue;
    for (const double size : sizes)
      for (const bool counted : {false, true})
        EXPECT_EQ(allocations_of_steps(m, s, size, dt(size), 20, counted), 0)
            << scene << " " << method_info(m).name << " size " << size << (counted ? " counted" : "");
  }
}

// The rope of 64 and 4096 masses, dt = 0.04 / N: omega_max h < 0.2 (omega_max ~ 4.5 N here),
// every method stable; its exact motion tracked (the errors) at every step.
TEST(Allocation, NoneInAStepOnTheRope) {
  expect_none_in_steps("rope", {64, 4096}, [](double n) { return 0.04 / n; });
}

// The soft body of 8 x 8 and 64 x 64 masses at dt 1e-4 (every method stable, the body in free
// fall). Its implicit methods' unsymmetric matrices are factorised and solved by KLU, in place.
TEST(Allocation, NoneInAStepOnTheSoftBody) {
  expect_none_in_steps("softbody", {8, 64}, [](double) { return 1e-4; });
}

// The cloth at dt 5e-6 (at 64 a side its dashpots' fastest rate, about 1.7e5 /s, times h is below
// 1: every method stable), its 3 x 3 blocks factorised by KLU in place: every method at 4 and 16
// a side; at 64 its own force and Jacobians through RK4 and implicit Euler, and the methods on its
// springs (every implicit method's sparse solves at that size are the soft body's, above: all of
// them at 64 a side took 150 s here).
TEST(Allocation, NoneInAStepOnTheCloth) {
  expect_none_in_steps("cloth", {4, 16}, [](double) { return 5e-6; });
  const std::size_t s = *find_scene("cloth");
  for (const char* name : {"rk4", "implicit_euler", "xpbd", "pbd", "baraff_witkin"})
    for (const bool counted : {false, true})
      EXPECT_EQ(allocations_of_steps(*find_method(name), s, 64, 5e-6, 20, counted), 0) << name << (counted ? " counted" : "");
}

// XPBD (core/methods/xpbd.hpp; not in the kernel table yet), 3 sweeps a step, by simulate.
template <class S> long xpbd_allocations_of_steps(const S& scene, double dt) {
  return allocations_of_steps(
      [&](long long n) {
        RunSpec spec;
        spec.dt = dt, spec.steps = n, spec.settings.sweeps = 3;
        simulate<Xpbd>(scene, spec);
      },
      20);
}
TEST(Allocation, NoneInAnXpbdStep) {
  for (const double size : {64.0, 4096.0}) {
    std::vector<double> p = default_param_values<Rope>();
    p[0] = size;
    EXPECT_EQ(xpbd_allocations_of_steps(Rope(p), 0.04 / size), 0) << "rope " << size;
  }
  for (const double side : {8.0, 64.0}) {
    std::vector<double> p = default_param_values<SoftBody>();
    p[0] = side;
    EXPECT_EQ(xpbd_allocations_of_steps(SoftBody(p), 1e-4), 0) << "soft body " << side;
    std::vector<double> c = default_param_values<Cloth>();
    c[0] = side;
    EXPECT_EQ(xpbd_allocations_of_steps(Cloth(c), 1e-4), 0) << "cloth " << side;
  }
}

}  // namespace
}  // namespace steplab
