// A x = b for a small fixed N (an implicit Runge-Kutta method's stages on a small scene) by
// Gaussian elimination with partial pivoting, PA = LU:
//
//   for k = 0 .. N-2:  p = the first row i >= k with the largest |a_ik|; swap rows k and p of A and b;
//                      if a_kk != 0: a_ik /= a_kk (i > k);   then a_ij -= a_ik a_kj (i, j > k)
//   forward (L unit lower):   c_i = b_i - sum_{j<i} l_ij c_j
//   backward (U upper):       x_i = (c_i - sum_{j>i} u_ij x_j) / u_ii
//
// One run (T = double) takes Eigen's PartialPivLU. A pack of runs (core/pack.hpp) takes the
// lines above lane by lane, each lane its own pivot row (a select where Eigen swaps), in the
// order of Eigen 3.4's unblocked factorisation and unrolled triangular solves (Eigen/src/LU/
// PartialPivLU.h, Core/SolveTriangular.h), so that a lane has the bits of its run alone
// (tests/core/small_lu_test.cpp, and every packed implicit method in tests/analysis/pack_test.cpp).
// Up to N = 3 that is Eigen's order of operations; at N = 4 last bits differ (measured, not
// traced): hence N <= 3 for a pack, the spring's stages.
#pragma once

#include <type_traits>

#include "core/state.hpp"

namespace steplab {

template <int N, class T> [[gnu::always_inline]] inline Vec<N, T> lu_solve(Mat<N, T> a, Vec<N, T> b) {
  if constexpr (std::is_same_v<T, double>) {
    return a.partialPivLu().solve(b);
  } else {
    static_assert(N <= 3, "a pack's LU has Eigen's order of operations up to N = 3");
    using std::abs;
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
        for (int j = 0; j < N; ++j) {
          const T row_k = a(k, j);
          a(k, j) = select(swap, a(i, j), row_k);
          a(i, j) = select(swap, row_k, a(i, j));
        }
        const T b_k = b[k];
        b[k] = select(swap, b[i], b_k);
        b[i] = select(swap, b_k, b[i]);
      }
      const auto nonzero = largest != T(0.0);
      for (int i = k + 1; i < N; ++i) a(i, k) = select(nonzero, a(i, k) / a(k, k), a(i, k));
      for (int j = k + 1; j < N; ++j)
        for (int i = k + 1; i < N; ++i) a(i, j) -= a(i, k) * a(k, j);
    }
    for (int i = 1; i < N; ++i) {
      T sum = a(i, 0) * b[0];
      for (int j = 1; j < i; ++j) sum += a(i, j) * b[j];
      b[i] -= sum;
    }
    for (int i = N - 1; i >= 0; --i) {
      if (i + 1 < N) {
        T sum = a(i, i + 1) * b[i + 1];
        for (int j = i + 2; j < N; ++j) sum += a(i, j) * b[j];
        b[i] -= sum;
      }
      b[i] /= a(i, i);
    }
    return b;
  }
}

}  // namespace steplab
