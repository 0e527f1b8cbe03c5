// steplab::core alone (header-only): RK4 on the default spring for 10 s at h = 0.01, against the
// exact solution. RK4's global error there is about C h^4 with C of order 1: the run must end
// within 1e-6 of the exact position (measured: 2.3e-8).
#include <cstdio>

#include <steplab/core/methods/rk4.hpp>
#include <steplab/core/scenes/spring.hpp>
#include <steplab/core/simulate.hpp>

int main() {
  using namespace steplab;
  const auto spring = make_default_scene<Spring>();
  const auto r = simulate<Rk4>(spring, RunSpec{.dt = 0.01, .steps = 1000});
  std::printf("rk4 on the spring: final position error %.3g\n", r.error_final);
  return r.status == RunStatus::Ok && r.error_final < 1e-6 ? 0 : 1;
}
