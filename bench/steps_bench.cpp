// Per-step cost: every method on every scene (step/<scene>/<method>), the same problems stepped
// with Boost.Odeint (odeint/<scene>/<method>), and the plainest hand-written loop of the same
// update (hand/<scene>/<method>) as the floor. After the run a table of time-per-step ratios
// steplab/odeint and steplab/hand-written (medians of the repetitions) is printed (console format
// only) and, with --ratios=FILE, written as Markdown. Every Google Benchmark flag works as it
// documents it (--benchmark_format=json prints JSON on stdout, --benchmark_out=FILE, ...).
//
// Every benchmark steps one state in place, benchmark::DoNotOptimize on it each step, at
// dt = 0.001, and starts again from the initial state every kRestart steps (10 simulated
// seconds): long enough that the restart costs nothing measurable, short enough that no run
// decays to rest (where denormals or an early Newton exit would distort the time) or grows
// without bound. steplab, odeint and the hand-written loops all restart alike.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <utility>

#include <boost/numeric/odeint.hpp>

#include "analysis/kernel/kernel.hpp"
#include "core/methods/explicit_euler.hpp"
#include "core/methods/rk4.hpp"
#include "core/scenes/falling.hpp"
#include "core/scenes/spring.hpp"

void register_odeint_implicit_euler();
// peers_bench.cpp: steplab's CVODE peer against plain C on the rope, and their ratios
void register_peers();
std::string peer_ratio_lines(const std::map<std::string, double>& ns);
// sized_bench.cpp: a step against the size of the rope and the soft body, the hand-written
// vectorised loops on the rope, and steplab's ratios to them
void register_sized();
std::string rope_floor_lines(const std::map<std::string, double>& ns);
// machine.cpp: what the times were measured on
std::string cpu_model();
double load_average();
std::string machine_line();
// throughput_bench.cpp: registers the throughput rows; returns their trajectories and trajectory-steps per iteration
std::pair<int, long long> register_throughput();

// Steps of method m on scene s (with parameter values p), timed through the kernel table: the
// kernel makes the scene and steps `runs` runs of `run` steps in place, each from the initial
// state (a multistep method with a fresh memory, so at kRestart its start-up steps are 2 in
// 10 000 at most); an iteration is one step.
benchmark::internal::Benchmark* register_step(const std::string& name, std::size_t m, std::size_t s, std::vector<double> p, double dt,
                                              int run, int runs) {
  return benchmark::RegisterBenchmark(name.c_str(), [m, s, p = std::move(p), dt, run, runs](benchmark::State& st) {
    const steplab::PairKernel& k = steplab::pair_kernel(m, s);
    while (st.KeepRunningBatch(static_cast<benchmark::IterationCount>(run) * runs)) k.time_steps(p, dt, static_cast<long long>(run) * runs, run);
    st.counters["steps_per_second"] = benchmark::Counter(static_cast<double>(st.iterations()), benchmark::Counter::kIsRate);
  });
}

