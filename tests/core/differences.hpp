// A scene of run-time size against central differences (step 1e-6), at a state y of the caller's:
// its force against minus the gradient of its energy (undamped: the energy at v = 0 is the
// potential), and its sparse Jacobians dF/dx, dF/dv against differences of its force. Both to
// 1e-7 of the largest entry: the differences' error is ~ h^2 f''' (1e-12 relative) plus the
// round-off of a difference of O(1) numbers over 2h (~1e-10 relative), far below it.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>

#include "core/scene.hpp"

namespace steplab {

template <class S> void expect_force_is_minus_energy_gradient(const S& s, const State<Eigen::Dynamic>& y) {
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(y.x.size());
  const Eigen::VectorXd f = force_value(s, 0.0, y.x, zero);
  const double h = 1e-6;
  for (int i = 0; i < y.x.size(); ++i) {
    Eigen::VectorXd up = y.x, down = y.x;
    up[i] += h, down[i] -= h;
    EXPECT_NEAR(f[i], -(s.energy(up, zero) - s.energy(down, zero)) / (2 * h), 1e-7 * f.cwiseAbs().maxCoeff()) << i;
  }
}

// Returns dF/dx, dense, for the caller's further checks.
template <class S> Eigen::MatrixXd expect_jacobians_match_differences(const S& s, const State<Eigen::Dynamic>& y) {
  const Jacobians<Eigen::Dynamic> j = s.jacobians(y.x, y.v);
  const Eigen::MatrixXd dx(j.dx), dv(j.dv);
  const double h = 1e-6, scale = std::max(dx.cwiseAbs().maxCoeff(), dv.cwiseAbs().maxCoeff());
  for (int c = 0; c < y.x.size(); ++c) {
    Eigen::VectorXd xu = y.x, xd = y.x, vu = y.v, vd = y.v;
    xu[c] += h, xd[c] -= h, vu[c] += h, vd[c] -= h;
    const Eigen::VectorXd fdx = (force_value(s, 0.0, xu, y.v) - force_value(s, 0.0, xd, y.v)) / (2 * h);
    const Eigen::VectorXd fdv = (force_value(s, 0.0, y.x, vu) - force_value(s, 0.0, y.x, vd)) / (2 * h);
    for (int r = 0; r < y.x.size(); ++r) {
      EXPECT_NEAR(dx(r, c), fdx[r], 1e-7 * scale) << r << ", " << c;
      EXPECT_NEAR(dv(r, c), fdv[r], 1e-7 * scale) << r << ", " << c;
    }
  }
  return dx;
}

}  // namespace steplab
