// The appendix: the physics the report rests on. Each scene's equation of motion and each
// method's update as the code declares them (the scene's `equation`, the method's row and its
// Butcher tableau: core/scene.hpp, core/method.hpp), how the implicit steps and the multistep
// starts are solved, velocity Verlet's damping, and the terms the report uses.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analysis/studies/defaults.hpp"
#include "analysis/kernel/kernel.hpp"
#include "core/method.hpp"
#include "core/scenes/spring.hpp"
#include "reports/document/claims.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"

namespace steplab {
namespace {

// A Butcher tableau's A and b in a line: "A = [[5/12, -1/12], [3/4, 1/4]], b = [3/4, 1/4]", to 4 digits.
std::string tableau_text(const MethodKernel& k) {
  const std::size_t s = k.butcher_b.size();
  std::string a;
  for (std::size_t i = 0; i < s; ++i) {
    std::string row;
    for (std::size_t j = 0; j < s; ++j) row += fmt::format("{}{:.4g}", j ? ", " : "", k.butcher_a[i * s + j]);
    a += fmt::format("{}[{}]", i ? ", " : "", row);
  }
  std::string b;
  for (std::size_t j = 0; j < s; ++j) b += fmt::format("{}{:.4g}", j ? ", " : "", k.butcher_b[j]);
  return fmt::format("A = [{}], b = [{}]", a, b);
}

class Physics : public Section {
 public:
  std::string title() const override { return "Appendix: the physics and the methods"; }
  std::string markdown(Page& page) const override {
    const ReportData& d = page.data;
    const ReportConfig& c = d.config;
    std::string md = "## " + title() + "\n\n### The scenes\n\n";
    if (page.ledger)
      page.ledger->theory("physics", "The appendix: each scene's equation, each method's formula and tableau, how the implicit steps "
                                     "are solved, and the terms, as the code writes them (definitions, not findings).");
    std::vector<std::size_t> scenes = c.covered;  // and the scenes the sections chosen run on beside them
    if (c.has_section("stiff_order")) scenes.push_back(c.stiffened.scene);
    if (c.has_section("cost"))
      for (const SweepScene& w : kWorkPrecisionScenes) scenes.push_back(scene_index(w.scene));
    std::sort(scenes.begin(), scenes.end());
    scenes.erase(std::unique(scenes.begin(), scenes.end()), scenes.end());
    for (std::size_t s : scenes) {
      const SceneKernel& k = scene_kernel(s);
      md += fmt::format("- **{}** (`{}`): {}.\n", k.title, k.name, k.equation.empty() ? std::string("its file does not give its equation") : fmt::format("`{}`", k.equation));
    }
    md += "\n### The methods\n\nEach on y' = f(y) with y = (x, v) and f = (v, a(x, v)), a = M^-1^ F, as its file writes it; "
          "an implicit Runge-Kutta method's Butcher tableau beside it.\n\n";
    for (std::size_t m : d.methods) {
      const MethodKernel& k = method_kernel(m);
      const MethodInfo& info = k.info;
      md += fmt::format("- `{}` ({}, order {}): {}", info.name, to_string(info.family), order_text(m), info.summary);
      if (!k.butcher_b.empty()) md += "; " + tableau_text(k);
      if (!k.starter.empty()) md += fmt::format("; its first steps by `{}`", k.starter);
      md += ".\n";
    }
    md += fmt::format(
        "\n### How the implicit steps are solved\n\n"
        "An implicit step solves for the new velocity u in M (u - w) = c F(t, x0 + c_x u, u) by Newton's method on the "
        "scene's analytic Jacobians, J = M - c dF/dv - c c_x dF/dx, until the residual is below {:g} of the size of its "
        "terms (at most {} iterations; a step that does not converge ends its run as `no_convergence`). On a scene of fixed "
        "size J is factorised by dense LU at every iteration; on the rope and the soft body by simplified Newton as RADAU5 "
        "and CVODE do: the Jacobians are kept while the iteration converges fast and J is factorised again only when they "
        "are refreshed (sparse LDL^T^ on the rope, KLU on the soft body). Gauss-Legendre and Radau IIA solve their coupled "
        "stages through the eigenvectors of A (Hairer and Wanner II, IV.8). A multistep method (Adams-Bashforth, BDF) "
        "makes its first steps with the one-step method named above, of at least its order, so that its start costs it no "
        "accuracy.\n\n"
        "**Velocity Verlet with damping.** Its closing kick v += h/2 a(x_(n+1), v_(n+1)) is implicit in v when the force is "
        "damped, and steplab solves it so (one Newton step: the force is affine in v). The damping then enters like the "
        "trapezoidal rule, which is stable for any damping, so the undamped spring's limit h omega < 2 holds at every "
        "damping: dt* = 2 / omega = {:.4g} on the sheet's spring, whatever gamma.\n\n",
        NewtonSettings::tolerance, NewtonSettings::max_iterations, 2 / std::sqrt(Spring(c.oscillator.params).k / Spring(c.oscillator.params).m));
    md += "### Terms\n\n"
          "- **Order p**: the global error at a fixed time shrinks as dt^p^.\n"
          "- **Step map**: a step as a map from (x, v) and a method's memory to the next; on a linear scene a matrix whose "
          "spectral radius decides stability.\n"
          "- **dt***: the largest step with every smaller step stable; $\\infty$ when every step tried is stable.\n"
          "- **Stability region**: the z = h lambda where a one-step method's R(z) (the step map on y' = lambda y) has "
          "|R(z)| <= 1; a multistep method's where the roots of its characteristic polynomial satisfy the root condition "
          "(all within the unit circle, those on it simple).\n"
          "- **A-stable**: the region holds the whole left half-plane: stable at every step on any damped linear system. "
          "**L-stable**: A-stable and R(z) -> 0 as z -> infinity (R(infinity) = 0), so stiff modes are damped out.\n"
          "- **Stage order q**: the order to which a Runge-Kutta method's stages are accurate; on a stiff problem the order "
          "can fall towards it (order reduction).\n"
          "- **Symplectic**: the step map preserves phase-space area (its Jacobian has determinant 1 on a one-dimensional "
          "system); such a method keeps a modified energy, exactly on a linear system and up to terms exponentially small in 1/dt "
          "over exponentially long times on a nonlinear one (Hairer, Lubich and Wanner, IX.8), so its energy error stays "
          "bounded instead of drifting.\n"
          "- **Stiff**: a system whose fastest modes are far faster than the motion one wants to follow; an explicit method's "
          "step is then held by stability, not by accuracy.\n"
          "- **Force evaluation**: one evaluation of F(x, v), the unit of cost where a report is not timed; Jacobian "
          "evaluations and factorisations are counted beside it.\n\n";
    return md;
  }
};

}  // namespace

std::unique_ptr<Section> make_physics_section() { return std::make_unique<Physics>(); }

}  // namespace steplab
