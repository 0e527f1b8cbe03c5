#include "reports/cli/cli.hpp"

#include <algorithm>
#include <array>
#include <span>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "reports/cli/commands.hpp"
#include "reports/cli/input_checks.hpp"
#include "analysis/kernel/kernel.hpp"
#include "reports/data/inputs.hpp"
#include "reports/cli/shards.hpp"
#include "reports/data/schemas.hpp"
#include "reports/studies/studies.hpp"
#include "analysis/kernel/parallel.hpp"
#include "analysis/studies/local_error.hpp"
#include "analysis/studies/defaults.hpp"
#include "reports/document/section.hpp"

namespace steplab {
namespace {

// The old command-line framework (the exercise slides): single-dash flags, its own defaults.
//   steplab -testcase spring1d -method euler -step 0.01 -damp 0.1 -mass 1 -stiff 10 [-length 1]
constexpr std::array<std::string_view, 7> legacy_flags{"-testcase", "-method", "-step", "-damp",
                                                       "-mass",     "-stiff",  "-length"};
// Its test cases: its scenes (analysis/studies/defaults.hpp; the first is where it starts and where the
// two measurements run) and two measurements.
constexpr std::array<std::string_view, 2> legacy_measurements{"error_measurement", "stability_measurement"};
std::string legacy_testcases() {
  std::string out;
  for (const auto& list : {std::span<const std::string_view>(kLegacyScenes), std::span<const std::string_view>(legacy_measurements)})
    for (const std::string_view name : list) out += (out.empty() ? "" : ", ") + std::string(name);
  return out;
}

// The studies, in `steplab study --help`'s order (STEPLAB_STUDIES, reports/studies/studies.hpp).
#define STEPLAB_STUDY_MAKER(name) name##_command,
constexpr StudyCommand (*kStudies[])(CLI::App*) = {STEPLAB_STUDIES(STEPLAB_STUDY_MAKER)};
#undef STEPLAB_STUDY_MAKER

// Its defaults: step 0.003, mass 0.1, stiffness 10, damping 0.01, rest length 1.
struct LegacyArgs {
  std::string testcase{kLegacyScenes[0]};
  std::string method = "euler";
  std::string step = "0.003";
  std::string damp, mass, stiff, length;
};

void add_legacy_options(CLI::App& app, LegacyArgs& l) {
  const char* group = "The old framework's flags (single or double dash; its defaults apply)";
  app.add_option("--testcase", l.testcase, legacy_testcases())
      ->capture_default_str()->group(group);
  app.add_option("--method", l.method, "integrator (old or new name)")->capture_default_str()->group(group);
  app.add_option("--step", l.step, "time step")->capture_default_str()->group(group);
  app.add_option("--damp", l.damp, "damping (default 0.01)")->group(group);
  app.add_option("--mass", l.mass, "mass (default 0.1)")->group(group);
  app.add_option("--stiff", l.stiff, "stiffness (default 10)")->group(group);
  app.add_option("--length", l.length, "rest length (default 1)")->group(group);
}

// The old framework's amplitude table (`-testcase amplitude`), the spring's.
int amplitude_command(const std::vector<double>& spring_params, double step, const Context& ctx) {
  if (ctx.dry_run) return 0;
  std::vector<std::size_t> methods = resolve_methods("", true);
  std::rotate(methods.begin(), methods.end() - 1, methods.end());  // the analytic column first
  const AmplitudeTable t = amplitude_table(spring_params, methods, step, 10);
  std::fputs(amplitude_table_text(t).c_str(), stdout);
  return 0;
}

int legacy_command(const LegacyArgs& l, Context& ctx) {
  const auto is = [&](std::span<const std::string_view> list) { return std::find(list.begin(), list.end(), l.testcase) != list.end(); };
  const bool measurement = is(legacy_measurements);
  if (!measurement && !is(kLegacyScenes))
    throw UsageError(fmt::format("-testcase '{}' is unknown{}; accepted: {}", l.testcase,
                                 did_you_mean(l.testcase, split_list(legacy_testcases())), legacy_testcases()));
  // Checked here first so that a message names the flag as typed.
  parse_number("-step", l.step, Bound::Positive);
  for (const auto& [flag, value] : {std::pair{"-mass", &l.mass}, {"-stiff", &l.stiff}, {"-damp", &l.damp}, {"-length", &l.length}})
    if (!value->empty()) parse_number(flag, *value, std::string_view(flag) == "-mass" ? Bound::Positive : Bound::NonNegative);
  RunArgs run;
  const std::size_t scene = *find_scene(measurement ? kLegacyScenes[0] : std::string_view(l.testcase));
  run.scene.scene = scene_name(scene);
  run.scene.old_defaults = {{"mass", 0.1}, {"stiffness", 10.0}, {"damping", 0.01}, {"rest-length", 1.0}};
  std::erase_if(run.scene.old_defaults, [&](const auto& d) { return !has_param(scene, d.first); });
  if (!l.mass.empty()) run.scene.set("mass", l.mass);
  if (!l.stiff.empty()) run.scene.set("stiffness", l.stiff);
  if (!l.damp.empty()) run.scene.set("damping", l.damp);
  if (!l.length.empty()) run.scene.set("rest-length", l.length);
  if (l.testcase == legacy_measurements[0]) {
    LocalErrorConfig c;
    c.params = run.scene.values(run.scene.scene_index());
    c.step = parse_number("-step", l.step, Bound::Positive);
    c.methods = resolve_methods("", false);
    if (ctx.dry_run) return 0;
    std::fputs(local_error_tables(local_error_study(c)).c_str(), stdout);
    return 0;
  }
  if (l.testcase == legacy_measurements[1])
    return amplitude_command(run.scene.values(run.scene.scene_index()), parse_number("-step", l.step, Bound::Positive), ctx);
  run.method = l.method;
  run.dt = l.step;
  return run_command(run, ctx);
}

// What each option takes, shown in --help instead of CLI11's TEXT (every value is read as text and
// checked by reports/data/inputs.cpp, so that a bad one gets steplab's own message). A list is
// "KIND,...". By command where one option takes different things in different commands.
std::string_view value_kind(std::string_view command, std::string_view option) {
  static constexpr std::pair<std::string_view, std::string_view> by_command[] = {
      {"scaling --error", "NUMBER[%],..."}, {"scaling --stiffness", "NUMBER,..."}, {"convergence --error", "final|max|rms"},
      {"scaling --sizes", "WHOLE,..."}};
  for (const auto& [name, kind] : by_command)
    if (name.substr(0, name.find(' ')) == command && name.substr(name.find(' ') + 1) == option) return kind;
  static constexpr std::pair<std::string_view, std::string_view> kinds[] = {
      {"--samples", "WHOLE"},         {"--error-every", "WHOLE"},     {"--threads", "WHOLE"},
      {"--lanes", "auto|1|2|4|8"},    {"--shard", "i/N"},             {"--frames", "WHOLE"},
      {"--max-steps", "WHOLE"},       {"--map-dt-points", "WHOLE"},   {"--map-damping-points", "WHOLE"},
      {"--methods", "NAME,..."},      {"--dts", "NUMBER,..."},        {"--threshold-dampings", "NUMBER,..."},
      {"--dampings", "NUMBER,..."},   {"--method", "NAME"},
      {"--scene", "NAME"},            {"--testcase", "NAME"},         {"--json", "FILE"},
      {"--config", "FILE"},           {"--out", "FOLDER"},            {"--scenes", "NAME,..."},
      {"--sweep", "NAME=NUMBER,..."}, {"--sections", "NAME,..."},     {"--sweeps", "WHOLE"},
      {"--cg-iterations", "WHOLE"}};
  for (const auto& [name, kind] : kinds)
    if (name == option) return kind;
  return "NUMBER";  // steps, times, ranges and every scene parameter
}

// Every option's help in one style: what it takes as its label, its default at the end of its
// description, "(default X)", as the scene parameters' help has it.
void name_value_kinds(CLI::App& app) {
  for (CLI::Option* o : app.get_options()) {
    if (o->get_expected_max() == 0 || o->get_lnames().empty() || o == app.get_help_ptr()) continue;  // flags, --help
    if (o->get_type_name() == "TEXT") o->type_name(std::string(value_kind(app.get_name(), "--" + o->get_lnames()[0])));
    if (const std::string d = o->get_default_str(); !d.empty()) {
      o->description(fmt::format("{} (default {})", o->get_description(), d));
      o->default_str("");
    }
  }
  for (CLI::App* sub : app.get_subcommands({})) name_value_kinds(*sub);
}

// "1234/4096 runs, 12 s, about 29 s left": a stage of a study (one parallel_for) as it goes.
std::string progress_text(std::size_t done, std::size_t total, double seconds) {
  const double left = seconds * static_cast<double>(total - done) / static_cast<double>(done);
  return fmt::format("steplab: {}/{} runs, {:.0f} s, about {:.0f} s left", done, total, seconds, left);
}

// On a terminal: one line rewritten in place, once a stage has run for a second.
void terminal_progress(std::size_t done, std::size_t total, double seconds) {
  if (seconds < 1) return;
  std::fprintf(stderr, "\r\033[K%s", progress_text(done, total, seconds).c_str());
  if (done == total) std::fputs("\r\033[K", stderr);
}

// Elsewhere (--progress, into a log): a line every 5 s of a stage, and its last one. Called under
// parallel_for's lock, one stage at a time.
void log_progress(std::size_t done, std::size_t total, double seconds) {
  static double printed = 0;
  if (done == 1) printed = 0;  // a new stage
  if (seconds < 1 || (seconds - printed < 5 && done < total)) return;
  printed = seconds;
  std::fprintf(stderr, "%s\n", progress_text(done, total, seconds).c_str());
}

std::vector<std::string> names_of(const std::vector<CLI::App*>& apps) {
  std::vector<std::string> out;
  for (const CLI::App* a : apps) out.push_back(a->get_name());
  return out;
}

// A command word that names no command (`steplab frobnicate`, `steplab study stabilty`): named,
// with the nearest command, before CLI11 would call it an extra argument or a missing subcommand.
void check_command_words(CLI::App& app, const std::vector<std::string>& args) {
  const auto check = [](CLI::App& parent, const std::string& word, const std::string& where) {
    const std::vector<std::string> names = names_of(parent.get_subcommands({}));
    if (std::find(names.begin(), names.end(), word) == names.end())
      throw UsageError(fmt::format("{} '{}' is unknown{}; accepted: {}", where, word, did_you_mean(word, names), fmt::join(names, ", ")));
  };
  if (args.empty() || args[0].empty() || args[0][0] == '-') return;
  check(app, args[0], "command");
  CLI::App* sub = app.get_subcommand(args[0]);
  if (sub->get_require_subcommand_min() == 0) return;
  if (args.size() < 2 || args[1].empty() || args[1][0] == '-') {
    if (args.size() >= 2 && (args[1] == "--help" || args[1] == "-h")) return;
    throw UsageError(fmt::format("{} needs a subcommand; accepted: {}", args[0], fmt::join(names_of(sub->get_subcommands({})), ", ")));
  }
  check(*sub, args[1], args[0]);
}

// What no option took (allow_extras): the first such word named, and for an option the nearest
// option of the command it was given to.
void check_no_extras(CLI::App& app) {
  CLI::App* at = &app;
  while (!at->get_subcommands().empty()) at = at->get_subcommands().front();
  const std::vector<std::string> extra = app.remaining(true);
  if (extra.empty()) return;
  const std::string command = at == &app ? "steplab" : at->get_parent() == &app ? "steplab " + at->get_name()
                                                                                 : "steplab " + at->get_parent()->get_name() + " " + at->get_name();
  const std::string& word = extra.front();
  if (word.rfind("-", 0) != 0)
    throw UsageError(fmt::format("'{}' is not expected by {} (a value needs the option it belongs to); see {} --help", word, command,
                                 command));
  std::vector<std::string> options;
  for (const CLI::Option* o : at->get_options())
    for (const std::string& n : o->get_lnames()) options.push_back("--" + n);
  const std::string name = word.substr(0, word.find('='));
  throw UsageError(fmt::format("{} is not an option of {}{}; see {} --help", name, command, did_you_mean(name, options), command));
}

}  // namespace

int cli_main(int argc, const char* const* argv, bool dry_run) {
  Context ctx;
  ctx.dry_run = dry_run;
  if (isatty(STDERR_FILENO)) ctx.progress = terminal_progress;
  // The old single-dash flags become GNU long options; everything else is left as typed.
  std::vector<std::string> args;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    for (auto flag : legacy_flags)
      if (a == flag) a = "-" + a;
    args.push_back(std::move(a));
  }
  return dispatch(args, ctx);
}

