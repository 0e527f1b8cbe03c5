#include "reports/data/study_command.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "analysis/kernel/kernel.hpp"
#include "reports/data/inputs.hpp"
#include "reports/data/schemas.hpp"

namespace steplab {
namespace {

using Json = nlohmann::ordered_json;

// The options that change how a study runs, not what it computes: left out of a part's command.
bool how_not_what(std::string_view option) {
  return option == "--shard" || option == "--json" || option == "--threads" || option == "--lanes";
}

std::vector<std::string> part_command(const Context& ctx) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < ctx.invocation.size(); ++i) {
    const std::string& a = ctx.invocation[i];
    const std::string name = a.substr(0, a.find('='));
    if (!how_not_what(name)) out.push_back(a);
    else if (name == a) ++i;  // "--opt value": skip the value too
  }
  return out;
}

std::string hex(const std::string& bytes) {
  static constexpr char digits[] = "0123456789abcdef";
  std::string out;
  out.reserve(2 * bytes.size());
  for (const unsigned char c : bytes) out += {digits[c >> 4], digits[c & 15]};
  return out;
}

std::string names_where(bool (*keep)(const MethodInfo&)) {
  std::string out;
  for (std::size_t m = 0; m < method_count(); ++m)
    if (keep(method_info(m))) out += (out.empty() ? "" : ", ") + std::string(method_info(m).name);
  return out;
}

}  // namespace

bool Context::stop_after_validation(const std::string& output_path) const {
  if (dry_run) return true;
  if (!output_path.empty()) check_writable(output_path);
  return false;
}

void SettingsArgs::add_to(CLI::App* app) {
  app->add_option("--sweeps", sweeps, "Gauss-Seidel sweeps a step of " + names_where(&takes_sweeps) + " (1 .. 1000000; default 1)");
  app->add_option("--cg-iterations", cg_iterations,
                  "most conjugate-gradient iterations a step of " + names_where(&takes_cg) + " (1 .. 1000000; default 100)");
  app->add_option("--cg-tolerance", cg_tolerance,
                  "CG stops once its residual is below this times the right-hand side's (0 < tol < 1; default 1e-8)");
}

MethodSettings SettingsArgs::resolve(const std::vector<std::size_t>& methods) const {
  MethodSettings s;
  const auto refuse = [&](std::string_view option, bool (*takes)(const MethodInfo&)) {
    if (std::none_of(methods.begin(), methods.end(), [&](std::size_t m) { return takes(method_info(m)); }))
      throw UsageError(fmt::format("{} applies to {}; {} {} none", option, names_where(takes),
                                   methods.size() == 1 ? "--method " + std::string(method_info(methods[0]).name) : "--methods",
                                   methods.size() == 1 ? "takes" : "take"));
  };
  if (!sweeps.empty()) {
    refuse("--sweeps", &takes_sweeps);
    s.sweeps = static_cast<int>(parse_count("--sweeps", sweeps, 1, 1'000'000));
  }
  if (!cg_iterations.empty()) {
    refuse("--cg-iterations", &takes_cg);
    s.cg_iterations = static_cast<int>(parse_count("--cg-iterations", cg_iterations, 1, 1'000'000));
  }
  if (!cg_tolerance.empty()) {
    refuse("--cg-tolerance", &takes_cg);
    s.cg_tolerance = parse_number("--cg-tolerance", cg_tolerance, Bound::Positive);
    if (s.cg_tolerance >= 1) throw UsageError(fmt::format("--cg-tolerance {} is not below 1; accepted: 0 < tol < 1", cg_tolerance));
  }
  return s;
}

std::size_t resolve_method(std::string_view name) {
  const auto m = find_method(name);
  if (!m)
    throw UsageError(fmt::format("--method '{}' is unknown{}; accepted: {}", name, did_you_mean(name, method_name_list()),
                                 method_names()));
  return *m;
}

std::vector<std::size_t> resolve_methods(const std::string& list, bool with_analytic, std::optional<std::size_t> scene) {
  std::vector<std::size_t> out;
  if (list.empty()) {
    for (std::size_t i = 0; i < method_count(); ++i)
      if ((in_ode_studies(i) || (with_analytic && method_info(i).exact_flow)) && (!scene || applies(i, *scene))) out.push_back(i);
    return out;
  }
  for (const std::string& name : split_list(list)) {
    const std::size_t m = resolve_method(name);
    if (std::find(out.begin(), out.end(), m) != out.end())
      throw UsageError(fmt::format("--methods names '{}' twice; accepted: each method once", name));
    if (scene && !applies(m, *scene))
      throw UsageError(fmt::format("--methods '{}' {}", name, why_not(m, *scene)));
    out.push_back(m);
  }
  return out;
}

