// The state of a scene: positions x and velocities v, kept apart, as fixed-size Eigen vectors
// of the scene's own dimension (1 for the hanging spring, 2 for the cannon ball, 6 for three
// 2-D particles). Fixed size means no heap allocation anywhere in a step. A scene whose size is
// set at run time (the rope of N masses) has D = Eigen::Dynamic: vectors of run-time size, and
// sparse force Jacobians.
#pragma once

#include <cmath>
#include <type_traits>

#include <Eigen/Core>
#include <Eigen/LU>
#include <Eigen/SparseCore>

#include "core/pack.hpp"

namespace steplab {

// T is double for one run, a Pack of runs (core/pack.hpp) for runs stepped together.
template <int D, class T = double> using Vec = Eigen::Matrix<T, D, 1>;
template <int D, class T = double> using Mat = Eigen::Matrix<T, D, D>;

// A time (t, h) of one run (T = double) or of a pack's lanes: the T of the state it goes with,
// so that T is deduced from the state alone (step(s, y, 0, h) with a whole 0 for t is fine).
template <class T> using Time = std::type_identity_t<T>;

template <int D, class T = double> struct State {
  Vec<D, T> x;
  Vec<D, T> v;
};

// Lane by lane a where c holds, else b (c a bool for one run, a Mask for a pack), for vectors
// and matrices alike, coefficient by coefficient.
template <class C, class T, int R, int K, int O, int MR, int MK>
Eigen::Matrix<T, R, K, O, MR, MK> select(const C& c, const Eigen::Matrix<T, R, K, O, MR, MK>& a, const Eigen::Matrix<T, R, K, O, MR, MK>& b) {
  Eigen::Matrix<T, R, K, O, MR, MK> r = b;
  for (Eigen::Index j = 0; j < a.size(); ++j) r(j) = select(c, a(j), b(j));
  return r;
}

// Lane l of a vector or matrix of packs, as one run's doubles.
template <class T, int R, int K> Eigen::Matrix<double, R, K> lane_of(const Eigen::Matrix<T, R, K>& m, int l) {
  return m.unaryExpr([l](const T& p) { return p[l]; });
}

// |v|^2 as Eigen sums it for one run. Eigen adds a vector of doubles in SIMD pairs (v0^2 + v2^2 +
// v4^2 in one half, v1^2 + ... in the other, for 6 coordinates) and a vector of packs in another
// order, so for more than 2 coordinates a pack's lanes are summed one by one, each by Eigen's own
// code: the bits of a run alone (tests/analysis/pack_test.cpp, the falling triangle's energy).
template <int D, class T> T squared_norm(const Vec<D, T>& v) {
  if constexpr (std::is_same_v<T, double> || D <= 2) {
    return v.squaredNorm();
  } else {
    T sum;
    for (int l = 0; l < T::width; ++l) sum.set(l, lane_of(v, l).squaredNorm());
    return sum;
  }
}

// A zero state; empty for a state whose size is set at run time (D = Eigen::Dynamic).
template <int D, class T = double> State<D, T> zero_state() {
  if constexpr (D == Eigen::Dynamic) return {};
  else return {Vec<D, T>::Zero(), Vec<D, T>::Zero()};
}

// Force Jacobians for the implicit methods: dF/dx and dF/dv at one state (of a pack's lanes, T a Pack).
template <int D, class T = double> struct Jacobians {
  Mat<D, T> dx;
  Mat<D, T> dv;
};

// A scene of run-time size N has sparse ones (tridiagonal for the rope): a dense N x N would
// cost N^2 memory and N^3 to factorise.
using SparseMat = Eigen::SparseMatrix<double>;
template <> struct Jacobians<Eigen::Dynamic, double> {
  SparseMat dx;
  SparseMat dv;
};

// Whether every coordinate is finite, checked after every step of every run. NaN and +-inf
// propagate through a sum (inf - inf is NaN), so one sum and one test find them all at a
// dozen additions; the sum also overflows, flagging the state, if its coordinates add up past
// 1.8e308, which is a blow-up too. (Eigen's allFinite costs ~4x more instructions.)
// On a pack of runs, lane by lane (a Mask).
template <int D, class T> auto all_finite(const State<D, T>& s) { return finite(s.x.sum() + s.v.sum()); }

// Exactly Eigen's allFinite (x - x is NaN for inf and NaN, 0 otherwise) and isZero(0), over the
// scalar: lane by lane on a vector of packs.
template <class V> auto all_finite(const Eigen::MatrixBase<V>& v) { return finite((v - v).sum()); }
template <class V> auto all_zero(const Eigen::MatrixBase<V>& v) {
  using T = typename V::Scalar;
  MaskOf<T> zero(true);
  for (Eigen::Index j = 0; j < v.size(); ++j) zero = zero && v[j] == T(0.0);
  return zero;
}

}  // namespace steplab
