// Long-time study: "stable for how long?". A scene with invariants (core/invariants.hpp: Kepler's
// orbit, the swinging spring, a user's) run for `periods` of its period at each step, every
// method; per run, on log-spaced times from one period on:
//   each invariant's largest relative error |I - I0| / |I0| up to t (every step read)
//   its growth exponent: the least-squares slope of log error against log t from `fit_from`
//             periods on, with its 95 % interval (analysis/fits/fit.hpp). Near 0: bounded (a
//             symplectic method's energy); near 1: a drift linear in t; near 0.5: round-off's
//             random walk. Marked `round_off` where the error at the end is within the level
//             round-off alone reaches, kRoundOff u sqrt(steps) (u = 2^-53, one rounding a step
//             walking at random): there the method's own error is below what double precision
//             resolves, and compensated summation of the updates would be needed to see it
//   on a scene with an exact solution, the position error and its growth exponent (t for the
//             symplectic and symmetric methods, t^2 otherwise: Hairer, Lubich and Wanner, ch. X),
//             fitted while it is below a tenth of the scene's extent, and the time it reaches the
//             extent (the orbit's size: out of phase), interpolated between the samples that
//             bracket it, or extrapolated from the fit when the run ends first (marked)
//   the time it blew up (a state not finite) or its Newton iteration gave up, if it did.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "analysis/kernel/kernel.hpp"
#include "analysis/kernel/parallel.hpp"

namespace steplab {

// Round-off's level, in units of u sqrt(steps): the largest relative invariant error a run of a
// method exact but for its roundings reaches (a step's few roundings of relative size u, each of
// either sign, add up as a random walk). Measured on the angular momentum of Kepler's orbit,
// which the symplectic explicit methods keep exactly but for round-off: 1 to 4 u sqrt(steps)
// (symplectic Euler, velocity Verlet; 10^6 to 10^7 steps), 13 for Yoshida 4 at 100 steps a
// period (its three Verlet substeps round more often, and its growth exponent there, 0.85, is
// nearer a drift than a walk: biased rounding, which compensated summation of the updates
// would remove).
inline constexpr double kRoundOff = 30;

struct LongTimeConfig {
  std::size_t scene = 0;
  std::vector<double> params;          // table order
  std::vector<std::size_t> methods;
  std::vector<int> steps_per_period;   // h = period / each
  double periods = 1e5;                // how long, in periods
  int samples_per_decade = 8;          // log-spaced sample times from one period
  double fit_from = 10;                // periods: the fits start here
  MethodSettings settings{};
  Workers workers;
};

struct GrowthFit {
  bool fitted = false;  // at least three samples to fit
  double exponent = 0, lo = 0, hi = 0;  // slope and its 95 % interval
};

struct LongTimeRow {
  std::size_t method = 0;
  int steps_per_period = 0;
  double dt = 0;
  RunStatus status = RunStatus::Ok;
  double ended = 0;                                // periods run with a finite state
  std::vector<double> times;                       // periods, the samples reached
  std::vector<std::vector<double>> error;          // [invariant][k]: largest relative error up to times[k]
  std::vector<GrowthFit> growth;                      // [invariant]
  std::vector<char> round_off;                     // [invariant]: its final error within round-off's level
  std::vector<double> change;                      // [invariant]: (I - I0) / |I0| at the last step, signed
  std::vector<double> position_error;              // [k]; empty without an exact solution
  GrowthFit position_growth;
  double out_of_phase = 0;                         // periods to reach the extent; 0: not known
  bool out_of_phase_extrapolated = false;
};

// A row crosses a shard as bytes (analysis/kernel/shard.hpp).
template <class F> void encode_fields(LongTimeRow& r, F&& f) {
  f(r.method), f(r.steps_per_period), f(r.dt), f(r.status), f(r.ended), f(r.times), f(r.error), f(r.growth), f(r.round_off);
  f(r.change), f(r.position_error), f(r.position_growth), f(r.out_of_phase), f(r.out_of_phase_extrapolated);
}

struct LongTimeResult {
  LongTimeConfig config;
  std::vector<std::string> invariants;
  double period = 0, extent = 0;
  bool has_exact = false;
  std::vector<LongTimeRow> rows;  // method-major, then steps_per_period
};

// The methods of the study by default: one of each structure per family where it has one, the
// ODE methods that apply to the scene (analysis/kernel/kernel.hpp, in_ode_studies).
// Its steps a period: analysis/studies/defaults.hpp, kLongTimeStepsPerPeriod.
LongTimeConfig default_long_time_config(std::size_t scene);
LongTimeResult long_time_study(const LongTimeConfig& c);

// Whether a growth is bounded (its interval below 0.5: neither a drift nor a random walk) or a
// drift (its interval above 0.5).
inline bool bounded(const GrowthFit& g) { return g.fitted && g.hi < 0.5; }
inline bool drifts(const GrowthFit& g) { return g.fitted && g.lo > 0.5; }

// A run's energy error (its first invariant's) over the whole run: Lost where the run ended (a
// blow-up, a Newton iteration that gave up) or the error reached `lost_at` (an orbit that escaped
// or fell in has an error that stops growing too, which would read as bounded); else Bounded (its
// growth's interval below 0.5, or within round-off), Drifting (above 0.5) or Unclear (across 0.5).
// `steplab check`'s symplectic claim and the report's sentences read it alike.
enum class EnergyVerdict { Bounded, Drifting, Unclear, Lost };
inline EnergyVerdict energy_verdict(const LongTimeRow& r, double lost_at) {
  if (r.status != RunStatus::Ok || r.error.empty() || r.error[0].empty() || !(r.error[0].back() < lost_at)) return EnergyVerdict::Lost;
  if (bounded(r.growth[0]) || r.round_off[0]) return EnergyVerdict::Bounded;
  return drifts(r.growth[0]) ? EnergyVerdict::Drifting : EnergyVerdict::Unclear;
}

}  // namespace steplab
