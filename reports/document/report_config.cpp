#include "reports/document/report_config.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "analysis/studies/defaults.hpp"
#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/order_reduction.hpp"
#include "analysis/studies/scaling.hpp"
#include "reports/data/inputs.hpp"
#include "reports/data/run_json.hpp"
#include "reports/studies/studies.hpp"
#include "reports/document/section.hpp"

namespace steplab {
namespace {

using Json = nlohmann::ordered_json;

std::string keys_of(const Json& j) {
  std::string out;
  for (const auto& [k, _] : j.items()) out += (out.empty() ? "" : ", ") + k;
  return out;
}

// Reads `user` (an object shaped like `defaults`) over `defaults`, checking keys and types.
void merge(Json& defaults, const Json& user, const std::string& path) {
  if (!user.is_object())
    throw UsageError(fmt::format("config: {} must be a JSON object; accepted keys: {}", path.empty() ? "the file" : path,
                                 keys_of(defaults)));
  for (const auto& [key, value] : user.items()) {
    const std::string where = path.empty() ? key : path + "." + key;
    if (!defaults.contains(key))
      throw UsageError(fmt::format("config: unknown key '{}'; accepted: {}", where, keys_of(defaults)));
    Json& target = defaults[key];
    if (target.is_object()) {
      merge(target, value, where);
    } else if (target.is_array() && !target.empty() && target.front().is_string()) {  // a list of names
      if (!value.is_array() || value.empty() || !std::all_of(value.begin(), value.end(), [](const Json& x) { return x.is_string(); }))
        throw UsageError(fmt::format("config: '{}' must be a non-empty array of names", where));
      target = value;
    } else if (target.is_array()) {
      if (!value.is_array() || value.empty() || !std::all_of(value.begin(), value.end(), [](const Json& x) { return x.is_number(); }))
        throw UsageError(fmt::format("config: '{}' must be a non-empty array of numbers", where));
      target = value;
    } else if (target.is_boolean()) {
      if (!value.is_boolean()) throw UsageError(fmt::format("config: '{}' must be true or false", where));
      target = value;
    } else {
      if (!value.is_number()) throw UsageError(fmt::format("config: '{}' must be a number", where));
      target = value;
    }
  }
}

double num(const Json& j, const std::string& path, Bound bound) {
  return check_number("config: " + path, j.get<double>(), bound);
}

std::vector<double> nums(const Json& j, const std::string& path, Bound bound) {
  std::vector<double> out;
  for (const Json& x : j) out.push_back(check_number("config: " + path, x.get<double>(), bound));
  return out;
}

int count(const Json& j, const std::string& path, int lo, int hi) {
  const double x = j.get<double>();
  if (!(x == std::floor(x)) || x < lo || x > hi)
    throw UsageError(fmt::format("config: {} = {} is not accepted; accepted: a whole number from {} to {}", path, x, lo, hi));
  return static_cast<int>(x);
}

std::vector<double> scene_values(const Json& j, std::size_t scene) {
  const std::string section(scene_name(scene));
  std::vector<double> out;
  for (const ParamSpec& p : scene_kernel(scene).params) out.push_back(num(j[param_key(p)], section + "." + param_key(p), p.bound));
  return out;
}

// The report's own keys beside its studies', declared as theirs are (reports/data/study_params.hpp):
// from these rows come their keys, their defaults in --print-config and the one rule each is read by.
constexpr StudyParam<ReportConfig> kSheetStabilityParams[] = {  // the "stability" object's, after the study's
    {"large-dt", "the sheet's large step, with the spring's damping", kPositive, &ReportConfig::large_dt},
    {"small-dt", "the sheet's small step, without damping", kPositive, &ReportConfig::small_dt},
};
// The stiff-order study is `study convergence --sweep` (reproduce.cpp): its stiffnesses are the
// report's own row, its steps and time the convergence study's rows (convergence_params()).
constexpr StudyParam<StiffOrderDefaults> kStiffnessesParam[] = {
    {"stiffnesses", "the stiffness of each sweep, increasing", kPositive, &StiffOrderDefaults::stiffnesses},
};
constexpr StudyParam<ReportConfig> kFigureParams[] = {
    {"cannonball-dt", "the cannon ball's step", kPositive, &ReportConfig::cannonball_dt},
    {"cannonball-t-end", "the cannon ball's time", kPositive, &ReportConfig::cannonball_t_end},
    {"spring-dts", "the spring's steps", kPositive, &ReportConfig::spring_figure_dts},
    {"spring-t-end", "the spring's time", kPositive, &ReportConfig::spring_figure_t_end},
    {"energy-t-end", "the energy figure's time", kPositive, &ReportConfig::energy_t_end},
};

// Indices of `names` in a table, each found by `find`, sorted into the table's order; UsageError
// for an empty list or name, an unknown or a repeated name (`accepted` lists the table).
template <class Find>
std::vector<std::size_t> chosen(const std::vector<std::string>& names, const std::string& what, Find find,
                                const std::string& accepted) {
  if (names.empty() || std::find(names.begin(), names.end(), "") != names.end())
    throw UsageError(fmt::format("{} is empty or has an empty name; accepted: a comma-separated list of {}", what, accepted));
  std::vector<std::size_t> out;
  for (const std::string& n : names) {
    const std::optional<std::size_t> i = find(n);
    if (!i) throw UsageError(fmt::format("{}: '{}' is not known{}; accepted: {}", what, n, did_you_mean(n, split_list(accepted)), accepted));
    if (std::find(out.begin(), out.end(), *i) != out.end())
      throw UsageError(fmt::format("{}: '{}' is named twice; accepted: each once", what, n));
    out.push_back(*i);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

void choose_methods(ReportConfig& c, const std::vector<std::string>& names, const std::string& what) {
  c.methods = chosen(names, what, find_method, method_names());
  for (std::size_t m : c.methods)
    if (method_info(m).on_springs) {
      std::vector<std::string_view> ode;
      for (std::size_t o : ode_methods()) ode.push_back(method_info(o).name);
      throw UsageError(fmt::format("{}: '{}' works on a scene's springs; the report measures the methods on springs together, at a "
                                   "frame budget (its section 'frames'); accepted: {}",
                                   what, method_info(m).name, fmt::join(ode, ", ")));
    }
  if (std::all_of(c.methods.begin(), c.methods.end(), [](std::size_t m) { return method_info(m).exact_flow; }))
    throw UsageError(fmt::format("{} has no numerical method; accepted: at least one of {}", what, method_names()));
}

void choose_scenes(ReportConfig& c, const std::vector<std::string>& names, const std::string& what) {
  c.covered = chosen(names, what, find_scene, scene_list());
}

void check_choice(const ReportConfig& c, const std::string& what) {
  for (std::size_t m : c.methods)
    if (std::none_of(c.covered.begin(), c.covered.end(), [&](std::size_t s) { return applies(m, s); }))
      throw UsageError(fmt::format("{}: '{}' runs on none of the chosen scenes (it {}); accepted: methods that run on at "
                                   "least one of them", what, method_info(m).name, why_not(m, c.covered.front())));
}

void choose_sections(ReportConfig& c, const std::vector<std::string>& names, const std::string& what) {
  const std::vector<std::string> all = section_names();
  const auto find = [&](const std::string& n) -> std::optional<std::size_t> {
    const auto it = std::find(all.begin(), all.end(), n);
    return it == all.end() ? std::nullopt : std::optional<std::size_t>(static_cast<std::size_t>(it - all.begin()));
  };
  c.sections.clear();
  for (std::size_t i : chosen(names, what, find, fmt::format("{}", fmt::join(all, ", ")))) c.sections.push_back(all[i]);
}

bool ReportConfig::covers(std::size_t scene) const {
  return std::find(covered.begin(), covered.end(), scene) != covered.end();
}

bool ReportConfig::has_section(std::string_view name) const {
  return std::find(sections.begin(), sections.end(), name) != sections.end();
}

std::vector<std::size_t> ReportConfig::own_scenes() const {
  std::vector<std::size_t> out;
  for (const ReportScene* s : scenes()) out.push_back(s->scene);
  out.push_back(stiffened.scene);
  for (const ReportSizes& s : scaling) out.push_back(s.scene);
  for (std::string_view n : {kLongTimeScene, kLongTimeSheetScene, kClothFramesScene})  // the long-time and cloth sections' own runs
    if (const auto s = find_scene(n)) out.push_back(*s);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<std::size_t> ReportConfig::convergence_scenes() const {
  std::vector<std::size_t> out;
  for (const ReportScene* s : scenes())
    if (covers(s->scene) && scene_kernel(s->scene).has_exact) out.push_back(s->scene);
  const std::vector<std::size_t> own = own_scenes();
  for (std::size_t s : covered)
    if (std::find(own.begin(), own.end(), s) == own.end() && scene_kernel(s).size_param < 0) out.push_back(s);
  return out;
}

double ReportConfig::damping() const {
  return oscillator.params[static_cast<std::size_t>(scene_kernel(oscillator.scene).damping_param)];
}

ReportConfig default_report_config() {
  ReportConfig c;
  for (std::size_t m = 0; m < method_count(); ++m)
    if (!method_info(m).on_springs) c.methods.push_back(m);  // those: the frame-budget section
  c.sections = full_report_sections();
  for (const auto& [role, name] : {std::pair{&c.oscillator, kSheetOscillator}, {&c.projectile, kSheetProjectile},
                                   {&c.rebound, kReboundScene}, {&c.body, kContactBodyScene}}) {
    role->scene = scene_index(name);
    role->params = default_param_values(role->scene);
  }
  c.stiffened = {scene_index(kStiffenedScene), default_param_values(scene_index(kStiffenedScene))};
  for (std::size_t s = 0; s < scene_count(); ++s)
    if (scales(scene_kernel(s))) c.scaling.push_back({s, scaling_defaults(scene_name(s)).report_sizes});
  c.covered = c.own_scenes();
  return c;
}

// The hand-in: the sheet's questions on its scenes, the figures and orders, and how to redo it.
ReportConfig sheet_report_config() {
  ReportConfig c = default_report_config();
  choose_methods(c, {kSheetMethods.begin(), kSheetMethods.end()}, "the sheet's methods");
  choose_scenes(c, {std::string(kSheetOscillator), std::string(kSheetProjectile), std::string(kLongTimeSheetScene), std::string(kContactBodyScene)},
                "the sheet's scenes and the slides' triangle");
  c.sections = {"answers", "sheet", "summary", "stable", "order", "energy", "scenes", "convergence", "long_run", "collision", "advice", "reproduce"};
  return c;
}

Json report_config_json(const ReportConfig& c) {
  Json j;
  j["methods"] = Json::array();
  for (std::size_t m : c.methods) j["methods"].push_back(std::string(method_info(m).name));
  j["scenes"] = Json::array();
  for (std::size_t s : c.covered) j["scenes"].push_back(std::string(scene_name(s)));
  j["sections"] = c.sections;
  for (const ReportScene* s : c.scenes()) j[std::string(scene_name(s->scene))] = scene_params_json(s->scene, s->params);
  j["convergence"] = params_json(convergence_params(), c.convergence);
  j["work_precision"] = params_json(work_precision_params(), c.work_precision);
  j["work_precision"]["timing"] = c.timing;
  j["stability"] = params_json(stability_params(), c.stability);
  j["stability"].update(params_json<ReportConfig>(kSheetStabilityParams, c));
  j["collision"] = params_json(collision_params(), c.collision);
  j["long_time"] = {{"periods", c.long_time_periods}};
  Json scaling;  // the sizes of each scene by its name, then the measure
  for (const ReportSizes& s : c.scaling) scaling[std::string(scene_name(s.scene))] = s.sizes;
  scaling["error"] = c.scaling_error;
  scaling["t_end"] = c.scaling_t_end;
  scaling["map_sizes"] = c.scaling_map_sizes;
  scaling["stiffening"] = c.scaling_stiffening;
  scaling["visual"] = c.scaling_visual;
  j["scaling"] = std::move(scaling);
  j[std::string(scene_name(c.stiffened.scene))] = scene_params_json(c.stiffened.scene, c.stiffened.params);
  j["stiff_order"] = params_json<StiffOrderDefaults>(kStiffnessesParam, c.stiff_order);
  j["stiff_order"].update(params_json(convergence_params(), stiff_order_config(c.stiffened.scene, {}, c.stiff_order, {})));
  j["figures"] = params_json<ReportConfig>(kFigureParams, c);
  j["threads"] = c.threads;
  return j;
}

ReportConfig report_config_from_json(const Json& user, const ReportConfig& base) {
  Json j = report_config_json(base);
  merge(j, user, "");
  ReportConfig c = base;
  choose_methods(c, j["methods"].get<std::vector<std::string>>(), "config: methods");
  choose_scenes(c, j["scenes"].get<std::vector<std::string>>(), "config: scenes");
  choose_sections(c, j["sections"].get<std::vector<std::string>>(), "config: sections");
  check_choice(c, "config: methods");
  for (ReportScene* s : c.scenes()) s->params = scene_values(j[std::string(scene_name(s->scene))], s->scene);
  params_from_json(convergence_params(), j["convergence"], "convergence", c.convergence);
  check_convergence(c.convergence, config_names("convergence"));
  const Json& wp = j["work_precision"];
  params_from_json(work_precision_params(), wp, "work_precision", c.work_precision);
  c.timing = wp["timing"].get<bool>();
  const Json& st = j["stability"];
  params_from_json(stability_params(), st, "stability", c.stability);
  check_stability(c.stability, config_names("stability"));
  params_from_json<ReportConfig>(kSheetStabilityParams, st, "stability", c);
  params_from_json(collision_params(), j["collision"], "collision", c.collision);
  check_collision(c.collision);
  LongTimeConfig long_time = default_long_time_config(scene_index(kLongTimeScene));  // the study's rules, as its command has them
  params_from_json(long_time_params(), j["long_time"], "long_time", long_time);  // its one key: periods
  check_long_time(long_time, {"config: ", [](std::string_view p) {
                    return p == "periods" ? std::string("long_time.periods") : fmt::format("the long-time study's {}", p);
                  }});
  c.long_time_periods = long_time.periods;
  const Json& sc = j["scaling"];
  for (ReportSizes& s : c.scaling) {  // each within its size parameter's range
    const SceneKernel& k = scene_kernel(s.scene);
    const ParamSpec& size = k.params[static_cast<std::size_t>(k.size_param)];
    const std::string key(k.name);
    s.sizes.clear();
    for (const Json& n : sc[key]) s.sizes.push_back(count(n, "scaling." + key, static_cast<int>(size.min_count), static_cast<int>(size.max_count)));
  }
  c.scaling_error = num(sc["error"], "scaling.error", Bound::Positive);
  ScalingConfig measure;  // scaling.t_end by the study's rule, as its command has it
  measure.t_end = c.scaling_t_end;
  params_from_json(scaling_params(), sc, "scaling", measure);  // of its rows, only t_end is a report key
  c.scaling_t_end = measure.t_end;
  c.scaling_map_sizes.clear();
  if (!c.scaling.empty()) {  // within the first scene's size range
    const SceneKernel& k = scene_kernel(c.scaling.front().scene);
    const ParamSpec& size = k.params[static_cast<std::size_t>(k.size_param)];
    for (const Json& n : sc["map_sizes"])
      c.scaling_map_sizes.push_back(count(n, "scaling.map_sizes", static_cast<int>(size.min_count), static_cast<int>(size.max_count)));
  }
  c.scaling_stiffening = nums(sc["stiffening"], "scaling.stiffening", Bound::Positive);
  if (c.scaling_stiffening.empty()) throw UsageError("config: scaling.stiffening is empty; accepted: 1 or more positive factors");
  c.scaling_visual = num(sc["visual"], "scaling.visual", Bound::Positive);
  c.stiffened.params = scene_values(j[std::string(scene_name(c.stiffened.scene))], c.stiffened.scene);
  StiffOrderDefaults& s = c.stiff_order;
  params_from_json<StiffOrderDefaults>(kStiffnessesParam, j["stiff_order"], "stiff_order", s);
  ConvergenceConfig sweep = stiff_order_config(c.stiffened.scene, {}, s, {});
  params_from_json(convergence_params(), j["stiff_order"], "stiff_order", sweep);
  s.dt_max = sweep.dt_max, s.dt_min = sweep.dt_min, s.points = sweep.points, s.t_end = sweep.t_end;
  check_increasing("config: stiff_order.stiffnesses", s.stiffnesses);
  if (s.stiffnesses.size() < 2) throw UsageError("config: stiff_order.stiffnesses has fewer than 2 values; accepted: 2 or more");
  check_sweep(s.dt_min, s.dt_max, s.t_end, config_names("stiff_order"));
  params_from_json<ReportConfig>(kFigureParams, j["figures"], "figures", c);
  step_count(c.cannonball_t_end, c.cannonball_dt);
  for (double dt : c.spring_figure_dts) step_count(c.spring_figure_t_end, dt);
  step_count(c.energy_t_end, c.large_dt);
  c.threads = static_cast<unsigned>(count(j["threads"], "threads", 0, 1024));
  return c;
}

ReportConfig read_report_config(const std::string& path, const ReportConfig& base) {
  std::ifstream in(path);
  if (!in) throw UsageError(fmt::format("--config '{}' cannot be read; accepted: a readable JSON file", path));
  std::stringstream text;
  text << in.rdbuf();
  Json j;
  try {
    j = Json::parse(text.str());
  } catch (const nlohmann::json::parse_error& e) {
    throw UsageError(fmt::format("--config '{}' is not valid JSON (at byte {}); accepted: a JSON object", path, e.byte));
  }
  return report_config_from_json(j, base);
}

}  // namespace steplab
