#include "reports/data/output.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "reports/data/inputs.hpp"

namespace steplab {
namespace {

namespace fs = std::filesystem;

std::string temp_name(const std::string& path) { return fmt::format("{}.{}.tmp", path, ::getpid()); }

std::string head(const fs::path& p, std::size_t bytes) {
  std::ifstream in(p, std::ios::binary);
  std::string s(bytes, '\0');
  in.read(s.data(), static_cast<std::streamsize>(bytes));
  s.resize(static_cast<std::size_t>(in.gcount()));
  return s;
}

// A JSON document steplab wrote: every one opens with its schema, "steplab.<kind>/<version>".
bool steplab_json(const fs::path& p) {
  static const std::regex opening(R"(^\s*\{\s*"schema"\s*:\s*"steplab\.)");
  return std::regex_search(head(p, 256), opening);
}

// The files a previous report in `out` wrote, relative to it: its marker's list; for a report of an
// older steplab (no marker, but its data/stamp, which names the binary that made it), its four
// parts. nullopt: no report of steplab's is there.
struct ReportFiles {
  std::set<std::string> listed;
  bool legacy = false;
  bool holds(const std::string& rel) const {
    if (legacy) return rel == "report.md" || rel == "report.pdf" || rel.rfind("figures/", 0) == 0 || rel.rfind("data/", 0) == 0;
    return listed.count(rel) > 0;
  }
};

ReportFiles previous_report(const fs::path& out) {
  ReportFiles r;
  std::ifstream marker(out / kReportMarker);
  std::string line;
  if (marker && std::getline(marker, line)) {
    while (std::getline(marker, line))
      if (!line.empty()) r.listed.insert(line);
    return r;
  }
  r.legacy = head(out / "data" / "stamp", 1 << 16).find("\nbinary ") != std::string::npos;
  return r;
}

}  // namespace

void check_writable(const std::string& path) {
  if (path.empty()) throw UsageError("output path is empty; accepted: a file path");
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw UsageError(fmt::format("output path '{}' is a directory; accepted: a file path", path));
  if (fs::exists(path, ec) && !steplab_json(path))
    throw UsageError(fmt::format("output path '{}' holds a file steplab did not write; accepted: a new path, or a JSON "
                                 "file of steplab's (which is replaced)", path));
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

namespace steplab {

void check_report_folder(const std::string& path) {
  const fs::path out(path);
  std::error_code ec;
  const fs::file_status st = fs::symlink_status(out, ec);
  if (!fs::exists(st)) return;
  const std::string accepted = "accepted: a new or empty folder, or one holding a previous steplab report and nothing else";
  if (fs::is_symlink(st)) throw UsageError(fmt::format("--out '{}' is a symbolic link; {}", path, accepted));
  if (!fs::is_directory(st)) throw UsageError(fmt::format("--out '{}' is a file steplab did not write; {}", path, accepted));
  const ReportFiles ours = previous_report(out);
  std::vector<std::string> foreign;
  for (auto it = fs::recursive_directory_iterator(out, fs::directory_options::skip_permission_denied, ec);
       !ec && it != fs::recursive_directory_iterator() && foreign.size() < 3; it.increment(ec)) {
    if (it->is_directory(ec)) continue;
    const std::string rel = it->path().lexically_relative(out).generic_string();
    if (rel != kReportMarker && !ours.holds(rel)) foreign.push_back(rel);
  }
  if (ec) throw UsageError(fmt::format("--out '{}' cannot be read ({}); {}", path, ec.message(), accepted));
  if (!foreign.empty())
    throw UsageError(fmt::format("--out '{}' holds files steplab did not write ({}{}); {}", path, fmt::join(foreign, ", "),
                                 foreign.size() == 3 ? ", ..." : "", accepted));
}

std::string report_marker(const std::string& folder) {
  std::set<std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(folder))
    if (!e.is_directory()) files.insert(e.path().lexically_relative(folder).generic_string());
  files.erase(kReportMarker);
  std::string out = "steplab report: the files below were written by steplab; `steplab report --out` replaces this folder whole\n";
  for (const std::string& f : files) out += f + "\n";
  return out;
}

}  // namespace steplab
