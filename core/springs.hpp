// What a mass-spring scene offers the methods that work on its springs rather than on its force
// (the position-based XPBD and PBD, Baraff and Witkin's large steps): its springs one by one, the
// forces that are not springs, and its ground. The same physical model as the scene's force(),
// written as parts; tests/core/springs_test.cpp holds the parts' sum to force() on every scene
// that offers them.
//
// A spring q joins masses i and j (j or i = -1: a fixed point, at the link's `fixed`, the origin
// unless the scene says otherwise), with rest length L, stiffness k and a dashpot c along itself.
// With p_i the position of mass i (p_-1 = fixed), its constraint C and the force on mass i (on j
// the opposite) are
//   one coordinate a mass:   C = (p_i - p_j) - L,   grad_i C = 1,        the line spring, signed
//   two or three a mass:     C = |p_i - p_j| - L,   grad_i C = n = (p_i - p_j) / |p_i - p_j|
//   F_i = -(k C + c dC/dt) grad_i C,   dC/dt = grad_i C . (v_i - v_j)
// (in one coordinate the signed form: the spring scene's -k (|y| - L) sign(y) is -k (-y - L) (-1)
// below its anchor, where it hangs; the chain's springs have L = 0 in its displacements). A spring
// with coincident ends in two or three coordinates has no direction: no force.
//
// The rest, per coordinate and affine in that coordinate's velocity: external(a, v_a) (gravity,
// absolute damping); and a ground (core/scenes/ground.hpp) under the vertical coordinate of each
// mass where the scene has one (`ground`).
#pragma once

#include <cmath>
#include <concepts>
#include <stdexcept>

#include "core/scene.hpp"
#include "core/scratch.hpp"
#include "core/scenes/ground.hpp"

namespace steplab {

struct Link {
  int i, j;     // the masses it joins; -1: the fixed point below
  double rest;  // L
  double k;     // stiffness
  double c;     // dashpot along the spring
  double fixed[3] = {0, 0, 0};  // where an end -1 is (a fixed point moves nothing: its velocity is 0)
};

// A scene of masses joined by springs: links() of them, link(q) for q = 0 .. links() - 1, and
// external(a, v) the force on coordinate a that is neither a spring nor the ground.
template <class S>
concept MassSpring = Scene<S> && requires(const S& s, int q, double v) {
  { s.links() } -> std::convertible_to<int>;
  { s.link(q) } -> std::same_as<Link>;
  { s.external(q, v) } -> std::convertible_to<double>;
};

// A mass-spring scene with a ground under its masses' vertical coordinates.
template <class S>
concept HasGround = MassSpring<S> && requires(const S& s) {
  { s.ground } -> std::convertible_to<Ground>;
};

// A spring's geometry at positions x, shared by whatever works on the springs: C and grad_i C
// (grad_j C = -grad_i C), as above, with d coordinates a mass.
struct LinkAt {
  double c = 0;               // C
  double g[3] = {1, 0, 0};    // grad_i C
  bool has_direction = true;  // false: two or three coordinates and coincident ends (no force)
};
// z at coordinate `axis` of mass i, for a vector z of the state's layout (a velocity, a
// difference of positions, an inverse mass); 0 at a fixed point.
template <int d, class Z> double at_end(const Z& z, int i, int axis) { return i < 0 ? 0.0 : double(z[d * i + axis]); }
// The position of end i (l.i or l.j) of l: the mass's, or the fixed point's.
template <int d, class X> double position_at_end(const Link& l, const X& x, int i, int axis) {
  return i < 0 ? l.fixed[axis] : double(x[d * i + axis]);
}
template <int d, class X> LinkAt link_at(const Link& l, const X& x) {
  static_assert(d >= 1 && d <= 3);
  LinkAt out;
  const auto delta = [&](int axis) { return position_at_end<d>(l, x, l.i, axis) - position_at_end<d>(l, x, l.j, axis); };
  if constexpr (d == 1) {
    out.c = delta(0) - l.rest;
  } else {
    const double dx = delta(0), dy = delta(1), dz = d == 3 ? delta(2) : 0.0;
    const double len = d == 2 ? std::hypot(dx, dy) : std::sqrt(dx * dx + dy * dy + dz * dz);
    if (len == 0) return {0, {0, 0, 0}, false};
    out.c = len - l.rest, out.g[0] = dx / len, out.g[1] = dy / len, out.g[2] = dz / len;
  }
  return out;
}
// `per` numbers for each spring (or mass) that a step keeps: on the stack for a fixed-size scene of
// D coordinates, which has at most D springs and D masses (only the first n are used), from the
// run's scratch pool (core/scratch.hpp) otherwise. Either way a step allocates nothing.
template <int D, int per> struct SpringNumbers {
  using type = Eigen::Matrix<double, per * D, 1>;
};
template <int per> struct SpringNumbers<Eigen::Dynamic, per> {
  using type = ScratchVec;
};
template <int D, int per> typename SpringNumbers<D, per>::type spring_numbers(Eigen::Index n) {
  if constexpr (D == Eigen::Dynamic) {
    return ScratchVec(n);
  } else {
    if (n > per * D) throw std::logic_error("spring_numbers: a fixed-size scene with more springs than coordinates");
    return SpringNumbers<D, per>::type::Zero();
  }
}

// A vector of zeros of any length, for `along` below (z0 = 0: dC/dt).
struct Zeros {
  double operator[](Eigen::Index) const { return 0.0; }
};
// grad C . ((z_i - z0_i) - (z_j - z0_j)): with z = v, z0 = 0, dC/dt; with z = x, z0 = x_n, how far
// the step has moved C's ends along grad C.
template <int d, class Z, class Z0> double along(const Link& l, const LinkAt& at, const Z& z, const Z0& z0) {
  double sum = 0;
  for (int axis = 0; axis < d; ++axis)
    sum += at.g[axis] * ((at_end<d>(z, l.i, axis) - at_end<d>(z0, l.i, axis)) - (at_end<d>(z, l.j, axis) - at_end<d>(z0, l.j, axis)));
  return sum;
}

// The force of the parts above, into f (sized as x): what the scene's force() is, written from
// its springs. For the tests, and the reference a method that works on the springs is held to.
template <MassSpring S, class X, class V, class F> void force_from_links(const S& s, const X& x, const V& v, F& f) {
  constexpr int d = coords_per_mass<S>();
  const int masses = static_cast<int>(x.size()) / d;
  for (int a = 0; a < static_cast<int>(x.size()); ++a) f[a] = s.external(a, v[a]);
  if constexpr (HasGround<S>)
    for (int i = 0; i < masses; ++i) f[d * i + d - 1] += s.ground.force(x[d * i + d - 1], v[d * i + d - 1]);
  const Zeros zero;
  for (int q = 0; q < s.links(); ++q) {
    const Link l = s.link(q);
    const LinkAt at = link_at<d>(l, x);
    if (!at.has_direction) continue;
    const double t = -(l.k * at.c + l.c * along<d>(l, at, v, zero));
    for (int axis = 0; axis < d; ++axis) {
      if (l.i >= 0) f[d * l.i + axis] += t * at.g[axis];
      if (l.j >= 0) f[d * l.j + axis] -= t * at.g[axis];
    }
  }
}

}  // namespace steplab
