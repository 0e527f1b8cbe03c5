// The defaults that name scenes: the one table in analysis/ and reports/ where a scene is named.
// Everything else asks a scene what it offers (core/scene.hpp, SceneKernel), so a new scene joins
// every study that applies without a line here; a line here only changes where a command starts.
#pragma once

#include <array>
#include <string_view>
#include <utility>
#include <vector>

namespace steplab {

// The scene `steplab run` and the studies of one small scene start from (--scene's default).
inline constexpr std::string_view kDefaultScene = "spring";
// The scene `study scaling` starts from: one of run-time size.
inline constexpr std::string_view kDefaultSizedScene = "rope";

// Work-precision's scenes and the dt range of their sweeps: a one-frequency oscillator, and a
// scene with a stiff part (the first that declares a stiff limit also gets the stiffness sweep).
struct SweepScene {
  std::string_view scene;
  double dt_max, dt_min;
};
inline constexpr std::array<SweepScene, 2> kWorkPrecisionScenes{{{"spring", 0.1, 1e-4}, {"chain", 0.5, 1e-5}}};

// The collision study's two scenes on the penalty ground: a body whose flight between contacts
// is known exactly (each rebound measured against it), and a body of several particles (its path
// drawn).
inline constexpr std::string_view kReboundScene = "bounce";
inline constexpr std::string_view kContactBodyScene = "falling";

// The report's scenes, the exercise's: the sheet's damped spring (its stability questions) and
// cannon ball, and the slides' two contact scenes (the collision study's).
inline constexpr std::string_view kSheetOscillator = "spring";
inline constexpr std::string_view kSheetProjectile = "cannonball";
// The sheet's four methods and its analytic solution (`steplab report --sheet`).
inline constexpr std::array<std::string_view, 5> kSheetMethods{"explicit_euler", "symplectic_euler", "explicit_midpoint",
                                                               "implicit_euler", "analytic"};

// The report's "Does the order hold when stiff?": a scene whose stiffness is a parameter, with an
// exact solution and modes, swept over these stiffnesses and steps (analysis/studies/order_reduction.hpp).
inline constexpr std::string_view kStiffenedScene = "target";
struct StiffOrderDefaults {
  // 1e-2: h |lambda| <= 0.075 at the largest step (non-stiff); 1e16: h |lambda| >= 2.7e5 and
  // h^2 |lambda| >= 2700 at the smallest, which Gauss-Legendre 4's stiff limit needs (>= 12 t)
  std::vector<double> stiffnesses{1e-2, 1, 1e2, 1e4, 1e6, 1e8, 1e10, 1e12, 1e14, 1e16};
  double dt_max = 0.2, dt_min = 0.01, t_end = 10;
  int points = 9;
};

// The frame-budget study's scene (analysis/studies/frames.hpp) and what it changes of the scene's
// defaults: the rope of 32 masses at total stiffness 5000, stiff at a frame of 1/60 s (its fastest
// mode omega h ~ 80 there), the rope "Small steps in physics simulation" measures on; and the
// methods it compares: the three on springs, and the ODE methods a simulator would otherwise use.
inline constexpr std::string_view kFramesScene = "rope";
inline constexpr std::array<std::pair<std::string_view, double>, 2> kFramesParams{{{"masses", 32}, {"stiffness", 5000}}};
inline constexpr std::array<std::string_view, 6> kFramesMethods{"xpbd", "pbd", "baraff_witkin", "symplectic_euler",
                                                                "implicit_euler", "rk4"};
// The report's second scene at a frame budget: the cloth of 16 a side over its first second (it
// falls from flat and swings to the far side), where the springs turn and XPBD's projections are
// nonlinear. Its reference, RK4 at 300 substeps a frame, agrees with RK4 at 150 to 7.8e-10 m over
// that second (and changes no error of the study by more than 6e-11 m from 1000 substeps').
inline constexpr std::string_view kClothFramesScene = "cloth";
inline constexpr double kClothFramesSeconds = 1;
inline constexpr int kClothReferenceSubsteps = 300;

// The long-time study's scene (`study long-time`'s default) and the report's two for it: an orbit
// whose energy, angular momentum and phase a long run tests, and the sheet's spring swinging in a
// plane (analysis/studies/long_time.hpp).
inline constexpr std::string_view kLongTimeScene = "kepler";
inline constexpr std::string_view kLongTimeSheetScene = "swing";
// The steps a period the study takes by default: 100, but 500 on the orbit, whose pericentre
// passage at eccentricity 0.6 is fast (ark_kepler's dt 0.01 is 628): at 100 every method but the
// symplectic ones and Gauss-Legendre 4 loses the orbit within 10^4 periods, at 500 only the
// first-order explicit and multistep ones do. And how long the report runs them: 10^4 periods
// (`study long-time` runs 10^5 by default: 25 s on 2 cores for every method on the orbit).
inline constexpr std::array<std::pair<std::string_view, int>, 1> kLongTimeStepsPerPeriod{{{"kepler", 500}}};
inline constexpr int kLongTimeDefaultStepsPerPeriod = 100;
inline constexpr double kLongTimeReportPeriods = 1e4;

// The old framework's -testcase values that name a scene (its others name a measurement on the
// first), and the one it starts from.
inline constexpr std::array<std::string_view, 2> kLegacyScenes{"spring1d", "falling"};

// The sizes `study scaling` refines a scene to, the most steps a search may try, and the sizes
// of the report's "As the system grows" (small: the report runs every study).
struct ScalingDefaults {
  std::vector<int> sizes{16, 64, 256, 1024};
  long long max_steps = 2'000'000;
  // Four sizes: an exponent fitted over three has one degree of freedom (a 95 % interval of
  // +-12.7 standard errors), which a 1.3x change of one size's time under load moved across the
  // +-0.5 a finding needs; over four (+-4.3) the report's set of exponents held (docs/design.md,
  // "Timing noise").
  std::vector<int> report_sizes{8, 32, 128, 256};
};
ScalingDefaults scaling_defaults(std::string_view scene);

}  // namespace steplab
