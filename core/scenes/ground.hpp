// The ground of the collision scenes: the line y = -1, and a repulsive (penalty) spring that
// pushes back a mass that is below it. With penetration p = -1 - y:
//
//   F_y = k_g p - c_g v_y            while p > 0, else 0
//   dF_y/dy = -k_g, dF_y/dv_y = -c_g while p > 0, else 0
//   energy 1/2 k_g p^2               while p > 0
//
// The force is continuous at contact (p = 0) but its derivative jumps there: the motion is
// only piecewise smooth, which is what the collision study measures the methods against.
// T = double: one ground; a Pack: one per lane, "while p > 0" a select (core/pack.hpp).
#pragma once

#include "core/pack.hpp"

namespace steplab {

template <class T> struct GroundT {
  static constexpr double level = -1.0;
  T k, c;  // stiffness k_g, damping c_g

  T penetration(const T& y) const { return level - y; }
  auto touching(const T& y) const { return y < level; }  // a Mask for a pack
  T force(const T& y, const T& vy) const { return select(touching(y), k * penetration(y) - c * vy, T(0.0)); }
  T dforce_dy(const T& y) const { return select(touching(y), -k, T(0.0)); }
  T dforce_dv(const T& y) const { return select(touching(y), -c, T(0.0)); }
  T energy(const T& y) const { return select(touching(y), 0.5 * k * penetration(y) * penetration(y), T(0.0)); }
};

using Ground = GroundT<double>;

}  // namespace steplab
