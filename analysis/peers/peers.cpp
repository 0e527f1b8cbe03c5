#include "analysis/peers/peers.hpp"

#include <algorithm>
#include <stdexcept>

#include <boost/version.hpp>
#include <sundials/sundials_config.h>

#include "analysis/peers/fixed_peers.hpp"
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
constexpr bool kRadau5 = STEPLAB_HAVE_RADAU5;

// ARKODE's guide: a DIRK table for stiff problems, its defaults of orders 4 and 5 (SDIRK-5-3-4,
// ARK5(4)8L[2]SA's implicit table), both L-stable; for non-stiff ones an explicit table, Verner's
// 6(5) its default of order 6.
constexpr ArkodeSettings kSdirk534{.table = ARKODE_SDIRK_5_3_4};
constexpr ArkodeSettings kArk548{.table = ARKODE_ARK548L2SA_DIRK_8_4_5};
constexpr ArkodeSettings kVerner65{.table = ARKODE_VERNER_8_5_6, .explicit_table = true};

// A CVODE peer: implicit (Newton), its linear solver and its settings.
constexpr PeerInfo cvode(std::string_view name, std::string_view solver, PeerScenes scenes, CvodeSettings settings,
                         bool built = true) {
  return {name, kCvodeLibrary, solver, scenes, true, built, settings, {}};
}
constexpr PeerInfo arkode(std::string_view name, std::string_view solver, PeerScenes scenes, ArkodeSettings settings,
                          bool built = true) {
  return {name, kArkodeLibrary, solver, scenes, !settings.explicit_table, built, {}, settings};
}

constexpr PeerInfo kPeers[] = {
    {"dopri5", "steplab", "", PeerScenes::Any, false, true, {}, {}},
    {"odeint_dopri5", "Boost.Odeint", "", PeerScenes::Any, false, true, {}, {}},
    cvode("cvode_adams_dense", "dense", PeerScenes::FixedSize, kAdams),
    cvode("cvode_bdf_dense", "dense", PeerScenes::FixedSize, kBdf),
    cvode("cvode_bdf_max2_dense", "dense", PeerScenes::FixedSize, kBdfMax2),
    {"radau5_dense", kRadau5Library, "dense", PeerScenes::FixedSize, true, kRadau5, {}, {}},
    arkode("arkode_sdirk534_dense", "dense", PeerScenes::FixedSize, kSdirk534),
    arkode("arkode_ark548_dense", "dense", PeerScenes::FixedSize, kArk548),
    arkode("arkode_verner65", "", PeerScenes::Any, kVerner65),
    cvode("cvode_adams_band", "band", PeerScenes::Banded, kAdams),
    cvode("cvode_bdf_band", "band", PeerScenes::Banded, kBdf),
    cvode("cvode_bdf_max2_band", "band", PeerScenes::Banded, kBdfMax2),
    {"radau5_band", kRadau5Library, "band", PeerScenes::Banded, true, kRadau5, {}, {}},
    arkode("arkode_sdirk534_band", "band", PeerScenes::Banded, kSdirk534),
    arkode("arkode_ark548_band", "band", PeerScenes::Banded, kArk548),
    cvode("cvode_adams_klu", "KLU", PeerScenes::Sparse, kAdams, kKlu),
    cvode("cvode_bdf_klu", "KLU", PeerScenes::Sparse, kBdf, kKlu),
    cvode("cvode_bdf_max2_klu", "KLU", PeerScenes::Sparse, kBdfMax2, kKlu),
    // RADAU5 has no sparse solver: on the soft body its band solver, as wide as the grid's pattern
    {"radau5_wideband", kRadau5Library, "band", PeerScenes::Sparse, true, kRadau5, {}, {}},
    arkode("arkode_sdirk534_klu", "KLU", PeerScenes::Sparse, kSdirk534, kKlu),
    arkode("arkode_ark548_klu", "KLU", PeerScenes::Sparse, kArk548, kKlu),
};

}  // namespace

std::span<const PeerInfo> peers() { return kPeers; }

std::string_view cvode_method_words(const PeerInfo& p) {
  return p.cvode.adams ? "Adams-Moulton" : p.cvode.max_order == 2 ? "BDF of orders 1-2" : "BDF";
}

std::string_view arkode_method_words(const PeerInfo& p) {
  switch (p.arkode.table) {
    case ARKODE_SDIRK_5_3_4: return "ARKStep, SDIRK-5-3-4 (L-stable, order 4, 5 stages)";
    case ARKODE_ARK548L2SA_DIRK_8_4_5: return "ARKStep, ARK5(4)8L[2]SA's DIRK table (L-stable, order 5, 8 stages)";
    case ARKODE_VERNER_8_5_6: return "ERKStep, Verner 6(5) (explicit, 8 stages)";
    default: return "ARKODE";
  }
}

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
  if (kRadau5) out.push_back({std::string(kRadau5Library), STEPLAB_RADAU5_SOURCE, STEPLAB_RADAU5_FLAGS, true});
  return out;
}

State<Eigen::Dynamic> run_fixed_peer(const PeerInfo& peer, std::string_view scene, std::span<const double> params, double tol,
                                     double t_end, PeerCounts& n, double* error_max) {
  const auto on = [&]<class S>(const S& s) -> State<Eigen::Dynamic> {
    State<S::dim> end;
    if (peer.name == "odeint_dopri5") end = OdeintDopri5<S>::run(s, tol, t_end, n, error_max);
    else if ((peer.is_cvode() || peer.is_arkode()) && (peer.linear_solver == "dense" || !peer.implicit))
      end = SundialsDense<S>::run(s, peer, tol, t_end, n, error_max);
    else if (peer.is_radau5() && peer.linear_solver == "dense") end = Radau5Fixed<S>::run(s, tol, t_end, n, error_max);
    else throw std::logic_error("run_fixed_peer: " + std::string(peer.name) + " does not run on a scene of fixed size");
    return {end.x, end.v};
  };
  if (scene == Spring::name) return on(Spring(params));
  if (scene == Chain::name) return on(Chain(params));
  throw std::logic_error("the peers run on the spring and the chain only, not on " + std::string(scene));
}

}  // namespace steplab
