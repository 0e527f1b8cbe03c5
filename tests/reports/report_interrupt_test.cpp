// Stops `steplab report` midway (SIGINT, then SIGKILL) and checks that the previous report is
// intact, byte for byte, and that no half-made folder is left behind (after SIGKILL, the next
// run removes it). Needs gnuplot, pandoc and LaTeX (tools/install-deps test).
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <thread>

#include "cli_helpers.hpp"

namespace steplab {
namespace {

namespace fs = std::filesystem;

std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = slurp(e.path().string());
  return files;
}

int staging_folders(const fs::path& parent) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(parent)) n += e.path().filename().string().find(".staging-") != std::string::npos;
  return n;
}

// Starts steplab report and sends `sig` after `after`; returns the raw wait status.
int interrupted_report(const std::string& config, const std::string& out, int sig, std::chrono::milliseconds after) {
  const pid_t pid = fork();
  if (pid == 0) {
    execl(STEPLAB_EXE, STEPLAB_EXE, "report", "--force", "--config", config.c_str(), "--out", out.c_str(), (char*)nullptr);
    _exit(127);
  }
  std::this_thread::sleep_for(after);
  kill(pid, sig);
  int status = 0;
  waitpid(pid, &status, 0);
  return status;
}

// A report of four sections with small studies (about a second on 2 cores), then its figures by
// gnuplot and its PDF by pandoc (about as long again): a signal at 300 ms comes during the studies,
// one at 1500 ms during the figures or the PDF. Returns the config's path.
std::string small_config_file(const TempDir& dir) {
  const std::string path = dir.path("small.json");
  std::ofstream(path) << R"({"sections": ["summary", "energy", "convergence", "stability"],
                             "convergence": {"points": 8, "dt_min": 0.001},
                             "stability": {"map_dt_points": 16, "map_damping_points": 16},
                             "figures": {"energy_t_end": 10}})";
  return path;
}

TEST(ReportInterrupted, PreviousReportStaysIntact) {
  TempDir dir;
  const std::string config = small_config_file(dir), out = dir.path("report");
  const Result first = run_steplab("report --config " + config + " --out " + out);
  ASSERT_EQ(first.status, 0) << first.err;
  const auto before = snapshot(out);
  ASSERT_TRUE(before.count("report.pdf") && before.count("report.md") && before.count("data/stability/stability.json"));

  // Up to date: a second run with nothing changed returns at once and touches nothing.
  const Result again = run_steplab("report --config " + config + " --out " + out);
  EXPECT_EQ(again.status, 0);
  EXPECT_NE(again.err.find("up to date"), std::string::npos) << again.err;
  EXPECT_EQ(snapshot(out), before);

  int interrupted = 0;
  for (int ms : {300, 1500}) {  // during the studies, and during the figures
    const int status = interrupted_report(config, out, SIGINT, std::chrono::milliseconds(ms));
    // Killed by the signal itself: it came before the process had started writing (under a
    // loaded sanitizer build, before main reached the report); the report must still be intact.
    const bool before_start = WIFSIGNALED(status) && WTERMSIG(status) == SIGINT;
    ASSERT_TRUE(WIFEXITED(status) || before_start) << "SIGINT at " << ms << " ms: status " << status;
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) continue;  // it finished first: a complete new report, also fine
    if (!before_start) {
      EXPECT_EQ(WEXITSTATUS(status), 130) << ms;
    }
    ++interrupted;
    EXPECT_EQ(snapshot(out), before) << "SIGINT at " << ms << " ms changed the report";
    EXPECT_EQ(staging_folders(dir.root()), 0);
  }

  EXPECT_GE(interrupted, 1);  // the report takes seconds: a signal at 300 ms stops it

  const int killed = interrupted_report(config, out, SIGKILL, std::chrono::milliseconds(500));
  ASSERT_TRUE(WIFSIGNALED(killed));
  EXPECT_EQ(snapshot(out), before) << "SIGKILL changed the report";
  EXPECT_EQ(staging_folders(dir.root()), 1);  // what the killed run left; the next run removes it

  const Result forced = run_steplab("report --force --config " + config + " --out " + out);
  ASSERT_EQ(forced.status, 0) << forced.err;
  EXPECT_EQ(staging_folders(dir.root()), 0);
  EXPECT_TRUE(fs::exists(fs::path(out) / "report.pdf"));
}

}  // namespace
}  // namespace steplab
