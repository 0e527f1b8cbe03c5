// Is an integrator what its row in the method table says it is? (`steplab check --method NAME`)
//
// The row's claims (core/method.hpp: MethodInfo) are set against what the method's own step
// code does, measured on the scenes where each claim can be seen:
//
//   order      The fitted order (analysis/fits/order_fit.hpp, over the convergence study's default
//              sweep dt = 0.1 .. 1e-4) within kOrderTolerance of the declared one, on the spring
//              and on the cannon ball. Every method of the table lands within 0.005 of its order on
//              the spring; a wrong declaration is off by 1 or more. The cannon ball's trajectory is
//              a quadratic in t, which every method of order >= 2 follows exactly: there an error at
//              round-off for every dt holds for a declared order >= 2 (and for the exact flow, order
//              0, on both scenes) and refutes order 1. And on the target (core/scenes/target.hpp)
//              at stiffness kTargetStiffness, a driven scene: a step that evaluates its force at
//              the wrong times (not each stage's own) is first order there, whatever its order on
//              the autonomous spring.
//   converges  The error at the smallest step is at most kConvergedRatio times the one at the
//              largest (three decades of dt: an order-1 method gains 1e3), or at round-off.
//   energy     On the undamped spring, kDriftSteps steps at omega h = kDriftOmegaH (stable for every
//              symplectic method of the table: their dt* is omega h >= 1.57), the energy's drift over
//              the run, T d(ln E)/dt from its least-squares slope. A symplectic method keeps a
//              modified energy exactly on a linear problem, so E only oscillates about it: the slope
//              of a bounded oscillation of relative amplitude A over N periods is ~ 3 A / (pi N):
//              measured |drift| <= 1.5e-5 (symplectic Euler; the other symplectic rows <= 1e-6).
//              A non-symplectic method's |R(i omega h)| != 1 changes ln E by 2 ln|R| every step:
//              Radau IIA, the smallest drift of the table, -0.428 over the run (theory: 1e5 ln|R(0.5 i)|^2
//              = -0.4275), RK4 -21. kDriftBound sits 65x above the one and 428x below the other
//              (at omega h = 0.2 Radau IIA's drift, -0.0018, would have been too close to call).
//              The claim holds when "bounded" (|drift| <= kDriftBound) agrees with the declaration.
//   long run   The same claim where it matters, on a nonlinear orbit: Kepler's (core/scenes/kepler.hpp,
//              its default eccentricity 0.6) for kOrbitPeriods periods at kOrbitStepsPerPeriod
//              steps a period (analysis/studies/long_time.hpp). "Bounded": the energy error's
//              growth exponent from 10 periods on has its 95 % interval below 0.5 (a drift is ~1,
//              round-off's random walk 0.5), or the error stays within round-off's level, and the
//              orbit is kept (relative energy error below kOrbitKept: an orbit that has escaped or
//              fallen in has an error that stops growing too). Measured: the symplectic rows
//              exponent 0.00 [0.00, 0.00], errors 1.2e-6 (Gauss-Legendre 4) .. 0.107 (symplectic
//              Euler, the one nearest the bound); RK4 and Radau IIA 1.00 [1.00, 1.00], the others
//              an orbit lost (error 1.0 or more) or a Newton iteration that gave up. 200 steps a
//              period, not the study's 500: the same verdicts at 2.5 times less work (the check runs
//              in every test of a claim). A method that does not run on the orbit (on springs) is
//              not checked there.
//   stability  dt* on the spring at the dampings 0, 0.1, 1 and 4 (analysis/studies/stability.hpp), predicted
//              from the step matrix and measured from runs. A-stable: infinite at every damping,
//              both ways. Not A-stable: finite at some damping. And at every damping the measured
//              dt* (and where stability comes back) agree with the prediction within
//              kStableAgreement relative.
//   rest       From rest at the spring's equilibrium (gravity on), kRestSteps steps of omega h = 0.1
//              (a multistep method's start-up included) stay there: the largest |y - y_eq| and
//              |v| / omega within kRestTolerance of |y_eq|. Newton stops at 1e-12 of the terms it
//              balances, explicit methods are exact to an ulp: measured <= 5.1e-17 (half an ulp of y_eq)
//              for every row of the table.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include "analysis/fits/order_fit.hpp"
#include "analysis/studies/stability.hpp"
#include "core/method.hpp"

namespace steplab {

inline constexpr double kOrderTolerance = 0.1;
// The target's stiffness for the order check: non-stiff over the whole sweep (its eigenvalues
// -0.27 and -3.7: h |lambda| <= 0.37 at dt 0.1), so every method shows its classical order.
inline constexpr double kTargetStiffness = 1;
inline constexpr double kConvergedRatio = 1e-2;
inline constexpr long long kDriftSteps = 100'000;
inline constexpr double kDriftOmegaH = 0.5;
inline constexpr double kDriftBound = 1e-3;
inline constexpr double kStableAgreement = 0.01;
inline constexpr double kOrbitPeriods = 1e4;
inline constexpr int kOrbitStepsPerPeriod = 200;
inline constexpr double kOrbitKept = 0.2;
inline constexpr int kRestSteps = 10;
inline constexpr double kRestTolerance = 1e-12;
inline constexpr double kCheckDampings[] = {0, 0.1, 1, 4};

struct OrderCheck {
  std::string_view scene;
  OrderFit fit;
  double dt_coarse, error_coarse;  // the largest step whose error is finite
  double dt_fine, error_fine;      // the smallest step
  bool at_roundoff;                 // the smallest step's error at its round-off floor
  bool order_holds, converges;
};

struct EnergyCheck {
  double h;
  long long steps;
  double drift;  // T d(ln E)/dt over the run; inf if it blew up
  bool bounded, holds;
};

struct OrbitCheck {
  bool ran = false;   // the method runs on Kepler's orbit
  double growth = 0, lo = 0, hi = 0;  // the energy error's growth exponent and its 95 % interval
  bool fitted = false, round_off = false;
  double error = 0;   // relative energy error, the largest over the run; inf if it blew up
  bool bounded = false, holds = true;
};

struct StabilityCheck {
  double damping;
  StableSet predicted, measured;
  bool agrees;  // measured within kStableAgreement of predicted (dt* and "stable again")
};

struct RestCheck {
  double h;
  double deviation;  // max over the steps of max(|y - y_eq|, |v| / omega) / |y_eq|
  bool holds;
};

struct CheckResult {
  std::size_t method;
  MethodInfo claims;
  std::vector<OrderCheck> orders;  // spring, cannonball, target: those the method runs on
  EnergyCheck energy;
  OrbitCheck orbit;
  std::vector<StabilityCheck> stability;  // one per kCheckDampings
  bool a_stable_holds;  // A-stable as claimed: dt* infinite everywhere; not: finite somewhere
  RestCheck rest;
  bool all_hold() const;
};

// The method's step code (the table row `method`) against `claims` (its row's info, or any other
// to test the check itself). Runs in parallel on the workers' threads; the result does not
// depend on their count.
CheckResult check_method(std::size_t method, const MethodInfo& claims, const Workers& workers = {});

}  // namespace steplab
