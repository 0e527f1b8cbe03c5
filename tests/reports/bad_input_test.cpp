// Every bad input, across the command line and the report's configuration file, gets one line
// on stderr naming the input, exit status 2, nothing on stdout, and leaves no new or changed file.
// Each case runs in its own empty folder (its working directory), holding only the files the
// case provides, which must come out unchanged.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <ostream>

#include "cli_helpers.hpp"
#include "core/batch.hpp"
#include "reports/studies/studies.hpp"

namespace steplab {
namespace {

namespace fs = std::filesystem;

struct BadInput {
  const char* args;        // {dir} is replaced by the case's folder
  const char* names;       // the message must contain this
  const char* file = "";   // written to {dir}/config.json first, if not empty
};

std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir)) files[e.path().string()] = e.is_regular_file() ? slurp(e.path().string()) : "<dir>";
  return files;
}

std::string replace_dir(std::string s, const std::string& dir) {
  for (std::size_t at; (at = s.find("{dir}")) != std::string::npos;) s.replace(at, 5, dir);
  return s;
}

class BadInputs : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadInputs, OneLineExitTwoNothingWritten) {
  const BadInput& in = GetParam();
  TempDir dir;
  if (*in.file) std::ofstream(dir.path("config.json")) << in.file;
  const auto before = snapshot(dir.root());
  const Result r = run_steplab_in(dir.root(), replace_dir(in.args, dir.root()));
  EXPECT_EQ(r.status, 2) << in.args << "\n" << r.err;
  const auto lines = split_lines(r.err);
  ASSERT_EQ(lines.size(), 1u) << in.args << "\n" << r.err;
  EXPECT_NE(lines[0].find(in.names), std::string::npos) << in.args << ": " << lines[0];
  EXPECT_EQ(lines[0].rfind("steplab: ", 0), 0u) << lines[0];
  EXPECT_TRUE(r.out.empty()) << in.args;
  EXPECT_EQ(snapshot(dir.root()), before) << in.args << " wrote or changed a file";
}

// How a case reads in the test list (CTest shows it as the test's name): the command, and the
// config file it is given.
void PrintTo(const BadInput& in, std::ostream* os) {
  *os << "steplab " << in.args;
  if (*in.file) *os << " with config.json " << in.file;
}

