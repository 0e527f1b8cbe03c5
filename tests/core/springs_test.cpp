// The mass-spring scenes as springs (core/springs.hpp): the force of their parts (each spring's
// constraint and dashpot, the external forces, the ground) is the scene's own force(), written
// separately in each scene file, at states away from the start (springs stretched and turned,
// velocities, masses below the ground). The two sum the same terms in another order: they agree
// to a few ulps of the largest force (tolerance 1e-12 of it).
#include <gtest/gtest.h>

#include <array>
#include <random>

#include "core/scenes/bounce.hpp"
#include "core/scenes/cannonball.hpp"
#include "core/scenes/chain.hpp"
#include "core/scenes/falling.hpp"
#include "core/scenes/rope.hpp"
#include "core/scenes/softbody.hpp"
#include "core/scenes/spring.hpp"
#include "core/scenes/target.hpp"
#include "core/springs.hpp"

namespace steplab {
namespace {

static_assert(MassSpring<Spring> && MassSpring<Chain> && MassSpring<Rope> && MassSpring<Falling> && MassSpring<SoftBody>);
static_assert(HasGround<Falling> && HasGround<SoftBody> && !HasGround<Rope> && !HasGround<Spring>);
static_assert(!MassSpring<Cannonball> && !MassSpring<Bounce> && !MassSpring<Target>, "no springs: a ball, a driven mass");

// The start moved by `spread` (uniform in each coordinate), `drop` down in every vertical
// coordinate, and velocities uniform in [-1, 1].
template <class S> State<S::dim> shaken(const S& s, std::mt19937& rng, double spread, double drop) {
  State<S::dim> y = s.initial();
  std::uniform_real_distribution<double> u(-1, 1);
  constexpr int d = coords_per_mass<S>();
  for (Eigen::Index a = 0; a < y.x.size(); ++a) {
    y.x[a] += spread * u(rng) - (a % d == d - 1 ? drop : 0.0);
    y.v[a] = u(rng);
  }
  return y;
}

template <class S> void expect_parts_are_the_force(const S& s, double spread, double drop, const char* what) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const State<S::dim> y = shaken(s, rng, spread, drop);
    const Vec<S::dim> f = force_value(s, 0.0, y.x, y.v);
    Vec<S::dim> parts = f;
    force_from_links(s, y.x, y.v, parts);
    EXPECT_LE((parts - f).cwiseAbs().maxCoeff(), 1e-12 * f.cwiseAbs().maxCoeff()) << what << ", trial " << trial;
  }
}

TEST(Springs, TheirForcesAreTheScenesForce) {
  expect_parts_are_the_force(Spring(default_param_values<Spring>()), 0.5, 0.0, "spring");
  expect_parts_are_the_force(Chain(default_param_values<Chain>()), 0.5, 0.0, "chain");
  std::vector<double> rope = default_param_values<Rope>();
  rope[param_index(Rope::params, "spring-damping")] = 0.3;
  expect_parts_are_the_force(Rope(rope), 0.2, 0.0, "rope with dashpots");
  expect_parts_are_the_force(Falling(default_param_values<Falling>()), 0.3, 0.6, "falling triangle, on and above the ground");
  std::vector<double> soft = default_param_values<SoftBody>();
  soft[param_index(SoftBody::params, "ground-damping")] = 0.5;
  expect_parts_are_the_force(SoftBody(soft), 0.05, 0.55, "soft body, its bottom row in the ground");
}

// The parts read as the scenes say: the rope's first spring hangs from the anchor, the chain's
// stiff spring is the second, the soft body has 2 (n - 1) n structural and 2 (n - 1)^2 shear ones.
TEST(Springs, LinksAreTheScenesSprings) {
  const Rope rope(default_param_values<Rope>());
  EXPECT_EQ(rope.links(), 8);
  EXPECT_EQ(rope.link(0).i, -1);
  EXPECT_DOUBLE_EQ(rope.link(3).rest, 5.0 / 8);
  EXPECT_DOUBLE_EQ(rope.link(3).k, 5.0 * 8);
  const Chain chain(default_param_values<Chain>());
  EXPECT_DOUBLE_EQ(chain.link(1).k, 5e4);
  EXPECT_NEAR(chain.link(0).c, 0.1, 1e-14);  // (c1 + c2) - c2
  const SoftBody soft(default_param_values<SoftBody>());
  EXPECT_EQ(soft.links(), 2 * 3 * 4 + 2 * 3 * 3);
}

}  // namespace
}  // namespace steplab
