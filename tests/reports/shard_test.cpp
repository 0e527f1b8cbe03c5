// A study split with --shard i/N and put together with `steplab merge` gives the JSON and the
// table one process writes, byte for byte, for N = 1, 2 and 3 and every study that takes --shard; merge refuses parts that do
// not belong together (exit 2, one line, no output written).
#include <gtest/gtest.h>

#include <algorithm>

#include "cli_helpers.hpp"

namespace steplab {
namespace {

// Runs the N shards of `study` into dir/part<i>.json; returns their paths, last shard first.
std::vector<std::string> run_shards(const TempDir& dir, const std::string& study, int n, const std::string& tag) {
  std::vector<std::string> parts;
  for (int i = 1; i <= n; ++i) {
    const std::string part = dir.path(tag + "part" + std::to_string(i) + ".json");
    const std::string args = study + " --shard " + std::to_string(i) + "/" + std::to_string(n) + " --json " + part;
    const Result r = run_steplab(args);
    EXPECT_EQ(r.status, 0) << args << "\n" << r.err;
    parts.push_back(part);
  }
  std::reverse(parts.begin(), parts.end());  // merge takes them in any order
  return parts;
}

std::string joined(const std::vector<std::string>& parts) {
  std::string out;
  for (const auto& p : parts) out += " " + p;
  return out;
}

class Shards : public ::testing::TestWithParam<const char*> {};

TEST_P(Shards, MergedPartsAreTheJsonOfOneProcess) {
  TempDir dir;
  const std::string study = GetParam();
  const Result whole = run_steplab(study + " --json " + dir.path("whole.json"));
  ASSERT_EQ(whole.status, 0) << whole.err;
  const std::string expected = slurp(dir.path("whole.json"));
  ASSERT_FALSE(expected.empty());
  for (const int n : {1, 2, 3}) {
    const std::string tag = "n" + std::to_string(n);
    const std::vector<std::string> parts = run_shards(dir, study, n, tag);
    const std::string out = dir.path(tag + "merged.json");
    const Result m = run_steplab("merge" + joined(parts) + " --json " + out);
    ASSERT_EQ(m.status, 0) << m.err;
    EXPECT_EQ(slurp(out), expected) << study << " in " << n << " shards";
    EXPECT_EQ(m.out, whole.out) << "merge prints the study's table";
  }
}

INSTANTIATE_TEST_SUITE_P(
    EveryStudy, Shards,
    ::testing::Values("study convergence --scene spring --dt-min 1e-3 --points 8",
                      "study convergence --scene falling --dt-min 1e-3 --points 6",
                      "study damping --dts 0.05,0.5 --dampings 0,0.5,1,2",
                      "study stability --map-dt-points 9 --map-damping-points 5 --threshold-dampings 0,1 --methods rk4,bdf3,symplectic_euler",
                      "study collision --dts 0.002,0.004 --t-end 2 --methods explicit_euler,rk4",
                      "study work-precision --points 4 --stiffnesses 5,5e4 --no-timing --methods rk4,radau_iia5,explicit_euler",
                      "study stability --scene rope --masses 8 --methods rk4,implicit_euler,symplectic_euler",
                      "study scaling --scene rope --sizes 8,16,32 --stiffness 5,50 --error 1e-3,1% --no-timing "
                      "--methods rk4,implicit_euler,cvode_bdf_max2_band",
                      "study frames --budget 4 --t-end 0.5 --no-timing --methods xpbd,implicit_euler",
                      "study long-time --scene swing --periods 100 --methods rk4,velocity_verlet,implicit_midpoint",
                      "study dense-output --points 4 --outputs 10 --methods rk4,explicit_euler,bdf2"));

// One line on stderr naming what is wrong, exit 2, no output file.
void expect_refused(const std::string& args, const std::string& names, const std::string& out) {
  const Result r = run_steplab(args);
  EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
  const auto lines = split_lines(r.err);
  ASSERT_EQ(lines.size(), 1u) << r.err;
  EXPECT_NE(lines[0].find(names), std::string::npos) << lines[0];
  EXPECT_FALSE(std::filesystem::exists(out)) << args << " wrote " << out;
}

TEST(Merge, RefusesPartsThatDoNotBelongTogether) {
  TempDir dir;
  const std::string study = "study damping --dts 0.05 --dampings 0,1,2 --methods rk4,bdf2";
  const auto parts = run_shards(dir, study, 3, "a");           // part3, part2, part1
  const auto other = run_shards(dir, study + " --mass 2", 3, "b");
  const auto fours = run_shards(dir, study, 4, "c");
  const std::string out = dir.path("out.json");
  expect_refused("merge " + parts[0] + " " + parts[1] + " --json " + out, "shard 1/3 is missing", out);
  expect_refused("merge" + joined(parts) + " " + parts[1] + " --json " + out, "both shard 2/3", out);
  expect_refused("merge " + parts[0] + " " + parts[1] + " " + other[2] + " --json " + out, "--mass 2", out);
  expect_refused("merge " + parts[0] + " " + parts[1] + " " + fours[3] + " --json " + out, "of 3", out);
  // A part whose command asks for work other than it holds: the same shard list, another study.
  std::string text = slurp(parts[2]);
  text.replace(text.find("0.05"), 4, "0.07");
  std::ofstream(dir.path("edited.json")) << text;
  const Result r = run_steplab("merge " + parts[0] + " " + parts[1] + " " + dir.path("edited.json") + " --json " + out);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace steplab
