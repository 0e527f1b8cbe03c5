// A soft body: an n x n grid of 2-D masses joined by structural springs (to the right and above)
// and shear springs (both diagonals), dropped onto the penalty ground y = -1 of the falling
// triangle (core/scenes/ground.hpp). Mass i = r n + c (row r from the bottom, column c) has
// coordinates x at 2i, y at 2i + 1. It starts at rest as a square of side S, undeformed, its
// bottom edge at y = -0.5 (where the triangle's is), centred on x = 0.
//
// A refinement of one body, not a larger one: the totals stay as n grows.
//   each mass         m = M / n^2              (total mass M)
//   spacing           h = S / (n - 1)          (rest lengths h and sqrt(2) h)
//   each spring       k, gamma                 (a 2-D lattice's elastic modulus and viscosity are
//                                               k and gamma themselves, whatever h: a spring of
//                                               length h strained by e carries k e h over a width h)
//   ground per mass   k_g / n, c_g / n         (the bottom row of n masses carries k_g, c_g)
// so the stiffest mode's frequency grows as n (omega^2 ~ k / m ~ n^2): an explicit method's
// stable step shrinks with the edge length h.
//
// Each spring pulls along itself, damped along itself, as the triangle's (core/scenes/
// pair_spring.hpp: its force, Jacobian blocks and energy). Plus gravity -m g on every y and the
// ground on every y. dF/dx is not symmetric where gamma > 0 (the damping force turns with the
// spring): Newton factorises by sparse LU (core/sparse.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <utility>
#include <vector>

#include <Eigen/SparseCore>

#include "core/scene.hpp"
#include "core/springs.hpp"
#include "core/scenes/block_pattern.hpp"
#include "core/scenes/ground.hpp"
#include "core/scenes/pair_spring.hpp"

namespace steplab {

struct SoftBody {
  static constexpr int dim = Eigen::Dynamic;
  static constexpr std::string_view name = "softbody";
  // What it offers the studies (core/scene.hpp): refined by its grid side n, two coordinates per
  // mass, its fastest mode (modes() below), contact (penetration).
  static constexpr std::string_view title = "Soft body of N = n x n masses";
  // The equation of motion, for the report (the math above is its derivation).
  static constexpr std::string_view equation = "m x_i'' = sum over the springs j of i: f_ij along the spring, damped along it; - m g in y; the ground below y = -1";
  static constexpr std::string_view size_param = "grid";
  static constexpr int coords_per_mass = 2;
  static constexpr std::string_view stiffness_param = "stiffness";
  static constexpr std::string_view damping_param = "damping";
  // Defaults: the falling triangle's (mass 0.1 each of three: M 0.3; k 10, gamma 0.01, ground
  // 100, 0), a square of side 1.5 from the triangle's bottom (-0.5) to its top (1), 4 x 4 masses.
  static constexpr std::array<ParamSpec, 8> params{{
      {"grid", 4, Bound::Positive, "masses along each side n (n x n masses; a whole number, 1 to 300)", true, 300},
      {"mass", 0.3, Bound::Positive, "total mass M (each mass M/n^2)"},
      {"stiffness", 10.0, Bound::NonNegative, "stiffness k of every spring (the lattice's modulus: kept as n grows)"},
      {"damping", 0.01, Bound::NonNegative, "damping gamma of every spring, along the spring"},
      {"side", 1.5, Bound::Positive, "side S of the square at rest (spacing S/(n-1))"},
      {"gravity", 9.81, Bound::NonNegative, "gravitational acceleration g (pointing down)"},
      {"ground-stiffness", 100.0, Bound::Positive, "stiffness k_g of the ground under a row (k_g/n each mass)"},
      {"ground-damping", 0.0, Bound::NonNegative, "damping c_g of the ground under a row (c_g/n each mass)"},
  }};

  struct Spring {
    int i, j;
    double rest;
  };

  int n;
  double M, k, gamma, side, g;
  Ground ground;
  PairSpring spring{k, gamma};
  int masses = n * n;
  double m = M / masses, inv_m = 1 / m;
  std::vector<Spring> springs;
  Eigen::VectorXd m_all = Eigen::VectorXd::Constant(2 * masses, m), inv_m_all = Eigen::VectorXd::Constant(2 * masses, inv_m);
  // The Jacobians' pattern (core/scenes/block_pattern.hpp: each mass's 2 x 2 block, each spring's
  // four), made once; where each mass's y diagonal sits in its values.
  BlockPattern<2> pattern;
  std::vector<int> y_slots;

