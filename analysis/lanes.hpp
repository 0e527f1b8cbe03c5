// Runs of one method, chosen at run time, on scenes of one type: one at a time (lanes <= 1, the
// scalar path: simulate) or stepped together in lanes (core/lanes.hpp). The results are the
// same bit for bit; lanes only change how fast they come.
#pragma once

#include <cstddef>

#include "core/lanes.hpp"
#include "core/methods.hpp"

namespace steplab {

// job(i) -> std::pair<S, RunSpec>, done(i, RunResult<S::dim>&&, const S& scene) for i in [0, n). A method that
// does not apply to S (the exact flow on a scene without one) runs nothing.
template <Scene S, class Job, class Done>
void run_batch(std::size_t method, std::size_t n, int lanes, Job&& job, Done&& done) {
  with_method(method, [&]<class M>() {
    if constexpr (applies<M, S>()) {
      if (lanes <= 1) {
        for (std::size_t i = 0; i < n; ++i) {
          const auto [scene, spec] = job(i);
          done(i, simulate<M>(scene, spec), scene);
        }
      } else {
        simulate_lanes<M, S>(n, lanes, job, done);
      }
    }
  });
}

}  // namespace steplab
