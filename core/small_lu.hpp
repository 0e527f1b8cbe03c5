// A x = b for a small fixed N (an implicit Runge-Kutta method's stages on a small scene) by
// Gaussian elimination with partial pivoting, PA = LU:
//
//   for k = 0 .. N-2:  p = the first row i >= k with the largest |a_ik|; swap rows k and p of A and b;
//                      if a_kk != 0: a_ik /= a_kk (i > k);   then a_ij -= a_ik a_kj (i, j > k)
//   forward (L unit lower):   c_i = b_i - sum_{j<i} l_ij c_j
//   backward (U upper):       x_i = (c_i - sum_{j>i} u_ij x_j) / u_ii
//
// One run (T = double) takes Eigen's PartialPivLU (N = 1: the one division it comes to, for
// every T). A pack of runs (core/pack.hpp) takes the
// lines above lane by lane, each lane its own pivot row (a select where Eigen swaps), in the
// order of Eigen 3.4's unblocked factorisation and unrolled triangular solves (Eigen/src/LU/
// PartialPivLU.h, Core/SolveTriangular.h), so that a lane has the bits of its run alone
// (tests/core/small_lu_test.cpp, and every packed implicit method in tests/analysis/pack_test.cpp).
// Up to N = 3 that is Eigen's order of operations; at N = 4 last bits differ (measured, not
// traced). A larger system of a pack is solved lane by lane by Eigen's PartialPivLU itself, out
// of line (lu_lanes): the bits of a run alone, slower than one run at a time. The built-in
// methods are not packed on a scene where theirs would be (core/method.hpp, solve_stages); a
// plug-in method that does not declare its solves may come here.
#pragma once

#include <type_traits>

#include "core/state.hpp"

namespace steplab {

// The largest system a pack solves lane-wise in SIMD (below).
inline constexpr int kPackLuSize = 3;

// Out of line (noipa): not inlined into, nor compiled for the instruction set of, a batch's
// flattened loop (core/batch.hpp), so Eigen's double code is the one a run alone executes. The
// solution through b (a pack is passed by reference: core/pack.hpp).
template <int N, class T> [[gnu::noipa]] void lu_lanes(const Mat<N, T>& a, Vec<N, T>& b) {
  for (int l = 0; l < T::width; ++l) {
    const Vec<N> x = lane_of(a, l).partialPivLu().solve(lane_of(b, l));
    for (int i = 0; i < N; ++i) b[i].set(l, x[i]);
  }
}

template <int N, class T> [[gnu::always_inline]] inline Vec<N, T> lu_solve(Mat<N, T> a, Vec<N, T> b) {
  if constexpr (N == 1) {
    return Vec<1, T>(b[0] / a(0, 0));  // what Eigen's LU of a 1 x 1 does, without its set-up
  } else if constexpr (std::is_same_v<T, double>) {
    return a.partialPivLu().solve(b);
  } else if constexpr (N > kPackLuSize) {
    lu_lanes(a, b);
    return b;
  } else {
    using std::abs;
    // p and q exchanged in the lanes of `where`.
    const auto swap_where = [](const auto& where, T& p, T& q) {
      const T old = p;
      p = select(where, q, old);
      q = select(where, old, q);
    };
    // sum_{j = from}^{to - 1} a_ij b_j, from the first term on (0 + a_i0 b_0 is not -0 where the product is).
    const auto row_dot = [&](int i, int from, int to) {
      T sum = a(i, from) * b[from];
      for (int j = from + 1; j < to; ++j) sum += a(i, j) * b[j];
      return sum;
    };
    for (int k = 0; k + 1 < N; ++k) {
      T largest = abs(a(k, k)), pivot = double(k);
      for (int i = k + 1; i < N; ++i) {
        const T candidate = abs(a(i, k));
        const auto larger = candidate > largest;
        largest = select(larger, candidate, largest);
        pivot = select(larger, T(double(i)), pivot);
      }
      for (int i = k + 1; i < N; ++i) {
        const auto swap = pivot == T(double(i));
        if (!any(swap)) continue;
        for (int j = 0; j < N; ++j) swap_where(swap, a(k, j), a(i, j));
        swap_where(swap, b[k], b[i]);
      }
      const auto nonzero = largest != T(0.0);
      for (int i = k + 1; i < N; ++i) a(i, k) = select(nonzero, a(i, k) / a(k, k), a(i, k));
      for (int j = k + 1; j < N; ++j)
        for (int i = k + 1; i < N; ++i) a(i, j) -= a(i, k) * a(k, j);
    }
    for (int i = 1; i < N; ++i) b[i] -= row_dot(i, 0, i);
    for (int i = N - 1; i >= 0; --i) {
      if (i + 1 < N) b[i] -= row_dot(i, i + 1, N);
      b[i] /= a(i, i);
    }
    return b;
  }
}

}  // namespace steplab