  explicit SoftBody(std::span<const double> p)
      : n(static_cast<int>(p[0])), M(p[1]), k(p[2]), gamma(p[3]), side(p[4]), g(p[5]), ground{p[6] / n, p[7] / n} {
    const double h = spacing();
    const auto at = [&](int r, int c) { return r * n + c; };
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) {
        if (c + 1 < n) springs.push_back({at(r, c), at(r, c + 1), h});
        if (r + 1 < n) springs.push_back({at(r, c), at(r + 1, c), h});
        if (r + 1 < n && c + 1 < n) springs.push_back({at(r, c), at(r + 1, c + 1), std::sqrt(2.0) * h});
        if (r + 1 < n && c > 0) springs.push_back({at(r, c), at(r + 1, c - 1), std::sqrt(2.0) * h});
      }
    pattern = BlockPattern<2>(2 * masses, springs);
    for (int i = 0; i < masses; ++i) y_slots.push_back(pattern.slot(2 * i + 1, 2 * i + 1));
  }

  std::array<double, 8> values() const { return {double(n), M, k, gamma, side, g, ground.k * n, ground.c * n}; }
  double spacing() const { return n > 1 ? side / (n - 1) : 0.0; }

  const Eigen::VectorXd& mass() const { return m_all; }
  const Eigen::VectorXd& inverse_mass() const { return inv_m_all; }

  // F into the run's f.
  void force(Eigen::Ref<const Eigen::VectorXd> x, Eigen::Ref<const Eigen::VectorXd> v, Eigen::Ref<Eigen::VectorXd> f) const {
    for (int i = 0; i < masses; ++i) f[2 * i] = 0, f[2 * i + 1] = -m * g + ground.force(x[2 * i + 1], v[2 * i + 1]);
    for (const Spring& s : springs) {
      const Eigen::Vector2d fi = spring.force(x.segment<2>(2 * s.i) - x.segment<2>(2 * s.j), v.segment<2>(2 * s.i) - v.segment<2>(2 * s.j), s.rest);
      f.segment<2>(2 * s.i) += fi;
      f.segment<2>(2 * s.j) -= fi;
    }
  }

