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

// The linear solver of an implicit peer's Newton iteration (None for an explicit one).
enum class LinearSolver { None, Dense, Band, Klu };
constexpr std::string_view to_string(LinearSolver s) {
  constexpr std::string_view words[] = {"", "dense", "band", "KLU"};
  return words[static_cast<int>(s)];
}

// ARKODE's stepper and table (analysis/peers/arkode.hpp): an ARKODE_DIRKTableID for ARKStep, an
// ARKODE_ERKTableID for ERKStep.
struct ArkodeSettings {
  int table = -1;
  bool explicit_table = false;
};

struct PeerInfo;
struct PeerCounts;
struct SceneKernel;
struct PeerFrames;  // analysis/peers/sized_peers.hpp

// A peer's library, one row each (analysis/peers/peers.cpp): its name, the group the report draws
// its implicit peers under (the crossover map's, a colour each), its set-up in words (the report's
// table of peers) and the code that runs it on a scene of fixed size (run_fixed_peer) and on one
// of run-time size (run_sized_peer); a null run: not on such scenes.
using FixedPeerRun = State<Eigen::Dynamic> (*)(const PeerInfo& peer, std::string_view scene, std::span<const double> params,
                                               double tol, double t_end, PeerCounts& n, double* error_max);
using SizedPeerRun = State<Eigen::Dynamic> (*)(const PeerInfo& peer, const SceneKernel& scene, const void* made, double tol,
                                               double t_end, PeerCounts& n, const PeerFrames& frames);
struct PeerLibrary {
  std::string_view name;   // "SUNDIALS CVODE"
  std::string_view group;  // "CVODE"
  std::string_view hue;    // its implicit peers' colour in the map (Paul Tol's colours the families leave free)
  std::string (*setup)(const PeerInfo& p);
  FixedPeerRun run_fixed;
  SizedPeerRun run_sized;
};

// How a peer is drawn in every figure: colour, gnuplot point type and dash.
struct PeerStyle {
  std::string_view colour;
  int point, dash;
};

struct PeerInfo {
  std::string_view name;
  const PeerLibrary* lib;
  LinearSolver linear_solver;
  PeerScenes scenes;
  bool implicit;
  bool built;                      // compiled into this steplab (CVODE's KLU solver, RADAU5 may not be)
  PeerStyle style;
  CvodeSettings cvode;             // CVODE's only
  ArkodeSettings arkode;           // ARKODE's only
  constexpr std::string_view library() const { return lib->name; }
  bool is_cvode() const;           // the two SUNDIALS integrators take different calls
  bool is_arkode() const;
  bool is_steplab() const;         // steplab's own (dopri5)
};

// Every peer, steplab's dopri5 first; the ones of a scene (PeerScenes::Any ones included).
std::span<const PeerInfo> peers();
const PeerInfo* find_peer(std::string_view name);
// The group the crossover map counts and colours a solver by: a table method's family
// ("explicit Runge-Kutta"), an implicit peer's library ("CVODE", "ARKODE", "RADAU5"), or
// "adaptive explicit" (dopri5 and the explicit peers).
std::string solver_group(std::string_view solver);
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
