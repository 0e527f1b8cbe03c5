// What the benchmark's times were measured on, for its JSON context and bench-ratios.md.
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>

// The CPU's model name (Google Benchmark's context gives its cores and clock only), and the load
// average over the last minute: what the times were measured on, and beside what else.
std::string cpu_model() {
  std::ifstream info("/proc/cpuinfo");
  for (std::string line; std::getline(info, line);)
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown CPU";
}
double load_average() {
  double load = -1;
  std::ifstream("/proc/loadavg") >> load;
  return load;
}
std::string machine_line() {
  char out[300];
  std::snprintf(out, sizeof out, "Measured on %s (%ld cores); load average over the last minute %.2f at the end.",
                cpu_model().c_str(), sysconf(_SC_NPROCESSORS_ONLN), load_average());
  return out;
}
