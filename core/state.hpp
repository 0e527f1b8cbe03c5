// The state of a scene: positions x and velocities v, kept apart, as fixed-size Eigen vectors
// of the scene's own dimension (1 for the hanging spring, 2 for the cannon ball, 6 for three
// 2-D particles). Fixed size means no heap allocation anywhere in a step. A scene whose size is
// set at run time (the rope of N masses) has D = Eigen::Dynamic: vectors of run-time size, and
// sparse force Jacobians.
#pragma once

#include <cmath>

#include <Eigen/Core>
#include <Eigen/LU>
#include <Eigen/SparseCore>

namespace steplab {

template <int D> using Vec = Eigen::Matrix<double, D, 1>;
template <int D> using Mat = Eigen::Matrix<double, D, D>;

template <int D> struct State {
  Vec<D> x;
  Vec<D> v;
};

// A zero state; empty for a state whose size is set at run time (D = Eigen::Dynamic).
template <int D> State<D> zero_state() {
  if constexpr (D == Eigen::Dynamic) return {};
  else return {Vec<D>::Zero(), Vec<D>::Zero()};
}

// Force Jacobians for the implicit methods: dF/dx and dF/dv at one state.
template <int D> struct Jacobians {
  Mat<D> dx;
  Mat<D> dv;
};

// A scene of run-time size N has sparse ones (tridiagonal for the rope): a dense N x N would
// cost N^2 memory and N^3 to factorise.
using SparseMat = Eigen::SparseMatrix<double>;
template <> struct Jacobians<Eigen::Dynamic> {
  SparseMat dx;
  SparseMat dv;
};

// Whether every coordinate is finite, checked after every step of every run. NaN and +-inf
// propagate through a sum (inf - inf is NaN), so one sum and one test find them all at a
// dozen additions; the sum also overflows, flagging the state, if its coordinates add up past
// 1.8e308, which is a blow-up too. (Eigen's allFinite costs ~4x more instructions.)
template <int D> bool all_finite(const State<D>& s) { return std::isfinite(s.x.sum() + s.v.sum()); }

}  // namespace steplab
