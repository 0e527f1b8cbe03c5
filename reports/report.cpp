// Rendering the report (reports/report.hpp): Markdown from the findings, gnuplot data and
// figures, the PDF, and the atomic swap of the output folder.
#include "reports/report.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/utsname.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "analysis/parallel.hpp"
#include "core/scenes.hpp"
#include "reports/gnuplot_scripts.hpp"
#include "reports/output.hpp"
#include "reports/study_output.hpp"

namespace steplab {
namespace fs = std::filesystem;

namespace {

std::string name(std::size_t m) { return std::string(method_infos[m].name); }
std::string dt_text(double x) { return std::isinf(x) ? "inf" : std::isnan(x) ? "-" : fmt::format("{:.4g}", x); }

std::string list(const Findings& f, const std::vector<std::size_t>& rows) {
  if (rows.empty()) return "none";
  std::string out;
  for (std::size_t i = 0; i < rows.size(); ++i)
    out += (i == 0 ? "" : i + 1 == rows.size() ? " and " : ", ") + fmt::format("`{}`", name(f.rows[rows[i]].method));
  return out;
}

std::string order_text(const MethodFinding& r) {
  const MethodInfo& info = method_infos[r.method];
  return info.exact_flow ? "exact" : std::to_string(info.order);
}

std::string fitted_text(const ConvergenceFit& fit) {
  if (fit.fit.exact) return "exact (round-off)";
  if (!fit.fit.fitted) return "-";
  return fmt::format("{:.3f} [{:.3f}, {:.3f}]", fit.fit.line.slope, fit.fit.line.ci95_lo, fit.fit.line.ci95_hi);
}

std::string strength(double rho) {
  const double a = std::abs(rho);
  const char* size = a < 0.3 ? "weak" : a < 0.7 ? "moderate" : "strong";
  return fmt::format("{} {}", size, rho >= 0 ? "positive" : "negative");
}

std::string fits_table(const ConvergenceResult& r) {
  std::string out = "| method | declared order | fitted order | 95 % interval | R² | points | dt range | extrapolated |\n"
                    "|------------------|------:|------:|-----------------|-------:|-----:|-------------------|-------:|\n";
  for (const ConvergenceFit& f : r.fits) {
    const MethodInfo& info = method_infos[f.method];
    const std::string declared = info.exact_flow ? "exact" : std::to_string(info.order);
    if (f.fit.exact) out += fmt::format("| `{}` | {} | exact | - | - | - | - | - |\n", info.name, declared);
    else if (!f.fit.fitted) out += fmt::format("| `{}` | {} | - ({}) | - | - | - | - | - |\n", info.name, declared, f.fit.note);
    else
      out += fmt::format("| `{}` | {} | {:.3f} | [{:.3f}, {:.3f}] | {:.5f} | {} | {:.3g} – {:.3g} | {} |\n", info.name, declared,
                         f.fit.line.slope, f.fit.line.ci95_lo, f.fit.line.ci95_hi, f.fit.line.r2, f.fit.line.n, f.fit.dt_lo,
                         f.fit.dt_hi, std::isfinite(f.fit.extrapolated) ? fmt::format("{:.3f}", f.fit.extrapolated) : "-");
  }
  return out;
}

std::string params_text(std::size_t scene, const std::vector<double>& v) {
  return with_scene(scene, [&]<class S>() {
    std::string out;
    for (std::size_t i = 0; i < S::params.size(); ++i) out += fmt::format("{}{} {}", i ? ", " : "", S::params[i].name, v[i]);
    return out;
  });
}

// A shell command wrapped with backslash continuations, so it fits a printed page.
std::string wrapped(const std::string& cmd) {
  std::string out, line;
  std::size_t start = 0;
  while (start < cmd.size()) {
    std::size_t next = cmd.find(" --", start + 1);
    if (next == std::string::npos) next = cmd.size();
    const std::string piece = cmd.substr(start, next - start);
    if (!line.empty() && line.size() + piece.size() > 76) {
      out += line + " \\\n   ";
      line.clear();
    }
    line += piece;
    start = next;
  }
  return out + line + "\n";
}

std::string words(const std::vector<double>& v) {  // gnuplot's word lists are space-separated
  std::string out;
  for (double x : v) out += fmt::format("{}{}", out.empty() ? "" : " ", x);
  return out;
}

std::string join(const std::vector<double>& v) {
  std::string out;
  for (double x : v) out += fmt::format("{}{}", out.empty() ? "" : ",", x);
  return out;
}

}  // namespace

std::string report_markdown(const ReportData& d, const Findings& f, const std::string& ext, const std::string& footer) {
  const ReportConfig& c = d.config;
  const double gamma = c.spring[2];
  // The Markdown names its figures; in the PDF, LaTeX numbers them (in order of appearance).
  const auto fig = [&](int n, const std::string& file, const std::string& caption) {
    const std::string label = ext == "pdf" ? caption : fmt::format("Figure {}: {}", n, caption);
    return fmt::format("![{}](figures/{}.{})\n\n", label, file, ext);
  };
  std::string md;
  md += "# steplab report: explicit, symplectic, midpoint and implicit integrators on the course's scenes\n\n";
  md += fmt::format("The hanging spring: {}. Every number below was measured by the commands at the end of this report; "
                    "every sentence that states a finding was generated from those numbers.\n\n",
                    params_text(*find_scene("spring"), c.spring));

  md += "## Summary\n\n";
  md += fmt::format("| method | declared order | fitted order [95 % interval] | stable at dt {} | stable at damping 0 (dt {}) | "
                    "dt* predicted | dt* measured | energy growth at dt {} (1/s) |\n"
                    "|------------------|-----:|-----------------------|:------:|:--------:|------:|------:|--------:|\n",
                    c.large_dt, c.small_dt, c.large_dt);
  for (const MethodFinding& r : f.rows)
    md += fmt::format("| `{}` | {} | {} | {} | {} | {} | {} | {:.3g} |\n", name(r.method), order_text(r), fitted_text(*r.fit),
                      r.stable_large_dt ? "yes" : "**no**", r.stable_undamped ? "yes" : "**no**", dt_text(r.dt_theory),
                      dt_text(r.dt_measured), r.growth_large_dt);
  md += fmt::format("\nFitted orders: spring, final position error over t = {}; dt* at damping {}: the largest step with "
                    "the energy not growing (measured: growth rate <= {:g} per unit time over {} steps; predicted: spectral "
                    "radius of the step matrix <= 1).\n\n",
                    c.conv_t_end, gamma, kStableRate, kRateSteps);

  md += "## Which methods are stable, and which are not?\n\n";
  md += fmt::format("- At the sheet's large step dt = {} (damping {}): stable: {}; unstable: {}.\n", c.large_dt, gamma,
                    list(f, f.stable_large), list(f, f.unstable_large));
  md += fmt::format("- Without damping (dt = {}): stable: {}; unstable: {}.\n", c.small_dt, list(f, f.stable_undamped),
                    list(f, f.unstable_undamped));
  if (!f.never_stable_undamped.empty())
    md += fmt::format("- Without damping no step at all is stable for {} (predicted dt* = 0: their amplification factor "
                      "exceeds 1 for every h > 0).\n", list(f, f.never_stable_undamped));
  if (!f.always_stable.empty())
    md += fmt::format("- Stable at every step (dt* = inf at damping {}): {}.\n", gamma, list(f, f.always_stable));
  md += "\n";

  md += "## Is stability correlated with the order?\n\n";
  md += fmt::format("Spearman's rank correlation between declared order (the exact solution counted as infinite) and measured "
                    "dt* over the {} methods is **{:.2f}**, a {} association.", f.rows.size(), f.spearman, strength(f.spearman));
  if (!f.breakers.empty()) {
    md += " Methods whose order rank and dt* rank lie at least a third of the table apart:";
    for (std::size_t i = 0; i < f.breakers.size(); ++i) {
      const MethodFinding& r = f.rows[f.breakers[i]];
      md += fmt::format("{} `{}` (order {}, dt* {})", i ? "," : "", name(r.method), order_text(r), dt_text(r.dt_measured));
    }
    md += ".";
  }
  // Methods of one order, side by side.
  for (int order = 1; order <= 4; ++order) {
    std::vector<const MethodFinding*> group;
    for (const MethodFinding& r : f.rows)
      if (!method_infos[r.method].exact_flow && method_infos[r.method].order == order) group.push_back(&r);
    if (group.size() < 2) continue;
    const auto [lo, hi] = std::minmax_element(group.begin(), group.end(), [](auto* a, auto* b) { return a->dt_measured < b->dt_measured; });
    if ((*lo)->dt_measured == (*hi)->dt_measured) {
      md += fmt::format(" The order-{} methods share dt* = {}.", order, dt_text((*lo)->dt_measured));
    } else {
      md += fmt::format(" Among the order-{} methods dt* ranges from {} (`{}`) to {} (`{}`).", order,
                        dt_text((*lo)->dt_measured), name((*lo)->method), dt_text((*hi)->dt_measured), name((*hi)->method));
    }
  }
  md += "\n\n";

  md += "## The scenes\n\n";
  md += fig(1, "fig1_cannonball", fmt::format("cannon ball paths at dt {} beside the exact parabola", c.cannonball_dt));
  md += fig(2, "fig2_spring", fmt::format("spring height y(t) per method against the exact solution, dt {}", words(c.spring_figure_dts)));
  md += "## Convergence\n\n";
  md += fmt::format("Errors against the exact solution over {} steps from {} to {} (t = {}); the order is the least-squares "
                    "slope over the asymptotic range the data show, with its 95 % interval. Truncation error is smooth, not "
                    "random: where it dominates, the interval measures the curvature of log(error), and the extrapolated order "
                    "(Aitken's delta-squared on the local slopes) estimates the limit the slopes approach.\n\n",
                    d.conv_spring.dts.size(), c.conv_dt_max, c.conv_dt_min, c.conv_t_end);
  md += fig(3, "fig3_convergence", "error against dt on the spring, fitted slopes (solid) and reference slopes 1, 2, 4 (dashed)");
  {
    int diverged = 0, runs = 0;
    for (const ConvergenceResult* r : {&d.conv_spring, &d.conv_cannonball, &d.conv_bounce})
      for (const ConvergenceRecord& rec : r->records) diverged += rec.status != RunStatus::Ok, ++runs;
    md += diverged == 0 ? fmt::format("All {} runs of the convergence studies stayed finite.\n\n", runs)
                        : fmt::format("{} of the {} runs of the convergence studies diverged (a non-finite state, recorded "
                                      "with its step in `data/`); they are left out of the fits and of figure 3.\n\n",
                                      diverged, runs);
  }
  md += "Spring:\n\n" + fits_table(d.conv_spring) + "\nCannon ball (constant acceleration):\n\n" + fits_table(d.conv_cannonball);
  md += "\n";

  md += "## Stability\n\n";
  md += "| method | damping | dt* predicted | dt* measured |\n|---|---:|---:|---:|\n";
  for (const ThresholdRow& r : d.thresholds)
    md += fmt::format("| `{}` | {} | {} | {} |\n", name(r.method), r.damping, dt_text(r.dt_theory), dt_text(r.dt_measured));
  md += "\n";
  {
    std::string ended;
    for (std::size_t i = 0; i < d.energy.size(); ++i)
      if (d.energy[i].status != RunStatus::Ok)
        ended += fmt::format("{}`{}` at t = {:g}", ended.empty() ? "" : ", ", name(d.methods[i]), d.energy[i].failed_t);
    if (!ended.empty())
      md += fmt::format("In figure 4 the curves of runs that diverged end where they did: {}.\n\n", ended);
  }
  md += fig(4, "fig4_energy", fmt::format("energy ratio E/E0 against time without damping at dt {} (log scale)", c.large_dt));
  md += fig(5, "fig5_damping", fmt::format("energy growth rate against damping at dt {}: measured (points), predicted 2 ln(rho)/h (lines)", c.large_dt));
  md += fig(6, "fig6_maps", "measured stable (dark) and unstable (light) steps over (dt, damping), predicted boundary dt* (line)");

  md += "## Cost\n\n";
  if (c.timing)
    md += fig(7, "fig7_work_precision", "work-precision on the spring: final error against the measured run time (integration only)");
  else
    md += "Work-precision (figure 7) is left out: the configuration turned timing off (`convergence.timing`).\n\n";

  md += "## Collision\n\n";
  md += fmt::format("The undamped bounce (dropped from y = 0 onto the penalty ground y = -1; {}) and the falling triangle ({}), "
                    "over {} s.\n\n", params_text(*find_scene("bounce"), c.bounce), params_text(*find_scene("falling"), c.falling),
                    c.collision_t_end);
  md += "| method | dt | bounces | E/E0 after the first | E/E0 after the last | deepest penetration |\n|---|---:|---:|---:|---:|---:|\n";
  for (const CollisionRun& r : d.collision.bounce)
    md += fmt::format("| `{}` | {} | {} | {} | {} | {:.4f} |\n", name(r.method), r.dt, r.bounces.size(),
                      r.bounces.empty() ? "-" : fmt::format("{:.4f}", r.bounces.front().energy_ratio),
                      r.bounces.empty() ? "-" : fmt::format("{:.4f}", r.bounces.back().energy_ratio), r.max_penetration);
  md += "\nOrders against the exact bounce (the contact's kink costs order):\n\n" + fits_table(d.conv_bounce) + "\n";
  md += fig(8, "fig8_triangle", fmt::format("falling triangle: height of its centre against time, dt {}", c.triangle_dt));
  md += fig(9, "fig9_bounce_energy", "bounce: energy ratio after the last bounce against dt");

  md += "## Reproduce\n\n```sh\n";
  md += "build/steplab report --config data/config.json   # this whole report\n";
  md += wrapped(fmt::format("build/steplab study convergence --scene spring --dt-max {} --dt-min {} --points {} --t-end {}{}",
                            c.conv_dt_max, c.conv_dt_min, c.conv_points, c.conv_t_end, c.timing ? " --timing" : ""));
  md += wrapped(fmt::format("build/steplab study stability --threshold-dampings {} --map-dt-points {} --map-damping-points {} "
                            "--map-dt-min {} --map-dt-max {}", join(c.threshold_dampings), c.map_dt_points,
                            c.map_damping_points, c.map_dt_min, c.map_dt_max));
  md += wrapped(fmt::format("build/steplab study damping --dts {}", join(c.sweep_dts)));
  md += wrapped(fmt::format("build/steplab study collision --dts {} --t-end {} --triangle-dt {}", join(c.collision_dts),
                            c.collision_t_end, c.triangle_dt));
  md += "```\n\n";
  md += "(with the scene parameters above as `--mass`, `--stiffness`, ... where they differ from the defaults). The data of "
        "every study is in `data/`.\n\n";
  md += "---\n\n" + footer + "\n";
  return md;
}

// ---------------------------------------------------------------- rendering

namespace {

std::string method_words(const std::vector<std::size_t>& methods) {
  std::string out;
  for (std::size_t m : methods) out += (out.empty() ? "" : " ") + name(m);
  return out;
}

class DataDir {
 public:
  explicit DataDir(fs::path dir) : dir_(std::move(dir)) {}
  void write(const std::string& file, const std::string& content) const {
    std::ofstream out(dir_ / file, std::ios::binary);
    out << content;
    if (!out) throw std::runtime_error("cannot write " + (dir_ / file).string());
  }

