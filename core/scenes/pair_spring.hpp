// A damped spring between two masses i and j of 2 coordinates each (the falling triangle's
// springs, the soft body's) or 3 (the cloth's), its force along the spring. With d = x_i - x_j,
// w = v_i - v_j, l = |d|, n = d / l, P = I - n n^T and rest length L:
//   F_i = -(k (l - L) + gamma n.w) n,   F_j = -F_i
//   dF_i/dd = -k (n n^T + (l - L)/l P) - gamma / l (n w^T P + (n.w) P)
//   dF_i/dv_i = -gamma n n^T
// and by symmetry dF_i/dx_j = dF_j/dx_i = -dF_i/dd, dF_j/dx_j = dF_i/dd (likewise in v): a
// spring's Jacobian is these two blocks with signs. Its energy is k (l - L)^2 / 2. Coincident
// masses (l = 0) have no direction: no force, zero blocks.
#pragma once

#include <cmath>

#include "core/state.hpp"

namespace steplab {

// T = double: one spring; a Pack: one per lane, "zero where l = 0" a select (core/pack.hpp).
template <class T, int n_coords = 2> struct PairSpringT {
  using V = Eigen::Matrix<T, n_coords, 1>;
  using M = Eigen::Matrix<T, n_coords, n_coords>;
  T k, gamma;

  // F_i; zero where l = 0.
  V force(const V& d, const V& w, const T& rest) const {
    // d.norm() written out: with Eigen's norm() the falling triangle's one-at-a-time runs took
    // 3 % more instructions (callgrind, study convergence with RK4)
    using std::sqrt;
    const T l = sqrt(d.squaredNorm());
    const V n = d / l;
    return select(l == 0.0, V(V::Zero()), V(-(k * (l - rest) + gamma * n.dot(w)) * n));
  }

  struct Blocks {
    M dd, dv;  // dF_i/dd, dF_i/dv_i
  };
  Blocks blocks(const V& d, const V& w, const T& rest) const {
    using std::sqrt;
    const T l = sqrt(d.squaredNorm());
    const V n = d / l;
    const M nn = n * n.transpose(), P = M::Identity() - nn;
    const M dd = -k * (nn + (l - rest) / l * P) - gamma / l * (n * w.transpose() * P + n.dot(w) * P), dv = -gamma * nn;
    const auto zero = l == 0.0;
    return {select(zero, M(M::Zero()), dd), select(zero, M(M::Zero()), dv)};
  }

  T energy(const V& d, const T& rest) const {
    using std::sqrt;
    const T stretch = sqrt(d.squaredNorm()) - rest;
    return 0.5 * k * stretch * stretch;
  }
};

using PairSpring = PairSpringT<double>;
using PairSpring3 = PairSpringT<double, 3>;

}  // namespace steplab