namespace {

using namespace steplab;
namespace odeint = boost::numeric::odeint;
constexpr double kDt = 0.001;
constexpr int kRestart = 10'000;

// Every row times batches of kRestart steps from the initial state (KeepRunningBatch), the rule
// of the kernel's rows (register_step, time_steps): Google Benchmark's own cost an iteration
// (Debian builds it without optimisation) is then spread over 10 000 steps in every row alike.
template <class Reset, class Step> void time_batches(benchmark::State& st, Reset&& reset, Step&& step) {
  while (st.KeepRunningBatch(kRestart)) {
    reset();
    for (int n = 0; n < kRestart; ++n) step(n);
  }
  st.counters["steps_per_second"] = benchmark::Counter(static_cast<double>(st.iterations()), benchmark::Counter::kIsRate);
}

// ---------------- steplab ----------------

// The cost of detecting a blow-up: the same stepping loop with and without the check that run()
// makes after every step (all_finite on x and v).
template <class S, class M, bool Check> void register_finite_check() {
  const std::string name = "finite_check/" + std::string(S::name) + "/" + std::string(M::info.name) + (Check ? "/on" : "/off");
  benchmark::RegisterBenchmark(name.c_str(), [](benchmark::State& st) {
    const S scene = make_default_scene<S>();
    State<S::dim> y = scene.initial();
    bool finite = true;
    time_batches(st, [&] { y = scene.initial(); }, [&](int n) {
      M::step(scene, y, n * kDt, kDt);
      if constexpr (Check) finite = finite && all_finite(y);
      benchmark::DoNotOptimize(y);
    });
    if (!finite) st.SkipWithError("non-finite state");
  });
}

void register_steplab() {
  register_finite_check<Spring, ExplicitEuler, true>();
  register_finite_check<Spring, ExplicitEuler, false>();
  register_finite_check<Falling, Rk4, true>();
  register_finite_check<Falling, Rk4, false>();
  // the undamped spring: odeint's velocity_verlet and symplectic_euler take x'' = a(x) only
  const std::size_t spring = scene_index("spring");
  for (const char* m : {"velocity_verlet", "symplectic_euler"})
    register_step(std::string("step/spring_undamped/") + m, *find_method(m), spring, {1.0, 5.0, 0.0, 5.0, 9.81}, kDt, kRestart, 1);
  for (std::size_t s = 0; s < scene_count(); ++s)
    for (std::size_t m = 0; m < method_count(); ++m)
      if (applies(m, s))
        register_step("step/" + std::string(scene_name(s)) + "/" + std::string(method_info(m).name), m, s, default_param_values(s), kDt,
                      kRestart, 1);
}

// ---------------- the default spring, written by hand ----------------
// m = 1, k = 5, L = 5, gamma = 0.1 (0 for the symplectic peers), g = 9.81; force as in Spring.
struct SpringForce {
  double m = 1, k = 5, L = 5, gamma = 0.1, g = 9.81;
  double operator()(double y, double v) const {
    const double sign = (y > 0) - (y < 0);
    return -k * (std::abs(y) - L) * sign - gamma * v - m * g;
  }
};

template <class Step> void register_loop(const char* name, SpringForce f, Step step) {
  benchmark::RegisterBenchmark(name, [f, step](benchmark::State& st) {
    double y = -f.L, v = 0;
    time_batches(st, [&] { y = -f.L, v = 0; }, [&](int) {
      step(f, y, v);
      benchmark::DoNotOptimize(y);
      benchmark::DoNotOptimize(v);
    });
  });
}

void register_hand_written() {
  const double h = kDt;
  SpringForce damped, undamped;
  undamped.gamma = 0;
  register_loop("hand/spring/explicit_euler", damped, [h](const SpringForce& f, double& y, double& v) {
    const double a = f(y, v) / f.m;
    y += h * v;
    v += h * a;
  });
  register_loop("hand/spring/symplectic_euler", damped, [h](const SpringForce& f, double& y, double& v) {
    v += h * f(y, v) / f.m;
    y += h * v;
  });
  register_loop("hand/spring/explicit_midpoint", damped, [h](const SpringForce& f, double& y, double& v) {
    const double ym = y + 0.5 * h * v, vm = v + 0.5 * h * f(y, v) / f.m;
    y += h * vm;
    v += h * f(ym, vm) / f.m;
  });
  register_loop("hand/spring/rk4", damped, [h](const SpringForce& f, double& y, double& v) {
    const double k1x = v, k1v = f(y, v) / f.m;
    const double k2x = v + 0.5 * h * k1v, k2v = f(y + 0.5 * h * k1x, k2x) / f.m;
    const double k3x = v + 0.5 * h * k2v, k3v = f(y + 0.5 * h * k2x, k3x) / f.m;
    const double k4x = v + h * k3v, k4v = f(y + h * k3x, k4x) / f.m;
    y += h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
  });
  register_loop("hand/spring/velocity_verlet", damped, [h](const SpringForce& f, double& y, double& v) {
    // closing kick implicit in the (linear) damping: v1 (1 + h/2 gamma/m) = v + h/2 (a0 + F(y1, 0)/m)
    const double a0 = f(y, v) / f.m;
    y += h * v + 0.5 * h * h * a0;
    v = (v + 0.5 * h * (a0 + f(y, 0.0) / f.m)) / (1 + 0.5 * h * f.gamma / f.m);
  });
  register_loop("hand/spring_undamped/velocity_verlet", undamped, [h](const SpringForce& f, double& y, double& v) {
    const double a0 = f(y, v) / f.m;
    y += h * v + 0.5 * h * h * a0;
    v += 0.5 * h * (a0 + f(y, v) / f.m);
  });
  register_loop("hand/spring_undamped/symplectic_euler", undamped, [h](const SpringForce& f, double& y, double& v) {
    v += h * f(y, v) / f.m;
    y += h * v;
  });
  register_loop("hand/spring/implicit_euler", damped, [h](const SpringForce& f, double& y, double& v) {
    // one Newton step is exact (linear below the anchor): v1 = v + h F(y + h v1, v1) / m
    const double r = -h * f(y + h * v, v);
    v -= r / (f.m + h * f.gamma + h * h * f.k);
    y += h * v;
  });
  register_loop("hand/spring/implicit_midpoint", damped, [h](const SpringForce& f, double& y, double& v) {
    const double c = 0.5 * h, r = -c * f(y + c * v, v);
    const double vm = v - r / (f.m + c * f.gamma + c * c * f.k);
    y += h * vm;
    v = 2 * vm - v;
  });
}

// ---------------- Boost.Odeint ----------------

using Y = std::array<double, 2>;

template <class Stepper> void register_odeint(const char* name, Stepper stepper, SpringForce f) {
  benchmark::RegisterBenchmark(name, [stepper, f](benchmark::State& st) mutable {
    Y y{-f.L, 0.0};
    const auto sys = [&f](const Y& s, Y& ds, double) {
      ds[0] = s[1];
      ds[1] = f(s[0], s[1]) / f.m;
    };
    time_batches(st, [&] { y = Y{-f.L, 0.0}; }, [&](int n) {
      stepper.do_step(sys, y, n * kDt, kDt);
      benchmark::DoNotOptimize(y);
    });
  });
}

void register_odeint_all() {
  SpringForce damped, undamped;
  undamped.gamma = 0;
  register_odeint("odeint/spring/explicit_euler", odeint::euler<Y>(), damped);
  using Rk2 = odeint::explicit_generic_rk<2, 2, Y, double>;
  register_odeint("odeint/spring/explicit_midpoint",
                  Rk2(Rk2::coef_a_type(boost::array<double, 1>{{0.5}}), Rk2::coef_b_type{{0.0, 1.0}}, Rk2::coef_c_type{{0.0, 0.5}}),
                  damped);
  register_odeint("odeint/spring/rk4", odeint::runge_kutta4<Y>(), damped);

  // velocity_verlet and symplectic_euler are for x'' = a(x): the undamped spring.
  using Q = std::array<double, 1>;
  benchmark::RegisterBenchmark("odeint/spring_undamped/velocity_verlet", [undamped](benchmark::State& st) {
    odeint::velocity_verlet<Q> vv;
    std::pair<Q, Q> qp{Q{-undamped.L}, Q{0.0}};
    const auto acc = [&undamped](const Q& q, const Q& p, Q& a, double) { a[0] = undamped(q[0], p[0]) / undamped.m; };
    time_batches(st, [&] { qp = {Q{-undamped.L}, Q{0.0}}, vv.reset(); }, [&](int n) {
      vv.do_step(acc, qp, n * kDt, kDt);
      benchmark::DoNotOptimize(qp);
    });
  });
  benchmark::RegisterBenchmark("odeint/spring_undamped/symplectic_euler", [undamped](benchmark::State& st) {
    odeint::symplectic_euler<Q> se;
    std::pair<Q, Q> qp{Q{-undamped.L}, Q{0.0}};
    const auto coor = [](const Q& p, Q& dq) { dq[0] = p[0]; };
    const auto mom = [&undamped](const Q& q, Q& dp) { dp[0] = undamped(q[0], 0.0) / undamped.m; };
    time_batches(st, [&] { qp = {Q{-undamped.L}, Q{0.0}}; }, [&](int n) {
      se.do_step(std::make_pair(coor, mom), qp, n * kDt, kDt);
      benchmark::DoNotOptimize(qp);
    });
  });

  register_odeint_implicit_euler();  // odeint_implicit_bench.cpp, compiled as C++17
}

// ---------------- the ratio table ----------------

// Collects the median (or the single) time per step of every benchmark while the reporter that
// --benchmark_format asks for (console, json or csv) prints as Google Benchmark documents it.
// Google Benchmark ignores --benchmark_format when given a reporter, so the format is read here.
template <class Base>
class Collecting : public Base {
 public:
  using Base::Base;
  void ReportRuns(const std::vector<benchmark::BenchmarkReporter::Run>& runs) override {
    for (const auto& r : runs) {
      const bool use = r.run_type == benchmark::BenchmarkReporter::Run::RT_Aggregate ? r.aggregate_name == "median"
                                                                                     : r.repetitions <= 1;
      // CPU time: a row's own thread's, which a busy core beside it hardly moves; wall time
      // counts the time the thread waited for a core (a ratio of wall times read 0.71 where
      // the same rows' CPU times gave 1.12, a build on the other core).
      if (use && !r.error_occurred) ns_per_step[r.run_name.function_name] = r.GetAdjustedCPUTime();
    }
    Base::ReportRuns(runs);
  }
  std::map<std::string, double> ns_per_step;
};

// Runs the benchmarks with a Collecting<Reporter>; returns the times it collected.
template <class Reporter, class... Args> std::map<std::string, double> run_collecting(Args... args) {
  Collecting<Reporter> reporter(args...);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  return reporter.ns_per_step;
}


std::string fmt_load(double load) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", load);
  return text;
}

