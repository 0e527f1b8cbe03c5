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
// Spring between i and j, d = x_i - x_j, l = |d|, n = d / l, P = I - n n^T (as the triangle's):
//   F_i = -(k (l - L) + gamma n.(v_i - v_j)) n,   F_j = -F_i
//   dF_i/dd = -k (n n^T + (l - L)/l P) - gamma / l (n (v_i - v_j)^T P + (n.(v_i - v_j)) P)
//   dF_i/dv_i = -gamma n n^T
// Plus gravity -m g on every y and the ground on every y. dF/dx is not symmetric where gamma > 0
// (the first damping term): Newton factorises by sparse LU (core/sparse.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <vector>

#include <Eigen/SparseCore>

#include "core/scene.hpp"
#include "core/scenes/ground.hpp"

namespace steplab {

struct SoftBody {
  static constexpr int dim = Eigen::Dynamic;
  static constexpr std::string_view name = "softbody";
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
  int masses = n * n;
  double m = M / masses, inv_m = 1 / m;
  std::vector<Spring> springs;
  Eigen::VectorXd m_all = Eigen::VectorXd::Constant(2 * masses, m), inv_m_all = Eigen::VectorXd::Constant(2 * masses, inv_m);

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
  }

  std::array<double, 8> values() const { return {double(n), M, k, gamma, side, g, ground.k * n, ground.c * n}; }
  double spacing() const { return n > 1 ? side / (n - 1) : 0.0; }

  const Eigen::VectorXd& mass() const { return m_all; }
  const Eigen::VectorXd& inverse_mass() const { return inv_m_all; }

  Eigen::VectorXd force(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const {
    Eigen::VectorXd f(2 * masses);
    for (int i = 0; i < masses; ++i) f[2 * i] = 0, f[2 * i + 1] = -m * g + ground.force(x[2 * i + 1], v[2 * i + 1]);
    for (const Spring& s : springs) {
      const Eigen::Vector2d d = x.segment<2>(2 * s.i) - x.segment<2>(2 * s.j);
      const double l = d.norm();
      if (l == 0) continue;  // coincident masses: no direction, no force
      const Eigen::Vector2d u = d / l;
      const double dv = u.dot(v.segment<2>(2 * s.i) - v.segment<2>(2 * s.j));
      const Eigen::Vector2d fi = -(k * (l - s.rest) + gamma * dv) * u;
      f.segment<2>(2 * s.i) += fi;
      f.segment<2>(2 * s.j) -= fi;
    }
    return f;
  }

  // Sparse, a 2 x 2 block per mass and per spring's pair: the pattern is the same at every
  // state (entries that are zero, as the ground's off contact, are kept), so the Newton solver's
  // ordering and symbolic factorisation are made once per run.
  Jacobians<Eigen::Dynamic> jacobians(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const {
    std::vector<Eigen::Triplet<double>> tx, tv;
    tx.reserve(2 * masses + 16 * springs.size()), tv.reserve(2 * masses + 16 * springs.size());
    for (int i = 0; i < masses; ++i) {
      const double y = x[2 * i + 1];
      tx.emplace_back(2 * i, 2 * i, 0.0), tx.emplace_back(2 * i + 1, 2 * i + 1, ground.dforce_dy(y));
      tv.emplace_back(2 * i, 2 * i, 0.0), tv.emplace_back(2 * i + 1, 2 * i + 1, ground.dforce_dv(y));
    }
    const auto add = [](std::vector<Eigen::Triplet<double>>& t, int i, int j, const Eigen::Matrix2d& b) {
      for (int a = 0; a < 2; ++a)
        for (int c = 0; c < 2; ++c) {
          t.emplace_back(2 * i + a, 2 * i + c, b(a, c)), t.emplace_back(2 * j + a, 2 * j + c, b(a, c));
          t.emplace_back(2 * i + a, 2 * j + c, -b(a, c)), t.emplace_back(2 * j + a, 2 * i + c, -b(a, c));
        }
    };
    for (const Spring& s : springs) {
      const Eigen::Vector2d d = x.segment<2>(2 * s.i) - x.segment<2>(2 * s.j);
      const double l = d.norm();
      Eigen::Matrix2d dfd = Eigen::Matrix2d::Zero(), dfv = Eigen::Matrix2d::Zero();
      if (l > 0) {
        const Eigen::Vector2d u = d / l, dv = v.segment<2>(2 * s.i) - v.segment<2>(2 * s.j);
        const Eigen::Matrix2d uu = u * u.transpose(), P = Eigen::Matrix2d::Identity() - uu;
        dfd = -k * (uu + (l - s.rest) / l * P) - gamma / l * (u * dv.transpose() * P + u.dot(dv) * P);
        dfv = -gamma * uu;
      }
      add(tx, s.i, s.j, dfd);
      add(tv, s.i, s.j, dfv);
    }
    Jacobians<Eigen::Dynamic> jac{SparseMat(2 * masses, 2 * masses), SparseMat(2 * masses, 2 * masses)};
    jac.dx.setFromTriplets(tx.begin(), tx.end());
    jac.dv.setFromTriplets(tv.begin(), tv.end());
    return jac;
  }

  bool velocity_dependent() const { return gamma != 0 || ground.c != 0; }
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
    for (const Spring& s : springs) {
      const double stretch = (x.segment<2>(2 * s.i) - x.segment<2>(2 * s.j)).norm() - s.rest;
      e += 0.5 * k * stretch * stretch;
    }
    return e;
  }

  State<Eigen::Dynamic> initial() const {
    const double h = spacing();
    Eigen::VectorXd x(2 * masses);
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) x[2 * (r * n + c)] = (c - 0.5 * (n - 1)) * h, x[2 * (r * n + c) + 1] = -0.5 + r * h;
    return {x, Eigen::VectorXd::Zero(2 * masses)};
  }
};

}  // namespace steplab

STEPLAB_SCENE(steplab::SoftBody);
