// Newton's method on scenes of run-time size (core/sparse.hpp): the transformed stage solve
// against the coupled system it replaces, solved densely; and what a run factorises.
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <string>

#include <Eigen/Dense>

#include "analysis/kernel/kernel.hpp"
#include "core/methods/gauss_legendre4.hpp"
#include "core/methods/radau_iia5.hpp"
#include "core/sparse.hpp"

namespace steplab {
namespace {

// A random sparse n x n matrix of `per_column` entries a column, symmetric if asked.
SparseMat random_sparse(int n, int per_column, bool symmetric, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> row(0, n - 1);
  std::vector<Eigen::Triplet<double>> e;
  for (int c = 0; c < n; ++c)
    for (int k = 0; k < per_column; ++k) {
      const int r = row(rng);
      const double v = u(rng);
      e.emplace_back(r, c, v);
      if (symmetric) e.emplace_back(c, r, v);
    }
  SparseMat a(n, n);
  a.setFromTriplets(e.begin(), e.end());
  a.makeCompressed();
  return a;
}

// K dV = r with K = I (x) M - h A (x) dF/dv - h^2 A^2 (x) dF/dx, the s n coupled system of the stage
// velocities (core/implicit_rk.hpp), assembled and solved densely by full-pivot LU: the reference
// the eigen-transformed solve must reproduce. The matrices have norm ~1 and h = 0.3, so K is well
// conditioned; agreement to 1e-11 relative leaves room for the two solves' round-off (~1e-14
// times a condition number of a few hundred at most).
template <int Stages>
void expect_transformed_solve_is_the_coupled_one(const ButcherTableau<Stages>& tab, bool symmetric) {
  std::mt19937 rng(7);
  const int n = 40;
  const double h = 0.3;
  const SparseMat jx = random_sparse(n, 3, symmetric, rng), jv = random_sparse(n, 2, symmetric, rng);
  Eigen::VectorXd mass = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  Eigen::MatrixXd a(Stages, Stages);
  for (int i = 0; i < Stages; ++i)
    for (int j = 0; j < Stages; ++j) a(i, j) = tab.a[i][j];
  const Eigen::MatrixXd a2 = a * a, dx = Eigen::MatrixXd(jx), dv = Eigen::MatrixXd(jv);
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(Stages * n, Stages * n);
  for (int i = 0; i < Stages; ++i)
    for (int j = 0; j < Stages; ++j) {
      k.block(i * n, j * n, n, n) = -h * a(i, j) * dv - h * h * a2(i, j) * dx;
      if (i == j) k.block(i * n, j * n, n, n).diagonal() += mass;
    }
  const Eigen::VectorXd r = Eigen::VectorXd::Random(Stages * n);
  const Eigen::VectorXd expected = k.fullPivLu().solve(r);

  IterationMatrices kept;
  kept.keep(jx, jv, mass, symmetric);
  const StageTransform tr = StageTransform::of({&tab.a[0][0], Stages * Stages}, Stages);
  std::array<Eigen::VectorXd, Stages> rs, dvs;
  for (int i = 0; i < Stages; ++i) rs[i] = r.segment(i * n, n);
  const SolveCounts c = kept.solve_stages(tr, h, rs, dvs);
  ASSERT_TRUE(c.ok);
  Eigen::VectorXd got(Stages * n);
  for (int i = 0; i < Stages; ++i) got.segment(i * n, n) = dvs[i];
  EXPECT_LE((got - expected).norm(), 1e-11 * expected.norm());

  // Kept: the same solve again factorises nothing; new Jacobians make every matrix anew.
  EXPECT_EQ(kept.solve_stages(tr, h, rs, dvs).factorisations, 0);
  kept.keep(jx, jv, mass, symmetric);
  EXPECT_EQ(kept.solve_stages(tr, h, rs, dvs).factorisations, c.factorisations);
}

// Radau IIA 5's A has one real eigenvalue and a complex pair: two systems of size n, one real
// and one complex (Hairer and Wanner II, IV.8). Gauss-Legendre 4's has one complex pair: one.
TEST(SparseNewton, RadauIIA5StagesSolvedAsOneRealAndOneComplexSystem) {
  const StageTransform tr = StageTransform::of({&RadauIIA5::tableau.a[0][0], 9}, 3);
  int real = 0, pairs = 0;
  for (int i = 0; i < 3; ++i) real += tr.real[i], pairs += tr.first_of_pair[i];
  EXPECT_EQ(real, 1);
  EXPECT_EQ(pairs, 1);
  // 1/lambda are RADAU5's gamma = 3.6378342527444957 and alpha +- i beta = 2.6810828736277521 +- 3.0504301992474105 i
  for (int i = 0; i < 3; ++i) {
    const Complex inv = 1.0 / tr.lambda[i];
    if (tr.real[i]) {
      EXPECT_NEAR(inv.real(), 3.6378342527444957, 1e-12);
    } else if (tr.first_of_pair[i]) {
      EXPECT_NEAR(inv.real(), 2.6810828736277521, 1e-12);
      EXPECT_NEAR(std::abs(inv.imag()), 3.0504301992474105, 1e-12);
    }
  }
  expect_transformed_solve_is_the_coupled_one(RadauIIA5::tableau, true);
  expect_transformed_solve_is_the_coupled_one(RadauIIA5::tableau, false);
}

TEST(SparseNewton, GaussLegendre4StagesSolvedAsOneComplexSystem) {
  const StageTransform tr = StageTransform::of({&GaussLegendre4::tableau.a[0][0], 4}, 2);
  EXPECT_FALSE(tr.real[0] || tr.real[1]);
  EXPECT_EQ(tr.first_of_pair[0] + tr.first_of_pair[1], 1);
  expect_transformed_solve_is_the_coupled_one(GaussLegendre4::tableau, true);
  expect_transformed_solve_is_the_coupled_one(GaussLegendre4::tableau, false);
}

// On the rope, a linear scene, at a fixed step, each iteration matrix a method uses is the same
// at every step: a run evaluates the Jacobians once and factorises each matrix once. The matrices
// each method uses, from its formulas: implicit Euler E(h, h^2), implicit midpoint E(h/2, h^2/4),
// velocity Verlet's kick E(h/2, 0), Yoshida's kicks at its two distinct substep weights,
// Gauss-Legendre 4 its complex pair, Radau IIA 5 its real eigenvalue and its pair, BDF its start's
// (Gauss-Legendre 4) and E(beta h, (beta h)^2). Each step solves with them: one Newton update (the
// force is linear), then the stopping test.
TEST(SparseNewton, LinearRopeFactorisesEachMatrixOncePerRun) {
  const std::map<std::string, long long> matrices{{"implicit_euler", 1}, {"implicit_midpoint", 1}, {"velocity_verlet", 1},
                                                  {"yoshida4", 2},       {"gauss_legendre4", 1},   {"radau_iia5", 2},
                                                  {"bdf2", 2},           {"bdf3", 2}};
  const std::size_t rope = *find_scene("rope");
  std::vector<double> p = default_param_values(rope);
  p[0] = 256;
  RunSpec spec;
  spec.dt = 0.001;
  spec.steps = 100;
  for (const auto& [name, expected] : matrices) {
    Counts n;
    const AnyResult r = pair_kernel(*find_method(name), rope).run_counted(p, spec, n);
    EXPECT_EQ(r.steps, 100) << name;
    EXPECT_EQ(n.factorisations, expected) << name;
    EXPECT_EQ(n.jacobians, 1) << name;
    EXPECT_GE(n.newton, 100) << name;
    EXPECT_LE(n.newton, 6 * 100) << name;  // two updates a solve (the second round-off's); Yoshida solves three kicks a step
  }
}

}  // namespace
}  // namespace steplab
