#pragma once
#include "core/implicit_rk.hpp"

namespace steplab {

// Three-stage Radau IIA, order 5 (Hairer & Wanner II, Table IV.5.6), with s6 = sqrt(6):
//   c = ((4 - s6)/10, (4 + s6)/10, 1)
//   A = [[(88 - 7 s6)/360,     (296 - 169 s6)/1800, (-2 + 3 s6)/225],
//        [(296 + 169 s6)/1800, (88 + 7 s6)/360,     (-2 - 3 s6)/225],
//        [(16 - s6)/36,        (16 + s6)/36,        1/9]],            b = the last row of A.
// R(z) = (1 + 2z/5 + z^2/20) / (1 - 3z/5 + 3z^2/20 - z^3/60): A-stable and L-stable (R(-inf) = 0),
// stiffly accurate (the last stage is the step). Not symplectic: |R(iy)| < 1. Newton on the three
// stages together (core/implicit_rk.hpp).
struct RadauIIA5 {
  static constexpr MethodInfo info{.name = "radau_iia5", .order = 5, .family = Family::ImplicitRungeKutta,
                                   .implicit = true, .a_stable = true,
                                   .summary = "three-stage Radau IIA (L-stable), all stages by Newton"};
  static constexpr int solve_stages = 3;  // core/method.hpp
  static constexpr double s6 = 2.4494897427831780982;  // sqrt(6)
  static constexpr ButcherTableau<3> tableau{{{{(88 - 7 * s6) / 360, (296 - 169 * s6) / 1800, (-2 + 3 * s6) / 225},
                                               {(296 + 169 * s6) / 1800, (88 + 7 * s6) / 360, (-2 - 3 * s6) / 225},
                                               {(16 - s6) / 36, (16 + s6) / 36, 1.0 / 9}}},
                                             {(16 - s6) / 36, (16 + s6) / 36, 1.0 / 9}};
  template <class S, class T> static Status<T> step(const S& s, State<S::dim, T>& y, Time<T> t, Time<T> h) {
    return implicit_rk_step(s, y, t, h, tableau);
  }
};

}  // namespace steplab

STEPLAB_METHOD(steplab::RadauIIA5);
