// One damped oscillator's exact motion, u'' - 2 alpha u' + (alpha^2 + beta^2) u = 0 (so that its
// roots are alpha +- i beta), over a time t from (u0, v0), in every damping regime. With
// c = v0 - alpha u0:
//   underdamped (beta^2 > 0, undamped too): u = e^{alpha t} (u0 cos(beta t) + c sin(beta t) / beta)
//   critical    (beta^2 = 0):               u = e^{alpha t} (u0 + c t)
//   overdamped  (beta^2 < 0, delta^2 = -beta^2): u = e^{alpha t} (u0 cosh(delta t) + c sinh(delta t) / delta)
// sin(x)/beta and sinh(x)/delta stay accurate as beta or delta -> 0, so each form is exact to
// round-off right up to critical damping. The spring is one such oscillator, the rope's modes N.
#pragma once

#include <cmath>

namespace steplab {

struct Oscillation {
  double u, du;
};

inline Oscillation damped_oscillation(double u0, double v0, double alpha, double beta2, double t) {
  const double c = v0 - alpha * u0;
  double u, du;
  if (beta2 > 0) {
    const double beta = std::sqrt(beta2), e = std::exp(alpha * t);
    const double cs = std::cos(beta * t), sn = std::sin(beta * t);
    u = e * (u0 * cs + c * sn / beta);
    du = alpha * u + e * (-u0 * beta * sn + c * cs);
  } else if (beta2 == 0) {
    const double e = std::exp(alpha * t);
    u = e * (u0 + c * t);
    du = alpha * u + e * c;
  } else {
    // e^{alpha t} cosh(delta t) and e^{alpha t} sinh(delta t); for delta t >= 1 written with
    // exp((alpha +- delta) t), which cannot overflow (alpha + delta < 0) and does not cancel.
    const double delta = std::sqrt(-beta2);
    double ch, sh;
    if (delta * t < 1) {
      const double e = std::exp(alpha * t);
      ch = e * std::cosh(delta * t);
      sh = e * std::sinh(delta * t);
    } else {
      const double ep = std::exp((alpha + delta) * t), em = std::exp((alpha - delta) * t);
      ch = 0.5 * (ep + em);
      sh = 0.5 * (ep - em);
    }
    u = u0 * ch + c * sh / delta;
    du = alpha * u + u0 * delta * sh + c * ch;
  }
  return {u, du};
}

}  // namespace steplab
