#include "analysis/studies/check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/studies/convergence.hpp"
#include "analysis/studies/defaults.hpp"
#include "analysis/studies/long_time.hpp"
#include "analysis/kernel/kernel.hpp"
#include "core/scenes/cannonball.hpp"
#include "core/scenes/target.hpp"
#include "core/scenes/spring.hpp"

namespace steplab {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

template <class S>
OrderCheck order_check(std::size_t method, const MethodInfo& claims, const Workers& workers, double stiffness = 0) {
  ConvergenceConfig c;
  c.scene = scene_index(S::name);
  c.params = default_param_values(c.scene);
  if (stiffness > 0) c.params[static_cast<std::size_t>(stiffness_param_index<S>())] = stiffness;
  c.methods = {method};
  c.workers = workers;
  const ConvergenceResult r = convergence_study(c);
  const ConvergenceRecord& fine = r.records.back();
  OrderCheck o{S::name, r.fits.front().fit, fine.dt, kInf, fine.dt, fine.error_final, false, false, false};
  for (const ConvergenceRecord& rec : r.records)  // by decreasing dt
    if (std::isfinite(rec.error_final)) {
      o.dt_coarse = rec.dt;
      o.error_coarse = rec.error_final;
      break;
    }
  o.at_roundoff = fine.error_final <= fine.floor;
  o.converges = o.at_roundoff || o.error_fine <= kConvergedRatio * o.error_coarse;
  if (claims.order == 0) o.order_holds = o.fit.exact;  // the exact flow
  else if (o.fit.exact) o.order_holds = claims.order >= 2;
  else o.order_holds = o.fit.fitted && std::abs(o.fit.order - claims.order) <= kOrderTolerance;
  return o;
}

EnergyCheck energy_check(std::size_t method, const MethodInfo& claims) {
  const Spring s = linear_spring(default_param_values<Spring>(), 0);
  EnergyCheck e{kDriftOmegaH / s.omega(), kDriftSteps, kInf, false, false};
  const RateRun run = measure_rate(method, s, e.h, e.steps);
  if (run.status == RunStatus::Ok) e.drift = std::isnan(run.rate) ? -kInf : run.rate * e.h * static_cast<double>(e.steps);
  e.bounded = std::abs(e.drift) <= kDriftBound;
  e.holds = e.bounded == claims.symplectic;
  return e;
}

OrbitCheck orbit_check(std::size_t method, const MethodInfo& claims, const Workers& workers) {
  OrbitCheck o;
  const auto kepler = find_scene(kLongTimeScene);
  if (!kepler || !applies(method, *kepler)) return o;
  LongTimeConfig c = default_long_time_config(*kepler);
  c.methods = {method};
  c.steps_per_period = {kOrbitStepsPerPeriod};
  c.periods = kOrbitPeriods;
  c.workers = workers;
  const LongTimeRow r = long_time_study(c).rows.front();
  o.ran = true;
  o.bounded = energy_verdict(r, kOrbitKept) == EnergyVerdict::Bounded;
  if (r.status == RunStatus::Ok && !r.error.empty() && !r.error[0].empty()) {
    const GrowthFit& g = r.growth[0];
    o.fitted = g.fitted, o.growth = g.exponent, o.lo = g.lo, o.hi = g.hi;
    o.round_off = r.round_off[0] != 0;
    o.error = r.error[0].back();
  } else {
    o.error = kInf;
  }
  o.holds = o.bounded == claims.symplectic;
  return o;
}

bool close(double measured, double predicted) {
  if (std::isinf(measured) || std::isinf(predicted) || predicted == 0) return measured == predicted;
  return std::abs(measured - predicted) <= kStableAgreement * predicted;
}

// From rest at equilibrium, kRestSteps steps with the method's own memory and start-up.
RestCheck rest_check(std::size_t method, const Spring& s) {
  const double y_eq = s.equilibrium(), h = 0.1 / s.omega();
  std::array<double, kRestSteps> x{}, v{};
  const StepStatus st = spring_kernel(method).steps_from(s.values(), y_eq, 0.0, h, kRestSteps, x.data(), v.data());
  double worst = 0;
  for (int i = 0; i < kRestSteps; ++i) worst = std::max({worst, std::abs(x[i] - y_eq), std::abs(v[i]) / s.omega()});
  if (st != StepStatus::Ok) worst = kInf;  // a failed step: no rest
  const double deviation = std::isnan(worst) ? kInf : worst / std::abs(y_eq);
  return {h, deviation, deviation <= kRestTolerance};
}

}  // namespace

bool CheckResult::all_hold() const {
  bool ok = energy.holds && orbit.holds && a_stable_holds && rest.holds;
  // A method that does not converge (PBD) claims no order, and its rest is not the scene's
  // equilibrium, about which dt* is predicted: those are not compared.
  for (const OrderCheck& o : orders) ok = ok && (claims.converges ? o.order_holds && o.converges : !o.converges);
  if (claims.converges)
    for (const StabilityCheck& st : stability) ok = ok && st.agrees;
  return ok;
}

CheckResult check_method(std::size_t method, const MethodInfo& claims, const Workers& workers) {
  CheckResult r;
  r.method = method;
  r.claims = claims;
  // on the scenes the method runs on (a method on springs: not the cannon ball, not the target)
  r.orders.push_back(order_check<Spring>(method, claims, workers));
  if (applies(method, scene_index(Cannonball::name))) r.orders.push_back(order_check<Cannonball>(method, claims, workers));
  if (applies(method, scene_index(Target::name)))
    r.orders.push_back(order_check<Target>(method, claims, workers, kTargetStiffness));
  r.energy = energy_check(method, claims);
  r.orbit = orbit_check(method, claims, workers);

  StabilityConfig c;
  c.params = default_param_values(scene_index(Spring::name));
  c.methods = {method};
  c.threshold_dampings.assign(std::begin(kCheckDampings), std::end(kCheckDampings));
  c.workers = workers;
  bool all_infinite = true;
  for (const ThresholdRow& row : threshold_study(c)) {
    const StableSet predicted{row.dt_theory, row.again_theory}, measured{row.dt_measured, row.again_measured};
    r.stability.push_back({row.damping, predicted, measured,
                           close(measured.dt_star, predicted.dt_star) && close(measured.again, predicted.again)});
    all_infinite = all_infinite && std::isinf(predicted.dt_star) && std::isinf(measured.dt_star);
  }
  r.a_stable_holds = all_infinite == claims.a_stable;

  r.rest = rest_check(method, make_default_scene<Spring>());
  if (!claims.converges) r.rest.holds = !r.rest.holds;  // PBD rests elsewhere: it leaves the scene's equilibrium
  return r;
}

}  // namespace steplab
