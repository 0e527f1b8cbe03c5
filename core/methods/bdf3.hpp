#pragma once
#include "core/linear_multistep.hpp"

namespace steplab {

// Third-order backward differentiation formula (core/linear_multistep.hpp):
//   y_{n+1} - 18/11 y_n + 9/11 y_{n-1} - 2/11 y_{n-2} = 6/11 h f(y_{n+1}):
//   w = 18/11 y_n - 9/11 y_{n-1} + 2/11 y_{n-2},  beta = 6/11
// Not A-stable (A(alpha)-stable with alpha ~ 86 degrees): its unstable set pokes into the left
// half-plane next to the imaginary axis, so an undamped oscillator grows at small steps and is
// damped again at large ones.
struct Bdf3 : BdfMethod<std::array{18.0 / 11, -9.0 / 11, 2.0 / 11}, 6.0 / 11> {
  static constexpr MethodInfo info{.name = "bdf3", .order = 3, .family = Family::Bdf,
                                   .implicit = true,
                                   .summary = "y_(n+1) - 18/11 y_n + 9/11 y_(n-1) - 2/11 y_(n-2) = 6/11 h f(y_(n+1)), by Newton, started by Gauss-Legendre"};
};

}  // namespace steplab

STEPLAB_METHOD(steplab::Bdf3);
