#pragma once
#include "core/linear_multistep.hpp"

namespace steplab {

// Three-step Adams-Bashforth, order 3 (core/linear_multistep.hpp):
//   y_{n+1} = y_n + h (23/12 f_n - 16/12 f_{n-1} + 5/12 f_{n-2})
// One force evaluation a step. Its stability region holds a piece of the imaginary axis,
// |Im h lambda| < ~0.72, so unlike AB2 it keeps an undamped oscillator bounded at small steps.
struct AdamsBashforth3 : AdamsBashforthMethod<std::array{23.0 / 12, -16.0 / 12, 5.0 / 12}> {
  static constexpr MethodInfo info{.name = "adams_bashforth3", .order = 3, .family = Family::AdamsBashforth,
                                   .summary = "y += h (23 f_n - 16 f_(n-1) + 5 f_(n-2)) / 12, started by RK4"};
};

}  // namespace steplab

STEPLAB_METHOD(steplab::AdamsBashforth3);
