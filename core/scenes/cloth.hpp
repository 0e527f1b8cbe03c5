// Cloth: an n x n grid of 3-D masses joined by stretch, shear and bending springs, pinned at the
// two corners of one edge, released flat and horizontal: it falls and swings about that edge
// through large rotations (what graphics simulates at a frame budget). Grid point (r, c), row r
// from the pinned edge, column c, rests at
//   p(r, c) = ((c - (n - 1)/2) h, r h, 0),   h = S / (n - 1)        (side S, z up)
// and (0, 0), (0, n - 1) are fixed there. The other n^2 - 2 masses are the state, in grid order
// with the two pins left out; mass i has coordinates x, y, z at 3i, 3i + 1, 3i + 2.
//
// A refinement of one sheet, not a larger one: the totals stay as n grows.
//   each mass      m = M / n^2                       (total mass M, the pins' share included)
//   stretch        to the right and below, rest h,       stiffness k_s
//   shear          both diagonals, rest sqrt(2) h,       stiffness k_sh
//   bending        across two (r, c)-(r, c+2), (r, c)-(r+2, c), rest 2 h, stiffness k_b
//   each spring    a dashpot gamma along itself
// A spring's k is kept as n grows: a 2-D lattice's modulus is k itself whatever h (the soft body's
// argument, core/scenes/softbody.hpp), so the stiffest mode's frequency grows as n
// (omega^2 ~ k / m ~ n^2) and an explicit method's stable step shrinks with the edge length h.
//
// Each spring pulls along itself, damped along itself (core/scenes/pair_spring.hpp in 3-D: its
// force, 3 x 3 Jacobian blocks and energy); a spring to a pin has the pin as its fixed end
// (core/springs.hpp, `fixed`), with no velocity. Plus gravity -m g on every z. dF/dx is not
// symmetric where gamma > 0 (the damping force turns with the spring): Newton factorises by
// sparse LU (core/sparse.hpp). No exact motion: the studies compare with a converged run.
#pragma once

#include <array>
#include <cmath>
#include <span>
#include <vector>

#include "core/scene.hpp"
#include "core/springs.hpp"
#include "core/scenes/block_pattern.hpp"
#include "core/scenes/pair_spring.hpp"

namespace steplab {

struct Cloth {
  static constexpr int dim = Eigen::Dynamic;
  static constexpr std::string_view name = "cloth";
  // What it offers the studies (core/scene.hpp): refined by its grid side n, three coordinates a
  // mass, springs (XPBD, PBD, Baraff-Witkin run on it), sparse Jacobians of 3 x 3 blocks.
  static constexpr std::string_view title = "Cloth of n x n masses";
  static constexpr std::string_view equation =
      "m x_i'' = sum over the stretch, shear and bending springs j of i: f_ij along the spring, damped along it; - m g in z; "
      "two corners pinned";
  static constexpr std::string_view size_param = "grid";
  static constexpr int coords_per_mass = 3;
  static constexpr std::string_view stiffness_param = "stiffness";
  static constexpr std::string_view damping_param = "damping";
  // Defaults: a sheet of 1 m and 0.5 kg (a heavy cotton), 16 x 16 masses; stretch stiff against
  // shear, bending softer still (cloth gives little in its plane, folds easily). Dashpots of
  // 1 N s/m: lighter ones leave the folds that form as it swings up to grow from round-off, so
  // that no run converges over the frames (RK4 at 500 and 1000 substeps a frame, 2 s: 0.04 m
  // apart at gamma 0.01 and n = 16, 7e-3 at 0.3 and n = 32; at 1, 3e-10 and 3e-7).
  static constexpr std::array<ParamSpec, 8> params{{
      {"grid", 16, Bound::Positive, "masses along each side n (n x n masses; a whole number, 2 to 128)", true, 128, 2},
      {"mass", 0.5, Bound::Positive, "total mass M (each mass M/n^2)"},
      {"stiffness", 1000.0, Bound::Positive, "stiffness k_s of every stretch spring (kept as n grows)"},
      {"shear", 100.0, Bound::NonNegative, "stiffness k_sh of every shear spring (the diagonals)"},
      {"bending", 10.0, Bound::NonNegative, "stiffness k_b of every bending spring (across two)"},
      {"damping", 1.0, Bound::NonNegative, "dashpot gamma of every spring, along the spring"},
      {"side", 1.0, Bound::Positive, "side S of the square at rest (spacing S/(n-1))"},
      {"gravity", 9.81, Bound::NonNegative, "gravitational acceleration g (pointing down, -z)"},
  }};

  int n;
  double M, gamma, side, g;
  int masses = n * n - 2;
  double m = M / (n * n), inv_m = 1 / m;
  std::vector<Link> springs;  // state masses i, j; j = -1: a pin, at `fixed`
  Eigen::VectorXd m_all = Eigen::VectorXd::Constant(3 * masses, m), inv_m_all = Eigen::VectorXd::Constant(3 * masses, inv_m);
  // The Jacobians' pattern (core/scenes/block_pattern.hpp: each mass's 3 x 3 block, each spring's
  // four, or one where it ends at a pin), made once.
  BlockPattern<3> pattern;

