#include "analysis/studies/local_error.hpp"

#include <cmath>
#include <limits>

#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/stability.hpp"
#include "core/scenes/spring.hpp"

namespace steplab {

LocalErrorResult local_error_study(const LocalErrorConfig& c) {
  LocalErrorResult out;
  out.config = c;
  const Spring s(c.params);
  const State<1> start = exact(s, c.t0);
  for (int i = 0; i < c.count; ++i) {
    const double h = c.step / std::pow(2.0, i);
    out.steps.push_back(h);
    const State<1> e = s.flow(start, h);
    out.exact_dv.push_back(e.v[0] - start.v[0]);
    out.exact_dx.push_back(e.x[0] - start.x[0]);
  }
  // One step from an O(1) state: round-off of about an ulp of the state.
  const double floor = 4 * std::numeric_limits<double>::epsilon() * std::max({1.0, std::abs(start.x[0]), std::abs(start.v[0])});
  for (std::size_t m : c.methods) {
    LocalErrorColumn col{m, {}, {}, {}, {}};
    std::vector<ErrorPoint> pts;
    for (int i = 0; i < c.count; ++i) {
      AnyState y;
      const double h = out.steps[i];
      // from the exact state at t0; a multistep method remembers the exact past: y(t0 - k h)
      const StepStatus st = spring_kernel(m).exact_step(c.params, c.t0, h, y);
      col.dv.push_back(y.v[0] - start.v[0]);
      col.dx.push_back(y.x[0] - start.x[0]);
      const double ex = col.dx.back() - out.exact_dx[i], ev = col.dv.back() - out.exact_dv[i];
      col.error.push_back(std::hypot(ex, ev));
      pts.push_back({out.steps[i], col.error.back(), floor, st != StepStatus::Ok || !all_finite(y)});
    }
    col.order = fit_order(pts);
    out.columns.push_back(std::move(col));
  }
  return out;
}

}  // namespace steplab