int dispatch(const std::vector<std::string>& args, Context& ctx) {
  bool legacy = false;
  for (const std::string& a : args)
    for (auto flag : legacy_flags)
      if (a == "-" + std::string(flag)) legacy = true;

  CLI::App app{"steplab: measures how time integrators behave (convergence order, stability, cost)"};
  app.name("steplab");
  app.allow_extras();  // inherited by every command: an unknown option is named below, with the nearest one
  app.set_version_flag("--version", "steplab " STEPLAB_VERSION);
  app.failure_message([](const CLI::App*, const CLI::Error& e) { return std::string(e.what()) + "\n"; });

  LegacyArgs legacy_args;
  add_legacy_options(app, legacy_args);

  RunArgs run;
  CLI::App* run_cmd = app.add_subcommand("run", "one method on one scene: CSV (t, x..., v..., energy) on stdout, or --json");
  run.scene.add_to(run_cmd);
  run_cmd->add_option("--method", run.method, "integrator: " + method_names() + ", or the adaptive dopri5")
      ->capture_default_str();
  run_cmd->add_option("--dt", run.dt, "time step h (> 0; default 0.01); fixed-step methods only");
  run_cmd->add_option("--rtol", run.rtol, "dopri5: relative tolerance, 1e-13 .. 1 (default 1e-3, as SciPy's RK45)");
  run_cmd->add_option("--atol", run.atol, "dopri5: absolute tolerance, > 0 (default 1e-6)");
  run_cmd->add_option("--t-end", run.t_end, "simulated time; t_end / dt steps, rounded up")->capture_default_str();
  run_cmd->add_option("--samples", run.samples, "at most this many rows, evenly decimated, last step kept (default 10001, "
                                                 "fewer on a large scene: at most 10^6 numbers in all)");
  run_cmd->add_option("--error-every", run.error_every,
                      "with --json, on a scene whose exact positions cost a transform (the rope): read the error every this "
                      "many steps and at the last (default: steps / 100, at least 1; 1: every step)");
  run.settings.add_to(run_cmd);
  run_cmd->add_option("--json", run.json, fmt::format("write JSON (schema {}) to this file instead of CSV", schema::run));

  CLI::App* study = app.add_subcommand("study", "a study over many runs; prints a table, --json writes its data");
  study->require_subcommand(1);
  std::vector<StudyCommand> studies;
  for (StudyCommand (*make)(CLI::App*) : kStudies) studies.push_back(make(study));

  ReportArgs rep;
  CLI::App* rep_cmd = app.add_subcommand("report", "run every study and write report.md, report.pdf, atlas.html, figures/ and data/ into one folder");
  rep_cmd->add_option("--out", rep.out, "output folder")->capture_default_str();
  rep_cmd->add_option("--config", rep.config, "JSON file overriding any study parameter (see --print-config)");
  CLI::Option* rep_methods = rep_cmd->add_option("--methods", rep.methods, "comma-separated methods the report covers (default every one, analytic included)");
  CLI::Option* rep_scenes = rep_cmd->add_option("--scenes", rep.scenes, "comma-separated scenes the report covers (default the report's own; a section that needs another is left out with one line): " + scene_list());
  CLI::Option* rep_sections = rep_cmd->add_option("--sections", rep.sections, "comma-separated sections, in any order (default the full report's): " + fmt::format("{}", fmt::join(section_names(), ", ")));
  rep_cmd->add_flag("--sheet", rep.sheet, "the exercise's hand-in: the sheet's four methods and the analytic solution on the cannon ball and the spring, with the slides' falling triangle, in 5 pages (--config, --methods, --scenes and --sections apply over it)");
  rep_cmd->add_flag("--force", rep.force, "redo the report even if it is up to date");
  rep_cmd->add_flag("--print-config", rep.print_config, "print the configuration (defaults, or --config applied) and exit");

  CheckArgs check;
  CLI::App* check_cmd = app.add_subcommand("check", "is a method what its row in the table claims? One line per claim, "
                                                    "PASS or FAIL; exit 0 if all hold, 1 if one fails");
  check_cmd->add_option("--method", check.method, "integrator: " + method_names());
  add_threads_option(check_cmd, check.threads);

  MergeArgs merge;
  add_merge_command(app, merge);

  bool progress = false;
  std::vector<CLI::App*> with_progress{rep_cmd, check_cmd};
  for (const StudyCommand& s : studies) with_progress.push_back(s.app);
  for (CLI::App* cmd : with_progress)
    cmd->add_flag("--progress", progress, "progress on stderr also where it is not a terminal (a log): runs done, time spent and left");

  name_value_kinds(app);
  ctx.invocation = args;

  std::vector<const char*> cargv{"steplab"};
  for (const auto& a : args) cargv.push_back(a.c_str());
  try {
    check_unique_names();
    check_command_words(app, args);
    check_repeats(args);
    app.parse(static_cast<int>(cargv.size()), cargv.data());
    check_no_extras(app);
    check_no_empty_values(app);
    if (progress) ctx.progress = log_progress;
    if (run_cmd->parsed()) return run_command(run, ctx);
    for (const StudyCommand& s : studies)
      if (s.app->parsed()) return s.run(ctx);
    if (rep_cmd->parsed()) {
      rep.methods_given = rep_methods->count() > 0, rep.scenes_given = rep_scenes->count() > 0,
      rep.sections_given = rep_sections->count() > 0;
      return report_command(rep, ctx);
    }
    if (check_cmd->parsed()) return check_command(check, ctx);
    if (app.got_subcommand("merge")) return merge_command(merge, ctx);
    if (legacy) return legacy_command(legacy_args, ctx);
    throw UsageError("no command given; accepted: run, study, report, check, or the old flags -testcase ... (see steplab --help)");
  } catch (const CLI::CallForHelp&) {
    std::fputs(app.help().c_str(), stdout);
    return 0;
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) {
      app.exit(e);
      return 0;
    }
    fmt::print(stderr, "steplab: {}; see steplab --help\n", e.what());
    return 2;
  } catch (const UsageError& e) {
    fmt::print(stderr, "steplab: {}\n", e.what());
    return 2;
  }
}

int program_main(int argc, char** argv) {
  try {
    return cli_main(argc, argv);
  } catch (const Interrupted&) {
    std::fputs("steplab: interrupted; nothing was written or replaced\n", stderr);
    return 130;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "steplab: %s\n", e.what());
    return 1;
  }
}

}  // namespace steplab