Solvers resolve_solvers(const std::string& list, const std::vector<std::string>& available, std::string_view scene, bool no_peers,
                        std::span<const PeerInfo> table) {
  Solvers out{{}, no_peers ? std::vector<std::string>{} : available};
  const std::optional<std::size_t> index = find_scene(scene);
  if (list.empty()) return {resolve_methods(list, false, index), out.adaptive};
  const auto accepted = [&] { return fmt::format("{}; and here {}", method_names(), fmt::join(available, ", ")); };
  std::vector<std::string> named;
  for (const std::string& name : split_list(list)) {
    const auto it = std::find_if(table.begin(), table.end(), [&](const PeerInfo& p) { return p.name == name; });
    const PeerInfo* peer = it == table.end() ? nullptr : &*it;
    if (!peer) {
      if (!find_method(name)) {
        std::vector<std::string> names = method_name_list();
        names.insert(names.end(), available.begin(), available.end());
        throw UsageError(fmt::format("--methods '{}' is unknown{}; accepted: {}", name, did_you_mean(name, names), accepted()));
      }
      const std::size_t m = *find_method(name);
      if (std::find(out.methods.begin(), out.methods.end(), m) != out.methods.end())
        throw UsageError(fmt::format("--methods names '{}' twice; accepted: each method once", name));
      if (index && !applies(m, *index)) throw UsageError(fmt::format("--methods '{}' {}", name, why_not(m, *index)));
      out.methods.push_back(m);
      continue;
    }
    if (!peer->built)
      throw UsageError(fmt::format("--methods '{}' is not built into this steplab (its {} solver is missing from SUNDIALS); "
                                   "accepted here: {}", name, to_string(peer->linear_solver), fmt::join(available, ", ")));
    if (std::find(available.begin(), available.end(), name) == available.end())
      throw UsageError(fmt::format("--methods '{}' does not run on the {}; accepted adaptive solvers there: {}", name, scene,
                                   fmt::join(available, ", ")));
    if (std::find(named.begin(), named.end(), name) != named.end())
      throw UsageError(fmt::format("--methods names '{}' twice; accepted: each method once", name));
    named.push_back(name);
  }
  if (!named.empty()) {
    if (no_peers) throw UsageError("--methods names adaptive solvers and --no-peers leaves them out; accepted: one of the two");
    out.adaptive = named;
  }
  return out;
}

unsigned resolve_thread_count(const std::string& text) {
  return static_cast<unsigned>(parse_count("--threads", text, 0, 1024));
}

int resolve_lanes(const std::string& text) {
  if (text == "auto") return 0;
  const long long n = parse_count("--lanes", text, 1, 64);
  if (!cpu_has_width(static_cast<int>(n)))  // also false for a width that is none of 1, 2, 4, 8
    throw UsageError(fmt::format("--lanes {} is not a pack width this CPU and build can step; accepted: auto, 1 (one run at a time), "
                                 "2 (SSE2){}{}{}",
                                 text, cpu_has_width(4) ? ", 4 (AVX2)" : "", cpu_has_width(8) ? ", 8 (AVX-512)" : "",
                                 n == 8 && kMaxPackWidth < 8 ? "; 8 needs AVX-512 and a build configured with -DSTEPLAB_MAX_PACK_WIDTH=8" : ""));
  return static_cast<int>(n);
}

void add_threads_option(CLI::App* app, std::string& threads, const std::string& help) {
  app->add_option("--threads", threads, help)->capture_default_str();
}

void add_lanes_option(CLI::App* app, std::string& lanes) {
  lanes = "auto";
  app->add_option("--lanes", lanes,
                  "runs of a method stepped together in SIMD lanes, where its kernel is packed (docs/design.md, \"Why a "
                  "step is fast\"): auto (4 with AVX2, else 2), 2 (SSE2), 4 (AVX2), 8 (AVX-512, in a build configured with "
                  "-DSTEPLAB_MAX_PACK_WIDTH=8), or 1: one at a time. "
                  "The output is the same")
      ->capture_default_str();
}

void add_shard_option(CLI::App* app, std::string& shard) {
  app->add_option("--shard", shard,
                  "i/N: run the i-th of N equal parts of the study's work and write it as a part to --json "
                  "(steplab merge puts the parts together)");
}

void StudyArgs::add_shard_and_json(CLI::App* cmd, std::string_view schema) {
  add_shard_option(cmd, shard);
  cmd->add_option("--json", json, fmt::format("write JSON (schema {}) to this file", schema));
}

void begin_shard(Context& ctx, const std::string& shard, const std::string& json, bool timed) {
  if (shard.empty()) return;
  const auto slash = shard.find('/');
  if (slash == std::string::npos)
    throw UsageError(fmt::format("--shard '{}' is not i/N; accepted: i/N with 1 <= i <= N, e.g. 3/7", shard));
  const long long n = parse_count("--shard (N)", shard.substr(slash + 1), 1, kMaxShards);
  const long long i = parse_count("--shard (i)", shard.substr(0, slash), 1, n);
  if (json.empty()) throw UsageError("--shard needs --json PART.json: the part is written there; accepted: --shard i/N --json FILE");
  if (timed)
    throw UsageError("--shard with timed runs: times taken on different machines do not compare; accepted: --shard "
                     "with --no-timing (study work-precision, scaling, frames), without --timing (study convergence)");
  if (!ctx.dry_run) ctx.log = WorkLog{WorkMode::Shard, static_cast<int>(i), static_cast<int>(n), {}, 0};
}

bool finish_shard(const Context& ctx, const std::string& json) {
  const WorkLog& work_log = ctx.log;
  if (work_log.mode != WorkMode::Shard) return false;
  Json calls = Json::array();
  std::size_t ran = 0, total = 0;
  for (const auto& call : work_log.calls) {
    Json results = Json::object();
    for (std::size_t t = 0; t < call.size(); ++t)
      if (call[t]) results[std::to_string(t)] = hex(*call[t]), ++ran;
    total += call.size();
    calls.push_back({{"tasks", call.size()}, {"results", std::move(results)}});
  }
  Json part;
  part["schema"] = schema::part;
  part["command"] = part_command(ctx);
  part["shard"] = {work_log.index, work_log.count};
  part["calls"] = std::move(calls);
  write_atomic(json, part.dump() + "\n");
  std::printf("steplab: shard %d/%d: %zu of %zu tasks, written to %s (steplab merge puts the parts together)\n",
              work_log.index, work_log.count, ran, total, json.c_str());
  return true;
}

}  // namespace steplab
