// steplab's CVODE peer against the same CVODE called from plain C (bench/cvode_rope.c), on the
// rope of N masses with the same settings: cvode_rope/steplab/<family>/<N> and
// cvode_rope/plain_c/<family>/<N>. An iteration is one whole run (CVODE's set-up and clean-up
// included in both, the rope made outside in steplab's). Both rows report CVODE's counts as
// counters: equal counts show that the two solve the same problem the same way, and the time
// ratio is what steplab's wrapper (its right side through Eigen, the scene's Jacobians) costs.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>

#include "analysis/kernel/kernel.hpp"
#include "analysis/peers/peers.hpp"
#include "analysis/peers/sized_peers.hpp"
#include "cvode_rope.h"

namespace {

using namespace steplab;

// The rope's size and the tolerance: near where `study scaling --scene rope --sizes 1024` finds
// the peers reaching error 1e-4.
constexpr int kMasses = 1024;
constexpr double kTol = 1e-5, kEnd = 2;

void counters(benchmark::State& st, long long steps, long long forces, long long jacobians, long long setups) {
  st.counters["steps"] = static_cast<double>(steps);
  st.counters["forces"] = static_cast<double>(forces);
  st.counters["jacobians"] = static_cast<double>(jacobians);
  st.counters["factorisations"] = static_cast<double>(setups);
}

}  // namespace

void register_peers() {
  for (const bool adams : {true, false}) {  // Adams; BDF of orders 1-2 (a second's run, not BDF 1-5's 2.5 s)
    const std::string family = adams ? "adams" : "bdf_max2", size = std::to_string(kMasses);
    benchmark::RegisterBenchmark(("cvode_rope/steplab/" + family + "/" + size).c_str(), [adams](benchmark::State& st) {
      const SceneKernel& rope = scene_kernel(*find_scene("rope"));
      std::vector<double> p = default_values(rope.params);
      p[rope.size_param] = kMasses;
      const std::shared_ptr<const void> made = rope.make(p);  // outside the timed region, as the study times it
      const PeerInfo& peer = *find_peer(adams ? "cvode_adams_band" : "cvode_bdf_max2_band");
      PeerCounts n;
      for (auto _ : st) benchmark::DoNotOptimize(run_sized_peer(peer, rope, made.get(), kTol, kEnd, n));
      counters(st, n.steps, n.forces, n.jacobians, n.factorisations);
    })->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("cvode_rope/plain_c/" + family + "/" + size).c_str(), [adams](benchmark::State& st) {
      cvode_rope_counts c{};
      for (auto _ : st) benchmark::DoNotOptimize(cvode_rope_run(kMasses, kTol, kEnd, {adams, adams ? 0 : 2, 0, 0, 0}, &c, nullptr));
      counters(st, c.steps, c.rhs, c.jacobians, c.setups);
    })->Unit(benchmark::kMillisecond);
  }
}

std::string peer_ratio_lines(const std::map<std::string, double>& t) {
  std::string out;
  for (const char* family : {"adams", "bdf_max2"}) {
    const std::string tail = std::string(family) + "/" + std::to_string(kMasses);
    const auto a = t.find("cvode_rope/steplab/" + tail), b = t.find("cvode_rope/plain_c/" + tail);
    if (a == t.end() || b == t.end()) continue;
    char line[200];
    std::snprintf(line, sizeof line, "CVODE %s on the rope of %d masses, one run: steplab's peer %.1f ms, plain C %.1f ms, ratio %.3f\n",
                  family, kMasses, a->second, b->second, a->second / b->second);  // the rows' unit: ms
    out += line;
  }
  return out;
}
