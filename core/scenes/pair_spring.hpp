// A damped spring between two 2-D masses i and j, its force along the spring (the falling
// triangle's springs, the soft body's). With d = x_i - x_j, w = v_i - v_j, l = |d|, n = d / l,
// P = I - n n^T and rest length L:
//   F_i = -(k (l - L) + gamma n.w) n,   F_j = -F_i
//   dF_i/dd = -k (n n^T + (l - L)/l P) - gamma / l (n w^T P + (n.w) P)
//   dF_i/dv_i = -gamma n n^T
// and by symmetry dF_i/dx_j = dF_j/dx_i = -dF_i/dd, dF_j/dx_j = dF_i/dd (likewise in v): a
// spring's Jacobian is these two blocks with signs. Its energy is k (l - L)^2 / 2. Coincident
// masses (l = 0) have no direction: no force, zero blocks.
#pragma once

#include <Eigen/Core>

namespace steplab {

struct PairSpring {
  double k, gamma;

  // F_i; zero where l = 0.
  Eigen::Vector2d force(const Eigen::Vector2d& d, const Eigen::Vector2d& w, double rest) const {
    const double l = d.norm();
    if (l == 0) return Eigen::Vector2d::Zero();
    const Eigen::Vector2d n = d / l;
    return -(k * (l - rest) + gamma * n.dot(w)) * n;
  }

  struct Blocks {
    Eigen::Matrix2d dd, dv;  // dF_i/dd, dF_i/dv_i
  };
  Blocks blocks(const Eigen::Vector2d& d, const Eigen::Vector2d& w, double rest) const {
    const double l = d.norm();
    if (l == 0) return {Eigen::Matrix2d::Zero(), Eigen::Matrix2d::Zero()};
    const Eigen::Vector2d n = d / l;
    const Eigen::Matrix2d nn = n * n.transpose(), P = Eigen::Matrix2d::Identity() - nn;
    return {-k * (nn + (l - rest) / l * P) - gamma / l * (n * w.transpose() * P + n.dot(w) * P), -gamma * nn};
  }

  double energy(const Eigen::Vector2d& d, double rest) const {
    const double stretch = d.norm() - rest;
    return 0.5 * k * stretch * stretch;
  }
};

}  // namespace steplab
