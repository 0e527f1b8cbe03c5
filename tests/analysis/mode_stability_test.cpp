// The rope's stability thresholds from its modes (analysis/studies/mode_stability.hpp) against the published stability
// limits on the imaginary axis: undamped, dt* = C / omega_max with C = 2 (symplectic Euler,
// velocity Verlet: Stoermer-Verlet's |omega h| < 2), 2 sqrt 2 (RK4), sqrt 3 (RK3), 1.5735
// (Yoshida's fourth-order composition: 2 / |1 - 2^{1/3}|^{...}, Hairer-Lubich-Wanner II.4),
// 0.7236 (AB3: Hairer-Wanner I, III.3, Fig. 3.1); A-stable methods none; explicit Euler and
// midpoint and AB2 none either (dt* = 0 predicted).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/mode_stability.hpp"
#include "core/scenes/rope.hpp"

namespace steplab {
namespace {

std::vector<double> undamped(int n) { return {double(n), 1, 5, 5, 0, 0, 9.81}; }

TEST(RopeStability, UndampedThresholdsAreThePublishedConstantsOverOmegaMax) {
  const struct {
    const char* method;
    double c;  // published, to the digits given
    double digits;
  } expected[] = {{"symplectic_euler", 2, 1e-6},         {"velocity_verlet", 2, 1e-6}, {"rk4", 2 * std::sqrt(2.0), 1e-6},
                  {"rk3", std::sqrt(3.0), 1e-6},          {"yoshida4", 1.5735, 1e-4},    {"adams_bashforth3", 0.7236, 1e-4}};
  for (int n : {4, 16}) {
    const Rope r(undamped(n));
    const double w = r.omega(n);
    EXPECT_NEAR(w, 2 * std::sqrt(5.0 * n * n) * std::sin((2 * n - 1) * M_PI / (2 * (2 * n + 1))), 1e-12 * w);
    for (const auto& e : expected) {
      const std::size_t m = *find_method(e.method);
      int mode = 0;
      const double dt = modes_predicted_threshold(m, r.modes(), &mode);
      EXPECT_NEAR(dt * w, e.c, e.digits * e.c) << e.method << " N " << n;
      EXPECT_EQ(mode, n) << e.method;  // the fastest mode binds
      // measured on the whole rope: the issue asks 1 %; bisected to 1e-3 and detected ~0.5 %
      // past dt* (mode_stability.hpp), measured within 0.5 % at N = 4 and 64
      EXPECT_NEAR(measured_threshold(m, *find_scene("rope"), undamped(n), w, 5000), dt, 0.01 * dt) << e.method << " N " << n;
    }
    for (const char* a_stable : {"implicit_euler", "implicit_midpoint", "gauss_legendre4", "bdf2", "radau_iia5"})
      EXPECT_TRUE(std::isinf(modes_predicted_threshold(*find_method(a_stable), r.modes()))) << a_stable;
    for (const char* none : {"explicit_euler", "explicit_midpoint", "adams_bashforth2"})
      EXPECT_EQ(modes_predicted_threshold(*find_method(none), r.modes()), 0) << none;
  }
}

// Damped (mass and dashpot damping): the prediction from the modes is the whole rope's. Each
// mode's damping ratio differs, so the binding mode need not be the fastest; the measured dt* of
// the rope agrees with the prediction within 1 %. Explicit Euler too: past its damped dt* the
// growth per step is so slow that runs of 5000 steps measured 1.8 x the prediction; each run
// now lasts as long as the growth the modes predict at its step needs to show (mode_stability.hpp).
TEST(RopeStability, DampedRopeMeasuredAsPredicted) {
  const std::vector<double> p{12, 1, 5, 5, 2.0, 0.002, 9.81};
  const Rope r(p);
  for (const char* name : {"rk4", "symplectic_euler", "rk3", "yoshida4", "explicit_euler"}) {
    const std::size_t m = *find_method(name);
    const double dt = modes_predicted_threshold(m, r.modes());
    ASSERT_TRUE(std::isfinite(dt) && dt > 0) << name;
    EXPECT_NEAR(measured_threshold(m, *find_scene("rope"), p, r.omega(r.n), 5000), dt, 0.01 * dt) << name;  // measured 0.002 % .. 0.14 %
  }
}

// The stiff chain: explicit Euler's fast mode, barely excited by the start, grows by 0.06 % a
// step at dt 0.00025 (25 % past the predicted dt* 0.000200): runs of 60 000 steps saw no growth
// and measured 0.000323 (+61 %), while `run --dt 0.00025 --t-end 200` overflows by t = 150. Each
// run now lasts until the growth predicted at its step would show: every method within 1 %
// (measured within 0.06 %), and the step 25 % past dt* is unstable.
TEST(ChainStability, MeasuredAsPredictedWhereAFastModeGrowsSlowly) {
  const std::size_t chain = *find_scene("chain");
  const std::vector<double> p = default_param_values(chain);
  const std::vector<Mode> modes = scene_kernel(chain).modes(p);
  const double w = modes.back().omega;
  for (const char* name : {"explicit_euler", "explicit_midpoint", "adams_bashforth2", "bdf3", "rk4"}) {
    const std::size_t m = *find_method(name);
    const double dt = modes_predicted_threshold(m, modes);
    EXPECT_NEAR(measured_threshold(m, chain, p, w, 60'000), dt, 0.01 * dt) << name;
  }
  RunSpec spec;
  spec.dt = 0.00025, spec.steps = 800'000, spec.errors = false, spec.stop_above = 1e4;
  EXPECT_NE(pair_kernel(*find_method("explicit_euler"), chain).run(p, spec).status, RunStatus::Ok);
}

}  // namespace
}  // namespace steplab
