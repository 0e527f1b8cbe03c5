// The chain's ODE written out from its parameters, independently of core/scenes/chain.hpp, for
// Boost.Odeint to integrate as a reference.
#pragma once
#include <array>

namespace steplab {

using Z = std::array<double, 4>;  // (u1, u2, v1, v2)

// M u'' = -K u - C u', K = [[k1 + k2, -k2], [-k2, k2]], C likewise.
struct ChainOde {
  double m1, m2, k1, k2, c1, c2;
  void operator()(const Z& z, Z& dz, double) const {
    const double f1 = -k1 * z[0] - c1 * z[2] + k2 * (z[1] - z[0]) + c2 * (z[3] - z[2]);
    const double f2 = -k2 * (z[1] - z[0]) - c2 * (z[3] - z[2]);
    dz = {z[2], z[3], f1 / m1, f2 / m2};
  }
};

}  // namespace steplab
