// The slides' problem 3: a triangle of three 2-D masses joined by three damped springs falls
// onto the ground y = -1 (core/scenes/ground.hpp), which pushes back any mass below it.
// State: x = (x1, y1, x2, y2, x3, y3). Start at rest at p1 = (0, 1), p2 = (cos 210°, sin 210°),
// p3 = (cos 330°, sin 330°); rest lengths from that shape (sqrt 3).
//
// Each spring pulls along itself, damped along itself (core/scenes/pair_spring.hpp: its force,
// Jacobian blocks and energy). Plus gravity -m g on every y and the ground.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>

#include "core/scene.hpp"
#include "core/springs.hpp"
#include "core/scenes/ground.hpp"
#include "core/scenes/pair_spring.hpp"

namespace steplab {

// T = double: one triangle; T = Pack<W>: W of them, one per lane (core/batch.hpp).
template <class T> struct FallingT {
  template <class U> using as = FallingT<U>;
  static constexpr int dim = 6;
  static constexpr int coords_per_mass = 2;
  static constexpr std::string_view name = "falling";
  // The equation of motion, for the report (the math above is its derivation).
  static constexpr std::string_view equation = "m x_i'' = the two damped springs along the triangle's sides + (0, -m g) + the ground's F_g on each mass below y = -1";
  // The old command-line framework's defaults: mass 0.1, stiffness 10, damping 0.01; ground 100.
  static constexpr std::array<ParamSpec, 6> params{{
      {"mass", 0.1, Bound::Positive, "mass of each of the three particles"},
      {"stiffness", 10.0, Bound::NonNegative, "stiffness k of the triangle's springs"},
      {"damping", 0.01, Bound::NonNegative, "damping gamma of the triangle's springs (along each spring)"},
      {"gravity", 9.81, Bound::NonNegative, "gravitational acceleration g (pointing down)"},
      {"ground-stiffness", 100.0, Bound::Positive, "stiffness k_g of the ground's penalty spring"},
      {"ground-damping", 0.0, Bound::NonNegative, "damping c_g of the ground's penalty spring"},
  }};
  static constexpr std::array<std::array<int, 2>, 3> springs{{{0, 1}, {1, 2}, {2, 0}}};

  T m, k, gamma, g;
  T inv_m = 1 / m;  // initialized after m (declaration order)
  PairSpringT<T> spring{k, gamma};
  GroundT<T> ground;
  double rest;  // rest length of every spring: the side of the start triangle, sqrt(3), in every lane

  explicit FallingT(std::span<const T> p) : m(p[0]), k(p[1]), gamma(p[2]), g(p[3]), ground{p[4], p[5]} {
    const Vec<6> x0 = start();
    rest = (x0.segment<2>(0) - x0.segment<2>(2)).norm();
  }

  Vec<6, T> mass() const { return Vec<6, T>::Constant(m); }
  Vec<6, T> inverse_mass() const { return Vec<6, T>::Constant(inv_m); }

  // force and jacobians always inlined: left out of line (GCC's stack-frame growth limit) a pack's
  // were compiled for the default instruction set, not the batch's (core/batch.hpp), and packs of
  // 4 ran slower than one run at a time.
  [[gnu::always_inline]] Vec<6, T> force(const Vec<6, T>& x, const Vec<6, T>& v) const {
    Vec<6, T> f = Vec<6, T>::Zero();
    for (int i = 0; i < 3; ++i) f[2 * i + 1] = -m * g + ground.force(x[2 * i + 1], v[2 * i + 1]);
    for (const auto& [i, j] : springs) {
      const Vec<2, T> fi = spring.force(x.template segment<2>(2 * i) - x.template segment<2>(2 * j),
                                        v.template segment<2>(2 * i) - v.template segment<2>(2 * j), rest);
      f.template segment<2>(2 * i) += fi;
      f.template segment<2>(2 * j) -= fi;
    }
    return f;
  }

  [[gnu::always_inline]] Jacobians<6, T> jacobians(const Vec<6, T>& x, const Vec<6, T>& v) const {
    Jacobians<6, T> jac{Mat<6, T>::Zero(), Mat<6, T>::Zero()};
    for (int i = 0; i < 3; ++i) {
      jac.dx(2 * i + 1, 2 * i + 1) = ground.dforce_dy(x[2 * i + 1]);
      jac.dv(2 * i + 1, 2 * i + 1) = ground.dforce_dv(x[2 * i + 1]);
    }
    for (const auto& [i, j] : springs) {
      const auto [dfd, dfv] = spring.blocks(x.template segment<2>(2 * i) - x.template segment<2>(2 * j),
                                            v.template segment<2>(2 * i) - v.template segment<2>(2 * j), rest);
      jac.dx.template block<2, 2>(2 * i, 2 * i) += dfd;
      jac.dx.template block<2, 2>(2 * i, 2 * j) -= dfd;
      jac.dx.template block<2, 2>(2 * j, 2 * i) -= dfd;
      jac.dx.template block<2, 2>(2 * j, 2 * j) += dfd;
      jac.dv.template block<2, 2>(2 * i, 2 * i) += dfv;
      jac.dv.template block<2, 2>(2 * i, 2 * j) -= dfv;
      jac.dv.template block<2, 2>(2 * j, 2 * i) -= dfv;
      jac.dv.template block<2, 2>(2 * j, 2 * j) += dfv;
    }
    return jac;
  }

  auto velocity_dependent() const { return gamma != 0.0 || ground.c != 0.0; }  // a Mask for a pack
  // As springs (core/springs.hpp; one run's, T = double): the three sides, damped along
  // themselves; gravity on each y; the ground.
  int links() const { return 3; }
  Link link(int q) const { return {springs[q][0], springs[q][1], rest, k, gamma}; }
  double external(int a, double) const { return a % 2 == 1 ? -m * g : 0.0; }
  // The deepest of the three particles below the ground.
  double penetration(const Vec<6>& x) const {
    double p = ground.penetration(x[1]);  // one run's (T = double)
    for (int i = 1; i < 3; ++i) p = std::max(p, ground.penetration(x[2 * i + 1]));
    return p;
  }

  // Total mechanical energy: kinetic + gravity (height above the ground) + springs + ground penalty.
  T energy(const Vec<6, T>& x, const Vec<6, T>& v) const {
    T e = 0.5 * m * squared_norm(v);  // v.squaredNorm(), in a pack lane by lane (core/state.hpp)
    for (int i = 0; i < 3; ++i) e += m * g * (x[2 * i + 1] - Ground::level) + ground.energy(x[2 * i + 1]);
    for (const auto& [i, j] : springs) e += spring.energy(x.template segment<2>(2 * i) - x.template segment<2>(2 * j), rest);
    return e;
  }

  // The start positions: p1 = (0, 1), p2 = (cos 210°, sin 210°), p3 = (cos 330°, sin 330°).
  static Vec<6> start() {
    using std::numbers::pi;
    const double a2 = 210 * pi / 180, a3 = 330 * pi / 180;
    Vec<6> x;
    x << 0, 1, std::cos(a2), std::sin(a2), std::cos(a3), std::sin(a3);
    return x;
  }
  State<6, T> initial() const { return {start().template cast<T>(), Vec<6, T>::Zero()}; }
};

using Falling = FallingT<double>;

}  // namespace steplab

STEPLAB_SCENE(steplab::Falling);
