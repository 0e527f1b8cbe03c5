#pragma once
#include "core/method.hpp"

namespace steplab {

// The exact flow: y_{n+1} = Phi_h(y_n), for scenes that have one (HasExact). The baseline
// every other method is compared with; error only from round-off.
struct Analytic {
  static constexpr MethodInfo info{.name = "analytic", .order = 0, .family = Family::Exact,
                                   .symplectic = true, .a_stable = true, .exact_flow = true,
                                   .summary = "the scene's exact solution"};
  // A driven scene's exact solution is known from its initial state (exact_at): a run of the
  // exact flow starts there.
  template <HasExact S> static StepStatus step(const S& s, State<S::dim>& y, double t, double h) {
    if constexpr (Driven<S>) y = s.exact_at(t + h);
    else if constexpr (requires { s.advance(y, h); }) s.advance(y, h);  // the flow in place (the rope: no allocation)
    else y = s.flow(y, h);
    return StepStatus::Ok;
  }
};

}  // namespace steplab

STEPLAB_METHOD(steplab::Analytic);
