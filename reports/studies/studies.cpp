// What several studies' JSON share: a scene's parameters by name, the peers' builds.
#include "reports/studies/studies.hpp"

#include "analysis/kernel/kernel.hpp"
#include "analysis/peers/peers.hpp"
#include "reports/data/run_json.hpp"

namespace steplab {

Json scene_params_json(std::size_t scene, const std::vector<double>& values) {
  return params_json(scene_kernel(scene).params, values);
}

Json peer_builds_json() {
  Json out = Json::array();
  for (const PeerBuild& b : peer_builds())
    out.push_back({{"library", b.library}, {"version", b.version}, {"optimised", b.optimised}, {"flags", b.flags}});
  return out;
}

}  // namespace steplab
