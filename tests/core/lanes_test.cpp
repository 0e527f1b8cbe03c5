// Runs in lanes (core/lanes.hpp) give what the same runs give one at a time, bit for bit, for
// every method on three scenes (1, 4 and 6 coordinates; the JSON of every study with lanes is
// compared on the others in tests/reports/determinism_test.cpp): 7 runs through 3 lanes, each
// with its own step, length and stop rule, some ending early (diverged or stopped) while the
// others go on. Three scenes, not six: under AddressSanitizer this file takes minutes to compile.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <vector>

#include "core/lanes.hpp"
#include "core/methods.hpp"
#include "core/scenes.hpp"

namespace steplab {
namespace {

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

template <int D> void expect_same(const RunResult<D>& a, const RunResult<D>& b, const std::string& what) {
  EXPECT_EQ(a.status, b.status) << what;
  EXPECT_EQ(a.steps, b.steps) << what;
  EXPECT_EQ(a.failed_step, b.failed_step) << what;
  EXPECT_EQ(a.has_exact, b.has_exact) << what;
  const std::vector<double> da{a.failed_t, a.t_final, a.error_final, a.error_max, a.error_rms, a.error_v_final,
                               a.energy0, a.energy_ratio_final, a.energy_ratio_max, a.energy_rate};
  const std::vector<double> db{b.failed_t, b.t_final, b.error_final, b.error_max, b.error_rms, b.error_v_final,
                               b.energy0, b.energy_ratio_final, b.energy_ratio_max, b.energy_rate};
  for (std::size_t i = 0; i < da.size(); ++i) EXPECT_EQ(bits(da[i]), bits(db[i])) << what << " field " << i;
  for (int k = 0; k < D; ++k) {
    EXPECT_EQ(bits(a.final.x[k]), bits(b.final.x[k])) << what;
    EXPECT_EQ(bits(a.final.v[k]), bits(b.final.v[k])) << what;
  }
  ASSERT_EQ(a.samples.size(), b.samples.size()) << what;
  for (std::size_t i = 0; i < a.samples.size(); ++i) EXPECT_EQ(bits(a.samples[i].energy), bits(b.samples[i].energy)) << what;
}

// Run i of 7: steps from 0.3x to 40x the base step, 150 .. 450 steps; the last two with large
// steps and an energy bound, so that explicit methods end early there (Diverged) while their
// lanes' neighbours run on.
RunSpec spec_of(std::size_t i) {
  constexpr double factors[] = {1, 0.3, 2.5, 1.7, 0.6, 15, 40};
  RunSpec spec;
  spec.dt = 0.004 * factors[i];
  spec.steps = 150 + 50 * static_cast<long long>(i);
  spec.energy_rate = true;
  spec.max_samples = i % 2 ? 0 : 17;
  if (i >= 5) spec.stop_above = 1e3;
  return spec;
}

using LaneScenes = std::tuple<Spring, Chain, Falling>;

TEST(Lanes, EveryMethodOnThreeScenesGivesTheSameBitsAsOneRunAtATime) {
  constexpr std::size_t n = 7;
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (([&]<class S>() {
       const S scene = make_default_scene<S>();
       [&]<std::size_t... J>(std::index_sequence<J...>) {
         (([&]<class M>() {
            if constexpr (applies<M, S>()) {
              std::vector<RunResult<S::dim>> alone, laned(n);
              for (std::size_t i = 0; i < n; ++i) alone.push_back(simulate<M>(scene, spec_of(i)));
              std::vector<int> calls(n, 0);
              simulate_lanes<M, S>(
                  n, 3, [&](std::size_t i) { return std::pair(scene, spec_of(i)); },
                  [&](std::size_t i, RunResult<S::dim>&& r, const S&) {
                    ++calls[i];
                    laned[i] = std::move(r);
                  });
              for (std::size_t i = 0; i < n; ++i) {
                EXPECT_EQ(calls[i], 1);
                expect_same(laned[i], alone[i], std::string(S::name) + " " + std::string(M::info.name) + " run " + std::to_string(i));
              }
            }
          }.template operator()<std::tuple_element_t<J, Methods>>()),
          ...);
       }(std::make_index_sequence<method_count>{});
     }.template operator()<std::tuple_element_t<I, LaneScenes>>()),
     ...);
  }(std::make_index_sequence<std::tuple_size_v<LaneScenes>>{});
}

// A lane's end is its own: explicit Euler on the undamped spring grows at every step, so the
// run at 40x the step passes the energy bound within a few dozen steps and ends Diverged while
// the run at the base step, in the next lane, completes all its steps.
TEST(Lanes, OneLaneDivergingEndsThatLaneOnly) {
  std::vector<double> p = default_param_values<Spring>();
  p[2] = 0;  // undamped
  const Spring s(p);
  std::vector<RunResult<1>> out(2);
  simulate_lanes<ExplicitEuler, Spring>(
      2, 2, [&](std::size_t i) { return std::pair(s, spec_of(i == 0 ? 6 : 0)); },
      [&](std::size_t i, RunResult<1>&& r, const Spring&) { out[i] = std::move(r); });
  EXPECT_EQ(out[0].status, RunStatus::Diverged);
  EXPECT_LT(out[0].steps, spec_of(6).steps);
  EXPECT_EQ(out[1].status, RunStatus::Ok);
  EXPECT_EQ(out[1].steps, spec_of(0).steps);
}

}  // namespace
}  // namespace steplab
