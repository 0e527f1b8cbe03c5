// Running the built steplab binary from tests: its exit status, stdout and stderr, and a
// temporary directory to check which files it wrote.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace steplab {

struct Result {
  int status = -1;
  std::string out, err;
};

class TempDir {
 public:
  TempDir() {
    std::string tmpl = (std::filesystem::temp_directory_path() / "steplab-test-XXXXXX").string();
    dir_ = ::mkdtemp(tmpl.data());
  }
  ~TempDir() { std::filesystem::remove_all(dir_); }
  std::string path(const std::string& name) const { return (std::filesystem::path(dir_) / name).string(); }
  bool empty() const { return std::filesystem::is_empty(dir_); }
  const std::string& root() const { return dir_; }

 private:
  std::string dir_;
};

inline std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs `cmd` through the shell, stdin from /dev/null, its output kept.
inline Result run_shell(const std::string& cmd) {
  TempDir io;
  const int raw = std::system((cmd + " </dev/null >" + io.path("out") + " 2>" + io.path("err")).c_str());
  Result r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(io.path("out"));
  r.err = slurp(io.path("err"));
  return r;
}

// Runs `steplab <args>` through the shell with `dir` as its working directory.
inline Result run_steplab_in(const std::string& dir, const std::string& args) {
  return run_shell("cd '" + dir + "' && " + std::string(STEPLAB_EXE) + " " + args);
}

// Runs `steplab <args>` from the tests' own working directory.
inline Result run_steplab(const std::string& args) { return run_steplab_in(".", args); }

// The report's claims (data/claims.json) re-evaluated by tools/verify_claims.py, which shares no
// code with the report: status 0 if every claim holds; `out` names each one that does not.
inline Result verify_claims(const std::string& report_dir) {
  return run_shell("python3 '" + std::string(STEPLAB_SOURCE_DIR) + "/tools/verify_claims.py' '" + report_dir + "'");
}

inline std::vector<std::string> split_lines(const std::string& s) {
  std::vector<std::string> lines;
  std::stringstream in(s);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

}  // namespace steplab
