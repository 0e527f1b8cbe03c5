// The studies of `steplab study`: their list, and each one's JSON document, printed table,
// parameters and schema name. Field names are an interface (docs/json.md).
//
// A new study: analysis/studies/<name>.{hpp,cpp} (its runs); reports/studies/<name>.cpp (its
// command, `StudyCommand <name>_command(CLI::App* study)`, built with study_command
// (reports/data/study_command.hpp); its StudyParam table, JSON and table, declared below with its
// schema name); and X(<name>) in this list, in `steplab study --help`'s order.
#pragma once

#define STEPLAB_STUDIES(X) \
  X(convergence)           \
  X(damping)               \
  X(stability)             \
  X(work_precision)        \
  X(collision)             \
  X(scaling)               \
  X(frames)                \
  X(long_time)             \
  X(dense_output)

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "analysis/studies/convergence.hpp"
#include "analysis/studies/order_reduction.hpp"
#include "reports/data/study_params.hpp"

namespace steplab {

using Json = nlohmann::ordered_json;

Json scene_params_json(std::size_t scene, const std::vector<double>& values);
// What an order fit cannot vouch for (analysis/fits/order_fit.hpp, step 7): of "few_points",
// "non_monotone" and "wide" those that hold, empty where none does (and where there is no fit).
Json fit_caveats(const OrderFit& f);
// The library builds the peers ran on (analysis/peers/peers.hpp, peer_builds): [{library, version,
// optimised, flags}], in every study's JSON that has peers.
Json peer_builds_json();

namespace schema {
inline constexpr std::string_view convergence = "steplab.convergence/2";              // study convergence
inline constexpr std::string_view convergence_sweep = "steplab.convergence_sweep/1";  // ... --sweep
}  // namespace schema
Json convergence_json(const ConvergenceResult& r);
std::string convergence_table(const ConvergenceResult& r);
// Its step sweep's parameters (the command's options, the report's convergence keys) and their
// rule (check_sweep; and at least 3 distinct steps). `name`: as the user wrote it.
std::span<const StudyParam<ConvergenceConfig>> convergence_params();
void check_convergence(const ConvergenceConfig& c, const ParamNamer& name);
// Order against stiffness: schema::convergence_sweep (each method's theory and its two
// limits checked, the fits by method and value, and each value's whole convergence study), and
// the table of fitted orders with the theory beside them (reports/studies/order_reduction.cpp).
Json order_reduction_json(const OrderReduction& r);
// A limit's check in a word: holds, fails, not reached, no fit, or "-" without a theory.
std::string limit_word(const LimitCheck& c, bool has_theory);
std::string order_reduction_table(const OrderReduction& r);

}  // namespace steplab

#include "analysis/studies/local_error.hpp"

namespace steplab {
// The old framework's error_measurement tables, %.5e.
std::string local_error_tables(const LocalErrorResult& r);
}  // namespace steplab

#include "analysis/studies/stability.hpp"

namespace steplab {
namespace schema {
// study stability and study damping on the spring: "unbounded" for a dt* of every step, "never"
// where a method is not stable again beyond dt* (version 1 wrote "inf" for both)
inline constexpr std::string_view stability = "steplab.stability/2";
// study stability on any other scene that declares its modes (version 1 was named after the rope)
inline constexpr std::string_view mode_stability = "steplab.mode_stability/1";
}  // namespace schema
// The spring's study's parameters (study stability's and study damping's options, the report's
// stability keys) and their rule: map-dt-min below map-dt-max.
std::span<const StudyParam<StabilityConfig>> stability_params();
void check_stability(const StabilityConfig& c, const ParamNamer& name);
// schema::stability; a study fills the parts it computed, the others are empty.
Json stability_json(const std::vector<double>& params, const std::vector<ThresholdRow>& thresholds,
                    const std::vector<SweepRow>& sweep, const StabilityMap* map);
std::string thresholds_table(const std::vector<ThresholdRow>& rows);
std::string sweep_table(const std::vector<SweepRow>& rows);
std::string map_summary(const StabilityMap& map);
std::string amplitude_table_text(const AmplitudeTable& t);
// A threshold dt*: a number, or "unbounded" (stable at every step).
Json threshold_json(double x);
std::string threshold_text(double x);
std::string again_text(double x);  // stable again from: "never" where infinite
}  // namespace steplab

#include "analysis/studies/mode_stability.hpp"

namespace steplab {
// `study stability` on a scene with modes (reports/studies/mode_stability.cpp): schema::mode_stability.
Json mode_stability_json(const ModeStabilityConfig& c, const std::vector<ModeThresholdRow>& rows);
std::string mode_thresholds_table(std::string_view scene, const std::vector<ModeThresholdRow>& rows);
}  // namespace steplab

#include "analysis/studies/scaling.hpp"