INSTANTIATE_TEST_SUITE_P(
    CliAndConfig, BadInputs,
    ::testing::Values(
        // run: names
        BadInput{"run --scene double_pendulum", "double_pendulum"}, BadInput{"run --method heun", "heun"},
        // a typo: the nearest name, whatever kind of name it is
        BadInput{"study stabilty", "study 'stabilty' is unknown (did you mean 'stability'?)"},
        BadInput{"run --dtt 0.01", "--dtt is not an option of steplab run (did you mean '--dt'?)"},
        BadInput{"study convergence --dt-mx 0.1", "(did you mean '--dt-max'?)"},
        BadInput{"run --method rk5", "(did you mean 'rk4'?)"}, BadInput{"run --scene sprign", "(did you mean 'spring'?)"},
        BadInput{"study convergence --methods rk4,explict_euler", "(did you mean 'explicit_euler'?)"},
        BadInput{"report --sections sumary --out {dir}/r", "(did you mean 'summary'?)"},
        BadInput{"rnu", "command 'rnu' is unknown (did you mean 'run'?)"},
        BadInput{"run --frobnicate 3", "--frobnicate"}, BadInput{"frobnicate", "frobnicate"},
        // a method's settings, and a method on springs where there are none
        BadInput{"run --method xpbd --sweeps 0", "--sweeps"}, BadInput{"run --method xpbd --sweeps -2", "--sweeps"},
        BadInput{"run --method pbd --sweeps abc", "--sweeps"}, BadInput{"run --method xpbd --sweeps 1.5", "--sweeps"},
        BadInput{"run --method baraff_witkin --cg-iterations 0", "--cg-iterations"},
        BadInput{"run --method baraff_witkin --cg-tolerance 0", "--cg-tolerance"},
        BadInput{"run --method baraff_witkin --cg-tolerance 2", "--cg-tolerance"},
        BadInput{"run --method baraff_witkin --cg-tolerance x", "--cg-tolerance"},
        BadInput{"run --method rk4 --sweeps 3", "--sweeps applies to xpbd, pbd; --method rk4 takes none"},
        BadInput{"run --method xpbd --cg-iterations 3", "--cg-iterations applies to baraff_witkin"},
        BadInput{"study convergence --methods rk4,bdf2 --sweeps 2", "--sweeps applies to xpbd, pbd; --methods take none"},
        BadInput{"study convergence --scene rope --methods xpbd --sweeps 0", "--sweeps"},
        BadInput{"run --scene cannonball --method xpbd", "cannonball is not made of springs; accepted: spring, falling, chain, rope, softbody, cloth"},
        BadInput{"study frames --scene cannonball", "--scene cannonball"}, BadInput{"study frames --budget 0", "--budget"},
        BadInput{"study frames --budget x", "--budget"}, BadInput{"study frames --fps 0", "--fps"},
        BadInput{"study frames --t-end 0.01", "a whole number of frames"},
        BadInput{"study long-time --scene spring", "--scene spring declares no invariants; accepted: kepler, swing"},
        BadInput{"study long-time --periods 0.5", "--periods"}, BadInput{"study long-time --periods 1e8", "--periods"},
        BadInput{"study long-time --steps-per-period 0", "--steps-per-period"},
        BadInput{"study long-time --scene swing --damping 0.1", "no invariant"},
        BadInput{"study long-time --fit-from 1e5", "--fit-from"}, BadInput{"study long-time --eccentricity 1", "eccentricity"},
        BadInput{"study long-time --methods rk5", "did you mean"},
        BadInput{"study frames --scene chain --methods xpbd,radau_iia5,xpbd", "twice"},
        BadInput{"report --methods xpbd --out {dir}/r", "'xpbd' works on a scene's springs"},
        // run: numbers
        BadInput{"run --dt 0", "--dt"}, BadInput{"run --dt -0.1", "--dt"}, BadInput{"run --dt nan", "--dt"},
        BadInput{"run --dt inf", "--dt"}, BadInput{"run --dt -inf", "--dt"}, BadInput{"run --dt abc", "--dt"},
        BadInput{"run --dt 1e400", "--dt"}, BadInput{"run --dt", "--dt"}, BadInput{"run --mass 0", "--mass"},
        BadInput{"run --mass -1", "--mass"}, BadInput{"run --stiffness -5", "--stiffness"},
        BadInput{"run --stiffness 0", "--stiffness"}, BadInput{"run --damping -0.1", "--damping"},
        BadInput{"run --rest-length -1", "--rest-length"}, BadInput{"run --t-end -1", "--t-end"},
        BadInput{"run --gravity -inf", "--gravity"}, BadInput{"run --dt 1e-12 --t-end 1e6", "steps"},
        BadInput{"run --samples 1", "--samples"}, BadInput{"run --samples many", "--samples"},
        // run: impossible combinations and outputs
        BadInput{"run --scene cannonball --stiffness 3", "--stiffness"},
        BadInput{"run --scene falling --method analytic", "analytic"},
        BadInput{"run --json {dir}/no/such/folder/out.json", "no/such/folder"}, BadInput{"run --json {dir}", "directory"},
        // run: the adaptive dopri5 takes tolerances, the fixed-step methods a step
        BadInput{"run --method dopri5 --dt 0.1", "--dt"}, BadInput{"run --method rk4 --rtol 1e-6", "--rtol"},
        BadInput{"run --method dopri5 --rtol 0", "--rtol"}, BadInput{"run --method dopri5 --rtol 1e-20", "--rtol"},
        BadInput{"run --method dopri5 --atol -1", "--atol"}, BadInput{"run --method dopri5 --atol nan", "--atol"},
        // the old flags
        BadInput{"-testcase nosuch", "nosuch"}, BadInput{"-testcase spring1d -step -1", "-step"},
        BadInput{"-testcase spring1d -stiff -1", "-stiff"}, BadInput{"-method nosuch", "nosuch"},
        BadInput{"-testcase error_measurement -step 0", "-step"}, BadInput{"-testcase spring1d -mass nan", "-mass"},
        // lanes, shards and merge
        BadInput{"study stability --lanes 0", "--lanes"}, BadInput{"study convergence --lanes 65", "--lanes"},
        BadInput{"study stability --lanes 3", "--lanes"}, BadInput{"study convergence --lanes wide", "--lanes"},
        BadInput{"study damping --shard 2", "--shard"}, BadInput{"study damping --shard 0/3 --json {dir}/p.json", "--shard"},
        BadInput{"study stability --shard 4/3 --json {dir}/p.json", "--shard"},
        BadInput{"study collision --shard 1/3", "--json"},
        BadInput{"study convergence --timing --shard 1/2 --json {dir}/p.json", "--timing"},
        BadInput{"study work-precision --shard 1/2 --json {dir}/p.json", "--no-timing"},
        BadInput{"merge --json {dir}/out.json", "parts"}, BadInput{"merge {dir}/config.json", "--json"},
        BadInput{"merge {dir}/config.json --json {dir}/out.json", "not a steplab part", "{\"schema\": \"steplab.stability/1\"}"},
        BadInput{"merge {dir}/nosuch.json --json {dir}/out.json", "nosuch.json"},
        // studies
        BadInput{"study", "subcommand"}, BadInput{"study convergence --dt-min 0.2 --dt-max 0.1", "--dt-min"},
        BadInput{"study convergence --points 2", "--points"}, BadInput{"study convergence --scene falling --error max", "--error"},
        BadInput{"study convergence --methods rk4,rk4", "rk4"}, BadInput{"study convergence --methods rk4,foo", "foo"},
        BadInput{"study convergence --error median", "median"}, BadInput{"study convergence --dt-min 1e-12", "steps"},
        BadInput{"study convergence --threads -1", "--threads"}, BadInput{"study convergence --dt-max 100", "--dt-max"},
        BadInput{"study convergence --json {dir}/no/out.json", "no/out.json"},
        BadInput{"study damping --dts 0.01,-0.05", "--dts"}, BadInput{"study damping --dampings 1,,2", "--dampings"},
        BadInput{"study stability --map-dt-min 1 --map-dt-max 0.1", "--map-dt-min"},
        BadInput{"study stability --threshold-dampings -1", "--threshold-dampings"},
        BadInput{"study stability --map-dt-points 1", "--map-dt-points"}, BadInput{"study collision --dts 0", "--dts"},
        BadInput{"study collision --rest-length 3", "--rest-length"}, BadInput{"study collision --t-end nan", "--t-end"},
        BadInput{"study scaling --scene spring", "--scene"},
        // a peer that does not run on the scene, one of an old name, one named twice, with --no-peers
        BadInput{"study scaling --scene rope --methods rk4,cvode_bdf_klu --json {dir}/s.json", "--methods 'cvode_bdf_klu'"},
        BadInput{"study scaling --scene softbody --methods cvode_adams_band", "--methods 'cvode_adams_band'"},
        BadInput{"study scaling --methods cvode_band", "--methods 'cvode_band'"},
        BadInput{"study scaling --methods dopri5,dopri5", "--methods names 'dopri5' twice"},
        BadInput{"study scaling --methods rk4,odeint_dopri5 --no-peers", "--no-peers"},
        BadInput{"study work-precision --methods cvode_bdf_band", "--methods 'cvode_bdf_band'"}, BadInput{"study scaling --scene softbody --sizes 2.5", "--sizes"},
        BadInput{"study scaling --scene softbody --sizes 301", "--sizes"}, BadInput{"study scaling --max-steps 0", "--max-steps"},
        // the stiffness axis, the targets (numbers or percentages of the extent), the frames
        BadInput{"study scaling --stiffness 5,-50 --json {dir}/s.json", "--stiffness"},
        BadInput{"study scaling --stiffness 5,,50", "--stiffness"}, BadInput{"study scaling --error 1e-4,abc%", "--error"},
        BadInput{"study scaling --error 0", "--error"}, BadInput{"study scaling --error ,", "--error"},
        BadInput{"study scaling --frames 0", "--frames"}, BadInput{"study scaling --frames 2.5", "--frames"},
        // a list names each value once, as the others do
        BadInput{"study scaling --stiffness 5,5", "--stiffness names 5 twice"},
        BadInput{"study scaling --error 1e-4,1e-4", "--error names 0.0001 twice"},
        BadInput{"study scaling --error 1%,1%", "--error names 1% twice"}, BadInput{"study scaling --sizes 8,8", "--sizes names 8 twice"},
        BadInput{"run --scene softbody --grid 0", "--grid"}, BadInput{"run --scene softbody --masses 4", "--masses"},
        // the cloth needs two pins and a mass: 2 a side at least (ParamSpec::min_count)
        BadInput{"run --scene cloth --grid 1", "--grid"}, BadInput{"study frames --scene cloth --reference-substeps 1", "--reference-substeps"},
        // check
        BadInput{"check", "--method"}, BadInput{"check --method heun", "heun"},
        BadInput{"check --method rk4 --threads -1", "--threads"},
        BadInput{"study work-precision --methods rk4,heun", "heun"}, BadInput{"study work-precision --threads x", "--threads"},
        // the report's configuration file
        BadInput{"report --config {dir}/missing.json --out {dir}/r", "missing.json"},
        BadInput{"report --config {dir}/config.json --out {dir}/r", "not valid JSON", "{ not json"},
        BadInput{"report --config {dir}/config.json --out {dir}/r", "spring.damping", R"({"spring": {"damping": "lots"}})"},
        BadInput{"report --config {dir}/config.json --out {dir}/r", "sprung", R"({"sprung": {}})"},
        BadInput{"report --config {dir}/config.json --out {dir}/r", "dt_min", R"({"convergence": {"dt_min": 0.5, "dt_max": 0.1}})"},
        BadInput{"report --config {dir}/config.json --out {dir}/r", "points", R"({"convergence": {"points": 2}})"},
        BadInput{"report --config {dir}/config.json --out {dir}/r", "steps", R"({"collision": {"triangle_dt": 1e-12}})"},
        BadInput{"report --config {dir}/config.json --out {dir}/r", "spring.mass", R"({"spring": {"mass": -1}})"},
        BadInput{"report --config {dir}/config.json --out {dir}/r", "JSON object", "[]"},
        BadInput{"report --config {dir}/config.json --out {dir}/r", "scaling.softbody", R"({"scaling": {"softbody": [2.5]}})"},
        BadInput{"report --config {dir}/config.json --out {dir}/r", "scaling.softbody", R"({"scaling": {"softbody": [301]}})"},
        BadInput{"report --config {dir}/config.json --out {dir}/r", "scaling.map_sizes", R"({"scaling": {"map_sizes": [0]}})"},
        BadInput{"report --config {dir}/config.json --out {dir}/r", "scaling.stiffening", R"({"scaling": {"stiffening": []}})"},
        BadInput{"report --config {dir}/config.json --out {dir}/r", "scaling.visual", R"({"scaling": {"visual": -1}})"},
        BadInput{"report --config {dir}/config.json --out {dir}/r", "sweep_dts", R"({"stability": {"sweep_dts": [0.01, "x"]}})"},
        BadInput{"report --config {dir}/config.json --out {dir}/r", "not valid JSON", R"({"spring": {"mass": NaN}})"},  // JSON has no NaN
        BadInput{"report --out {dir}/no/such/report", "no/such"},
        // no file of a user's replaced: a folder that holds one, a file, a JSON file not steplab's
        BadInput{"report --sheet --out {dir}", "holds files steplab did not write (config.json)", "my thesis"},
        BadInput{"report --sheet --out {dir}/config.json", "is a file steplab did not write", "my notes"},
        BadInput{"run --json {dir}/config.json", "holds a file steplab did not write", "my notes"},
        BadInput{"study convergence --json {dir}/config.json", "holds a file steplab did not write", R"({"mine": 1})"},
        // what the report covers: known names, each once, not an empty list, a numerical method
        BadInput{"report --methods heun,rk4 --out {dir}/r", "heun"}, BadInput{"report --methods rk4,rk4 --out {dir}/r", "twice"},
        BadInput{"report --methods ,rk4 --out {dir}/r", "--methods is empty"}, BadInput{"report --methods analytic --out {dir}/r", "numerical"},
        BadInput{"report --sections summary,appendix --out {dir}/r", "appendix"}, BadInput{"report --sections summary, --out {dir}/r", "--sections is empty"},
        BadInput{"report --config {dir}/config.json --out {dir}/r", "'methods' must be a non-empty array", R"({"methods": []})"},
        BadInput{"report --config {dir}/config.json --out {dir}/r", "'sections' must be a non-empty array", R"({"sections": ["summary", 3]})"},
        BadInput{"report --config {dir}/config.json --out {dir}/r", "pendulum", R"({"methods": ["rk4", "pendulum"]})"},
        // order against a parameter: one of the scene's, values in its bound, strictly increasing
        BadInput{"study convergence --scene target --sweep hardness=1,10", "names no parameter of target"},
        BadInput{"study convergence --scene target --sweep stiffness=", "has no values"},
        BadInput{"study convergence --scene target --sweep stiffness=100,10 --json {dir}/s.json", "strictly increasing"},
        BadInput{"study convergence --scene target --sweep stiffness=-1,10", "stiffness"},
        BadInput{"study convergence --scene rope --sweep masses=4,8", "names no parameter"},
        BadInput{"study convergence --scene target --sweep stiffness=1,10 --shard 1/2 --json {dir}/s.json", "not both"},
        // the scenes: known names, each once, not an empty list; each method runs on one of them
        BadInput{"report --scenes spring,double_pendulum --out {dir}/r", "double_pendulum"}, BadInput{"report --scenes spring,spring --out {dir}/r", "twice"},
        BadInput{"report --scenes , --out {dir}/r", "--scenes is empty"},
        BadInput{"report --scenes falling --methods rk4,analytic --out {dir}/r", "'analytic' runs on none of the chosen scenes"},
        BadInput{"report --sheet --scenes falling --out {dir}/r", "'analytic' runs on none"},
        BadInput{"report --config {dir}/config.json --out {dir}/r", "'scenes' must be a non-empty array", R"({"scenes": []})"},
        BadInput{"report --config {dir}/config.json --out {dir}/r", "stiff_order.stiffnesses are not increasing",
                 R"({"stiff_order": {"stiffnesses": [1, 1e4, 1e2]}})"},
        BadInput{"report --config {dir}/config.json --out {dir}/r", "config: stiff_order.stiffnesses",
                 R"({"stiff_order": {"stiffnesses": [1, -5]}})"},
        // the report's own keys, read by their tables' rule as the studies' are (report_config.cpp)
        BadInput{"report --config {dir}/config.json --out {dir}/r", "config: stiff_order.points 3.5 is not a whole number; accepted: 3 .. 1000",
                 R"({"stiff_order": {"points": 3.5}})"},
        BadInput{"report --config {dir}/config.json --out {dir}/r", "config: figures.spring_dts -1 is out of range; accepted: > 0",
                 R"({"figures": {"spring_dts": [0.01, -1]}})"},
        BadInput{"report --config {dir}/config.json --out {dir}/r", "config: stability.large_dt 0 is out of range; accepted: > 0",
                 R"({"stability": {"large_dt": 0}})"},
        BadInput{"report --config {dir}/config.json --out {dir}/r", "config: target.stiffness",
                 R"({"target": {"stiffness": 0}})"}));

