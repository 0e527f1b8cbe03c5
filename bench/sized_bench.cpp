// A step against the size of the scene: steplab's on the rope of N masses (rope_size/<method>/<N>)
// and the soft body of n x n (softbody_size/<method>/<n^2>), through the kernel table; and the
// floor under the rope's: RK4 and explicit Euler written by hand over plain arrays, the force with
// the spring tensions computed first (core/scenes/rope.hpp), so that every loop vectorises
// (hand/rope_size/<method>/<N>), at the same step, in runs of the same length from the same start.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "analysis/kernel/kernel.hpp"

namespace {

// The rope's defaults (M 1, K 5, L 5, gamma 0.1, no dashpot, g 9.81) cut into n masses.
struct RopeArrays {
  int n;
  double m, k, l, c, w, inv_m;
  std::vector<double> x, v, kx, kv, sx, sv, xt, vt, a;
  explicit RopeArrays(int masses)
      : n(masses), m(1.0 / n), k(5.0 * n), l(5.0 / n), c(0.1 / n), w(m * 9.81), inv_m(1 / m), x(n), v(n), kx(n), kv(n), sx(n), sv(n),
        xt(n), vt(n), a(n) {}
  void start() {
    for (int i = 0; i < n; ++i) x[i] = -(i + 1) * l, v[i] = 0;
  }
  // a = M^-1 F(x, v): tensions T_(i+1) into a, then a_i = ((T_(i+1) - T_(i+2)) - c v_i - m g) / m.
  void acceleration(const double* __restrict xs, const double* __restrict vs, double* __restrict out) const {
    out[0] = k * ((0 - xs[0]) - l);
    for (int i = 1; i < n; ++i) out[i] = k * ((xs[i - 1] - xs[i]) - l);
    for (int i = 0; i + 1 < n; ++i) out[i] = ((out[i] - out[i + 1]) - c * vs[i] - w) * inv_m;
    out[n - 1] = (out[n - 1] - c * vs[n - 1] - w) * inv_m;
  }
  void explicit_euler(double h) {
    acceleration(x.data(), v.data(), a.data());
    double *__restrict xs = x.data(), *__restrict vs = v.data();
    const double* __restrict as = a.data();
    for (int i = 0; i < n; ++i) xs[i] += h * vs[i], vs[i] += h * as[i];
  }
  // k1 = f(y), k2 = f(y + h/2 k1), k3 = f(y + h/2 k2), k4 = f(y + h k3); the sums s gathered as
  // the stages come: y += h/6 (k1 + 2 k2 + 2 k3 + k4).
  void rk4(double h) {
    const int N = n;
    double *__restrict xs = x.data(), *__restrict vs = v.data(), *__restrict ax = kx.data(), *__restrict av = kv.data();
    double *__restrict tx = xt.data(), *__restrict tv = vt.data(), *__restrict px = sx.data(), *__restrict pv = sv.data();
    acceleration(xs, vs, av);  // k1: (v, a)
    for (int i = 0; i < N; ++i) px[i] = vs[i], pv[i] = av[i], tx[i] = xs[i] + 0.5 * h * vs[i], tv[i] = vs[i] + 0.5 * h * av[i];
    for (const double step : {0.5 * h, h}) {  // k2 (into k3's arguments), k3 (into k4's)
      acceleration(tx, tv, av);
      for (int i = 0; i < N; ++i) {
        ax[i] = tv[i];
        px[i] += 2 * ax[i], pv[i] += 2 * av[i];
        tx[i] = xs[i] + step * ax[i], tv[i] = vs[i] + step * av[i];
      }
    }
    acceleration(tx, tv, av);  // k4
    for (int i = 0; i < N; ++i) xs[i] += (h / 6) * (px[i] + tv[i]), vs[i] += (h / 6) * (pv[i] + av[i]);
  }
};

constexpr int kSizes[] = {1024, 4096, 16384};

}  // namespace

// steps_bench.cpp: `runs` runs of `run` steps of method m on scene s through the kernel table.
benchmark::internal::Benchmark* register_step(const std::string& name, std::size_t m, std::size_t s, std::vector<double> p, double dt,
                                              int run, int runs);

