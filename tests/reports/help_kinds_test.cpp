// What --help says an option takes is what the parser takes: for every command, each option and
// scene parameter its help labels NUMBER refuses a list, each labelled WHOLE refuses a fraction,
// and each labelled with a list (NUMBER,..., WHOLE,...) takes two values that it takes one by one.
// The command line is checked in-process in dry-run mode (cli_main stops after its input is
// checked), so no study runs.
#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <sstream>

#include "cli_helpers.hpp"
#include "reports/cli/cli.hpp"

namespace steplab {
namespace {

// Exit status of `steplab <words> <option> <value>` checked and not run.
int dry_status(const std::vector<std::string>& words, const std::string& option, const std::string& value) {
  std::vector<std::string> args{"steplab"};
  args.insert(args.end(), words.begin(), words.end());
  args.push_back(option);
  args.push_back(value);
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  testing::internal::CaptureStderr();
  const int status = cli_main(static_cast<int>(argv.size()), argv.data(), /*dry_run=*/true);
  testing::internal::GetCapturedStderr();
  return status;
}

std::vector<std::string> words_of(const std::string& command) {
  std::istringstream in(command);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

TEST(HelpKinds, EachOptionTakesWhatItsHelpSays) {
  // Each command with the options that make it a valid command line on their own.
  const std::vector<std::string> commands{"run", "study convergence", "study damping", "study stability", "study collision",
                                          "study work-precision --no-timing", "study scaling --no-timing", "study frames --no-timing",
                                          "study long-time", "study dense-output", "check --method rk4", "report"};
  const std::regex option_line(R"(^\s+(--[a-z0-9-]+) (NUMBER|WHOLE)(,\.\.\.)?(\s|$))");
  const std::vector<std::string> scalars{"1", "2", "3", "0.5", "5", "50", "0.01", "0.001", "10", "100"};
  int checked = 0;
  for (const std::string& command : commands) {
    const std::vector<std::string> words = words_of(command);
    const Result help = run_steplab(command + " --help");
    ASSERT_EQ(help.status, 0) << command;
    std::set<std::string> seen;
    std::istringstream lines(help.out);
    for (std::string line; std::getline(lines, line);) {
      std::smatch m;
      if (!std::regex_search(line, m, option_line)) continue;
      const std::string option = m[1], kind = m[2];
      const bool list = m[3].matched;
      if (!seen.insert(option).second) continue;  // a scene parameter under several scenes
      if (std::find(words.begin(), words.end(), option) != words.end()) continue;
      ++checked;
      if (!list) {
        EXPECT_EQ(dry_status(words, option, "1,2"), 2) << command << " " << option << " is labelled " << kind << " but takes a list";
        if (kind == "WHOLE") {
          EXPECT_EQ(dry_status(words, option, "1.5"), 2) << command << " " << option << " takes a fraction";
        }
        continue;
      }
      std::vector<std::string> taken;  // values it takes one by one
      for (const std::string& v : scalars)
        if ((kind == "NUMBER" || v.find('.') == std::string::npos) && dry_status(words, option, v) == 0) taken.push_back(v);
      if (taken.size() < 2) continue;  // no two single values it takes here (another option decides)
      EXPECT_EQ(dry_status(words, option, taken[0] + "," + taken[1]), 0)
          << command << " " << option << " is labelled " << kind << ",... but refuses " << taken[0] << "," << taken[1];
    }
  }
  EXPECT_GT(checked, 100);  // every command's options and its scenes' parameters
}

}  // namespace
}  // namespace steplab