  // Sparse, on the pattern made once (entries that are zero, as the ground's off contact, are
  // kept: the Newton solver's ordering and symbolic factorisation are made once per run): the
  // ground on each y diagonal, then each spring's blocks added in spring order. Into the run's
  // jac, which takes the pattern on its first call; by value for a caller outside a run.
  Jacobians<Eigen::Dynamic> jacobians(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const {
    Jacobians<Eigen::Dynamic> jac;
    jacobians(x, v, jac);
    return jac;
  }
  void jacobians(Eigen::Ref<const Eigen::VectorXd> x, Eigen::Ref<const Eigen::VectorXd> v, Jacobians<Eigen::Dynamic>& jac) const {
    pattern.zero(jac);
    double *fx = jac.dx.valuePtr(), *fv = jac.dv.valuePtr();
    for (int i = 0; i < masses; ++i) {
      const double y = x[2 * i + 1];
      fx[y_slots[i]] = ground.dforce_dy(y), fv[y_slots[i]] = ground.dforce_dv(y);
    }
    for (std::size_t q = 0; q < springs.size(); ++q) {
      const Spring& s = springs[q];
      const auto [dd, dv] = spring.blocks(x.segment<2>(2 * s.i) - x.segment<2>(2 * s.j), v.segment<2>(2 * s.i) - v.segment<2>(2 * s.j), s.rest);
      pattern.add(fx, q, dd);
      pattern.add(fv, q, dv);
    }
  }

  bool velocity_dependent() const { return gamma != 0 || ground.c != 0; }
  // As springs (core/springs.hpp): the structural and shear springs, damped along themselves;
  // gravity on each y; the ground.
  int links() const { return static_cast<int>(springs.size()); }
  Link link(int q) const { return {springs[q].i, springs[q].j, springs[q].rest, k, gamma}; }
  double external(int a, double) const { return a % 2 == 1 ? -m * g : 0.0; }
  // The deepest mass below the ground.
  double penetration(const Eigen::VectorXd& x) const {
    double p = ground.penetration(x[1]);
    for (int i = 1; i < masses; ++i) p = std::max(p, ground.penetration(x[2 * i + 1]));
    return p;
  }

  // Total mechanical energy: kinetic + gravity (height above the ground) + springs + ground penalty.
  double energy(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const {
    double e = 0.5 * m * v.squaredNorm();
    for (int i = 0; i < masses; ++i) e += m * g * (x[2 * i + 1] - Ground::level) + ground.energy(x[2 * i + 1]);
    for (const Spring& s : springs) e += spring.energy(x.segment<2>(2 * s.i) - x.segment<2>(2 * s.j), s.rest);
    return e;
  }

  // The body is not linear (springs turn, the ground switches on), so its modes are those of its
  // linearisation at the start shape lowered onto the ground (the bottom row just in contact, its
  // penalty springs on), where the fastest mode is fastest: at rest every spring is at its rest
  // length, so dF/dx = -K and dF/dv = -(gamma/k) K_springs - C_ground, both symmetric. With equal
  // masses M = m I the modes are K's eigenvectors; only the fastest is given,
  //   omega_max^2 = lambda_max(K) / m,
  // by power iteration on K started from the checkerboard (neighbours moving apart, the shape of
  // a lattice's fastest mode), its Rayleigh quotient converged to 1e-12 relative (at most
  // kPowerIterations products); its damping ratio from the same vector u:
  //   2 zeta omega_max = u^T C u / (m u^T u).
  // On the rope the fastest mode binds every method at small damping ratios (`study stability
  // --scene rope` reports the binding mode), so the slower ones are not examined here.
  static constexpr int kPowerIterations = 20'000;
  std::vector<Mode> modes() const;
  // The start shape lowered until its bottom row is 1e-9 below the ground (Ground::level): every
  // spring at rest, the bottom row's penalty springs on.
  State<Eigen::Dynamic> lowered_onto_ground() const;

  State<Eigen::Dynamic> initial() const {
    const double h = spacing();
    Eigen::VectorXd x(2 * masses);
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) x[2 * (r * n + c)] = (c - 0.5 * (n - 1)) * h, x[2 * (r * n + c) + 1] = -0.5 + r * h;
    return {x, Eigen::VectorXd::Zero(2 * masses)};
  }
};

// Compiled once, in the scene's generated translation unit (core/scene.hpp).
#ifdef STEPLAB_SCENE_SOURCE
State<Eigen::Dynamic> SoftBody::lowered_onto_ground() const {
  State<Eigen::Dynamic> y = initial();
  const double drop = (y.x[1] - Ground::level) + 1e-9;  // mass 0 is in the bottom row
  for (int i = 1; i < y.x.size(); i += 2) y.x[i] -= drop;
  return y;
}

std::vector<Mode> SoftBody::modes() const {
  const State<Eigen::Dynamic> y = lowered_onto_ground();
  const Jacobians<Eigen::Dynamic> j = jacobians(y.x, y.v);
  const SparseMat K = -j.dx, C = -j.dv;
  Eigen::VectorXd u(y.x.size());
  for (int i = 0; i < u.size(); ++i) {
    const int mass = i / 2, r = mass / n, c = mass % n;
    u[i] = ((r + c) % 2 == 0 ? 1.0 : -1.0) * (1 + 0.1 * std::sin(1.3 * i));  // not orthogonal to it by symmetry
  }
  u.normalize();
  double rq = 0;
  for (int it = 0; it < kPowerIterations; ++it) {
    const Eigen::VectorXd w = K * u;
    const double last = std::exchange(rq, u.dot(w));
    u = w.normalized();
    if (std::abs(rq - last) <= 1e-12 * std::abs(rq)) break;
  }
  const double omega = std::sqrt(rq / m);
  return {{omega, u.dot(C * u) / (m * omega)}};
}
#endif

}  // namespace steplab

STEPLAB_SCENE(steplab::SoftBody);
