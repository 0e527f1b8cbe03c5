// Many independent runs of one method on one kind of scene, stepped together in lanes.
//
// One run is a chain of dependent steps: each waits for the last, and a core that could start
// several instructions a cycle mostly waits. Runs of a study are independent (a stability map
// is 4,096 of them per method), so L of them, each in its own lane, are advanced one step per
// round: the core overlaps L independent chains. A lane whose run has ended (all steps taken,
// diverged, Newton failed, stopped early) hands its result over and takes the next run, so the
// lanes stay full until the runs run out. Each lane holds its own scene (its own parameters),
// step size and status.
//
// Every lane runs the very Run that simulate() runs alone (core/simulate.hpp), the same
// operations in the same order; built with -ffp-contract=off (CMakeLists.txt) no compiler
// clone fuses them differently, so a run's result is the same bit for bit in a lane or alone.
//
// The driver is compiled twice, for plain x86-64 and for AVX2 (GCC's target_clones), and the
// CPU picks at load time: the default build runs anywhere and uses the wider units where they
// exist.
#pragma once

#include <algorithm>
#include <cstddef>
#include <memory>
#include <optional>
#include <utility>

#include "core/simulate.hpp"

namespace steplab {

// The lanes the studies use unless told otherwise (--lanes): one, a run at a time. A lane carries
// its whole run loop with its state in memory, and a run alone already keeps the core busy, so
// on the machine of README.md (Speed: measured there) more lanes made the studies slower; lanes
// that pay need the step and the run loop on packs of lanes (SIMD with per-lane masks).
inline constexpr int kDefaultLanes = 1;
inline constexpr int kMaxLanes = 64;

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__SANITIZE_ADDRESS__)
#define STEPLAB_MULTIVERSION __attribute__((target_clones("avx2", "default")))
#else
#define STEPLAB_MULTIVERSION
#endif
// Everything a round calls inlined into it. Not under AddressSanitizer: there the flattened
// rounds of every method on every scene grow until GCC runs out of memory (convergence.cpp).
#if defined(__GNUC__) && !defined(__SANITIZE_ADDRESS__)
#define STEPLAB_FLATTEN [[gnu::flatten]]
#else
#define STEPLAB_FLATTEN
#endif

// One round: each lane's run takes a step; ended[k] says whether lane k's run has ended.
// Flattened (every call inside inlined: the method's step, the scene's force, the run's
// bookkeeping) so that the lanes' independent work sits side by side for the core to overlap,
// and compiled for plain x86-64 and for AVX2.
template <class Lane>
STEPLAB_FLATTEN STEPLAB_MULTIVERSION std::size_t advance_lanes(Lane* lane, std::size_t count, unsigned char* ended) {
  std::size_t n = 0;
  for (std::size_t k = 0; k < count; ++k) {
    ended[k] = lane[k].run && !lane[k].run->advance();
    n += ended[k];
  }
  return n;
}

// Runs n runs, `lanes` at a time: job(i) returns run i's scene and spec as a
// std::pair<S, RunSpec>, done(i, RunResult<S::dim>&&, const S&) takes its result and the scene
// it ran on (a scene may count what was asked of it), in the order the runs end, which is not
// i's order (done writes slot i, so the output is the same whatever the lanes). Allocates the
// lanes once, before stepping; a run with samples reserves its buffer when it enters a lane.
template <class M, Scene S, class Job, class Done>
void simulate_lanes(std::size_t n, int lanes, Job&& job, Done&& done) {
  struct Lane {
    std::optional<S> scene;
    std::optional<RunResult<S::dim>> result;
    std::optional<Run<M, S>> run;
    std::size_t index = 0;
  };
  const std::size_t count = std::min<std::size_t>(n, static_cast<std::size_t>(std::clamp(lanes, 1, kMaxLanes)));
  const std::unique_ptr<Lane[]> lane(new Lane[count]);
  unsigned char ended[kMaxLanes] = {};
  std::size_t next = 0, active = 0;
  const auto load = [&](Lane& l) {
    l.run.reset();
    l.result.reset();
    l.scene.reset();
    if (next == n) return false;
    auto [scene, spec] = job(next);
    l.index = next++;
    l.run.emplace(l.scene.emplace(std::move(scene)), spec, l.result.emplace());
    return true;
  };
  for (std::size_t k = 0; k < count; ++k) active += load(lane[k]);
  while (active > 0) {
    if (advance_lanes(lane.get(), count, ended) == 0) continue;
    for (std::size_t k = 0; k < count; ++k) {
      if (!ended[k]) continue;
      lane[k].run->finish();
      done(lane[k].index, std::move(*lane[k].result), *lane[k].scene);
      if (!load(lane[k])) --active;
    }
  }
}

}  // namespace steplab
