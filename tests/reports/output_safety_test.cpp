// No command deletes or replaces a file it did not write: `report --out` writes into a new or
// empty folder, or one that holds a report steplab wrote and nothing else (its marker lists every
// file); `--json` replaces a file only if it is a JSON document of steplab's. The refusals (one
// line, exit 2, nothing touched) are in bad_input_test.cpp; here what is accepted, and what a
// report leaves.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "cli_helpers.hpp"
#include "reports/data/inputs.hpp"
#include "reports/data/output.hpp"

namespace steplab {
namespace {

namespace fs = std::filesystem;

// A quick report: one section, no study.
constexpr const char* kQuick = "report --sections reproduce --out r";

TEST(ReportFolder, NewEmptyOrPreviousReportIsWrittenAndMarked) {
  TempDir dir;
  fs::create_directory(dir.path("r"));  // empty
  Result r = run_steplab_in(dir.root(), kQuick);
  ASSERT_EQ(r.status, 0) << r.err;
  // the marker lists exactly the files the report holds
  std::set<std::string> listed, held;
  const auto lines = split_lines(slurp(dir.path("r/.steplab-report")));
  ASSERT_FALSE(lines.empty());
  for (std::size_t i = 1; i < lines.size(); ++i) listed.insert(lines[i]);
  for (const auto& e : fs::recursive_directory_iterator(dir.path("r")))
    if (!e.is_directory()) held.insert(e.path().lexically_relative(dir.path("r")).generic_string());
  held.erase(".steplab-report");
  EXPECT_EQ(listed, held);
  EXPECT_TRUE(listed.count("report.md") && listed.count("report.pdf") && listed.count("data/config.json"));
  // a previous report is replaced (--force: it is up to date otherwise)
  r = run_steplab_in(dir.root(), std::string(kQuick) + " --force");
  EXPECT_EQ(r.status, 0) << r.err;
  // ... but not with a file of the user's in it: refused, the file kept
  std::ofstream(dir.path("r/figures/my_notes.txt")) << "mine";
  r = run_steplab_in(dir.root(), std::string(kQuick) + " --force");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("figures/my_notes.txt"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(dir.path("r/figures/my_notes.txt")), "mine");
  EXPECT_TRUE(fs::exists(dir.path("r/report.md")));
}

// A report of an older steplab, without the marker, is known by its data/stamp (the binary that
// made it): its four parts are steplab's.
TEST(ReportFolder, AnOlderSteplabReportIsReplaced) {
  TempDir dir;
  fs::create_directories(dir.path("r/data"));
  fs::create_directories(dir.path("r/figures"));
  std::ofstream(dir.path("r/data/stamp")) << "{\"methods\": []}\nbinary 0.2.0 123 456\n";
  std::ofstream(dir.path("r/report.md")) << "# old\n";
  std::ofstream(dir.path("r/figures/fig1.png")) << "png";
  const Result r = run_steplab_in(dir.root(), kQuick);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_FALSE(fs::exists(dir.path("r/figures/fig1.png")));
  EXPECT_TRUE(fs::exists(dir.path("r/.steplab-report")));
}

// --json replaces a steplab JSON document (a previous run's), whatever its schema.
TEST(JsonOutput, ReplacesOnlySteplabsJson) {
  TempDir dir;
  std::ofstream(dir.path("old.json")) << "{\n \"schema\": \"steplab.stability/1\",\n \"rows\": []\n}\n";
  const Result r = run_steplab_in(dir.root(), "run --t-end 0.1 --json old.json");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(slurp(dir.path("old.json")).find("\"schema\": \"steplab.run/1\""), std::string::npos);
  std::ofstream(dir.path("mine.json")) << "{\"schema\": \"mine/1\"}";
  EXPECT_THROW(check_writable(dir.path("mine.json")), UsageError);
  EXPECT_NO_THROW(check_writable(dir.path("new.json")));
}

}  // namespace
}  // namespace steplab
