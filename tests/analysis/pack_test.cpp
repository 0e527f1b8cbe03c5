// Runs stepped in SIMD packs (core/batch.hpp, PairKernel::run_batch) against the same runs one
// at a time: every field of every result the same bits, at every pack width this CPU has, for
// runs that end every way a run ends (steps done, E/E0 above or below its bounds, a non-finite
// state, no steps at all) at different times, so that lanes are refilled mid-batch; and the
// studies that batch their runs give the same tables at every width.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "analysis/studies/convergence.hpp"
#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/stability.hpp"

namespace steplab {
namespace {

std::size_t spring() { return scene_index("spring"); }

std::vector<int> widths_here() {
  std::vector<int> w;
  for (int width : kPackWidths)
    if (width > 1 && cpu_has_width(width)) w.push_back(width);
  return w;
}

// Bits, not values: NaN == NaN here, and 0.0 != -0.0.
bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

void expect_same(const AnyResult& a, const AnyResult& b, const std::string& where) {
  SCOPED_TRACE(where);
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.failed_step, b.failed_step);
  EXPECT_EQ(a.has_exact, b.has_exact);
  const std::pair<double, double> fields[] = {
      {a.failed_t, b.failed_t},       {a.t_final, b.t_final},
      {a.error_final, b.error_final}, {a.error_max, b.error_max},
      {a.error_rms, b.error_rms},     {a.error_v_final, b.error_v_final}, {a.energy0, b.energy0},
      {a.energy_ratio_final, b.energy_ratio_final}, {a.energy_ratio_max, b.energy_ratio_max},
      {a.energy_rate, b.energy_rate}};
  for (std::size_t i = 0; i < std::size(fields); ++i)
    EXPECT_TRUE(same_bits(fields[i].first, fields[i].second)) << "field " << i << ": " << fields[i].first << " vs " << fields[i].second;
  ASSERT_EQ(a.final.x.size(), b.final.x.size());
  for (Eigen::Index j = 0; j < a.final.x.size(); ++j) {
    EXPECT_TRUE(same_bits(a.final.x[j], b.final.x[j])) << "x[" << j << "]: " << a.final.x[j] << " vs " << b.final.x[j];
    EXPECT_TRUE(same_bits(a.final.v[j], b.final.v[j])) << "v[" << j << "]: " << a.final.v[j] << " vs " << b.final.v[j];
  }
}

// The scenes whose runs are packed: every scene of fixed size.
const char* const kPackedScenes[] = {"spring", "cannonball", "bounce", "falling", "chain"};

// The methods stepped one run at a time on a packed scene: the exact flow (its closed form is
// scalar), and those whose stages' dense solve has more than 3 unknowns (core/method.hpp):
// Gauss-Legendre 4 (2 stages) and BDF (its Gauss-Legendre start) from 2 coordinates, Radau IIA
// 5 (3 stages) too, and on the falling triangle's 6 every method that solves.
std::vector<std::string_view> unpacked_on(std::string_view scene) {
  if (scene == "spring" || scene == "bounce") return {"analytic"};
  if (scene == "falling")
    return {"implicit_euler", "implicit_midpoint", "velocity_verlet", "yoshida4", "gauss_legendre4", "radau_iia5", "bdf2", "bdf3"};
  return {"analytic", "gauss_legendre4", "radau_iia5", "bdf2", "bdf3"};  // 2 coordinates
}

// 40 runs of a scene: steps 0 .. 3000 (so lanes end at different times), stable and unstable
// steps, with and without errors and the energy-rate fit, and stop bounds that end some runs
// early (E/E0 above 10: Diverged; below 0.9: Ok). On the spring (explicit Euler's dt* on the
// default spring is gamma/k = 0.02; RK4's ~1.25): undamped, damped and overdamped springs; on
// the others, each run one parameter scaled by 0.5, 1 or 2 (the scene's bounds hold). A step of
// 1e200 fails Newton on the spring: its matrix m + h gamma + h^2 k overflows to inf, so the
// update is 0 while the residual, h |F| ~ 1e201, is not below 1e-12 of its scale (NoConvergence
// after 50 iterations).
struct Batch {
  std::vector<std::vector<double>> params;
  std::vector<BatchRun> runs;
  explicit Batch(std::size_t scene = spring()) {
    const double dts[] = {1e-3, 0.01, 0.05, 0.3, 1.0, 2.5, 7.0, 1e-4, 1e200};
    const double dampings[] = {0.0, 0.1, 3.0, 10.0};
    const double scales[] = {0.5, 1.0, 2.0};
    const std::vector<double> defaults = default_param_values(scene);
    params.reserve(40);
    for (int i = 0; i < 40; ++i) {
      std::vector<double> p = defaults;
      if (scene == spring()) p[2] = dampings[i % 4];
      else p[static_cast<std::size_t>(i) % p.size()] *= scales[i % 3];
      params.push_back(p);
      RunSpec s;
      s.dt = dts[i % 9];
      s.steps = (i * 377) % 3001;
      if (i % 10 == 3) s.steps = 0;
      s.errors = i % 3 != 0;
      s.energy_rate = i % 2 == 0;
      if (i % 5 == 1) s.stop_above = 10, s.stop_below = 0.9;
      runs.push_back({params.back(), s});
    }
  }
};

TEST(Packs, EveryFixedSizeSceneIsPackedWhereTheSolvesAllow) {
  for (std::size_t scene = 0; scene < scene_count(); ++scene) {
    const std::string_view name = scene_name(scene);
    const bool packed_scene = std::ranges::find(kPackedScenes, name) != std::end(kPackedScenes);
    const std::vector<std::string_view> unpacked = unpacked_on(name);
    for (std::size_t m = 0; m < method_count(); ++m) {
      if (!applies(m, scene)) continue;
      // the methods on springs step one run at a time: their sweeps and CG are written for one run's springs
      const bool expected = packed_scene && !method_info(m).on_springs &&
                            std::ranges::find(unpacked, method_info(m).name) == unpacked.end();
      EXPECT_EQ(pair_kernel(m, scene).run_batch != nullptr, expected) << method_info(m).name << " on " << name;
    }
  }
  EXPECT_TRUE(cpu_has_width(2));  // SSE2: every x86-64
}

TEST(Packs, EveryWidthGivesTheBitsOfOneRunAtATime) {
  for (const char* name : kPackedScenes) {
    const std::size_t scene = scene_index(name);
    const Batch b(scene);
    std::size_t packed = 0, diverged = 0, stopped_low = 0, no_convergence = 0;
    for (std::size_t m = 0; m < method_count(); ++m) {
      if (!applies(m, scene)) continue;
      const PairKernel& k = pair_kernel(m, scene);
      if (!k.run_batch) continue;
      ++packed;
      const std::vector<AnyResult> one = run_all(k, b.runs, 1);
      for (std::size_t i = 0; i < one.size(); ++i) {
        diverged += one[i].status == RunStatus::Diverged;
        no_convergence += one[i].status == RunStatus::NoConvergence;
        stopped_low += one[i].status == RunStatus::Ok && one[i].steps < b.runs[i].spec.steps;
      }
      for (int w : widths_here()) {
        const std::vector<AnyResult> packs = run_all(k, b.runs, w);
        for (std::size_t i = 0; i < one.size(); ++i)
          expect_same(one[i], packs[i], std::string(name) + " " + std::string(method_info(m).name) + " width " + std::to_string(w) +
                                            " run " + std::to_string(i));
      }
    }
    SCOPED_TRACE(name);
    const std::size_t methods = std::string_view(name) == "falling" ? 15 : 16;  // no closed form: no analytic method
    EXPECT_EQ(packed, methods - unpacked_on(name).size());
    EXPECT_GT(diverged, 0u);  // the batch covers every way a run ends
    EXPECT_GT(stopped_low, 0u);
    if (std::string_view(name) == "spring") {
      EXPECT_GT(no_convergence, 0u);
    }
  }
}

TEST(Packs, AWidthThisCpuCannotStepIsRefused) {
  const PairKernel& k = pair_kernel(*find_method("rk4"), spring());
  const Batch b;
  EXPECT_THROW(run_all(k, b.runs, 3), std::invalid_argument);
  if (!cpu_has_width(8)) {
    EXPECT_THROW(run_all(k, b.runs, 8), std::invalid_argument);
  }
}

// The studies that batch their runs: the same map, damping sweep and convergence records at
// every width.
TEST(Packs, StudiesGiveTheSameNumbersAtEveryWidth) {
  StabilityConfig s;
  s.params = {1.0, 5.0, 0.1, 5.0, 9.81};
  s.methods = {*find_method("explicit_euler"), *find_method("rk4"), *find_method("adams_bashforth3"),
               *find_method("implicit_euler")};
  s.map_dt_points = 24, s.map_damping_points = 6, s.map_steps = 2000;
  s.sweep_dampings = {0.0, 0.1, 4.0};
  s.workers.threads = 1;
  ConvergenceConfig c;
  c.scene = spring();
  c.params = default_param_values(spring());
  c.methods = s.methods;
  c.workers.threads = 1;
  s.pack_width = c.pack_width = 1;
  const StabilityMap map1 = stability_map(s);
  const std::vector<SweepRow> sweep1 = damping_sweep(s);
  const ConvergenceResult conv1 = convergence_study(c);
  for (int w : widths_here()) {
    SCOPED_TRACE("width " + std::to_string(w));
    s.pack_width = c.pack_width = w;
    EXPECT_EQ(stability_map(s).stable, map1.stable);
    const std::vector<SweepRow> sweep = damping_sweep(s);
    ASSERT_EQ(sweep.size(), sweep1.size());
    for (std::size_t i = 0; i < sweep.size(); ++i) {
      EXPECT_TRUE(same_bits(sweep[i].run.rate, sweep1[i].run.rate)) << "sweep row " << i;
      EXPECT_TRUE(same_bits(sweep[i].run.error_final, sweep1[i].run.error_final)) << "sweep row " << i;
      EXPECT_EQ(sweep[i].run.steps, sweep1[i].run.steps);
    }
    const ConvergenceResult conv = convergence_study(c);
    ASSERT_EQ(conv.records.size(), conv1.records.size());
    for (std::size_t i = 0; i < conv.records.size(); ++i) {
      EXPECT_TRUE(same_bits(conv.records[i].error_final, conv1.records[i].error_final)) << "record " << i;
      EXPECT_TRUE(same_bits(conv.records[i].error_max, conv1.records[i].error_max)) << "record " << i;
      EXPECT_EQ(conv.records[i].steps, conv1.records[i].steps);
    }
  }
}

}  // namespace
}  // namespace steplab
