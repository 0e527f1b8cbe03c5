// steplab::analysis: the convergence study of explicit Euler and RK4 on the spring; the fitted
// orders must be 1 and 4 within 0.05 (in the tree: 1.000 and 3.999).
#include <cmath>
#include <cstdio>

#include "analysis/convergence.hpp"
#include "core/scenes.hpp"

int main() {
  using namespace steplab;
  ConvergenceConfig c;
  c.scene = *find_scene("spring");
  const auto p = default_params<Spring>();
  c.params.assign(p.begin(), p.end());
  c.methods = {*find_method("explicit_euler"), *find_method("rk4")};
  const ConvergenceResult r = convergence_study(c);
  int status = 0;
  for (const ConvergenceFit& f : r.fits) {
    const int declared = method_infos[f.method].order;
    std::printf("%s: fitted order %.3f, declared %d\n", method_infos[f.method].name.data(), f.fit.order, declared);
    if (!f.fit.fitted || std::abs(f.fit.order - declared) > 0.05) status = 1;
  }
  return status;
}
