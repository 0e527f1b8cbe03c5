#pragma once
#include <algorithm>
#include <cmath>

#include "core/method.hpp"
#include "core/springs.hpp"

namespace steplab {

// Position-based dynamics (Mueller, Heidelberger, Hennix, Ratcliff, "Position based dynamics",
// VRIPHYS 2006 / JVCIR 2007, Algorithm 1), on a mass-spring scene's springs (core/springs.hpp).
// One step of h:
//   v += h M^-1 f_ext(v);  v += h M^-1 f_dashpots(x, v)         (its lines 5-6: the dashpots,
//                                                                 explicitly, as dampVelocities)
//   p  = x + h v
//   `sweeps` Gauss-Seidel sweeps; each spring q moves its ends along grad C by
//     dp_i = -k' w_i / (w_i + w_j) C grad_i C,   dp_j = +k' w_j / (w_i + w_j) C grad_i C
//   with the per-sweep stiffness k' = 1 - (1 - k_s)^(1/sweeps) (its section 3.3), so that the
//   sweeps together close the fraction k_s of a lone constraint's violation, whatever their number;
//   the ground a one-sided constraint likewise, where a mass is below it
//   v = (p - x) / h,  x = p
// PBD has no stiffness of its own: k_s in [0, 1] is set by hand, once. Here it is set from the
// scene's own spring so that at one step of a frame at 60 a second and one sweep a spring moves
// as XPBD's does (core/methods/xpbd.hpp, its first sweep: k h^2 w / (k h^2 w + 1), h = 1/60,
// w = w_i + w_j). At another step or sweep count the same k_s makes another material: halve h and
// each second has twice the projections, each closing the same fraction: stiffer. That is what
// XPBD's compliance fixes, and what the frame-budget study measures. So it does not converge to
// the scene's motion as h -> 0 (`converges = false`, order 0: none): the springs stiffen towards
// rigid rods instead; `steplab check --method pbd` measures that.
struct Pbd {
  static constexpr MethodInfo info{.name = "pbd", .order = 0, .family = Family::PositionBased, .on_springs = true,
                                   .converges = false,
                                   .summary = "v += h M^-1 f_ext; p = x + h v; sweeps projecting each spring by k' = 1 - (1 - "
                                              "k_s)^(1/sweeps), k_s fixed at a frame of 1/60 s; v = (p - x) / h"};
  static constexpr double kFrame = 1.0 / 60;  // the step k_s is set at

  // k_s of a constraint of stiffness k between ends of inverse masses summing to w.
  static double stiffness(double k, double w) {
    const double s = k * kFrame * kFrame * w;
    return s / (s + 1);
  }
  static double per_sweep(double ks, int sweeps) { return 1 - std::pow(1 - ks, 1.0 / sweeps); }

  template <MassSpring S> static StepStatus step(const S& s, State<S::dim>& y, double, double h, const MethodSettings& set) {
    constexpr int d = coords_per_mass<S>();
    decltype(auto) w = s.inverse_mass();  // per coordinate
    const int links = s.links(), masses = static_cast<int>(y.x.size()) / d;
    // Lines 5-6: external forces, then the dashpots (each at the velocities the step has reached).
    for (Eigen::Index a = 0; a < y.v.size(); ++a) y.v[a] += h * w[a] * s.external(static_cast<int>(a), y.v[a]);
    for (int q = 0; q < links; ++q) {
      const Link l = s.link(q);
      const LinkAt at = link_at<d>(l, y.x);
      if (!at.has_direction || l.c == 0) continue;
      const double impulse = -h * l.c * along<d>(l, at, y.v, Zeros{});
      for (int axis = 0; axis < d; ++axis) {
        if (l.i >= 0) y.v[d * l.i + axis] += at_end<d>(w, l.i, 0) * impulse * at.g[axis];
        if (l.j >= 0) y.v[d * l.j + axis] -= at_end<d>(w, l.j, 0) * impulse * at.g[axis];
      }
    }
    const Temp<S::dim> start = y.x;
    y.x += h * y.v;
    // k' of each spring, then of the ground under each mass: the same in every sweep, so a pow each
    // in the first sweep (where it overlaps the projections' chain) and kept for the others.
    const int grounds = HasGround<S> ? masses : 0;
    auto k1 = spring_numbers<S::dim, 2>(links + grounds);
    for (int sweep = 0; sweep < set.sweeps; ++sweep) {
      for (int q = 0; q < links; ++q) {
        const Link l = s.link(q);
        const LinkAt at = link_at<d>(l, y.x);
        const double wi = at_end<d>(w, l.i, 0), wj = at_end<d>(w, l.j, 0);
        if (sweep == 0) k1[q] = per_sweep(stiffness(l.k, wi + wj), set.sweeps);
        if (!at.has_direction || wi + wj == 0) continue;
        const double move = -k1[q] * at.c / (wi + wj);
        for (int axis = 0; axis < d; ++axis) {
          if (l.i >= 0) y.x[d * l.i + axis] += wi * move * at.g[axis];
          if (l.j >= 0) y.x[d * l.j + axis] -= wj * move * at.g[axis];
        }
      }
      if constexpr (HasGround<S>)
        for (int i = 0; i < masses; ++i) {
          const int a = d * i + d - 1;
          if (sweep == 0) k1[links + i] = per_sweep(stiffness(s.ground.k, w[a]), set.sweeps);
          if (y.x[a] < Ground::level) y.x[a] -= k1[links + i] * (y.x[a] - Ground::level);
        }
    }
    y.v = (y.x - start) / h;
    return StepStatus::Ok;
  }
};

}  // namespace steplab

STEPLAB_METHOD(steplab::Pbd);
