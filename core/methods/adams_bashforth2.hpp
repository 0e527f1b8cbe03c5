#pragma once
#include "core/linear_multistep.hpp"

namespace steplab {

// Two-step Adams-Bashforth, order 2 (core/linear_multistep.hpp):
//   y_{n+1} = y_n + h (3/2 f_n - 1/2 f_{n-1})
// One force evaluation a step. Stability: |rho| <= 1 only for h lambda in a bounded region
// touching the imaginary axis at 0 alone: an undamped oscillator grows at every step.
struct AdamsBashforth2 : AdamsBashforthMethod<std::array{3.0 / 2, -1.0 / 2}> {
  static constexpr MethodInfo info{.name = "adams_bashforth2", .order = 2, .family = Family::AdamsBashforth,
                                   .summary = "y += h (3/2 f_n - 1/2 f_(n-1)), started by RK4"};
};

}  // namespace steplab

STEPLAB_METHOD(steplab::AdamsBashforth2);
