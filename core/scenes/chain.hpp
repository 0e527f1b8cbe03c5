#pragma once
#include <array>
#include <cmath>
#include <complex>
#include <span>
#include <string_view>

#include "core/scene.hpp"
#include "core/springs.hpp"
#include "core/scenes/spring.hpp"

namespace steplab {

// A stiff two-mass chain on a line, no gravity:
//
//   wall --[k1, c1]-- m1 --[k2, c2]-- m2
//
// u1, u2 are the displacements from rest; M u'' = -K u - C u' with M = diag(m1, m2),
//   K = [[k1 + k2, -k2], [-k2, k2]],   C = [[c1 + c2, -c2], [-c2, c2]].
// Defaults: the sheet's soft spring (m 1, k 5, c 0.1) holding a second mass through a spring
// 10^4 times stiffer (k2 = 5e4, damped by c2 = 10), started with both masses displaced by 1, which
// is almost exactly the slow mode (the masses move together, omega^2 ~ k1 / (m1 + m2) = 2.5). The
// fast mode (the masses against each other, omega^2 ~ k2 (1/m1 + 1/m2) = 1e5, so omega ~ 316,
// eigenvalue ~ -10 +- 316i) carries almost none of the motion but bounds every explicit step:
// accuracy alone would allow steps set by omega ~ 1.6, stability allows about 1/100 of that.
// Its dynamics, T = double for one chain, a Pack for one per lane (core/batch.hpp); Chain below
// adds the exact flow, scalar.
template <class T> struct ChainT {
  template <class U> using as = ChainT<U>;
  static constexpr int dim = 2;
  static constexpr std::string_view name = "chain";
  static constexpr std::array<ParamSpec, 8> params{{
      {"mass1", 1.0, Bound::Positive, "mass m1 (next to the wall)"},
      {"mass2", 1.0, Bound::Positive, "mass m2 (the free end)"},
      {"stiffness1", 5.0, Bound::Positive, "stiffness k1 of the wall spring"},
      {"stiffness2", 5e4, Bound::Positive, "stiffness k2 of the spring between the masses"},
      {"damping1", 0.1, Bound::NonNegative, "damping c1 of the wall spring (force -c1 u1')"},
      {"damping2", 10.0, Bound::NonNegative, "damping c2 between the masses"},
      {"u1", 1.0, Bound::Any, "start displacement of m1 (at rest)"},
      {"u2", 1.0, Bound::Any, "start displacement of m2 (at rest)"},
  }};

  Vec<2, T> m, inv_m, u0;
  Mat<2, T> K, C;

  explicit ChainT(std::span<const T> p) : m(p[0], p[1]), inv_m(1 / p[0], 1 / p[1]), u0(p[6], p[7]) {
    const T k1 = p[2], k2 = p[3], c1 = p[4], c2 = p[5];
    K << k1 + k2, -k2, -k2, k2;
    C << c1 + c2, -c2, -c2, c2;
  }

  Vec<2, T> mass() const { return m; }
  Vec<2, T> inverse_mass() const { return inv_m; }
  Vec<2, T> force(const Vec<2, T>& x, const Vec<2, T>& v) const { return -(K * x) - C * v; }
  Jacobians<2, T> jacobians(const Vec<2, T>&, const Vec<2, T>&) const { return {-K, -C}; }
  // C != 0: a Mask for a pack
  auto velocity_dependent() const { return C(0, 0) != 0.0 || C(0, 1) != 0.0 || C(1, 1) != 0.0; }
  // As springs (core/springs.hpp; one run's, T = double), in displacements (rest lengths 0): the
  // wall's spring and dashpot on m1, C = u1; the stiff one between them, C = u2 - u1.
  int links() const { return 2; }
  Link link(int q) const {
    const double k2 = -K(0, 1), c2 = -C(0, 1);
    return q == 0 ? Link{0, -1, 0.0, K(0, 0) - k2, C(0, 0) - c2} : Link{1, 0, 0.0, k2, c2};
  }
  double external(int, double) const { return 0.0; }

  // Kinetic energy plus the springs' potential: 1/2 v^T M v + 1/2 u^T K u.
  T energy(const Vec<2, T>& x, const Vec<2, T>& v) const {
    return 0.5 * v.dot(m.cwiseProduct(v)) + 0.5 * x.dot(K * x);
  }

  State<2, T> initial() const { return {u0, Vec<2, T>::Zero()}; }
};

struct Chain : ChainT<double> {
  static constexpr bool affine_flow = true;  // flow(y, h) = e^{A h} y (core/scene.hpp)
  static constexpr std::string_view stiffness_param = "stiffness2";  // the stiff spring
  static constexpr std::string_view title = "Stiff two-mass chain";
  // The equation of motion, for the report (the math above is its derivation).
  static constexpr std::string_view equation = "m1 u1'' = -k1 u1 - c1 u1' + k2 (u2 - u1) + c2 (u2' - u1'),  m2 u2'' = -k2 (u2 - u1) - c2 (u2' - u1')";

