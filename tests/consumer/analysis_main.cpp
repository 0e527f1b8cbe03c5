// steplab::analysis: the convergence study of explicit Euler and RK4 on the spring; the fitted
// orders must be 1 and 4 within 0.05 (in the tree: 1.000 and 3.999).
#include <cmath>
#include <cstdio>

#include <steplab/analysis/studies/convergence.hpp>
#include <steplab/analysis/kernel/kernel.hpp>

int main() {
  using namespace steplab;
  ConvergenceConfig c;
  c.scene = *find_scene("spring");
  c.params = default_param_values(c.scene);
  c.methods = {*find_method("explicit_euler"), *find_method("rk4")};
  const ConvergenceResult r = convergence_study(c);
  int status = 0;
  for (const ConvergenceFit& f : r.fits) {
    const int declared = method_info(f.method).order;
    std::printf("%s: fitted order %.3f, declared %d\n", method_info(f.method).name.data(), f.fit.order, declared);
    if (!f.fit.fitted || std::abs(f.fit.order - declared) > 0.05) status = 1;
  }
  return status;
}