 private:
  fs::path dir_;
};

std::string num(double x) { return std::isfinite(x) ? fmt::format("{}", x) : "NaN"; }

void write_figure_data(const ReportData& d, const DataDir& dat) {
  const std::size_t nm = d.methods.size();
  for (std::size_t i = 0; i < nm; ++i) {
    const std::string m = name(d.methods[i]);
    std::string s = "# x y\n";
    for (const auto& p : d.cannon[i].samples) s += num(p.x[0]) + " " + num(p.x[1]) + "\n";
    dat.write("cannon_" + m + ".dat", s);
    for (std::size_t k = 0; k < d.spring.size(); ++k) {
      s = "# t y\n";
      for (const auto& p : d.spring[k][i].samples) s += num(p.t) + " " + num(p.x[0]) + "\n";
      dat.write(fmt::format("spring{}_{}.dat", k, m), s);
    }
    s = "# t energy_ratio\n";
    const double e0 = d.energy[i].samples.empty() ? 1 : d.energy[i].samples.front().energy;
    for (const auto& p : d.energy[i].samples) s += num(p.t) + " " + num(p.energy / e0) + "\n";
    dat.write("energy_" + m + ".dat", s);
    s = "# damping rate_measured\n";
    for (const SweepRow& r : d.sweep)
      if (r.method == d.methods[i] && r.dt == d.config.large_dt) s += num(r.damping) + " " + num(r.run.rate) + "\n";
    dat.write("sweep_" + m + ".dat", s);
    s = "# damping rate_predicted\n";
    for (std::size_t g = 0; g < d.curve_damping.size(); ++g) s += num(d.curve_damping[g]) + " " + num(d.curve_rate[i][g]) + "\n";
    dat.write("predicted_" + m + ".dat", s);
    s = "# dt damping stable\n";
    for (std::size_t g = 0; g < d.map.damping.size(); ++g)
      for (std::size_t k = 0; k < d.map.dt.size(); ++k)
        s += num(d.map.dt[k]) + " " + num(d.map.damping[g]) + " " + (d.map.stable[i][g][k] ? "1" : "0") + "\n";
    dat.write("map_" + m + ".dat", s);
    s = "# dt* damping\n";
    for (std::size_t g = 0; g < d.map.damping.size(); ++g) {
      const double b = d.map.boundary[i][g];
      if (b > 0 && std::isfinite(b)) s += num(std::min(b, d.map.dt.back())) + " " + num(d.map.damping[g]) + "\n";
    }
    dat.write("boundary_" + m + ".dat", s);
    const std::size_t nd = d.conv_spring.dts.size();
    s = "# dt error seconds\n";
    for (std::size_t k = 0; k < nd; ++k) {
      const ConvergenceRecord& r = d.conv_spring.records[i * nd + k];
      if (r.status == RunStatus::Ok && r.error_final > 0) s += num(r.dt) + " " + num(r.error_final) + " " + num(r.seconds) + "\n";
    }
    dat.write("conv_" + m + ".dat", s);
    const OrderFit& fit = d.conv_spring.fits[i].fit;
    s = "# dt error (fitted line over its range)\n";
    if (fit.fitted)
      for (double x : {fit.dt_lo, fit.dt_hi}) s += num(x) + " " + num(std::exp(fit.line.intercept + fit.line.slope * std::log(x))) + "\n";
    dat.write("fit_" + m + ".dat", s);
  }
  // reference slopes 1, 2, 4 over the sweep's largest decade, under the lowest fitted curve there
  double anchor = INFINITY;
  const double top = d.conv_spring.dts.front();
  for (std::size_t i = 0; i < nm; ++i) {
    const OrderFit& fit = d.conv_spring.fits[i].fit;
    if (fit.fitted) anchor = std::min(anchor, std::exp(fit.line.intercept + fit.line.slope * std::log(top)));
  }
  if (!std::isfinite(anchor)) anchor = 1;
  std::string ref;
  for (int p : {1, 2, 4}) {
    ref += fmt::format("# slope {}\n", p);
    for (double x : {top / 10, top}) ref += num(x) + " " + num(0.1 * anchor * std::pow(x / top, p)) + "\n";
    ref += "\n\n";
  }
  dat.write("reference_slopes.dat", ref);
  std::string curve = "# x y\n";
  const Cannonball cannon(d.config.cannonball);
  for (int k = 0; k <= 400; ++k) {
    const State<2> y = exact(cannon, d.config.cannonball_t_end * k / 400.0);
    curve += num(y.x[0]) + " " + num(y.x[1]) + "\n";
  }
  dat.write("cannon_exact.dat", curve);
  curve = "# t y\n";
  const Spring spring(d.config.spring);
  for (int k = 0; k <= 2000; ++k) {
    const double t = d.config.spring_figure_t_end * k / 2000.0;
    curve += num(t) + " " + num(exact(spring, t).x[0]) + "\n";
  }
  dat.write("spring_exact.dat", curve);
  for (const CollisionRun& r : d.collision.triangle) {
    std::string s = "# t centre_y\n";
    for (const auto& p : r.path) s += num(p.t) + " " + num((p.x[1] + p.x[3] + p.x[5]) / 3) + "\n";
    dat.write("triangle_" + name(r.method) + ".dat", s);
  }
  for (std::size_t m : d.collision.config.methods) {
    std::string s = "# dt energy_ratio_after_last_bounce\n";
    for (const CollisionRun& r : d.collision.bounce)
      if (r.method == m && !r.bounces.empty()) s += num(r.dt) + " " + num(r.bounces.back().energy_ratio) + "\n";
    dat.write("bounce_" + name(m) + ".dat", s);
  }
}

// Runs `sh -c cmd` with its output discarded and returns its exit status. Not std::system:
// that ignores SIGINT in the caller while the child runs, and an interrupt must not be lost.
int run_quiet(const std::string& cmd) {
  posix_spawn_file_actions_t io;
  posix_spawn_file_actions_init(&io);
  posix_spawn_file_actions_addopen(&io, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&io, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  const std::string full = cmd;
  const char* argv[] = {"/bin/sh", "-c", full.c_str(), nullptr};
  pid_t pid = 0;
  const int err = posix_spawn(&pid, "/bin/sh", &io, nullptr, const_cast<char* const*>(argv), environ);
  posix_spawn_file_actions_destroy(&io);
  if (err != 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (stop_requested) throw Interrupted();
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Staging folders left by a run that was killed (SIGKILL cannot be handled): removed when the
// process that made them is gone.
void remove_stale_staging(const fs::path& out) {
  const std::string prefix = fmt::format(".{}.staging-", out.filename().string());
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(out.parent_path(), ec)) {
    const std::string n = entry.path().filename().string();
    if (n.rfind(prefix, 0) != 0) continue;
    const pid_t pid = static_cast<pid_t>(std::atol(n.c_str() + prefix.size()));
    if (pid > 0 && kill(pid, 0) != 0 && errno == ESRCH) fs::remove_all(entry.path(), ec);
  }
}

extern "C" void on_interrupt(int) { stop_requested = true; }

std::string machine_footer() {
  std::string cpu = "unknown CPU";
  std::ifstream info("/proc/cpuinfo");
  for (std::string line; std::getline(info, line);)
    if (line.rfind("model name", 0) == 0) {
      cpu = line.substr(line.find(':') + 2);
      break;
    }
  utsname u{};
  uname(&u);
  const std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  return fmt::format("steplab {} · {} ({} cores) · {} {} · compiler {} · {}", STEPLAB_VERSION, cpu, sysconf(_SC_NPROCESSORS_ONLN),
                     u.sysname, u.release, __VERSION__, date);
}

// What decides whether a report is up to date: the configuration and this very binary.
std::string stamp_for(const ReportConfig& c) {
  char exe[4096] = {};
  const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
  struct stat bin {};
  if (n > 0) stat(exe, &bin);
  return fmt::format("{}\nbinary {} {} {}\n", report_config_json(c).dump(), STEPLAB_VERSION, bin.st_size,
                     static_cast<long long>(bin.st_mtime));
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

int write_report(const ReportConfig& c, const std::string& out_dir, bool force) {
  const fs::path out = fs::absolute(out_dir);
  const std::string stamp = stamp_for(c);
  if (!force && fs::exists(out / "data" / "stamp") && slurp(out / "data" / "stamp") == stamp && fs::exists(out / "report.pdf")) {
    std::fprintf(stderr, "steplab: %s is up to date (same configuration, same binary); --force redoes it\n", out.c_str());
    return 0;
  }
  remove_stale_staging(out);
  if (run_quiet("command -v gnuplot") != 0 || run_quiet("command -v pandoc") != 0 || run_quiet("command -v pdflatex") != 0)
    throw std::runtime_error("the report needs gnuplot, pandoc and pdflatex; run: tools/install-deps report");

  const fs::path staging = out.parent_path() / fmt::format(".{}.staging-{}", out.filename().string(), getpid());
  // SIGINT and SIGTERM stop the work at the next task or tool; the staging folder is removed
  // and the previous report stays as it was.
  struct sigaction sa {};
  sa.sa_handler = on_interrupt;
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
  fs::remove_all(staging);
  fs::create_directories(staging / "data");
  fs::create_directories(staging / "figures");
  try {
    const auto t0 = std::chrono::steady_clock::now();
    const ReportData d = run_report_studies(c);
    if (stop_requested) throw Interrupted();
    const Findings f = compute_findings(d);
    const double study_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    const DataDir data(staging / "data");
    data.write("config.json", report_config_json(c).dump(1) + "\n");
    data.write("convergence_spring.json", convergence_json(d.conv_spring).dump(1) + "\n");
    data.write("convergence_cannonball.json", convergence_json(d.conv_cannonball).dump(1) + "\n");
    data.write("convergence_bounce.json", convergence_json(d.conv_bounce).dump(1) + "\n");
    data.write("stability.json", stability_json(c.spring, d.thresholds, d.sweep, &d.map).dump(1) + "\n");
    data.write("collision.json", collision_json(d.collision).dump(1) + "\n");
    write_figure_data(d, data);

    // Figures: each script twice, PNG for the Markdown and PDF (vector) for the PDF.
    const std::string all = method_words(d.methods), numeric = method_words(d.collision.config.methods);
    for (const GnuplotScript& gp : gnuplot_scripts) {
      if (gp.name == "fig7_work_precision" && !c.timing) continue;  // no timings, no work-precision
      DataDir(staging / "figures").write(std::string(gp.name) + ".gp", std::string(gp.text));
      for (const char* fmt_name : {"png", "pdf"}) {
        const std::string cmd = fmt::format(
            "cd '{}' && gnuplot -e \"datadir='../data'; outfile='{}.{}'; format='{}'; methods='{}'; numeric='{}'; "
            "springdts='{}'; largedt='{}'\" '{}.gp'",
            (staging / "figures").string(), gp.name, fmt_name, fmt_name, all, numeric, words(c.spring_figure_dts), c.large_dt,
            gp.name);
        if (run_quiet(cmd) != 0) throw std::runtime_error(fmt::format("gnuplot failed on {}.gp ({})", gp.name, fmt_name));
      }
    }
    const std::string footer = machine_footer() + fmt::format(" · studies {:.1f} s", study_seconds);
    write_atomic((staging / "report.md").string(), report_markdown(d, f, "png", footer));
    write_atomic((staging / "report-pdf.md").string(), report_markdown(d, f, "pdf", footer));
    const std::string pandoc = fmt::format(
        "cd '{}' && pandoc report-pdf.md -o report.pdf --pdf-engine=pdflatex -V geometry:margin=1.8cm -V fontsize=10pt "
        "-V colorlinks=true -V 'header-includes=\\usepackage{{float}}\\floatplacement{{figure}}{{H}}'",
        staging.string());
    if (run_quiet(pandoc) != 0) throw std::runtime_error("pandoc could not make report.pdf (rerun it by hand to see why)");
    fs::remove(staging / "report-pdf.md");
    data.write("stamp", stamp);
    if (stop_requested) throw Interrupted();
  } catch (...) {
    fs::remove_all(staging);
    throw;
  }
  // Swap the new report in: one atomic exchange of the two folders, then the old one goes.
  if (fs::exists(out)) {
    if (renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, out.c_str(), RENAME_EXCHANGE) != 0) {
      fs::remove_all(staging);
      throw std::runtime_error(fmt::format("cannot replace {}", out.string()));
    }
    fs::remove_all(staging);
  } else {
    fs::rename(staging, out);
  }
  std::printf("wrote %s: report.md, report.pdf, figures/, data/\n", out.c_str());
  return 0;
}

}  // namespace steplab