  // Its stiff limit k2 -> inf: the two masses move as one, (m1 + m2) u'' = -k1 u - c1 u', the
  // spring scene (which starts at rest, m g / k above its equilibrium: g is chosen for the
  // amplitude of the chain's mass-weighted mean displacement, times sqrt 2, the norm of (u, u), so
  // that errors compare with the chain's two-coordinate ones).
  static constexpr std::string_view stiff_limit_scene = SpringT<double>::name;
  static std::vector<double> stiff_limit(std::span<const double> p) {
    const double m = p[0] + p[1], u = (p[0] * p[6] + p[1] * p[7]) / m;
    std::vector<double> s = default_values(SpringT<double>::params);  // mass, stiffness, damping, rest length, g
    s[0] = m, s[1] = p[2], s[2] = p[4], s[4] = p[2] * std::sqrt(2.0) * std::abs(u) / m;
    return s;
  }

  // Its two undamped modes, slowest first: omega^2 the eigenvalues of M^-1 K,
  //   omega^2 = a/2 -+ sqrt(a^2/4 - b),   a = (k1 + k2)/m1 + k2/m2,   b = k1 k2 / (m1 m2),
  // each with its modal damping 2 zeta omega = phi^T C phi / phi^T M phi, phi the mode's shape
  // (K - omega^2 M) phi = 0. The damping is a projection: exact when C is a combination of M and
  // K, here it leaves out C's coupling of the two modes (c2 is small against the fast mode's
  // 2 sqrt(k2 m)).
  std::vector<Mode> modes() const {
    const double a = K(0, 0) / m[0] + K(1, 1) / m[1], b = (K(0, 0) * K(1, 1) - K(0, 1) * K(1, 0)) / (m[0] * m[1]);
    const double disc = std::sqrt(a * a / 4 - b);
    std::vector<Mode> out;
    for (const double w2 : {a / 2 - disc, a / 2 + disc}) {
      const Vec<2, double> phi(K(0, 1), w2 * m[0] - K(0, 0));
      const double omega = std::sqrt(w2);
      out.push_back({omega, phi.dot(C * phi) / phi.dot(m.cwiseProduct(phi)) / omega});
    }
    return out;
  }

  using Vec4 = Eigen::Vector4d;
  using CMat4 = Eigen::Matrix4cd;
  using CVec4 = Eigen::Vector4cd;

  using LMat4 = Eigen::Matrix<long double, 4, 4>;
  using LCMat4 = Eigen::Matrix<std::complex<long double>, 4, 4>;

