#include "analysis/peers/peers.hpp"

#include <algorithm>
#include <stdexcept>

#include <boost/version.hpp>
#include <sundials/sundials_config.h>

#include <fmt/format.h>

#include "analysis/peers/fixed_peers.hpp"
#include "analysis/peers/sized_peers.hpp"
#include "analysis/kernel/kernel.hpp"
#include "core/scenes/chain.hpp"
#include "core/scenes/spring.hpp"

namespace steplab {
namespace {

// CVODE's user guide: Adams-Moulton for non-stiff problems, BDF for stiff ones; and where the
// Jacobian has eigenvalues near the imaginary axis (a lightly damped oscillator: every scene
// here), BDF of orders 3-5 is not stable there, so BDF also with its order capped at 2 (A-stable):
// CVodeSetMaxOrd. The stability-limit detection CVODE offers for that case (CVodeSetStabLimDet)
// took more steps on the rope, not fewer, and a setup frequency other than the default 20 changed
// factorisations, not steps (docs/peers.md).
constexpr CvodeSettings kAdams{.adams = true};
constexpr CvodeSettings kBdf{.adams = false};
constexpr CvodeSettings kBdfMax2{.adams = false, .max_order = 2};
constexpr bool kKlu = STEPLAB_HAVE_KLU;
constexpr bool kRadau5Built = STEPLAB_HAVE_RADAU5;

// ARKODE's guide: a DIRK table for stiff problems, its defaults of orders 4 and 5 (SDIRK-5-3-4,
// ARK5(4)8L[2]SA's implicit table), both L-stable; for non-stiff ones an explicit table, Verner's
// 6(5) its default of order 6.
constexpr ArkodeSettings kSdirk534{.table = ARKODE_SDIRK_5_3_4};
constexpr ArkodeSettings kArk548{.table = ARKODE_ARK548L2SA_DIRK_8_4_5};
constexpr ArkodeSettings kVerner65{.table = ARKODE_VERNER_8_5_6, .explicit_table = true};

// The libraries' builds in words: "7.1.1, built optimised".
std::string build_text(const PeerInfo& p) {
  for (const PeerBuild& b : peer_builds())
    if (b.library == p.library()) return fmt::format("{}, {}", b.version, b.optimised ? "built optimised" : "Debian's build, not optimised");
  return "?";
}

std::string cvode_setup(const PeerInfo& p) {
  const std::string_view method = p.cvode.adams ? "Adams-Moulton" : p.cvode.max_order == 2 ? "BDF of orders 1-2" : "BDF";
  return fmt::format("{}; Newton on the analytic Jacobian, {} LU ({})", method, to_string(p.linear_solver), build_text(p));
}

std::string arkode_setup(const PeerInfo& p) {
  const std::string_view table = p.arkode.table == ARKODE_SDIRK_5_3_4 ? "ARKStep, SDIRK-5-3-4 (L-stable, order 4, 5 stages)"
                                 : p.arkode.table == ARKODE_ARK548L2SA_DIRK_8_4_5
                                     ? "ARKStep, ARK5(4)8L[2]SA's DIRK table (L-stable, order 5, 8 stages)"
                                     : "ERKStep, Verner 6(5) (explicit, 8 stages)";
  const std::string newton = p.implicit ? fmt::format("; Newton on the analytic Jacobian, {} LU, told the scene is linear",
                                                      to_string(p.linear_solver))
                                        : std::string();
  return fmt::format("{}{} ({})", table, newton, build_text(p));
}

// The runs on the fixed-size scenes the peers are compiled for (the work-precision study's):
// `run` called on the scene made from `params`.
template <class Run>
State<Eigen::Dynamic> on_fixed_scene(const PeerInfo& peer, std::string_view scene, std::span<const double> params, Run&& run) {
  const auto as_dynamic = [](const auto& end) { return State<Eigen::Dynamic>{end.x, end.v}; };
  if (scene == Spring::name) return as_dynamic(run(Spring(params)));
  if (scene == Chain::name) return as_dynamic(run(Chain(params)));
  throw std::logic_error(fmt::format("{} runs on the spring and the chain only, not on the {}", peer.name, scene));
}

// A library's run on them (FixedPeerRun): Solver<S>::run, handed the peer where it takes one
// (SUNDIALS: CVODE or ARKODE and their settings).
template <template <Scene> class Solver>
State<Eigen::Dynamic> fixed_run(const PeerInfo& peer, std::string_view scene, std::span<const double> params, double tol,
                                double t_end, PeerCounts& n, double* error_max) {
  return on_fixed_scene(peer, scene, params, [&]<class S>(const S& s) {
    if constexpr (requires { Solver<S>::run(s, peer, tol, t_end, n, error_max); }) return Solver<S>::run(s, peer, tol, t_end, n, error_max);
    else return Solver<S>::run(s, tol, t_end, n, error_max);
  });
}

constexpr PeerLibrary kSteplab{"steplab", "adaptive explicit", "#999999",
                               [](const PeerInfo&) { return std::string("Dormand-Prince 5(4) with its own step control"); },
                               nullptr, nullptr};
constexpr PeerLibrary kOdeint{"Boost.Odeint", "adaptive explicit", "#999999",
                              [](const PeerInfo&) { return std::string("controlled runge_kutta_dopri5, odeint's own controller"); },
                              fixed_run<OdeintDopri5>, run_sized_odeint};
constexpr PeerLibrary kCvode{kCvodeLibrary, "CVODE", "#56B4E9", cvode_setup, fixed_run<SundialsDense>, run_sized_sundials};
constexpr PeerLibrary kArkode{kArkodeLibrary, "ARKODE", "#44AA99", arkode_setup, fixed_run<SundialsDense>, run_sized_sundials};
constexpr PeerLibrary kRadau5{kRadau5Library, "RADAU5", "#CC6677",
                              [](const PeerInfo&) {
                                return std::string("Radau IIA of order 5, its own step control; Newton on the analytic Jacobian of "
                                                   "the second-order form (M1 = N/2), dense LU (gfortran -O2)");
                              },
                              fixed_run<Radau5Fixed>, run_sized_radau5};

using enum LinearSolver;
using enum PeerScenes;

// A CVODE peer: implicit (Newton), its linear solver, its settings and its style: by set-up,
// whatever the linear solver (one figure has one of each), Adams sky blue, BDF indigo, BDF of
// orders 1-2 olive (Paul Tol's), each with a point and a dash of its own.
constexpr PeerInfo cvode(std::string_view name, LinearSolver solver, PeerScenes scenes, CvodeSettings settings, bool built = true) {
  const PeerStyle style = settings.adams ? PeerStyle{"#56B4E9", 13, 2} : settings.max_order == 2 ? PeerStyle{"#999933", 9, 5}
                                                                                                 : PeerStyle{"#332288", 15, 4};
  return {name, &kCvode, solver, scenes, true, built, style, settings, {}};
}
// ARKODE's: SDIRK-5-3-4 teal, ARK5(4)8L[2]SA's DIRK green, Verner's explicit table dark grey.
constexpr PeerInfo arkode(std::string_view name, LinearSolver solver, PeerScenes scenes, ArkodeSettings settings, bool built = true) {
  const PeerStyle style = settings.explicit_table ? PeerStyle{"#444444", 4, 3} : settings.table == ARKODE_SDIRK_5_3_4
                                                                                    ? PeerStyle{"#44AA99", 11, 1}
                                                                                    : PeerStyle{"#117733", 12, 2};
  return {name, &kArkode, solver, scenes, !settings.explicit_table, built, style, {}, settings};
}
// RADAU5 rose.
constexpr PeerInfo radau5(std::string_view name, LinearSolver solver, PeerScenes scenes) {
  return {name, &kRadau5, solver, scenes, true, kRadau5Built, {"#CC6677", 5, 1}, {}, {}};
}

constexpr PeerInfo kPeers[] = {
    {"dopri5", &kSteplab, None, Any, false, true, {"#000000", 7, 1}, {}, {}},
    {"odeint_dopri5", &kOdeint, None, Any, false, true, {"#777777", 6, 2}, {}, {}},
    cvode("cvode_adams_dense", Dense, FixedSize, kAdams),
    cvode("cvode_bdf_dense", Dense, FixedSize, kBdf),
    cvode("cvode_bdf_max2_dense", Dense, FixedSize, kBdfMax2),
    radau5("radau5_dense", Dense, FixedSize),
    arkode("arkode_sdirk534_dense", Dense, FixedSize, kSdirk534),
    arkode("arkode_ark548_dense", Dense, FixedSize, kArk548),
    arkode("arkode_verner65", None, Any, kVerner65),
    cvode("cvode_adams_band", Band, Banded, kAdams),
    cvode("cvode_bdf_band", Band, Banded, kBdf),
    cvode("cvode_bdf_max2_band", Band, Banded, kBdfMax2),
    radau5("radau5_band", Band, Banded),
    arkode("arkode_sdirk534_band", Band, Banded, kSdirk534),
    arkode("arkode_ark548_band", Band, Banded, kArk548),
    cvode("cvode_adams_klu", Klu, Sparse, kAdams, kKlu),
    cvode("cvode_bdf_klu", Klu, Sparse, kBdf, kKlu),
    cvode("cvode_bdf_max2_klu", Klu, Sparse, kBdfMax2, kKlu),
    // RADAU5 has no sparse solver: on the soft body its band solver, as wide as the grid's pattern
    radau5("radau5_wideband", Band, Sparse),
    arkode("arkode_sdirk534_klu", Klu, Sparse, kSdirk534, kKlu),
    arkode("arkode_ark548_klu", Klu, Sparse, kArk548, kKlu),
};

}  // namespace

std::span<const PeerInfo> peers() { return kPeers; }

bool PeerInfo::is_cvode() const { return lib == &kCvode; }
bool PeerInfo::is_arkode() const { return lib == &kArkode; }
bool PeerInfo::is_steplab() const { return lib == &kSteplab; }

const PeerInfo* find_peer(std::string_view name) {
  const auto it = std::find_if(std::begin(kPeers), std::end(kPeers), [&](const PeerInfo& p) { return p.name == name; });
  return it == std::end(kPeers) ? nullptr : &*it;
}

PeerScenes peer_scenes(const SceneKernel& scene) {
  if (!scene.has_jacobians) return PeerScenes::Explicit;
  if (scene.dim != Eigen::Dynamic) return PeerScenes::FixedSize;
  return scene.jacobian_bandwidth >= 0 ? PeerScenes::Banded : PeerScenes::Sparse;
}

bool peer_runs_on(const PeerInfo& p, PeerScenes scenes) { return p.scenes == PeerScenes::Any || p.scenes == scenes; }

std::vector<const PeerInfo*> peers_on(PeerScenes scenes) {
  std::vector<const PeerInfo*> out;
  for (const PeerInfo& p : kPeers)
    if (p.built && peer_runs_on(p, scenes)) out.push_back(&p);
  return out;
}

std::vector<std::string> peer_names(PeerScenes scenes) {
  std::vector<std::string> out;
  for (const PeerInfo* p : peers_on(scenes)) out.emplace_back(p->name);
  return out;
}

std::vector<PeerBuild> peer_builds() {
  std::vector<PeerBuild> out{
      {std::string(kCvodeLibrary), SUNDIALS_VERSION, STEPLAB_CVODE_FLAGS, STEPLAB_CVODE_OPTIMISED != 0},
      {std::string(kArkodeLibrary), SUNDIALS_VERSION, STEPLAB_CVODE_FLAGS, STEPLAB_CVODE_OPTIMISED != 0},
      {"Boost.Odeint", BOOST_LIB_VERSION, "header-only, compiled with steplab's own flags", true}};
  if (kRadau5Built) out.push_back({std::string(kRadau5Library), STEPLAB_RADAU5_SOURCE, STEPLAB_RADAU5_FLAGS, true});
  return out;
}

State<Eigen::Dynamic> run_fixed_peer(const PeerInfo& peer, std::string_view scene, std::span<const double> params, double tol,
                                     double t_end, PeerCounts& n, double* error_max) {
  if (!peer.lib->run_fixed || peer.linear_solver == LinearSolver::Band || peer.linear_solver == LinearSolver::Klu)
    throw std::logic_error("run_fixed_peer: " + std::string(peer.name) + " does not run on a scene of fixed size");
  return peer.lib->run_fixed(peer, scene, params, tol, t_end, n, error_max);
}

std::string solver_group(std::string_view solver) {
  if (const auto m = find_method(solver)) return std::string(to_string(method_info(*m).family));
  const PeerInfo* p = find_peer(solver);
  return p && p->implicit ? std::string(p->lib->group) : "adaptive explicit";
}

}  // namespace steplab