// The value of --flag=value among the arguments (the last one given), or `fallback`.
std::string flag_value(int argc, char** argv, const std::string& flag, const std::string& fallback) {
  std::string v = fallback;
  for (int i = 1; i < argc; ++i)
    if (std::string a = argv[i]; a.rfind(flag + "=", 0) == 0) v = a.substr(flag.size() + 1);
  return v;
}

std::pair<int, long long> throughput_work{1, 1};  // trajectories, trajectory-steps per iteration

// Every ratio is a time over a time, steplab's first: below 1 steplab is faster.
std::string ratio_table(const std::map<std::string, double>& t) {
  std::string out = "| scene/method | steplab ns/step | odeint ns/step | hand-written ns/step | steplab/odeint | steplab/hand-written |\n"
                    "|---|---:|---:|---:|---:|---:|\n";
  const auto cell = [&](const std::string& key) {
    const auto it = t.find(key);
    return it == t.end() ? std::string("-") : std::to_string(it->second).substr(0, 6);
  };
  for (const auto& [name, ns] : t) {
    if (name.rfind("step/", 0) != 0) continue;
    const std::string rest = name.substr(5);
    const auto od = t.find("odeint/" + rest), base = t.find("hand/" + rest);
    char r1[32] = "-", r2[32] = "-";
    if (od != t.end()) std::snprintf(r1, sizeof r1, "%.2f", ns / od->second);
    if (base != t.end()) std::snprintf(r2, sizeof r2, "%.2f", ns / base->second);
    if (od == t.end() && base == t.end()) continue;
    out += "| " + rest + " | " + cell(name) + " | " + cell("odeint/" + rest) + " | " + cell("hand/" + rest) + " | " + r1 +
           " | " + r2 + " |\n";
  }
  // Throughput (throughput_bench.cpp): the same trajectory-steps per iteration in every row;
  // ns per trajectory-step of a row, 0 if it did not run.
  const auto per_step = [&](const std::string& row) {
    const auto it = t.find(row + "/spring/explicit_euler");
    return it == t.end() ? 0.0 : it->second / static_cast<double>(throughput_work.second);
  };
  const double table = per_step("throughput"), hand = per_step("throughput_hand"), rate = per_step("throughput_rate"),
               hand_rate = per_step("throughput_hand_rate"), one = per_step("throughput_w1");
  char line[400];
  if (table > 0 && hand > 0) {
    std::snprintf(line, sizeof line,
                  "\nthroughput/spring/explicit_euler (%d trajectories in packs of %d through the kernel table): %.3f ns per "
                  "trajectory-step; the same runs interleaved by hand %.3f; steplab/hand-written %.2f\n",
                  throughput_work.first, best_width(), table, hand, table / hand);
    out += line;
  }
  if (one > 0 && table > 0) {
    std::snprintf(line, sizeof line, "one run at a time: %.3f ns per trajectory-step; packs/one at a time %.2f\n", one, table / one);
    out += line;
  }
  if (rate > 0 && hand_rate > 0) {
    std::snprintf(line, sizeof line,
                  "with the energy-rate fit of study stability: %.3f ns per trajectory-step; hand-written with the same fit "
                  "%.3f; steplab/hand-written %.2f\n",
                  rate, hand_rate, rate / hand_rate);
    out += line;
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  // Our own flag, taken out before Google Benchmark reads the rest.
  std::string ratios_path;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("--ratios=", 0) == 0) ratios_path = a.substr(9);
    else argv[kept++] = argv[i];
  }
  argc = kept;
  register_steplab();
  register_hand_written();
  register_sized();
  register_odeint_all();
  throughput_work = register_throughput();
  register_peers();
  // Read before Initialize, which takes the flags it knows out of argv.
  const std::string format = flag_value(argc, argv, "--benchmark_format", "console");
  if (format != "console" && format != "json" && format != "csv") {
    std::fprintf(stderr, "steplab_bench: --benchmark_format=%s: accepted: console, json, csv\n", format.c_str());
    return 2;
  }
  const std::string color = flag_value(argc, argv, "--benchmark_color", "auto");
  const bool colored = color == "auto" ? isatty(STDOUT_FILENO) != 0 : color == "true" || color == "yes" || color == "1";
  // The build beside the machine in the JSON's context: docs/performance.md is generated from it
  // (tools/performance-md).
  benchmark::AddCustomContext("compiler", "GCC " __VERSION__);
  benchmark::AddCustomContext("cxx_flags", STEPLAB_BENCH_CXX_FLAGS);
  benchmark::AddCustomContext("steplab_version", STEPLAB_BENCH_VERSION);
  benchmark::AddCustomContext("cpu_model", cpu_model());
  const double load_at_start = load_average();
  benchmark::AddCustomContext("load_at_start", std::to_string(load_at_start));
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"  // CSVReporter: deprecated, but still a documented format
  const std::map<std::string, double> ns_per_step =
      format == "json"  ? run_collecting<benchmark::JSONReporter>()
      : format == "csv" ? run_collecting<benchmark::CSVReporter>()
                        : run_collecting<benchmark::ConsoleReporter>(colored ? benchmark::ConsoleReporter::OO_ColorTabular
                                                                             : benchmark::ConsoleReporter::OO_Tabular);
