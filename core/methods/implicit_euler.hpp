#pragma once
#include "core/method.hpp"

namespace steplab {

// Implicit (backward) Euler, first order, A-stable (damps every mode, even undamped ones):
//   x_{n+1} = x_n + h v_{n+1}
//   v_{n+1} = v_n + h a(x_{n+1}, v_{n+1})
// Eliminating x_{n+1}: M (v_{n+1} - v_n) = h F(x_n + h v_{n+1}, v_{n+1}), solved by Newton
// (solve_implicit with w = v_n, c = cx = h).
struct ImplicitEuler {
  static constexpr MethodInfo info{.name = "implicit_euler", .order = 1, .family = Family::ImplicitRungeKutta,
                                   .implicit = true, .a_stable = true,
                                   .summary = "y_(n+1) = y_n + h f(y_(n+1)), solved by Newton for the new velocity", .first_of = Family::Bdf};
  static constexpr int solve_stages = 1;  // core/method.hpp
  static constexpr ButcherTableau<1> tableau{{{{1.0}}}, {1.0}};  // c = 1: stiffly accurate
  template <class S, class T> static Status<T> step(const S& s, State<S::dim, T>& y, Time<T> t, Time<T> h) {
    Temp<S::dim, T> v1 = temp_like<S::dim, T>(y.v);
    const Status<T> status = solve_implicit(s, t + h, y.x, h, y.v, h, v1);
    y.x += h * v1;
    y.v = v1;
    return status;
  }
};

}  // namespace steplab

STEPLAB_METHOD(steplab::ImplicitEuler);
