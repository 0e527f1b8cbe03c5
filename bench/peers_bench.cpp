// steplab's CVODE peer against the same CVODE called from plain C (bench/cvode_rope.c), on the
// rope of N masses with the same settings: cvode_rope/steplab/<family>/<N> and
// cvode_rope/plain_c/<family>/<N>. An iteration is one whole run (CVODE's set-up and clean-up
// included in both, the rope made outside in steplab's). Both rows report CVODE's counts as
// counters: equal counts show that the two solve the same problem the same way, and the time
// ratio is what steplab's wrapper (its right side through Eigen, the scene's Jacobians) costs.
// The same for RADAU5 on the stiff chain against bench/radau5_chain.c: radau5_chain/steplab/<tol>
// and radau5_chain/plain_c/<tol>, at tol 1e-4 and 1e-8.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>

#include "analysis/kernel/kernel.hpp"
#include "analysis/peers/peers.hpp"
#include "analysis/peers/sized_peers.hpp"
#include "cvode_rope.h"
#if STEPLAB_HAVE_RADAU5
#include "analysis/peers/fixed_peers.hpp"
#include "core/scenes/chain.hpp"
#include "radau5_chain.h"
#endif

namespace {

using namespace steplab;

// The rope's size and the tolerance: near where `study scaling --scene rope --sizes 1024` finds
// the peers reaching error 1e-4.
constexpr int kMasses = 1024;
constexpr double kTol = 1e-5, kEnd = 2;
constexpr double kChainTols[] = {1e-4, 1e-8};
constexpr double kChainEnd = 10;

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
#if STEPLAB_HAVE_RADAU5
  for (const double tol : kChainTols) {
    char name[64];
    std::snprintf(name, sizeof name, "radau5_chain/steplab/%g", tol);
    benchmark::RegisterBenchmark(name, [tol](benchmark::State& st) {
      const std::vector<double> p = default_values(scene_kernel(*find_scene("chain")).params);
      const Chain chain(p);  // made outside the timed region, as the rope above (its exact flow's eigenvectors)
      PeerCounts n;
      for (auto _ : st) benchmark::DoNotOptimize(Radau5Fixed<Chain>::run(chain, tol, kChainEnd, n));
      counters(st, n.steps, n.forces, n.jacobians, n.factorisations);
    })->Unit(benchmark::kMicrosecond);
    std::snprintf(name, sizeof name, "radau5_chain/plain_c/%g", tol);
    benchmark::RegisterBenchmark(name, [tol](benchmark::State& st) {
      radau5_chain_counts c{};
      double z[4];
      for (auto _ : st) radau5_chain_run(tol, kChainEnd, &c, z), benchmark::DoNotOptimize(z);
      counters(st, c.accepted, c.rhs, c.jacobians, c.decompositions);
    })->Unit(benchmark::kMicrosecond);
  }
#endif
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
  for (const double tol : kChainTols) {
    char a_name[64], b_name[64];
    std::snprintf(a_name, sizeof a_name, "radau5_chain/steplab/%g", tol);
    std::snprintf(b_name, sizeof b_name, "radau5_chain/plain_c/%g", tol);
    const auto a = t.find(a_name), b = t.find(b_name);
    if (a == t.end() || b == t.end()) continue;
    char line[200];
    std::snprintf(line, sizeof line, "RADAU5 on the chain at tol %g, one run: steplab's peer %.1f us, plain C %.1f us, ratio %.3f\n",
                  tol, a->second, b->second, a->second / b->second);  // the rows' unit: us
    out += line;
  }
  return out;
}
