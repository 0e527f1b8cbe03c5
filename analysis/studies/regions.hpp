// Stability regions in the complex plane z = h lambda, measured through each method's own code.
//
// The linear test system  u'' + c u' + k u = 0  (m = 1) has characteristic roots lambda, conj(lambda)
// with c = -2 Re lambda, k = |lambda|^2 (any sign: the test scene below takes any real c, k; a
// real lambda is a double root, c = -2 lambda, k = lambda^2). One step of length h = 1 is then
// linear, and its matrix (the whole step map, memory included) has the eigenvalues
//   one-step method:   R(z), R(conj z) = conj R(z)            so rho = |R(z)|
//   multistep method:  the roots zeta of rho(zeta) - z sigma(zeta), and of its conjugate
// so "rho <= 1" is |R(z)| <= 1, or the root condition, at z = lambda. Methods without a scalar
// stability function (the partitioned ones: symplectic Euler, Verlet, Yoshida; see
// has_stability_function) are left out: their step matrix is not a function of h A.
#pragma once

#include <cstddef>
#include <vector>

#include "analysis/kernel/parallel.hpp"

namespace steplab {

struct RegionConfig {
  std::vector<std::size_t> methods;  // those without a stability function are skipped
  double re_min = -7, re_max = 3, im_max = 5;
  int re_points = 161, im_points = 81;  // im from 0 to im_max; the region is symmetric about the real axis
  Workers workers;  // threads (0: all cores), progress, shard log
};

struct StabilityRegion {
  std::size_t method;
  std::vector<std::vector<double>> rho;  // [im][re]: spectral radius of the step map at z
};

struct RegionResult {
  RegionConfig config;
  std::vector<double> re, im;
  std::vector<StabilityRegion> regions;
};

inline constexpr double kRegionTolerance = 1e-9;  // rho <= 1 + this counts as stable (round-off)

// The spectral radius of method's step map at z = re + i im (h = 1).
double region_rho(std::size_t method, double re, double im);

RegionResult stability_regions(const RegionConfig& config);

// Whether the region holds every grid point with Re z <= 0 (A-stability, as far as the grid sees).
bool left_half_plane_stable(const RegionResult& r, const StabilityRegion& region);

}  // namespace steplab
