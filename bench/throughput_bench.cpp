// Study throughput: many trajectories at once, in trajectory-steps per second.
//
//   throughput/spring/explicit_euler           a study's path: kLanes runs of explicit Euler on
//                                              the default spring through the kernel table
//                                              (analysis/kernel.hpp, run_all), in packs of the
//                                              CPU's best width, each kSteps steps, with the run
//                                              loop's checks (non-finite state, energy ratio)
//   throughput_w<N>/...                        the same at pack width N (1: one run at a time)
//   throughput_baseline/spring/explicit_euler  the same update written by hand over the same
//                                              number of interleaved trajectories, nothing else
//   throughput_rate/spring/explicit_euler      the first with the energy-rate fit, as in
//                                              `study stability` (ln E and its slope, a log a step)
//   throughput_baseline_rate/...               the baseline with the same fit written by hand
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

// The baseline with the energy-rate fit of `study stability` written by hand: E of the spring
// (kinetic, spring and gravity terms, m = 1), ln E, and Welford's update of its slope against t.
STEPLAB_MULTIVERSION double baseline_rate_steps(std::array<double, kLanes>& y_out, std::array<double, kLanes>& v_out,
                                                const std::array<double, kLanes>& h_in) {
  const double m = 1, k = 5, gamma = 0.1, L = 5, g = 9.81, inv_m = 1 / m, weight = m * g;
  std::array<double, kLanes> y = y_out, v = v_out, h = h_in, n{}, mt{}, ml{}, c{}, m2{};
  for (long long i = 0; i < kSteps; ++i)
#pragma GCC unroll 1
    for (std::size_t l = 0; l < kLanes; ++l) {
      const double sign = (y[l] > 0 ? 1.0 : 0.0) - (y[l] < 0 ? 1.0 : 0.0);
      const double a = (-k * (std::abs(y[l]) - L) * sign - gamma * v[l] - weight) * inv_m;
      y[l] += h[l] * v[l];
      v[l] += h[l] * a;
      const double s = std::abs(y[l]) - L, e = 0.5 * m * v[l] * v[l] + 0.5 * k * s * s + weight * (y[l] + 20);
      const double t = static_cast<double>(i + 1) * h[l], lg = std::log(e), n1 = n[l] + 1, dt = t - mt[l];
      const double mt1 = mt[l] + dt / n1, ml1 = ml[l] + (lg - ml[l]) / n1;
      c[l] += dt * (lg - ml1), m2[l] += dt * (t - mt1), n[l] = n1, mt[l] = mt1, ml[l] = ml1;
    }
  y_out = y;
  v_out = v;
  double slope = 0;
  for (std::size_t l = 0; l < kLanes; ++l) slope += c[l] / m2[l];
  return slope;
}

void set_rate(benchmark::State& st) {
  st.counters["trajectory_steps_per_second"] =
      benchmark::Counter(static_cast<double>(st.iterations() * kLanes * kSteps), benchmark::Counter::kIsRate);
}

void register_steplab_throughput(const std::string& prefix, bool rate, int width) {
  benchmark::RegisterBenchmark((prefix + "/spring/explicit_euler").c_str(), [rate, width](benchmark::State& st) {
    const std::size_t spring = scene_index("spring");
    const PairKernel& k = pair_kernel(*find_method("explicit_euler"), spring);
    const std::vector<double> p = default_param_values(spring);
    std::vector<BatchRun> runs;
    for (std::size_t l = 0; l < kLanes; ++l) runs.push_back({p, throughput_spec(l, rate)});
    double sink = 0;
    for (auto _ : st) {
      for (const AnyResult& r : run_all(k, runs, width)) sink += r.final.x[0];
      benchmark::DoNotOptimize(sink);
    }
    set_rate(st);
  });
}

}  // namespace

std::pair<int, long long> register_throughput() {
  register_steplab_throughput("throughput", false, 0);
  register_steplab_throughput("throughput_rate", true, 0);
  for (int w : kPackWidths)
    if (cpu_has_width(w)) register_steplab_throughput("throughput_w" + std::to_string(w), false, w);
  benchmark::RegisterBenchmark("throughput_baseline_rate/spring/explicit_euler", [](benchmark::State& st) {
    std::array<double, kLanes> y, v, h;
    for (std::size_t l = 0; l < kLanes; ++l) h[l] = step_of(l);
    for (auto _ : st) {
      y.fill(-5);
      v.fill(0);
      benchmark::DoNotOptimize(h);
      benchmark::DoNotOptimize(baseline_rate_steps(y, v, h));
      benchmark::DoNotOptimize(y);
    }
    set_rate(st);
  });
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