void register_sized() {
  using namespace steplab;
  // One step against the number of masses N, RK4 beside the implicit methods' sparse solves:
  // the rope at dt = 0.2 / omega_max (omega_max ~ 2 sqrt(K/M) N), runs of 100 steps; the soft
  // body (a 2-D grid, whose sparse factors fill in as the rope's do not) at dt 1e-4, every method
  // stable, runs of 200 steps. Making the rope of 4096 masses (its modes and sine transform)
  // costs about 0.7 ms, 200 steps of explicit Euler on it: the scene is made once every 100 runs
  // of the explicit methods and every 10 of the implicit ones (each kept iteration matrix
  // factorised once a scene, core/sparse.hpp), about 1 % of the time stepping either way.
  const std::size_t rope = scene_index("rope"), soft = scene_index("softbody");
  for (const char* name : {"explicit_euler", "rk4", "implicit_euler", "implicit_midpoint", "bdf2", "gauss_legendre4", "radau_iia5"})
    for (int n : {64, 256, 1024, 4096, 16384}) {
      std::vector<double> p = default_param_values(rope);
      p[0] = n;
      const std::size_t m = *find_method(name);
      register_step("rope_size/" + std::string(name) + "/" + std::to_string(n), m, rope, p,
                    0.2 / (2 * std::sqrt(p[2] / p[1]) * n), 100, method_info(m).implicit ? 10 : 100)
          ->Unit(benchmark::kMicrosecond);
    }
  // XPBD's step of one sweep (a projection per spring) beside symplectic Euler's (a force
  // evaluation) on the rope of 1024 masses, at the same step.
  for (const char* name : {"symplectic_euler", "xpbd"}) {
    std::vector<double> p = default_param_values(rope);
    p[0] = 1024;
    register_step("rope_size/" + std::string(name) + "/1024", *find_method(name), rope, p, 0.2 / (2 * std::sqrt(p[2] / p[1]) * 1024),
                  100, 100)
        ->Unit(benchmark::kMicrosecond);
  }
  // Baraff-Witkin's matrix-free CG (at most 100 iterations to 1e-8) beside the sparse LU of the
  // implicit methods, against the soft body's size.
  for (const char* name : {"rk4", "implicit_euler", "gauss_legendre4", "radau_iia5", "baraff_witkin"})
    for (int side : {8, 16, 32, 64}) {
      std::vector<double> p = default_param_values(soft);
      p[0] = side;
      register_step("softbody_size/" + std::string(name) + "/" + std::to_string(side * side), *find_method(name), soft, p, 1e-4, 200, 10)
          ->Unit(benchmark::kMicrosecond);
    }
  // The hand-written floor, at the rope's step, in runs of 100 steps.
  for (const int n : kSizes)
    for (const bool rk4 : {true, false}) {
      const std::string name = std::string("hand/rope_size/") + (rk4 ? "rk4/" : "explicit_euler/") + std::to_string(n);
      benchmark::RegisterBenchmark(name.c_str(), [n, rk4](benchmark::State& st) {
        RopeArrays r(n);
        const double h = 0.2 / (2 * std::sqrt(5.0) * n);
        while (st.KeepRunningBatch(100)) {
          r.start();
          for (int i = 0; i < 100; ++i) {
            if (rk4) r.rk4(h);
            else r.explicit_euler(h);
            benchmark::DoNotOptimize(r.x.data());
            benchmark::ClobberMemory();
          }
        }
      })->Unit(benchmark::kMicrosecond);
    }
}

// steplab's step on the rope over the hand-written one's, at each size both ran (both rows in us).
std::string rope_floor_lines(const std::map<std::string, double>& ns) {
  std::string out;
  for (const int n : kSizes)
    for (const char* m : {"rk4", "explicit_euler"}) {
      const std::string tail = std::string(m) + "/" + std::to_string(n);
      const auto a = ns.find("rope_size/" + tail), b = ns.find("hand/rope_size/" + tail);
      if (a == ns.end() || b == ns.end()) continue;
      char line[300];
      std::snprintf(line, sizeof line, "%s on the rope of %d masses, one step: steplab %.2f us, hand-written (vectorised) %.2f us; steplab/hand-written %.2f\n",
                    m, n, a->second, b->second, a->second / b->second);
      out += line;
    }
  return out;
}
