// A run of method M that reads a scene's invariants at every step (PairKernel::invariants_run, analysis/kernel/
// kernel.hpp), instantiated by the generated translation units alone (kernel_impl.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "analysis/kernel/kernel.hpp"
#include "core/invariants.hpp"
#include "core/simulate.hpp"
#include "core/stepper.hpp"

namespace steplab {

// Every step's invariants read, their largest distance from the start kept; the state checked
// every step as a run's is (finite, its energy within the blow-up bound of core/simulate.hpp): a
// blow-up ends the run, its samples after it left out.
template <class M, HasInvariants S> InvariantsRun invariants_run(Params p, const InvariantsRunSpec& spec) {
  const S s(p);
  constexpr std::size_t ni = S::invariant_names.size();
  State<S::dim> y = s.initial();
  const std::array<double, ni> i0 = s.invariants(y.x, y.v);
  std::array<double, ni> largest{}, now = i0;
  InvariantsRun out;
  out.invariant0.assign(i0.begin(), i0.end());
  out.largest.assign(ni, {});
  const double e0 = s.energy(y.x, y.v), blow_up = blow_up_energy(s, y, e0);
  Stepper<M, S> stepper;
  if constexpr (TakesSettings<M>) stepper.settings = spec.settings;
  // One step; false where the run ends there (its Newton iteration gave up, or the state is not
  // finite), with its status set.
  const auto step = [&](long long k) {
    if (steplab::failed(stepper.step(s, y, static_cast<double>(k) * spec.dt, spec.dt))) out.status = RunStatus::NoConvergence;
    else if (!all_finite(y) || !within_blow_up(s.energy(y.x, y.v), e0, blow_up)) out.status = RunStatus::Diverged;
    return out.status == RunStatus::Ok;
  };
  long long k = 0;
  for (const long long until : spec.at) {
    for (; k < until && step(k); ++k) {
      now = s.invariants(y.x, y.v);
      for (std::size_t i = 0; i < ni; ++i) largest[i] = std::max(largest[i], std::abs(now[i] - i0[i]));
    }
    out.steps = k;
    if (out.status != RunStatus::Ok) break;
    for (std::size_t i = 0; i < ni; ++i) out.largest[i].push_back(largest[i]);
    if constexpr (HasExact<S>) out.position_error.push_back((y.x - exact(s, static_cast<double>(until) * spec.dt).x).norm());
  }
  out.last.assign(now.begin(), now.end());
  return out;
}

}  // namespace steplab
