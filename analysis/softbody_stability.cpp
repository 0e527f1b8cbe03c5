#include "analysis/softbody_stability.hpp"

#include <cmath>
#include <utility>

#include "analysis/rope_stability.hpp"
#include "core/scenes/softbody.hpp"

namespace steplab {

State<Eigen::Dynamic> lowered_onto_ground(const SoftBody& s) {
  State<Eigen::Dynamic> y = s.initial();
  const double drop = (y.x[1] - Ground::level) + 1e-9;  // mass 0 is in the bottom row
  for (int i = 1; i < y.x.size(); i += 2) y.x[i] -= drop;
  return y;
}

FastestMode softbody_fastest_mode(const SoftBody& s) {
  const State<Eigen::Dynamic> y = lowered_onto_ground(s);
  const Jacobians<Eigen::Dynamic> j = s.jacobians(y.x, y.v);
  const SparseMat K = -j.dx, C = -j.dv;
  Eigen::VectorXd u(y.x.size());
  for (int i = 0; i < u.size(); ++i) {
    const int mass = i / 2, r = mass / s.n, c = mass % s.n;
    u[i] = ((r + c) % 2 == 0 ? 1.0 : -1.0) * (1 + 0.1 * std::sin(1.3 * i));  // not orthogonal to it by symmetry
  }
  u.normalize();
  double rq = 0;
  for (int it = 0; it < kPowerIterations; ++it) {
    const Eigen::VectorXd w = K * u;
    const double last = std::exchange(rq, u.dot(w));
    u = w.normalized();
    if (std::abs(rq - last) <= 1e-12 * std::abs(rq)) break;
  }
  const double omega = std::sqrt(rq / s.m);
  return {omega, u.dot(C * u) / (s.m * omega)};
}

double softbody_predicted_threshold(std::size_t method, const SoftBody& s) {
  const FastestMode f = softbody_fastest_mode(s);
  return unit_oscillator_threshold(method, f.two_zeta) / f.omega;
}

}  // namespace steplab
