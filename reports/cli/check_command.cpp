// `steplab check --method NAME`: one line per claim of the method's row, with the figures and
// PASS or FAIL (analysis/studies/check.hpp says what is measured and why each tolerance). Exit status 0
// when every claim holds, 1 when one fails, 2 for bad input.
#include "reports/cli/check_command.hpp"

#include <cmath>
#include <cstdio>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/defaults.hpp"
#include "reports/cli/commands.hpp"
#include "reports/data/inputs.hpp"

namespace steplab {
namespace {

std::string dt_text(double dt) {
  if (std::isinf(dt)) return "unbounded";
  return fmt::format("{:.4g}", dt);
}

void order_lines(std::vector<ClaimLine>& out, const OrderCheck& o, const MethodInfo& claims) {
  if (!claims.converges) {  // no order claimed (PBD): that it does not converge is the claim
    out.push_back({!o.converges, fmt::format("does not converge on the {}: error {:.3g} at dt {:.3g}, {:.3g} at dt {:.3g} "
                                             "(converging means <= {} x)",
                                             o.scene, o.error_coarse, o.dt_coarse, o.error_fine, o.dt_fine, kConvergedRatio)});
    return;
  }
  std::string text;
  if (claims.order == 0)
    text = fmt::format("exact flow on the {}: {}", o.scene,
                       o.fit.exact ? "error at round-off for every dt" : "error above round-off");
  else if (o.fit.exact)
    text = fmt::format("order {} on the {}: error at round-off for every dt (a quadratic in t, exact for order >= 2)",
                       claims.order, o.scene);
  else if (o.fit.fitted)
    text = fmt::format("order {} on the {}: fitted {:.3f} [{:.3f}, {:.3f}] over dt {:.3g} .. {:.3g} (within {})",
                       claims.order, o.scene, o.fit.order, o.fit.bound_lo, o.fit.bound_hi, o.fit.dt_lo, o.fit.dt_hi,
                       kOrderTolerance);
  else
    text = fmt::format("order {} on the {}: no order could be fitted ({})", claims.order, o.scene, o.fit.note);
  out.push_back({o.order_holds, text});
  out.push_back({o.converges, fmt::format("converges on the {}: error {:.3g} at dt {:.3g}, {:.3g} at dt {:.3g}{}",
                                       o.scene, o.error_coarse, o.dt_coarse, o.error_fine, o.dt_fine,
                                       o.at_roundoff ? " (round-off)" : fmt::format(" (<= {} x)", kConvergedRatio))});
}

ClaimLine energy_line(const EnergyCheck& e, const MethodInfo& claims) {
  const std::string change = std::isinf(e.drift) ? (e.drift > 0 ? "blows up" : "decays to nothing")
                                                 : fmt::format("changes by {:.3g} in ln E", e.drift);
  return {e.holds, fmt::format("{}: energy {} over {} steps of omega h = {} on the undamped spring: {} "
                               "(bounded means |change| <= {})",
                               claims.symplectic ? "symplectic" : "not symplectic", change, e.steps, kDriftOmegaH,
                               e.bounded ? "bounded" : "drifts", kDriftBound)};
}

ClaimLine orbit_line(const OrbitCheck& o, const MethodInfo& claims) {
  const std::string growth = o.fitted ? fmt::format("grows as t^{:.2f} [{:.2f}, {:.2f}]", o.growth, o.lo, o.hi) : "has no fitted growth";
  return {o.holds, fmt::format("{}: on {} over {:g} periods of {} steps the energy error {}, largest {}{}: {} "
                               "(bounded means the interval below 0.5 or round-off, and the orbit kept: error < {})",
                               claims.symplectic ? "symplectic" : "not symplectic", scene_kernel(*find_scene(kLongTimeScene)).title, kOrbitPeriods,
                               kOrbitStepsPerPeriod, growth,
                               std::isinf(o.error) ? "- it blew up" : fmt::format("{:.3g}", o.error), o.round_off ? " (round-off)" : "",
                               o.bounded ? "bounded" : "not bounded", kOrbitKept)};
}

void stability_lines(std::vector<ClaimLine>& out, const CheckResult& r) {
  std::string pairs;
  for (const StabilityCheck& s : r.stability)
    pairs += fmt::format("{}{} at damping {}", pairs.empty() ? "" : ", ", dt_text(s.measured.dt_star), s.damping);
  out.push_back({r.a_stable_holds, fmt::format("{}: dt* on the spring {}", r.claims.a_stable ? "A-stable" : "not A-stable", pairs)});
  if (!r.claims.converges) return;  // its rest is not the scene's equilibrium: no linear prediction there
  for (const StabilityCheck& s : r.stability) {
    std::string again;
    if (std::isfinite(s.predicted.again) || std::isfinite(s.measured.again))
      again = fmt::format("; stable again from {} / {}", dt_text(s.predicted.again), dt_text(s.measured.again));
    out.push_back({s.agrees, fmt::format("dt* at damping {}: predicted {}, measured {}{} (within {:g} %)", s.damping,
                                         dt_text(s.predicted.dt_star), dt_text(s.measured.dt_star), again,
                                         100 * kStableAgreement)});
  }
}

}  // namespace

std::vector<ClaimLine> check_lines(const CheckResult& r) {
  std::vector<ClaimLine> out;
  for (const OrderCheck& o : r.orders) order_lines(out, o, r.claims);
  out.push_back(energy_line(r.energy, r.claims));
  if (r.orbit.ran) out.push_back(orbit_line(r.orbit, r.claims));
  stability_lines(out, r);
  out.push_back({r.rest.holds, fmt::format("rest at equilibrium {}: {} steps of h = {:.3g} move it by {:.2g} "
                                           "of |y_eq| (<= {})",
                                           r.claims.converges ? "stays there" : "is not its rest (it leaves)",
                                           kRestSteps, r.rest.h, r.rest.deviation, kRestTolerance)});
  return out;
}

std::string check_text(const CheckResult& r) {
  const MethodInfo& c = r.claims;
  std::string out = fmt::format("steplab check {}: {}, order {}, {}, {}, {}\n", c.name, to_string(c.family), c.order,
                                c.symplectic ? "symplectic" : "not symplectic", c.implicit ? "implicit" : "explicit",
                                c.a_stable ? "A-stable" : "not A-stable");
  const std::vector<ClaimLine> lines = check_lines(r);
  std::size_t failed = 0;
  for (const ClaimLine& l : lines) {
    out += fmt::format("{}  {}\n", l.holds ? "PASS" : "FAIL", l.text);
    failed += !l.holds;
  }
  out += failed == 0 ? fmt::format("all {} claims hold\n", lines.size())
                     : fmt::format("{} of {} claims fail\n", failed, lines.size());
  return out;
}

int check_command(CheckArgs& a, Context& ctx) {
  if (a.method.empty()) throw UsageError(fmt::format("--method is required; accepted: {}", method_names()));
  const std::size_t method = resolve_method(a.method);
  const Workers workers = ctx.workers(resolve_thread_count(a.threads));
  if (ctx.stop_after_validation("")) return 0;
  const CheckResult r = check_method(method, method_info(method), workers);
  std::fputs(check_text(r).c_str(), stdout);
  return r.all_hold() ? 0 : 1;
}

}  // namespace steplab
