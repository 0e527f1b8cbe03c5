// `steplab study collision`: the bounce and the falling triangle on the penalty ground, each
// method's energy at each bounce and its depth (analysis/studies/collision.hpp). Table on stdout,
// JSON (steplab.collision/2) with --json.
#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/collision.hpp"
#include "analysis/studies/defaults.hpp"
#include "reports/cli/commands.hpp"
#include "reports/cli/shards.hpp"
#include "reports/data/inputs.hpp"
#include "reports/data/studies.hpp"

namespace steplab {
namespace {

struct CollisionArgs {
  SceneArgs scene;  // parameters shared by the bounce and the triangle (ground, mass, gravity)
  std::string methods;
  std::map<std::string, std::string> params;  // as typed, by name (collision_params())
  std::string threads = "0";
  std::string shard;
  std::string json;
};

// The collision study's scenes: the rebound scene and the contact body (analysis/studies/defaults.hpp).
bool collision_scene(const SceneKernel& s) { return s.name == kReboundScene || s.name == kContactBodyScene; }

int run_collision(CollisionArgs& a, Context& ctx) {
  CollisionConfig c;
  // A parameter given applies to each scene that has it (--ground-stiffness to both, --stiffness
  // to the triangle's springs).
  const auto values_for = [&](std::string_view scene) {
    SceneArgs only = a.scene;
    only.scene = std::string(scene);
    const std::size_t index = only.scene_index();
    for (auto& [name, text] : only.text)
      if (!has_param(index, name)) text.clear();
    only.app = nullptr;
    return only.values(index);
  };
  const std::size_t bounce = c.rebound_scene, body = c.body_scene;
  std::string accepted;  // the parameters of either collision scene
  for (const auto& [name, text] : a.scene.text)
    if (has_param(bounce, name) || has_param(body, name)) accepted += (accepted.empty() ? "--" : ", --") + name;
  for (const auto& [name, text] : a.scene.text)
    if (a.scene.given(name) && !has_param(bounce, name) && !has_param(body, name))
      throw UsageError(fmt::format("--{} does not apply to the collision scenes; accepted: {}", name, accepted));
  c.rebound_params = values_for(scene_name(bounce));
  c.body_params = values_for(scene_name(body));
  c.methods = resolve_methods(a.methods, false);
  read_params(collision_params(), a.params, c);
  check_collision(c);
  c.workers = ctx.workers(resolve_thread_count(a.threads));
  return run_study(ctx, a.shard, a.json, false, [&] { return collision_study(c); },
                   [](const CollisionResult& r) { return collision_table(r); }, [](const CollisionResult& r) { return collision_json(r); });
}

CLI::App* add_collision(CLI::App* study, CollisionArgs& a) {
  CLI::App* cmd = study->add_subcommand("collision", "the bounce and the falling triangle on the penalty ground");
  a.scene.add_to(cmd, collision_scene, false);
  cmd->add_option("--methods", a.methods, "comma-separated methods (default every numerical method)");
  add_params(cmd, collision_params(), a.params, CollisionConfig{});
  add_threads_option(cmd, a.threads);
  add_shard_option(cmd, a.shard);
  cmd->add_option("--json", a.json, fmt::format("write JSON (schema {}) to this file", schema::collision));
  return cmd;
}

}  // namespace

StudyCommand collision_command(CLI::App* study) { return study_command(study, add_collision, run_collision); }

}  // namespace steplab