#pragma GCC diagnostic pop
  benchmark::Shutdown();
  const std::string table = ratio_table(ns_per_step) + "\n" + rope_floor_lines(ns_per_step) + peer_ratio_lines(ns_per_step);
  const std::string rule = "CPU time per step, the median of the repetitions (interleaved at random with the other rows' where "
                           "--benchmark_enable_random_interleaving is on, as make bench has it); every ratio is steplab's time over "
                           "the other's (below 1: steplab is faster). Load average at the start " +
                           fmt_load(load_at_start) + ", at the end " + fmt_load(load_average()) + ".\n\n";
  if (format == "console" && !ns_per_step.empty()) {  // json and csv on stdout stay machine-readable
    std::printf("\n%s%s", rule.c_str(), table.c_str());
    for (const auto& [name, ns] : ns_per_step) {
      if (name.rfind("finite_check/", 0) != 0 || name.size() < 3 || name.substr(name.size() - 3) != "/on") continue;
      const auto off = ns_per_step.find(name.substr(0, name.size() - 3) + "/off");
      if (off != ns_per_step.end())
        std::printf("%s: %.2f ns with the non-finite check, %.2f ns without (%+.1f %%)\n", name.substr(13, name.size() - 16).c_str(),
                    ns, off->second, 100 * (ns / off->second - 1));
    }
  }
  if (!ratios_path.empty())
    std::ofstream(ratios_path) << "# steplab bench: a step against Boost.Odeint and hand-written loops\n\n"
                               << machine_line() << "\n\n" << rule << table;
  return 0;
}
