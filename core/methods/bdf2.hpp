#pragma once
#include "core/linear_multistep.hpp"

namespace steplab {

// Second-order backward differentiation formula (core/linear_multistep.hpp):
//   y_{n+1} - 4/3 y_n + 1/3 y_{n-1} = 2/3 h f(y_{n+1}):   w = 4/3 y_n - 1/3 y_{n-1},  beta = 2/3
// A-stable (and L-stable): the highest order an A-stable linear multistep method can have
// (Dahlquist's second barrier).
struct Bdf2 : BdfMethod<std::array{4.0 / 3, -1.0 / 3}, 2.0 / 3> {
  static constexpr MethodInfo info{.name = "bdf2", .order = 2, .family = Family::Bdf,
                                   .implicit = true, .a_stable = true,
                                   .summary = "y' = 3/2 y_(n+1) - 2 y_n + 1/2 y_(n-1) = h f(y_(n+1)), by Newton, started by Gauss-Legendre"};
};

}  // namespace steplab

STEPLAB_METHOD(steplab::Bdf2);
