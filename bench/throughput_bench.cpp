// Study throughput: many trajectories at once, in trajectory-steps per second.
//
//   throughput/spring/explicit_euler           a study's path: kLanes runs of explicit Euler on
//                                              the default spring, one at a time through the
//                                              kernel table (analysis/kernel.hpp), each kSteps
//                                              steps, with the run loop's checks (non-finite
//                                              state, energy ratio)
//   throughput_baseline/spring/explicit_euler  the same update written by hand over the same
//                                              number of interleaved trajectories, nothing else
//   throughput_rate/spring/explicit_euler      the first with the energy-rate fit, as in
//                                              `study stability` (ln E and its slope, a log a step)
//
// Each iteration runs every trajectory kSteps steps from the initial state, each with its own
// step (no error against the exact solution: the runs of `study stability` do without it).
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <span>
#include <string>

#include "analysis/kernel.hpp"

namespace {

using namespace steplab;
constexpr long long kSteps = 10'000;
constexpr double kDt = 0.001;
constexpr std::size_t kLanes = 8;  // trajectories per iteration

// The baseline compiled for plain x86-64 and AVX2, the CPU picking at load time.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__SANITIZE_ADDRESS__)
#define STEPLAB_MULTIVERSION __attribute__((target_clones("avx2", "default")))
#else
#define STEPLAB_MULTIVERSION
#endif

// Trajectory i's step: each its own (a compiler given identical lanes computes one and copies it).
double step_of(std::size_t i) { return kDt * (1 + 1e-3 * static_cast<double>(i)); }

RunSpec throughput_spec(std::size_t i, bool rate) {
  RunSpec spec;
  spec.dt = step_of(i);
  spec.steps = kSteps;
  spec.errors = false;
  spec.energy_rate = rate;
  return spec;
}

// The baseline's loop: the spring's force as Spring::force (sign(y) as two selects, so that GCC
// vectorises it across the lanes), a = F * (1/m), x += h v, v += h a; compiled for plain x86-64
// and AVX2.
STEPLAB_MULTIVERSION void baseline_steps(std::array<double, kLanes>& y_out, std::array<double, kLanes>& v_out,
                                         const std::array<double, kLanes>& h_in) {
  const double m = 1, k = 5, gamma = 0.1, L = 5, g = 9.81, inv_m = 1 / m, weight = m * g;
  std::array<double, kLanes> y = y_out, v = v_out, h = h_in;  // local: no aliasing between them
  for (long long i = 0; i < kSteps; ++i)
#pragma GCC unroll 1  // left a loop, for the vectoriser (unrolled first, GCC 12 leaves it scalar)
    for (std::size_t l = 0; l < kLanes; ++l) {
      const double sign = (y[l] > 0 ? 1.0 : 0.0) - (y[l] < 0 ? 1.0 : 0.0);
      const double a = (-k * (std::abs(y[l]) - L) * sign - gamma * v[l] - weight) * inv_m;
      y[l] += h[l] * v[l];
      v[l] += h[l] * a;
    }
  y_out = y;
  v_out = v;
}

void set_rate(benchmark::State& st) {
  st.counters["trajectory_steps_per_second"] =
      benchmark::Counter(static_cast<double>(st.iterations() * kLanes * kSteps), benchmark::Counter::kIsRate);
}

void register_steplab_throughput(const std::string& suffix, bool rate) {
  benchmark::RegisterBenchmark(("throughput" + suffix + "/spring/explicit_euler").c_str(), [rate](benchmark::State& st) {
    const std::size_t spring = scene_index("spring");
    const PairKernel& k = pair_kernel(*find_method("explicit_euler"), spring);
    const std::vector<double> p = default_param_values(spring);
    double sink = 0;
    for (auto _ : st) {
      for (std::size_t l = 0; l < kLanes; ++l) sink += k.run(p, throughput_spec(l, rate)).final.x[0];
      benchmark::DoNotOptimize(sink);
    }
    set_rate(st);
  });
}

}  // namespace

std::pair<int, long long> register_throughput() {
  register_steplab_throughput("", false);
  register_steplab_throughput("_rate", true);
  benchmark::RegisterBenchmark("throughput_baseline/spring/explicit_euler", [](benchmark::State& st) {
    std::array<double, kLanes> y, v, h;
    for (std::size_t l = 0; l < kLanes; ++l) h[l] = step_of(l);
    for (auto _ : st) {
      y.fill(-5);
      v.fill(0);
      benchmark::DoNotOptimize(h);
      baseline_steps(y, v, h);
      benchmark::DoNotOptimize(y);
      benchmark::DoNotOptimize(v);
    }
    set_rate(st);
  });
  return {static_cast<int>(kLanes), static_cast<long long>(kLanes) * kSteps};
}
