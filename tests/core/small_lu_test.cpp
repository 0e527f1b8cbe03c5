// core/small_lu.hpp on packs against Eigen's PartialPivLU, lane by lane: each lane's solution has
// the bits Eigen gives for that lane's system alone, for N = 2 and 3, over systems that pivot
// every way: random reals (a different pivot row per lane), and small whole numbers in [-2, 2],
// which give ties in |a_ik| (Eigen keeps the first largest), zero pivots and singular matrices
// (Eigen skips the division by a zero pivot and its solution is inf or NaN).
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include "core/small_lu.hpp"

namespace steplab {
namespace {

// Bits, but any NaN equals any NaN: which operand's payload a NaN carries is the compiler's choice
// of operand order in a commutative operation, not the arithmetic's.
bool same_bits(double a, double b) {
  return (std::isnan(a) && std::isnan(b)) || std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

template <int N, int W> void expect_eigens_bits(int systems) {
  std::mt19937_64 rng(N * 10 + W);
  std::uniform_real_distribution<double> real(-1.0, 1.0);
  std::uniform_int_distribution<int> whole(-2, 2);
  int pivoted = 0, singular = 0;
  for (int k = 0; k < systems; ++k) {
    std::array<Mat<N>, W> a;
    std::array<Vec<N>, W> b;
    Mat<N, Pack<W>> pa;
    Vec<N, Pack<W>> pb;
    for (int l = 0; l < W; ++l) {
      const bool whole_numbers = l % 2 == 1;
      for (int i = 0; i < N; ++i) {
        for (int j = 0; j < N; ++j) {
          a[l](i, j) = whole_numbers ? whole(rng) : real(rng);
          pa(i, j).set(l, a[l](i, j));
        }
        b[l][i] = real(rng);
        pb[i].set(l, b[l][i]);
      }
    }
    const Vec<N, Pack<W>> x = lu_solve(pa, pb);
    for (int l = 0; l < W; ++l) {
      const Eigen::PartialPivLU<Mat<N>> lu(a[l]);
      const Vec<N> expected = lu.solve(b[l]);
      pivoted += lu.permutationP().indices() != Eigen::Matrix<int, N, 1>::LinSpaced(0, N - 1);
      singular += !expected.allFinite();
      for (int i = 0; i < N; ++i)
        EXPECT_TRUE(same_bits(x[i][l], expected[i]))
            << "N " << N << " system " << k << " lane " << l << " x_" << i << ": " << x[i][l] << " vs Eigen's " << expected[i]
            << "\n" << a[l];
    }
  }
  EXPECT_GT(pivoted, systems / 2);  // the cases the test is for do occur
  EXPECT_GT(singular, 0);
}

TEST(SmallLu, EveryLaneHasTheBitsOfEigensPartialPivLu) {
  expect_eigens_bits<2, 2>(3000);
  expect_eigens_bits<2, 4>(3000);
  expect_eigens_bits<3, 4>(3000);
  expect_eigens_bits<3, 8>(3000);
}

}  // namespace
}  // namespace steplab