// One rule whichever way a value arrives: for every parameter of the studies' tables, a value
// just outside its range is refused typed and in a configuration, each message naming the value's
// origin and accepting the same range, and one inside it is taken both ways.
template <class C>
void one_rule_each_way(std::span<const StudyParam<C>> table, const char* section) {
  for (const StudyParam<C>& p : table) {
    const double outside = p.range.lo_open ? p.range.lo : p.range.lo - 1, inside = p.range.lo_open ? p.range.lo + 1 : p.range.lo;
    const std::string name(p.name), key = config_key(p);
    const bool list = std::holds_alternative<std::vector<double> C::*>(p.field) || std::holds_alternative<std::vector<int> C::*>(p.field);
    const auto message = [&](auto&& f) {
      try {
        f();
      } catch (const UsageError& e) {
        return std::string(e.what());
      }
      return std::string();
    };
    C typed, read;
    std::map<std::string, std::string> text;
    for (const StudyParam<C>& q : table) text[std::string(q.name)] = "";
    text[name] = fmt::format("{}", outside);
    const std::string from_option = message([&] { read_params(table, text, typed); });
    nlohmann::ordered_json j;
    j[key] = list ? nlohmann::ordered_json::array({outside}) : nlohmann::ordered_json(outside);
    const std::string from_config = message([&] { params_from_json(table, j, section, read); });
    const std::string accepted = "accepted: " + range_text(p.range);
    EXPECT_EQ(from_option, fmt::format("--{} {} is out of range; {}", name, outside, accepted)) << name;
    EXPECT_EQ(from_config, fmt::format("config: {}.{} {} is out of range; {}", section, key, outside, accepted)) << name;
    text[name] = fmt::format("{}", inside);
    j[key] = list ? nlohmann::ordered_json::array({inside}) : nlohmann::ordered_json(inside);
    EXPECT_EQ(message([&] { read_params(table, text, typed); }), "") << name;
    EXPECT_EQ(message([&] { params_from_json(table, j, section, read); }), "") << name;
    EXPECT_EQ(params_json(table, typed)[key], params_json(table, read)[key]) << name;
  }
}

// AVX-512's 8 lanes are compiled only where the build is configured for them (CMakeLists.txt):
// elsewhere the refusal says how to get them.
TEST(Lanes, EightNamesTheBuildOptionWhereTheBuildHasNoAvx512Loop) {
  if (kMaxPackWidth >= 8) GTEST_SKIP() << "this build compiles the 8-lane loop";
  const Result r = run_steplab("study stability --lanes 8");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("--lanes 8 is not a pack width"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("-DSTEPLAB_MAX_PACK_WIDTH=8"), std::string::npos) << r.err;
}

TEST(StudyParams, OneRuleEachWay) {
  one_rule_each_way(convergence_params(), "convergence");
  one_rule_each_way(collision_params(), "collision");
  one_rule_each_way(dense_output_params(), "dense_output");
  one_rule_each_way(long_time_params(), "long_time");
  one_rule_each_way(work_precision_params(), "work_precision");
  one_rule_each_way(frames_params(), "frames");
  one_rule_each_way(stability_params(), "stability");
  one_rule_each_way(scaling_params(), "scaling");
}

}  // namespace
}  // namespace steplab
