// The ground of the collision scenes: the line y = -1, and a repulsive (penalty) spring that
// pushes back a mass that is below it. With penetration p = -1 - y:
//
//   F_y = k_g p - c_g v_y            while p > 0, else 0
//   dF_y/dy = -k_g, dF_y/dv_y = -c_g while p > 0, else 0
//   energy 1/2 k_g p^2               while p > 0
//
// The force is continuous at contact (p = 0) but its derivative jumps there: the motion is
// only piecewise smooth, which is what the collision study measures the methods against.
#pragma once

namespace steplab {

struct Ground {
  static constexpr double level = -1.0;
  double k, c;  // stiffness k_g, damping c_g

  double penetration(double y) const { return level - y; }
  bool touching(double y) const { return y < level; }
  double force(double y, double vy) const { return touching(y) ? k * penetration(y) - c * vy : 0.0; }
  double dforce_dy(double y) const { return touching(y) ? -k : 0.0; }
  double dforce_dv(double y) const { return touching(y) ? -c : 0.0; }
  double energy(double y) const { return touching(y) ? 0.5 * k * penetration(y) * penetration(y) : 0.0; }
};

}  // namespace steplab
