// The solvers users would pick instead of steplab's, run on steplab's scenes, each on the
// scene's first-order system z = (x, v), z' = (v, M^-1 F(x, v)), at rtol = atol = tol:
//
//   dopri5              steplab's own Dormand-Prince 5(4) (core/dopri5.hpp), beside the peers
//   odeint_dopri5       Boost.Odeint's controlled runge_kutta_dopri5: odeint's own controller and
//                       its max norm of the error over rtol |z| + atol
//   cvode_adams_*       SUNDIALS CVODE, Adams-Moulton of orders 1..12
//   cvode_bdf_*         SUNDIALS CVODE, BDF of orders 1..5
//   cvode_bdf_max2_*    SUNDIALS CVODE, BDF of orders 1..2 (A-stable)
//   radau5_*            Hairer's RADAU5: Radau IIA of order 5 with step-size control
//                       (analysis/peers/radau5.hpp), the adaptive peer of steplab's radau_iia5
//   arkode_sdirk534_*   SUNDIALS ARKODE's ARKStep, SDIRK-5-3-4 (L-stable, order 4, 5 stages)
//   arkode_ark548_*     ARKStep, ARK5(4)8L[2]SA's DIRK table (L-stable, order 5, 8 stages)
//   arkode_verner65     ERKStep, Verner's 6(5) (8 stages), explicit
//
// CVODE as its user guide advises: Adams for non-stiff problems, BDF for stiff ones, and BDF with
// its order capped at 2 where eigenvalues lie near the imaginary axis (every scene here is a
// lightly damped oscillator); each with Newton's iteration on the scene's analytic Jacobian and
// the linear solver that fits the Jacobian's structure: dense on the fixed-size scenes, band on
// the scenes that declare a banded Jacobian (the rope; its state interleaved), KLU (SuiteSparse's
// sparse LU) on the other scenes of run-time size (the soft body). Its other
// settings at their defaults (the iteration matrix reused for up to 20 steps, refreshed when gamma
// changes by 30 %); what the other settings measured on the rope is in docs/peers.md. CVODE is built
// optimised from its Debian source package (tools/sundials.cmake); peer_builds() says which build
// runs.
//
// A run returns its end state and counts (analysis/kernel/counts.hpp): accepted and rejected steps,
// right-side and Jacobian evaluations and, for CVODE, its linear-solver setups (factorisations),
// Newton iterations and linear solves.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/kernel/counts.hpp"
#include "core/state.hpp"

namespace steplab {

struct PeerCounts : Counts {
  bool failed = false;  // the solver stopped before t_end
};

// CVODE's family and options (CVodeCreate, CVodeSetMaxOrd, CVodeSetStabLimDet).
struct CvodeSettings {
  bool adams = false;                      // CV_ADAMS, else CV_BDF
  int max_order = 0;                       // 0: the family's own (12, 5)
  bool stability_limit_detection = false;  // BDF: lower the order where it is unstable
};

// The k-th of `frames` output times over [0, t_end], k = 1 .. frames: k t_end / frames, the last
// t_end itself (no rounding past the run's end). Every peer and the scaling study output there.
inline double frame_time(int k, int frames, double t_end) { return k == frames ? t_end : t_end * k / frames; }

// Which scenes a peer runs on, by the linear solver that fits their Jacobian: the fixed-size
// scenes of the work-precision study (dense), the scenes of run-time size that declare their
// Jacobians banded (core/scene.hpp, jacobian_bandwidth: the rope), the other scenes of run-time
// size (sparse: the soft body); or any scene (the explicit solvers). A scene without Jacobians
// (Explicit) has the explicit solvers alone.
enum class PeerScenes { FixedSize, Banded, Sparse, Explicit, Any };
struct SceneKernel;  // analysis/kernel/kernel.hpp
PeerScenes peer_scenes(const SceneKernel& scene);

inline constexpr std::string_view kCvodeLibrary = "SUNDIALS CVODE";
inline constexpr std::string_view kArkodeLibrary = "SUNDIALS ARKODE";
inline constexpr std::string_view kRadau5Library = "RADAU5";

// ARKODE's stepper and table (analysis/peers/arkode.hpp): an ARKODE_DIRKTableID for ARKStep, an
// ARKODE_ERKTableID for ERKStep.
struct ArkodeSettings {
  int table = -1;
  bool explicit_table = false;
};

struct PeerInfo {
  std::string_view name;
  std::string_view library;        // "steplab", "Boost.Odeint", kCvodeLibrary, kArkodeLibrary, kRadau5Library
  std::string_view linear_solver;  // "" for an explicit solver; dense, band, KLU
  PeerScenes scenes;
  bool implicit;
  bool built;                      // compiled into this steplab (CVODE's KLU solver, RADAU5 may not be)
  CvodeSettings cvode;             // CVODE's only
  ArkodeSettings arkode;           // ARKODE's only
  constexpr bool is_cvode() const { return library == kCvodeLibrary; }
  constexpr bool is_arkode() const { return library == kArkodeLibrary; }
  constexpr bool is_radau5() const { return library == kRadau5Library; }
};

// "Adams-Moulton", "BDF", "BDF of orders 1-2": a CVODE peer's method in words; an ARKODE peer's
// table ("SDIRK-5-3-4, L-stable, order 4", ...).
std::string_view cvode_method_words(const PeerInfo& p);
std::string_view arkode_method_words(const PeerInfo& p);

// Every peer, steplab's dopri5 first; the ones of a scene (PeerScenes::Any ones included).
std::span<const PeerInfo> peers();
const PeerInfo* find_peer(std::string_view name);
bool peer_runs_on(const PeerInfo& p, PeerScenes scenes);
std::vector<const PeerInfo*> peers_on(PeerScenes scenes);
// The names of peers_on(scenes): a study's default adaptive solvers.
std::vector<std::string> peer_names(PeerScenes scenes);

// The library builds the peers run on: the SUNDIALS version, whether it was compiled optimised,
// with which flags; Boost's version. In every study's JSON that has peers, and in the report.
struct PeerBuild {
  std::string library, version, flags;
  bool optimised;
};
std::vector<PeerBuild> peer_builds();

// A peer on one of the work-precision study's fixed-size scenes (by its name in the kernel table
// and its parameter values): the end state; `error_max`, when given, receives the largest
// position error against the exact solution at the accepted steps (the measure steplab's own
// runs use), and is left out of a timed run.
State<Eigen::Dynamic> run_fixed_peer(const PeerInfo& peer, std::string_view scene, std::span<const double> params, double tol,
                                     double t_end, PeerCounts& n, double* error_max = nullptr);

}  // namespace steplab