namespace steplab {
namespace schema {
// study scaling: "unbounded" for a stable step of every size (version 3 wrote "inf")
inline constexpr std::string_view scaling = "steplab.scaling/6";
}  // namespace schema
// `study scaling`. Its parameters
// that do not depend on the scene (t-end, frames, max-steps; the first is the report's scaling.t_end).
std::span<const StudyParam<ScalingConfig>> scaling_params();
Json scaling_json(const ScalingResult& r);
std::string scaling_table(const ScalingResult& r);
// The map alone: per target, stiffness and size the cheapest solver and its margins.
std::string scaling_map_table(const ScalingResult& r);
// ", stiffness 5000" (the scene's stiffness parameter); empty where NaN (the scene has none).
std::string stiffness_text(const ScalingConfig& c, double stiffness);
// "1.02 [0.95, 1.09]" (its 95 % interval), "*" appended where `early`; "-" where not fitted.
std::string exponent_text(const Exponent& e);
// An exponent's note under a table: what "-" and "*" mean, with the rule's numbers.
std::string exponent_rule_text();
}  // namespace steplab

#include "analysis/studies/collision.hpp"

namespace steplab {
namespace schema {
inline constexpr std::string_view collision = "steplab.collision/2";  // study collision
}  // namespace schema
Json collision_json(const CollisionResult& r);
std::string collision_table(const CollisionResult& r);
// Its parameters (the command's options, the report's collision keys) and their rule: at most
// max_steps steps a run.
std::span<const StudyParam<CollisionConfig>> collision_params();
void check_collision(const CollisionConfig& c);
}  // namespace steplab

#include "analysis/studies/work_precision.hpp"

namespace steplab {
namespace schema {
// study work-precision: the untimed cost is force evaluations, the Jacobians beside (version 1 added
// them in): by_forces, forces, explicit_forces, implicit_forces where it had *evaluations*
inline constexpr std::string_view work_precision = "steplab.work_precision/2";
}  // namespace schema
Json work_precision_json(const WorkPrecisionResult& r);
std::string work_precision_table(const WorkPrecisionResult& r);
// Its parameters (the command's options, the report's work_precision keys).
std::span<const StudyParam<WorkPrecisionConfig>> work_precision_params();
// "427 steps, 1708 forces": a run's counts (analysis/kernel/counts.hpp), with the rejected steps,
// Jacobians and factorisations where it has them.
std::string counts_text(const Counts& n);
}  // namespace steplab

#include "analysis/studies/frames.hpp"

namespace steplab {
namespace schema {
inline constexpr std::string_view frames = "steplab.frames/4";  // study frames
}  // namespace schema
Json frames_json(const FramesResult& r);
std::string frames_table(const FramesResult& r);
// Its parameters (the command's options) and their rule: a whole number of frames, at least 1.
std::span<const StudyParam<FramesConfig>> frames_params();
void check_frames(const FramesConfig& c);
// "30 x 1 sweep", "5 x 6 CG", "10 substeps": a set-up's substeps a frame and its settings.
std::string frame_setup_text(const FrameSetup& s);
// "1 sweep", "1000 CG", "": its settings alone.
std::string frame_settings_text(const FrameSetup& s);
}  // namespace steplab

#include "analysis/studies/long_time.hpp"

namespace steplab {
namespace schema {
inline constexpr std::string_view long_time = "steplab.long_time/1";  // study long-time
}  // namespace schema
Json long_time_json(const LongTimeResult& r);
std::string long_time_table(const LongTimeResult& r);
// Its parameters (the command's options, the report's long_time keys) and the rules between
// them: fit-from below periods, at most 1e10 steps a run. `name` gives a parameter's name as
// the user wrote it ("--periods", "config: long_time.periods").
std::span<const StudyParam<LongTimeConfig>> long_time_params();
void check_long_time(const LongTimeConfig& c, const ParamNamer& name);
// "0.02 [0.01, 0.03]" for a fitted growth exponent, "-" where there were too few samples.
std::string growth_text(const GrowthFit& g);
}  // namespace steplab

#include "analysis/studies/dense_output.hpp"

namespace steplab {
namespace schema {
inline constexpr std::string_view dense_output = "steplab.dense_output/1";  // study dense-output
}  // namespace schema
Json dense_output_json(const DenseOutputResult& r);
std::string dense_output_table(const DenseOutputResult& r);
// Its parameters (the command's options); their rule is check_sweep's.
std::span<const StudyParam<DenseOutputConfig>> dense_output_params();
}  // namespace steplab

namespace steplab {
struct StudyCommand;  // reports/data/study_command.hpp
// Each study's command, `<name>_command`, made in reports/studies/<name>.cpp (damping's beside
// stability's).
#define STEPLAB_STUDY_COMMAND(name) StudyCommand name##_command(CLI::App* study);
STEPLAB_STUDIES(STEPLAB_STUDY_COMMAND)
#undef STEPLAB_STUDY_COMMAND
}  // namespace steplab
