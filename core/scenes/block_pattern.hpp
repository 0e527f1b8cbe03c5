// The sparse pattern of a mass-spring scene's Jacobians dF/dx and dF/dv (they share it), made once
// for a run: d x d blocks, every coordinate's diagonal, and for each spring joining masses i and j
// its four blocks (i, i), (j, j), (i, j), (j, i), or only (i, i) where j is a fixed point (-1). A
// spring's blocks are B, B, -B, -B (core/scenes/pair_spring.hpp): add() puts them into a matrix's
// values through the slots found once, so that a step's Jacobians are a pass over the springs
// with no search and no allocation (the soft body's, the cloth's).
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include <Eigen/SparseCore>

#include "core/state.hpp"

namespace steplab {

template <int d> struct BlockPattern {
  SparseMat matrix;
  // Per spring and entry (a, c) of its blocks, in that order: the slots of (d i + a, d i + c),
  // (d j + a, d j + c), (d i + a, d j + c), (d j + a, d i + c); the last three -1 at a fixed end.
  std::vector<int> slots;

  BlockPattern() = default;
  // For `coords` coordinates and springs with ends .i and .j, j = -1 for a fixed point.
  template <class Springs> BlockPattern(int coords, const Springs& springs) {
    std::vector<std::pair<int, int>> entries;  // (-1, -1): no entry
    for (const auto& s : springs)
      for (int a = 0, i = s.i, j = s.j; a < d; ++a)
        for (int c = 0; c < d; ++c) {
          entries.push_back({d * i + a, d * i + c});
          if (j >= 0) entries.insert(entries.end(), {{d * j + a, d * j + c}, {d * i + a, d * j + c}, {d * j + a, d * i + c}});
          else entries.insert(entries.end(), 3, {-1, -1});
        }
    std::vector<Eigen::Triplet<double>> t;
    for (int k = 0; k < coords; ++k) t.emplace_back(k, k, 0.0);
    for (const auto& [r, c] : entries)
      if (r >= 0) t.emplace_back(r, c, 0.0);
    matrix = SparseMat(coords, coords);
    matrix.setFromTriplets(t.begin(), t.end());
    for (const auto& [r, c] : entries) slots.push_back(r < 0 ? -1 : slot(r, c));
  }

  // Where entry (r, c) sits in the values (it is in the pattern).
  int slot(int r, int c) const {
    const int *inner = matrix.innerIndexPtr(), *outer = matrix.outerIndexPtr();
    return static_cast<int>(std::lower_bound(inner + outer[c], inner + outer[c + 1], r) - inner);
  }

  // jac on this pattern (given it on a run's first call), its values zeroed.
  void zero(Jacobians<Eigen::Dynamic>& jac) const {
    if (jac.dx.nonZeros() != matrix.nonZeros() || jac.dx.rows() != matrix.rows()) jac = {matrix, matrix};
    std::fill(jac.dx.valuePtr(), jac.dx.valuePtr() + matrix.nonZeros(), 0.0);
    std::fill(jac.dv.valuePtr(), jac.dv.valuePtr() + matrix.nonZeros(), 0.0);
  }

  // Spring q's blocks B, B, -B, -B added into the values f.
  void add(double* f, std::size_t q, const Eigen::Matrix<double, d, d>& b) const {
    const int* slot = &slots[4 * d * d * q];
    for (int a = 0; a < d; ++a)
      for (int c = 0; c < d; ++c, slot += 4) {
        f[slot[0]] += b(a, c);
        if (slot[1] >= 0) f[slot[1]] += b(a, c), f[slot[2]] -= b(a, c), f[slot[3]] -= b(a, c);
      }
  }
};

}  // namespace steplab
