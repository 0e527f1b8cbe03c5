// The soft body's largest stable step (core/scenes/softbody.hpp), predicted from its fastest
// mode: the body is not linear (springs turn, the ground switches on), so the prediction is for
// its linearisation at the start shape lowered onto the ground (the bottom row just in contact,
// its penalty springs on), where the fastest mode is fastest: at rest every spring is at its rest
// length, so dF/dx = -K and dF/dv = -(gamma/k) K_springs - C_ground, both symmetric.
//
// With equal masses M = m I, the modes are K's eigenvectors; the fastest,
//   omega_max^2 = lambda_max(K) / m,
// comes from power iteration on K started from the checkerboard (neighbours moving apart, the
// shape of a lattice's fastest mode), its Rayleigh quotient converged to 1e-12 relative (at most
// kPowerIterations products). Its damping ratio from the same vector u:
//   2 zeta omega_max = u^T C u / (m u^T u),
// and dt* = the unit oscillator's dt* at that zeta / omega_max (analysis/rope_stability.hpp), as
// for one mode of the rope. Slower modes are not examined (on the rope the fastest mode binds
// every method at small damping ratios: `study stability --scene rope` reports the binding mode).
#pragma once

#include <cstddef>

#include "core/state.hpp"

namespace steplab {

struct SoftBody;  // core/scenes/softbody.hpp

inline constexpr int kPowerIterations = 20'000;

struct FastestMode {
  double omega;     // omega_max
  double two_zeta;  // 2 zeta of that mode
};

// The start shape lowered until its bottom row is 1e-9 below the ground (Ground::level): every
// spring at rest, the bottom row's penalty springs on. Where the fastest mode is taken.
State<Eigen::Dynamic> lowered_onto_ground(const SoftBody& s);
FastestMode softbody_fastest_mode(const SoftBody& s);
double softbody_predicted_threshold(std::size_t method, const SoftBody& s);

}  // namespace steplab
