#include "reports/data/output.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <fmt/format.h>

#include "reports/data/inputs.hpp"

namespace steplab {
namespace {

std::string temp_name(const std::string& path) { return fmt::format("{}.{}.tmp", path, ::getpid()); }

}  // namespace

void check_writable(const std::string& path) {
  namespace fs = std::filesystem;
  if (path.empty()) throw UsageError("output path is empty; accepted: a file path");
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw UsageError(fmt::format("output path '{}' is a directory; accepted: a file path", path));
  const std::string probe = temp_name(path);
  std::FILE* f = std::fopen(probe.c_str(), "wx");
  if (!f) throw UsageError(fmt::format("output path '{}' cannot be written ({})", path, std::strerror(errno)));
  std::fclose(f);
  std::remove(probe.c_str());
}

void write_atomic(const std::string& path, const std::string& content) {
  const std::string tmp = temp_name(path);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << content;
    out.flush();
    if (!out) {
      std::remove(tmp.c_str());
      throw std::runtime_error(fmt::format("cannot write '{}'", path));
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error(fmt::format("cannot rename into '{}' ({})", path, std::strerror(errno)));
  }
}

}  // namespace steplab
