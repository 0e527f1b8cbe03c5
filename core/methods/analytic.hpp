#pragma once
#include "core/method.hpp"

namespace steplab {

// The exact flow: y_{n+1} = Phi_h(y_n), for scenes that have one (HasExact). The baseline
// every other method is compared with; error only from round-off.
struct Analytic {
  static constexpr MethodInfo info{.name = "analytic", .order = 0, .family = Family::Exact,
                                   .symplectic = true, .a_stable = true, .exact_flow = true,
                                   .summary = "the scene's exact solution"};
  template <HasExact S> static StepStatus step(const S& s, State<S::dim>& y, double /*t*/, double h) {
    y = s.flow(y, h);
    return StepStatus::Ok;
  }
};

}  // namespace steplab

STEPLAB_METHOD(steplab::Analytic);
