// Tests of the steplab command line (reports/cli/cli.cpp, reports/cli/run_command.cpp): runs the built
// binary and checks exit status, stderr and the files it writes or must not write.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_helpers.hpp"

namespace steplab {
namespace {

// Spaces around a list's items are dropped, as a shell user types them.
TEST(Cli, ListItemsAreTrimmed) {
  const Result r = run_steplab("study convergence --methods \"rk4, explicit_euler\" --points 4 --dt-min 0.01");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("explicit_euler"), std::string::npos);
}

// A step that does not divide the time span: the run still takes whole steps, and says where it ends.
TEST(Cli, RunSaysWhereAStepThatDoesNotDivideTheSpanEnds) {
  Result r = run_steplab("run --dt 5 --t-end 1");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "steplab: --t-end 1 is not a whole number of steps of --dt 5: the run takes 1 step and ends at t = 5\n");
  r = run_steplab("run --dt 0.3 --t-end 1 --samples 2");
  EXPECT_NE(r.err.find("takes 4 steps and ends at t = 1.2"), std::string::npos) << r.err;
  EXPECT_TRUE(run_steplab("run --dt 0.1 --t-end 1").err.empty());  // 10 steps of 0.1 (to round-off)
}

TEST(Cli, RunWritesTheRunJson) {
  TempDir dir;
  const std::string out = dir.path("out.json");
  const Result r = run_steplab("run --scene spring --method symplectic_euler --dt 0.05 --t-end 100 --damping 0 --json " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(std::ifstream(out));
  EXPECT_EQ(j["schema"], "steplab.run/1");
  EXPECT_EQ(j["scene"], "spring");
  EXPECT_EQ(j["method"], "symplectic_euler");
  for (const char* key : {"mass", "stiffness", "damping", "rest_length", "gravity", "dt", "t_end"})
    EXPECT_TRUE(j["params"].contains(key)) << key;
  EXPECT_EQ(j["params"]["damping"], 0.0);
  EXPECT_EQ(j["status"], "ok");
  EXPECT_EQ(j["steps"], 2000);
  EXPECT_DOUBLE_EQ(j["final"]["t"].get<double>(), 100.0);
  EXPECT_EQ(j["final"]["x"].size(), 1u);
  EXPECT_TRUE(j["error"]["final"].is_number());
  EXPECT_TRUE(j["error"]["max"].is_number());
  // symplectic Euler at h = 0.05 < 2/omega keeps the energy within a few percent of its start
  EXPECT_NEAR(j["energy_ratio"]["final"].get<double>(), 1.0, 0.1);
  EXPECT_GE(j["energy_ratio"]["max"].get<double>(), 1.0);
  ASSERT_EQ(j["samples"].size(), 2001u);
  EXPECT_EQ(j["samples"][0]["x"][0], -5.0);
}

// A run's counts, as the methods define them: RK4 evaluates the force 4 times a step and solves
// nothing; implicit Euler on the rope (linear: its kept iteration matrix is exact, so one update
// a step, as full Newton) factorises once in the run and solves once each update. Where the
// table does not count (the falling triangle: no exact solution, fixed size) counts is null.
TEST(Cli, RunJsonCarriesTheCounts) {
  TempDir dir;
  const std::string out = dir.path("out.json");
  ASSERT_EQ(run_steplab("run --scene spring --method rk4 --dt 0.05 --t-end 1 --json " + out).status, 0);
  auto j = nlohmann::json::parse(std::ifstream(out));
  EXPECT_EQ(j["counts"]["steps"], 20);
  EXPECT_EQ(j["counts"]["force_evaluations"], 80);
  EXPECT_EQ(j["counts"]["factorisations"], 0);
  EXPECT_EQ(j["counts"]["newton_iterations"], 0);

  ASSERT_EQ(run_steplab("run --scene rope --masses 64 --method implicit_euler --dt 0.01 --t-end 0.1 --json " + out).status, 0);
  j = nlohmann::json::parse(std::ifstream(out));
  const long long steps = j["counts"]["steps"], newton = j["counts"]["newton_iterations"];
  EXPECT_EQ(steps, 10);
  EXPECT_GE(newton, steps);
  EXPECT_LE(newton, 2 * steps);
  EXPECT_EQ(j["counts"]["factorisations"], 1);
  EXPECT_EQ(j["counts"]["jacobian_evaluations"], 1);
  EXPECT_EQ(j["counts"]["linear_solves"], newton);

  ASSERT_EQ(run_steplab("run --scene falling --method rk4 --dt 0.01 --t-end 0.1 --json " + out).status, 0);
  j = nlohmann::json::parse(std::ifstream(out));
  EXPECT_TRUE(j["counts"].is_null());
}

// The adaptive dopri5 takes tolerances; the JSON carries them instead of dt, and its step counts.
// At rtol 1e-8, atol 1e-10 the chain ends within rtol |u(10)| + atol = 7.9e-9 of the exact solution.
TEST(Cli, RunDopri5WritesToleranceAndSteps) {
  TempDir dir;
  const std::string out = dir.path("d.json");
  const Result r = run_steplab("run --scene chain --method dopri5 --rtol 1e-8 --atol 1e-10 --samples 11 --json " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(std::ifstream(out));
  EXPECT_EQ(j["method"], "dopri5");
  EXPECT_EQ(j["params"]["rtol"], 1e-8);
  EXPECT_EQ(j["params"]["atol"], 1e-10);
  EXPECT_FALSE(j["params"].contains("dt"));
  EXPECT_EQ(j["status"], "ok");
  EXPECT_DOUBLE_EQ(j["final"]["t"].get<double>(), 10.0);
  EXPECT_LT(j["error"]["final"].get<double>(), 7.9e-9);
  const auto& a = j["adaptive"];
  EXPECT_EQ(a["accepted_steps"], j["steps"]);
  EXPECT_EQ(a["force_evaluations"].get<long long>(),
            2 + 6 * (a["accepted_steps"].get<long long>() + a["rejected_steps"].get<long long>()));
  // the stiff spring's stability, not accuracy, bounds the steps: |h lambda| <~ 3.3 at |lambda| ~ 316
  EXPECT_LT(a["h_max"].get<double>(), 3.4 / 316);
  ASSERT_EQ(j["samples"].size(), 11u);
  EXPECT_DOUBLE_EQ(j["samples"][5]["t"].get<double>(), 5.0);
}

TEST(Cli, BlowUpIsAResult) {
  TempDir dir;
  const std::string out = dir.path("d.json");
  const Result r = run_steplab("run --scene spring --method explicit_euler --damping 0 --dt 0.5 --t-end 10000 --json " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(std::ifstream(out));
  EXPECT_EQ(j["status"], "diverged");
  // |amplification| = sqrt(1 + h^2 k / m) = 1.5 a step, the energy's 2.25: it passes the blow-up
  // bound, 10^12 times the start's energy (core/simulate.hpp), after ln(1e12) / ln(2.25) = 34.1
  // steps (give or take the phase of the first swing), where overflow would take ~1750
  const long long step = j["diverged_at"]["step"];
  EXPECT_GE(step, 30);
  EXPECT_LE(step, 38);
  EXPECT_LE(j["energy_ratio"]["max"].get<double>(), 1e12 + 1);  // its last state is within the bound
  EXPECT_DOUBLE_EQ(j["diverged_at"]["t"].get<double>(), step * 0.5);
  EXPECT_EQ(j["steps"], step - 1);
}

TEST(Cli, SamplesAreCappedAndKeepTheLastStep) {
  const Result r = run_steplab("run --scene cannonball --method symplectic_euler --dt 0.001 --t-end 17.1 --samples 7");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto lines = split_lines(r.out);
  ASSERT_EQ(lines.size(), 8u);  // header + 7
  EXPECT_EQ(lines[0], "t,x0,x1,v0,v1,energy");
  EXPECT_EQ(lines[7].substr(0, 5), "17.1,");
}

TEST(Cli, OldFlags) {
  const Result a = run_steplab("-testcase spring1d -method euler -step 0.01 -damp 0.1 -mass 1 -stiff 10");
  const Result b = run_steplab("run --scene spring --method explicit_euler --dt 0.01 --damping 0.1 --mass 1 --stiffness 10 --rest-length 1");
  ASSERT_EQ(a.status, 0) << a.err;
  EXPECT_EQ(a.out, b.out);  // the old framework's rest length 1
  const Result c = run_steplab("--testcase spring1d --method backwards_euler --length 2");
  const Result d = run_steplab("run --method implicit_euler --dt 0.003 --mass 0.1 --stiffness 10 --damping 0.01 --rest-length 2");
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_EQ(c.out, d.out);  // the old defaults: step 0.003, mass 0.1, stiffness 10, damping 0.01
}

TEST(Cli, HelpListsEveryOption) {
  const Result r = run_steplab("run --help");
  EXPECT_EQ(r.status, 0);
  for (const char* opt : {"--scene", "--method", "--dt", "--t-end", "--samples", "--json", "--mass", "--stiffness",
                          "--damping", "--rest-length", "--gravity"})
    EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
}

// --help names each option's kind of value (never CLI11's TEXT) and lists the scene parameters
// under each scene that has them.
TEST(Cli, HelpShowsKindsOfValueAndParametersByScene) {
  for (const char* cmd : {"--help", "run --help", "study convergence --help", "study damping --help", "study stability --help",
                          "study collision --help", "report --help"}) {
    const Result r = run_steplab(cmd);
    ASSERT_EQ(r.status, 0) << cmd;
    EXPECT_EQ(r.out.find("TEXT"), std::string::npos) << cmd << "\n" << r.out;
    EXPECT_EQ(r.out.find("--help NUMBER"), std::string::npos) << cmd << "\n" << r.out;  // flags take no value
  }
  const std::string run = run_steplab("run --help").out;
  for (const char* shown : {"--dt NUMBER", "--samples WHOLE", "--method NAME", "--json FILE"})
    EXPECT_NE(run.find(shown), std::string::npos) << shown << "\n" << run;
  // Under "spring:" its own parameters, up to the next scene; cannon ball's speed is not there.
  const std::size_t spring = run.find("\n  spring:\n"), next = run.find(":\n", spring + 11);
  ASSERT_NE(spring, std::string::npos) << run;
  const std::string block = run.substr(spring, next - spring);
  for (const char* p : {"--mass NUMBER", "--stiffness NUMBER", "--damping NUMBER", "--rest-length NUMBER", "--gravity NUMBER"})
    EXPECT_NE(block.find(p), std::string::npos) << p << "\n" << block;
  EXPECT_EQ(block.find("--speed"), std::string::npos) << block;
  const std::string conv = run_steplab("study convergence --help").out;
  EXPECT_NE(conv.find("--methods NAME,..."), std::string::npos) << conv;
  EXPECT_NE(conv.find("--points WHOLE"), std::string::npos) << conv;
}

TEST(Cli, UnwritableOutputIsRefused) {
  const Result r = run_steplab("run --json /nonexistent-dir/out.json");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(split_lines(r.err).size(), 1u) << r.err;
  EXPECT_NE(r.err.find("/nonexistent-dir/out.json"), std::string::npos);
}

TEST(Cli, ExistingFileIsNotTouchedByARefusedRun) {
  TempDir dir;
  const std::string out = dir.path("keep.json");
  std::ofstream(out) << "previous";
  EXPECT_EQ(run_steplab("run --dt 0 --json " + out).status, 2);
  std::ifstream in(out);
  std::string content((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(content, "previous");
}

// `steplab check`: a line per claim on stdout, PASS for a row of the table, exit 0 (the exit-1
// path, a failing claim, is tested on planted rows in tests/analysis/check_test.cpp).
TEST(Cli, CheckPrintsOneLinePerClaimAndExitsZero) {
  const Result r = run_steplab("check --method velocity_verlet");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  const auto lines = split_lines(r.out);
  ASSERT_EQ(lines.size(), 16u) << r.out;
  EXPECT_EQ(lines[0].rfind("steplab check velocity_verlet: symplectic splitting, order 2, symplectic", 0), 0u) << lines[0];
  for (std::size_t i = 1; i + 1 < lines.size(); ++i) EXPECT_EQ(lines[i].rfind("PASS  ", 0), 0u) << lines[i];
  EXPECT_EQ(lines.back(), "all 14 claims hold");
  EXPECT_NE(r.out.find("PASS  symplectic: on Kepler's orbit over 10000 periods of 200 steps the energy error grows as t^0.00"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("PASS  order 2 on the spring: fitted 2.000"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("PASS  symplectic: energy changes by"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace steplab

namespace steplab {
namespace {

// Each command's --help names the schema of the JSON it writes: read back from a file it wrote.
TEST(CliHelp, NamesTheSchemaEachCommandWrites) {
  struct Case {
    const char* command;  // the --help of the first words
    const char* args;     // a small run of it
  };
  const Case cases[] = {
      {"run", "run --t-end 0.1"},
      {"study convergence", "study convergence --points 3 --dt-min 0.01"},
      {"study convergence", "study convergence --scene target --sweep stiffness=1,10 --points 3 --dt-min 0.01 --methods rk4"},
      {"study damping", "study damping --methods rk4 --dts 0.1"},
      {"study stability", "study stability --methods rk4 --map-dt-points 2 --map-damping-points 2"},
      {"study stability", "study stability --scene rope --masses 4 --methods rk4"},
      {"study collision", "study collision --methods rk4 --t-end 0.5 --dts 0.01"},
      {"study work-precision", "study work-precision --methods rk4 --points 3 --stiffnesses 5 --no-timing"},
      {"study scaling", "study scaling --sizes 2,4 --methods rk4 --no-peers --no-timing --error 1e-2"},
  };
  for (const Case& c : cases) {
    const Result help = run_steplab(std::string(c.command) + " --help");
    ASSERT_EQ(help.status, 0) << c.command;
    const std::size_t at = help.out.find("--json FILE");
    ASSERT_NE(at, std::string::npos) << c.command;
    const std::string json_line = help.out.substr(at, help.out.find('\n', at) - at);
    TempDir dir;
    const Result r = run_steplab(std::string(c.args) + " --json " + dir.path("out.json"));
    ASSERT_EQ(r.status, 0) << c.args << ": " << r.err;
    const std::string schema = nlohmann::json::parse(std::ifstream(dir.path("out.json")))["schema"];
    EXPECT_NE(json_line.find(" " + schema), std::string::npos) << c.args << " wrote " << schema << "; its help says: " << json_line;
  }
}

// The options of a study list only the scenes it takes, and a list's label says it is one.
TEST(CliHelp, ListsWhatEachCommandTakes) {
  const Result stability = run_steplab("study stability --help");
  EXPECT_NE(stability.out.find("scene: spring, chain, rope, softbody, target"), std::string::npos) << stability.out;
  EXPECT_EQ(stability.out.find("  cannonball:"), std::string::npos);  // no parameters of a scene it refuses
  const Result scaling = run_steplab("study scaling --help");
  EXPECT_NE(scaling.out.find("--sizes WHOLE,..."), std::string::npos);
  EXPECT_NE(scaling.out.find("--error NUMBER[%],..."), std::string::npos);
  EXPECT_EQ(scaling.out.find("README, Speed"), std::string::npos);
  EXPECT_EQ(scaling.out.find("=1e-4"), std::string::npos);  // defaults in one style: "(default ...)"
  EXPECT_NE(scaling.out.find("(default 1e-4,1%)"), std::string::npos);
}

}  // namespace
}  // namespace steplab
