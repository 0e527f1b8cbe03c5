// What a scene offers the long-time study (analysis/studies/long_time.hpp): the quantities its
// exact motion keeps, and the scales that study measures time and distance in.
//
//   invariant_names               static: their names, e.g. {"energy", "angular momentum"}
//   invariants(x, v)              their values at a state, in that order (an std::array)
//   period()                      the time the study counts in (Kepler's orbit: its period;
//                                 the swinging spring: its slowest linearised period)
//   extent()                      a length the position error is compared with (the orbit's
//                                 semi-major axis): a run is "out of phase" once its error
//                                 reaches it
//
// Theory the study measures against (Hairer, Lubich and Wanner, Geometric Numerical Integration,
// ch. I, IX, X): a symplectic method of order p keeps the energy error O(h^p), bounded, over
// exponentially long times; a method that is neither symplectic nor symmetric drifts, about
// linearly in t. Symplectic (partitioned) Runge-Kutta methods keep every quadratic invariant
// x^T C v, angular momentum among them, to round-off. The phase error grows like t for the
// symplectic and symmetric methods and like t^2 otherwise.
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <string_view>

#include "core/scene.hpp"

namespace steplab {

// The four members as the study reads them (core/scene_checks.hpp, where STEPLAB_SCENE checks that
// a scene naming one declares all four so).
template <class S>
concept HasInvariants = Scene<S> && InvariantsAsRead<S> && PeriodAsRead<S> && ExtentAsRead<S>;

}  // namespace steplab