  explicit Cloth(std::span<const double> p)
      : n(static_cast<int>(p[0])), M(p[1]), gamma(p[5]), side(p[6]), g(p[7]) {
    const double h = spacing(), stretch = p[2], shear = p[3], bending = p[4];
    const auto join = [&](int r0, int c0, int r1, int c1, double rest, double k) {
      if (r1 >= n || c1 < 0 || c1 >= n) return;
      const int a = index(r0, c0), b = index(r1, c1);
      if (a < 0 && b < 0) return;  // both pinned: a constant force on nothing
      if (a >= 0 && b >= 0) return springs.push_back({a, b, rest, k, gamma});
      const std::array<double, 3> pin = a < 0 ? rest_position(r0, c0) : rest_position(r1, c1);
      springs.push_back({a < 0 ? b : a, -1, rest, k, gamma, {pin[0], pin[1], pin[2]}});
    };
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) {
        join(r, c, r, c + 1, h, stretch), join(r, c, r + 1, c, h, stretch);
        join(r, c, r + 1, c + 1, std::sqrt(2.0) * h, shear), join(r, c, r + 1, c - 1, std::sqrt(2.0) * h, shear);
        join(r, c, r, c + 2, 2 * h, bending), join(r, c, r + 2, c, 2 * h, bending);
      }
    pattern = BlockPattern<3>(3 * masses, springs);
  }

  double spacing() const { return side / (n - 1); }
  // The state mass of grid point (r, c); -1 at a pin.
  int index(int r, int c) const {
    const int grid = r * n + c;
    return grid == 0 || grid == n - 1 ? -1 : grid - (grid < n - 1 ? 1 : 2);
  }
  std::array<double, 3> rest_position(int r, int c) const { return {(c - 0.5 * (n - 1)) * spacing(), r * spacing(), 0.0}; }

  const Eigen::VectorXd& mass() const { return m_all; }
  const Eigen::VectorXd& inverse_mass() const { return inv_m_all; }

  // p_i - p_j and v_i - v_j of a spring (p_j the pin, v_j = 0, where j = -1); the spring itself.
  template <class X> static Eigen::Vector3d apart(const Link& s, const X& x) {
    return s.j < 0 ? Eigen::Vector3d(x.template segment<3>(3 * s.i) - Eigen::Vector3d(s.fixed))
                   : Eigen::Vector3d(x.template segment<3>(3 * s.i) - x.template segment<3>(3 * s.j));
  }
  template <class V> static Eigen::Vector3d closing(const Link& s, const V& v) {
    return s.j < 0 ? Eigen::Vector3d(v.template segment<3>(3 * s.i))
                   : Eigen::Vector3d(v.template segment<3>(3 * s.i) - v.template segment<3>(3 * s.j));
  }
  static PairSpring3 pull(const Link& s) { return {s.k, s.c}; }

  // F into the run's f.
  void force(Eigen::Ref<const Eigen::VectorXd> x, Eigen::Ref<const Eigen::VectorXd> v, Eigen::Ref<Eigen::VectorXd> f) const {
    for (int i = 0; i < masses; ++i) f[3 * i] = 0, f[3 * i + 1] = 0, f[3 * i + 2] = -m * g;
    for (const Link& s : springs) {
      const Eigen::Vector3d fi = pull(s).force(apart(s, x), closing(s, v), s.rest);
      f.segment<3>(3 * s.i) += fi;
      if (s.j >= 0) f.segment<3>(3 * s.j) -= fi;
    }
  }

  // Sparse, on the pattern made once: each spring's blocks added in spring order. Into the run's
  // jac, which takes the pattern on its first call; by value for a caller outside a run.
  Jacobians<Eigen::Dynamic> jacobians(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const {
    Jacobians<Eigen::Dynamic> jac;
    jacobians(x, v, jac);
    return jac;
  }
  void jacobians(Eigen::Ref<const Eigen::VectorXd> x, Eigen::Ref<const Eigen::VectorXd> v, Jacobians<Eigen::Dynamic>& jac) const {
    pattern.zero(jac);
    double *fx = jac.dx.valuePtr(), *fv = jac.dv.valuePtr();
    for (std::size_t q = 0; q < springs.size(); ++q) {
      const Link& s = springs[q];
      const auto [dd, dv] = pull(s).blocks(apart(s, x), closing(s, v), s.rest);
      pattern.add(fx, q, dd);
      pattern.add(fv, q, dv);
    }
  }

  bool velocity_dependent() const { return gamma != 0; }
  // As springs (core/springs.hpp): every spring, damped along itself, a pin its fixed end;
  // gravity on each z.
  int links() const { return static_cast<int>(springs.size()); }
  Link link(int q) const { return springs[q]; }
  double external(int a, double) const { return a % 3 == 2 ? -m * g : 0.0; }

  // Total mechanical energy: kinetic + gravity + springs, heights from z = -S, where the far edge
  // hangs when the cloth hangs straight down unstretched: so E0 = (n^2 - 2) m g S > 0 at the flat
  // start (the studies' E/E0 needs E0 away from 0), and E stays near or above 0 as it swings.
  double energy(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const {
    double e = 0.5 * m * v.squaredNorm();
    for (int i = 0; i < masses; ++i) e += m * g * (x[3 * i + 2] + side);
    for (const Link& s : springs) e += pull(s).energy(apart(s, x), s.rest);
    return e;
  }

  State<Eigen::Dynamic> initial() const {
    Eigen::VectorXd x(3 * masses);
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c)
        if (const int i = index(r, c); i >= 0) x.segment<3>(3 * i) = Eigen::Vector3d(rest_position(r, c).data());
    return {x, Eigen::VectorXd::Zero(3 * masses)};
  }
};

}  // namespace steplab

STEPLAB_SCENE(steplab::Cloth);
