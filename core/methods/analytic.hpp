#pragma once
#include "core/method.hpp"

namespace steplab {

// The exact flow: y_{n+1} = Phi_h(y_n), for scenes that have one (HasExact). The baseline
// every other method is compared with; error only from round-off.
struct Analytic {
  static constexpr MethodInfo info{"analytic", 0, Family::Exact, true, false, true, "the scene's exact solution"};
  template <HasExact S> static StepStatus step(const S& s, State<S::dim>& y, double /*t*/, double h) {
    y = s.flow(y, h);
    return StepStatus::Ok;
  }
};

}  // namespace steplab
