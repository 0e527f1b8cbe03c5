// Study throughput: many trajectories at once, in trajectory-steps per second.
//
//   throughput/spring/explicit_euler           a study's path: kLanes runs of explicit Euler on
//                                              the default spring through the kernel table
//                                              (analysis/kernel/kernel.hpp, run_all), in packs of the
//                                              CPU's best width, each kSteps steps, with the run
//                                              loop's checks (non-finite state, energy ratio)
//   throughput_w<N>/...                        the same at pack width N (1: one run at a time)
//   throughput_hand/spring/explicit_euler  the same update written by hand over the same
//                                              number of interleaved trajectories, nothing else
//   throughput_rate/spring/explicit_euler      the first with the energy-rate fit, as in
//                                              `study stability` (ln E and its slope, a log a step)
//   throughput_hand_rate/...               the baseline with the same fit written by hand
//
// Each iteration runs every trajectory kSteps steps from the initial state, each with its own
// step (no error against the exact solution: the runs of `study stability` do without it).
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <span>
#include <string>

#include "analysis/kernel/kernel.hpp"

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

// The baseline's spring (the defaults) and one explicit Euler step of one lane: the force as
// Spring::force (sign(y) as two selects, so that GCC vectorises it across the lanes),
// a = F * (1/m), x += h v, v += h a.
constexpr double kM = 1, kK = 5, kGamma = 0.1, kL = 5, kG = 9.81, kInvM = 1 / kM, kWeight = kM * kG;
constexpr double kEquilibrium = -kL - kM * kG / kK;
[[gnu::always_inline]] inline void euler_lane(double& y, double& v, double h) {
  const double sign = (y > 0 ? 1.0 : 0.0) - (y < 0 ? 1.0 : 0.0);
  const double a = (-kK * (std::abs(y) - kL) * sign - kGamma * v - kWeight) * kInvM;
  y += h * v;
  v += h * a;
}

// The baseline's loops, compiled for plain x86-64 and AVX2: the steps alone, and the steps with
// the energy-rate fit of `study stability` (E as Spring::energy, ln E, Welford's update of its
// slope against t); each returns something of its lanes for the benchmark to keep.
STEPLAB_MULTIVERSION double baseline_steps(std::array<double, kLanes>& y_out, std::array<double, kLanes>& v_out,
                                           const std::array<double, kLanes>& h_in) {
  std::array<double, kLanes> y = y_out, v = v_out, h = h_in;  // local: no aliasing between them
  for (long long i = 0; i < kSteps; ++i)
#pragma GCC unroll 1  // left a loop, for the vectoriser (unrolled first, GCC 12 leaves it scalar)
    for (std::size_t l = 0; l < kLanes; ++l) euler_lane(y[l], v[l], h[l]);
  y_out = y;
  v_out = v;
  return y[0];
}

STEPLAB_MULTIVERSION double baseline_rate_steps(std::array<double, kLanes>& y_out, std::array<double, kLanes>& v_out,
                                                const std::array<double, kLanes>& h_in) {
  std::array<double, kLanes> y = y_out, v = v_out, h = h_in, n{}, mt{}, ml{}, c{}, m2{};
  for (long long i = 0; i < kSteps; ++i)
#pragma GCC unroll 1
    for (std::size_t l = 0; l < kLanes; ++l) {
      euler_lane(y[l], v[l], h[l]);
      const double u = y[l] - kEquilibrium, e = 0.5 * kM * v[l] * v[l] + 0.5 * kK * u * u;
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

using BaselineLoop = double (*)(std::array<double, kLanes>&, std::array<double, kLanes>&, const std::array<double, kLanes>&);

void register_baseline(const std::string& prefix, BaselineLoop loop) {
  benchmark::RegisterBenchmark((prefix + "/spring/explicit_euler").c_str(), [loop](benchmark::State& st) {
    std::array<double, kLanes> y, v, h;
    for (std::size_t l = 0; l < kLanes; ++l) h[l] = step_of(l);
    for (auto _ : st) {
      y.fill(-kL);
      v.fill(0);
      benchmark::DoNotOptimize(h);
      benchmark::DoNotOptimize(loop(y, v, h));
      benchmark::DoNotOptimize(y);
      benchmark::DoNotOptimize(v);
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
  register_baseline("throughput_hand", baseline_steps);
  register_baseline("throughput_hand_rate", baseline_rate_steps);
  return {static_cast<int>(kLanes), static_cast<long long>(kLanes) * kSteps};
}
