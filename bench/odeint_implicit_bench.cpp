// Boost.Odeint's implicit_euler on the default spring, with its ublas Jacobian (a dense LU and
// heap-allocated ublas temporaries every step). Its own translation unit, compiled as C++17:
// Boost 1.74's ublas storage calls std::allocator::construct, which C++20 removed.
#include <benchmark/benchmark.h>

#include <cmath>
#include <utility>

#include <boost/numeric/odeint.hpp>
#include <boost/numeric/ublas/matrix.hpp>
#include <boost/numeric/ublas/vector.hpp>

void register_odeint_implicit_euler() {
  benchmark::RegisterBenchmark("odeint/spring/implicit_euler", [](benchmark::State& st) {
    using V = boost::numeric::ublas::vector<double>;
    using M = boost::numeric::ublas::matrix<double>;
    constexpr double m = 1, k = 5, L = 5, gamma = 0.1, g = 9.81, dt = 0.001;
    boost::numeric::odeint::implicit_euler<double> stepper;
    V y(2);
    y[0] = -L;
    y[1] = 0;
    const auto sys = [](const V& s, V& ds, double) {
      const double sign = (s[0] > 0) - (s[0] < 0);
      ds[0] = s[1];
      ds[1] = (-k * (std::abs(s[0]) - L) * sign - gamma * s[1] - m * g) / m;
    };
    const auto jac = [](const V&, M& j, double) {
      j(0, 0) = 0, j(0, 1) = 1, j(1, 0) = -k / m, j(1, 1) = -gamma / m;
    };
    int n = 0;
    for (auto _ : st) {
      stepper.do_step(std::make_pair(sys, jac), y, n * dt, dt);
      benchmark::DoNotOptimize(y);
      if (++n == 10'000) n = 0, y[0] = -L, y[1] = 0;  // as every benchmark: restart every 10 s
    }
    st.counters["steps_per_second"] = benchmark::Counter(static_cast<double>(st.iterations()), benchmark::Counter::kIsRate);
  });
}
