// The same inputs give byte-identical JSON across runs and thread counts, for every study and for
// a run: each command twice with one thread and twice with two, all four files equal.
#include <gtest/gtest.h>

#include "cli_helpers.hpp"

namespace steplab {
namespace {

// Runs `command` once with each of `options`, each writing its own JSON, and expects all the
// files equal and not empty.
void expect_same_bytes(const std::string& command, const std::vector<std::string>& options) {
  TempDir dir;
  std::vector<std::string> docs;
  for (const std::string& opts : options) {
    const std::string out = dir.path("out" + std::to_string(docs.size()) + ".json");
    const std::string args = command + " " + opts + " --json " + out;
    const Result r = run_steplab(args);
    ASSERT_EQ(r.status, 0) << args << "\n" << r.err;
    docs.push_back(slurp(out));
    ASSERT_FALSE(docs.back().empty());
  }
  for (std::size_t i = 1; i < docs.size(); ++i) EXPECT_EQ(docs[i], docs[0]) << command << ": file " << i << " differs";
}

class Determinism : public ::testing::TestWithParam<const char*> {};

TEST_P(Determinism, SameBytesForOneAndTwoThreads) {
  const std::string command = GetParam();
  if (command.rfind("run", 0) == 0) return expect_same_bytes(command, {"", "", "", ""});  // `run` has no --threads
  expect_same_bytes(command, {"--threads 1", "--threads 2", "--threads 1", "--threads 2"});
}

INSTANTIATE_TEST_SUITE_P(
    EveryStudy, Determinism,
    ::testing::Values("run --scene falling --method implicit_midpoint --dt 0.001 --t-end 3",
                      "study convergence --scene spring --dt-min 1e-3",
                      "study convergence --scene bounce --dt-min 1e-3 --error rms",
                      "study convergence --scene falling --dt-min 1e-3",
                      "study damping --dts 0.05",
                      "study stability --map-dt-points 12 --map-damping-points 8 --threshold-dampings 0,1",
                      "study collision --dts 0.002,0.004 --t-end 3",
                      "study frames --no-timing --budget 6 --t-end 0.5"));

}  // namespace
}  // namespace steplab
