// A step's temporaries on a scene of run-time size (core/scratch.hpp), and the interfaces from
// before them: a scene that returns its force by value and a method that calls
// acceleration(s, x, v) still build and give the same numbers, to the bit.
#include <gtest/gtest.h>

#include <array>

#include "core/methods/explicit_euler.hpp"
#include "core/methods/implicit_euler.hpp"
#include "core/methods/radau_iia5.hpp"
#include "core/methods/rk4.hpp"
#include "core/scenes/rope.hpp"
#include "core/scenes/spring.hpp"
#include "core/simulate.hpp"

namespace steplab {
namespace {

TEST(ScratchPool, LendsVectorsOfTheAskedSizeAndTakesThemBack) {
  ScratchPool pool;
  const UseScratch in_use(pool);
  const double* first;
  {
    ScratchVec a(5), b(7);
    EXPECT_EQ(a.size(), 5);
    EXPECT_EQ(b.size(), 7);
    first = a.data();
    a.setConstant(2.0);
    b.setConstant(3.0);
    const ScratchVec c = a + a;  // from an expression: its value, in a vector of its own
    EXPECT_EQ(c.size(), 5);
    EXPECT_EQ(c[4], 4.0);
    EXPECT_NE(c.data(), a.data());
    EXPECT_EQ(pool.size(), 3u);
  }
  ScratchVec d(5), e(5), f(7);  // the same three back, each to a request of its size
  EXPECT_EQ(pool.size(), 3u);
  EXPECT_TRUE(d.data() == first || e.data() == first);
  ScratchVec moved = std::move(f);  // the borrowed vector handed on, not copied
  EXPECT_EQ(moved.size(), 7);
  EXPECT_EQ(pool.size(), 3u);
}

// The rope as a scene written before: its force returned by value, computed tension by tension as
// the rope's equation reads (T_i from the mass above, carried down), its Jacobians by value. Name
// hiding leaves it the by-value forms only.
struct ByValueRope : Rope {
  using Rope::Rope;
  Eigen::VectorXd force(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const {
    Eigen::VectorXd f(n);
    double above = k * ((0 - x[0]) - l) + d * (0 - v[0]);  // T_1
    for (int i = 0; i < n; ++i) {
      const double below = i + 1 < n ? k * ((x[i] - x[i + 1]) - l) + d * (v[i] - v[i + 1]) : 0;
      f[i] = (above - below) - c * v[i] - weight;
      above = below;
    }
    return f;
  }
  Jacobians<Eigen::Dynamic> jacobians(const Eigen::VectorXd&, const Eigen::VectorXd&) const { return jac; }
  void acceleration() const = delete;  // hides the rope's acceleration(x, v, a), as a scene written before has none
};
static_assert(ForceByValue<ByValueRope> && !ForceInto<ByValueRope> && !AccelerationInto<ByValueRope>);
static_assert(ForceInto<Rope> && AccelerationInto<Rope>);
static_assert(HasJacobians<ByValueRope> && HasJacobians<Rope>);

template <class M> void expect_same_runs(double spring_damping) {
  const std::array<double, 7> p{64, 1.0, 5.0, 5.0, 0.1, spring_damping, 9.81};
  const Rope rope(p);
  const ByValueRope old(p);
  RunSpec spec;
  spec.dt = 1e-4;
  spec.steps = 300;
  const RunResult<Eigen::Dynamic> a = simulate<M>(rope, spec), b = simulate<M>(old, spec);
  EXPECT_EQ(a.status, RunStatus::Ok);
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_TRUE(a.final.x == b.final.x) << M::info.name;
  EXPECT_TRUE(a.final.v == b.final.v) << M::info.name;
  EXPECT_GT(a.error_max, 0);
  EXPECT_EQ(a.error_max, b.error_max);  // the same exact motion tracked against both
}

// The vectorised force (tensions first, then their differences) against the recurrence: the same
// bits, explicit and implicit, with and without the springs' dashpots.
TEST(ScratchScenes, ByValueSceneRunsAndGivesTheSameBits) {
  for (const double cs : {0.0, 0.05}) {
    expect_same_runs<ExplicitEuler>(cs);
    expect_same_runs<Rk4>(cs);
    expect_same_runs<ImplicitEuler>(cs);
    expect_same_runs<RadauIIA5>(cs);
  }
}

// A method written against acceleration(s, x, v), the form before driven scenes: explicit Euler.
struct OldEuler {
  static constexpr MethodInfo info{.name = "old_euler", .order = 1, .family = Family::ExplicitRungeKutta, .summary = "explicit Euler"};
  template <class S, class T> static StepStatus step(const S& s, State<S::dim, T>& y, Time<T>, Time<T> h) {
    const Vec<S::dim, T> a = acceleration(s, y.x, y.v);
    y.x += h * y.v;
    y.v += h * a;
    return StepStatus::Ok;
  }
};

TEST(ScratchScenes, OldAccelerationCallStillSteps) {
  RunSpec spec;
  spec.dt = 1e-3;
  spec.steps = 500;
  const Spring spring = make_default_scene<Spring>();
  const auto a = simulate<OldEuler>(spring, spec), b = simulate<ExplicitEuler>(spring, spec);
  EXPECT_TRUE(a.final.x == b.final.x && a.final.v == b.final.v);
  const std::array<double, 7> p{16, 1.0, 5.0, 5.0, 0.1, 0.0, 9.81};
  const Rope rope(p);
  const auto c = simulate<OldEuler>(rope, spec), d = simulate<ExplicitEuler>(rope, spec);
  EXPECT_TRUE(c.final.x == d.final.x && c.final.v == d.final.v);
}

}  // namespace
}  // namespace steplab