  // The first-order system z' = A z, z = (u1, u2, v1, v2): A = [[0, I], [-M^-1 K, -M^-1 C]],
  // its entries rounded once from the parameters in long double.
  LMat4 A;
  // Its eigen-decomposition A = V diag(lambda) V^-1, so that z(t) = V diag(e^{lambda t}) V^-1 z0.
  // Computed once in long double: in double the slow eigenvalues carry the backward error of the
  // whole matrix, eps |A| ~ 1e-11 (|A| ~ k2 / m), and z(10) came out 3e-12 off (against a 50-digit
  // matrix exponential, mpmath); from long double, evaluated in double, 1.0e-14. Where V is
  // ill-conditioned (a mode at critical damping, where A is defective) the flow is e^{A t} from
  // Eigen's matrix exponential in long double instead (Pade, scaling and squaring: slower, exact to
  // round-off for every A; tests/core/chain_test.cpp checks both against the ODE).
  CMat4 V, V_inv;
  CVec4 lambda, start;  // start: V^-1 z0
  bool use_eigen = false;
  static constexpr double kMaxCondition = 1e8;

  // Defined at the end of this file, compiled once (STEPLAB_SCENE_SOURCE below).
  explicit Chain(std::span<const double> p);

  State<2> exact_at(double t) const { return use_eigen ? modal(start, t) : flow(initial(), t); }

  State<2> flow(const State<2>& y, double t) const {
    if (!use_eigen) return expm_flow(y, t);
    return modal(V_inv * to_z(y).cast<std::complex<double>>(), t);
  }

 private:
  State<2> expm_flow(const State<2>& y, double t) const;  // e^{A t} y in long double
  // z(t) = V diag(e^{lambda t}) c for modal coordinates c = V^-1 z(0).
  State<2> modal(const CVec4& c, double t) const {
    return to_state((V * (lambda * t).array().exp().matrix().cwiseProduct(c)).real());
  }
  static Vec4 to_z(const State<2>& y) { return {y.x[0], y.x[1], y.v[0], y.v[1]}; }
  static State<2> to_state(const Vec4& z) { return {z.head<2>(), z.tail<2>()}; }
};

}  // namespace steplab

// The eigen-decomposition and the matrix exponential in long double take GCC about 10 s to
// compile: here, not in every file that includes the chain. A scene's generated translation unit
// (tools/kernels.cmake) defines STEPLAB_SCENE_SOURCE, so they are compiled once, into the kernel
// library (steplab::kernels).
#ifdef STEPLAB_SCENE_SOURCE
#include <Eigen/Eigenvalues>
#include <unsupported/Eigen/MatrixFunctions>

namespace steplab {

Chain::Chain(std::span<const double> p) : ChainT<double>(p) {
  const double k1 = p[2], k2 = p[3], c1 = p[4], c2 = p[5];
  const long double lm1 = p[0], lm2 = p[1], lk1 = k1, lk2 = k2, lc1 = c1, lc2 = c2;
  A << 0, 0, 1, 0, 0, 0, 0, 1, -(lk1 + lk2) / lm1, lk2 / lm1, -(lc1 + lc2) / lm1, lc2 / lm1, lk2 / lm2, -lk2 / lm2,
      lc2 / lm2, -lc2 / lm2;
  const Eigen::EigenSolver<LMat4> es(A);
  if (es.info() == Eigen::Success) {
    const LCMat4 v = es.eigenvectors(), v_inv = v.inverse();
    const long double condition = v.cwiseAbs().rowwise().sum().maxCoeff() * v_inv.cwiseAbs().rowwise().sum().maxCoeff();
    use_eigen = std::isfinite(condition) && condition < kMaxCondition;
    V = v.cast<std::complex<double>>();
    V_inv = v_inv.cast<std::complex<double>>();
    lambda = es.eigenvalues().cast<std::complex<double>>();
    start = (v_inv * Eigen::Matrix<std::complex<long double>, 4, 1>(u0[0], u0[1], 0, 0)).cast<std::complex<double>>();
  }
}

State<2> Chain::expm_flow(const State<2>& y, double t) const {
  return to_state(((A * t).exp() * to_z(y).cast<long double>()).cast<double>());
}

}  // namespace steplab
#endif

STEPLAB_SCENE(steplab::Chain);
