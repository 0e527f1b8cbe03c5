// The exercise's hand-in opens with the sheet's two problems and the analytic solution of the
// hanging cube: the constants c1 and c2 of the sheet's equation (2), derived from the rest start.
//
// While the cube hangs below the anchor (y < 0), the sheet's equation (1) on the vertical line is
//   m y'' = -k (y + L) - gamma y' - m g,
// linear, with its rest point at y_eq = -L - m g / k. When 4 k m > gamma^2 (underdamped) every
// solution has the sheet's form
//   y(t) = c1 e^(alpha t) cos(beta t) + c2 e^(alpha t) sin(beta t) - L - m g / k,
//   alpha = -gamma / (2 m),  beta = sqrt(4 k m - gamma^2) / (2 m),
// and the rest start fixes the constants:
//   y(0)  = c1 - L - m g / k = -L       =>  c1 = m g / k,
//   y'(0) = alpha c1 + beta c2 = 0      =>  c2 = -alpha c1 / beta.
// The section evaluates this formula with its constants and sets it against the exact solution
// the errors are measured against (core/scenes/oscillator.hpp, written for every damping regime
// from any start), so a slip in either shows as a difference far above round-off.
#include <algorithm>
#include <cmath>
#include <complex>

#include <fmt/format.h>

#include "analysis/studies/defaults.hpp"
#include "analysis/kernel/kernel.hpp"
#include "core/scenes/spring.hpp"
#include "reports/document/claims.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"

namespace steplab {
namespace {

struct SheetConstants {
  bool underdamped;
  double alpha, beta, c1, c2;
  double largest_difference;  // |formula - exact| over the figure's time span
};

constexpr int kAnalyticSamples = 2000;  // intervals of [0, t_end] the formula is checked over

SheetConstants sheet_constants(const ReportConfig& c) {
  const Spring s(c.oscillator.params);
  const std::complex<double> lambda = s.eigenvalue();  // alpha + i beta when underdamped, else real
  SheetConstants k{lambda.imag() > 0, lambda.real(), lambda.imag(), s.m * s.g / s.k, 0, 0};
  if (!k.underdamped) return k;
  k.c2 = -k.alpha * k.c1 / k.beta;
  const SceneKernel& scene = scene_kernel(c.oscillator.scene);
  for (int i = 0; i <= kAnalyticSamples; ++i) {
    const double t = c.spring_figure_t_end * i / kAnalyticSamples;
    const double y = std::exp(k.alpha * t) * (k.c1 * std::cos(k.beta * t) + k.c2 * std::sin(k.beta * t)) + s.equilibrium();
    k.largest_difference = std::max(k.largest_difference, std::abs(y - scene.exact(c.oscillator.params, t).x[0]));
  }
  return k;
}

class Sheet : public Section {
 public:
  std::string title() const override { return "The exercise"; }
  std::string missing(const ReportConfig& c) const override { return uncovered(c, {c.projectile.scene, c.oscillator.scene}); }

  std::string markdown(Page& page) const override {
    const ReportConfig& c = page.data.config;
    // The cannon ball's launch velocity and gravity, read off its exact solution: v(0) and v(1) - v(0).
    const SceneKernel& projectile = scene_kernel(c.projectile.scene);
    const AnyState start = projectile.exact(c.projectile.params, 0), later = projectile.exact(c.projectile.params, 1);
    const Spring s(c.oscillator.params);
    std::string md = "## " + title() + "\n\n";
    // The sheet's own methods, and those of this hand-in that are not the sheet's (a user's choice).
    const std::vector<std::size_t> sheet = sheet_methods();
    std::vector<std::size_t> added, left_out;
    for (std::size_t m : page.data.numerical_methods())
      if (std::find(sheet.begin(), sheet.end(), m) == sheet.end()) added.push_back(m);
    for (std::size_t m : sheet)
      if (std::find(page.data.methods.begin(), page.data.methods.end(), m) == page.data.methods.end()) left_out.push_back(m);
    md += fmt::format("The 2018 sheet (exercise 1, time integration) asks for {} on two scenes, each compared with the analytic "
                      "solution.", method_list(sheet));
    if (!added.empty())  // the hand-in's are a user's choice; the full report's are every family's
      md += c.hand_in() ? fmt::format(" Beside them this hand-in measures {}, chosen with `--methods`.", method_list(added))
                                    : fmt::format(" Beside them this report measures {} more ODE methods, family by family{}.",
                                                  added.size(), page.springs ? ", and the methods on springs" : "");
    if (!left_out.empty()) md += fmt::format(" It leaves out {}, not chosen.", method_list(left_out));
    md += "\n\n";
    md += fmt::format("- **Problem 1, the cannon ball** ({}): from the origin with v0 = ({:.4g}, {:.4g}); the analytic solution is "
                      "x(t) = v0 t + g t^2 / 2 with g = (0, -{:g}).\n",
                      params_text(c.projectile.scene, c.projectile.params), start.v[0], start.v[1], start.v[1] - later.v[1]);
    md += fmt::format("- **Problem 2, the cube hanging from the ceiling** ({}): y is its height relative to the anchor "
                      "(negative below it); it starts at rest at rest length, y(0) = -L, y'(0) = 0.\n\n",
                      params_text(c.oscillator.scene, c.oscillator.params));
    md += "### The analytic solution of the hanging cube\n\n"
          "While the cube hangs below the anchor, the sheet's equation (1) on the vertical line is "
          "$m y'' = -k (y + L) - \\gamma y' - m g$, linear, at rest at $y = -L - m g / k$. The sheet's form (2),\n\n"
          "$$y(t) = c_1 e^{\\alpha t} \\cos \\beta t + c_2 e^{\\alpha t} \\sin \\beta t - L - \\frac{m g}{k}, \\qquad "
          "\\alpha = -\\frac{\\gamma}{2m}, \\quad \\beta = \\frac{\\sqrt{4 k m - \\gamma^2}}{2m},$$\n\n"
          "solves it for any $c_1, c_2$ when $4 k m > \\gamma^2$. The rest start fixes them: $y(0) = c_1 - L - m g / k = -L$ "
          "gives $c_1 = m g / k$, and $y'(0) = \\alpha c_1 + \\beta c_2 = 0$ gives $c_2 = -\\alpha c_1 / \\beta$.\n\n";
    const SheetConstants k = sheet_constants(c);
    if (k.underdamped) {
      const double within = two_digits(k.largest_difference, true);  // "to within": an upper bound as printed
      md += fmt::format("Here $4 k m = {:g} > \\gamma^2 = {:g}$ (underdamped): $\\alpha = {:.6g}$, $\\beta = {:.6g}$, "
                        "**$c_1 = {:.6g}$**, **$c_2 = {:.6g}$**. With these constants the formula agrees with the exact solution "
                        "the errors below are measured against (the scene's own, written for every damping regime) to within "
                        "{:.1e} over 0 <= t <= {:g}.\n\n",
                        4 * s.k * s.m, s.gamma * s.gamma, k.alpha, k.beta, k.c1, k.c2, within, c.spring_figure_t_end);
      if (Ledger* l = page.ledger) {  // the agreement, as printed
        const char* file = "sheet/analytic.json";
        l->document(file, [&] {
          return Json{{"schema", "steplab.sheet_analytic/1"}, {"alpha", k.alpha}, {"beta", k.beta}, {"c1", k.c1}, {"c2", k.c2},
                      {"t_end", c.spring_figure_t_end}, {"samples", kAnalyticSamples + 1}, {"largest_difference", k.largest_difference}};
        });
        Claim cl = claim_text("sheet.analytic_agrees", "sheet", fmt::format("the formula agrees with the exact solution to within {:.1e}", within));
        cl.kind = "threshold", cl.rule = {{"op", "<="}, {"limit", within}};
        cl.evidence.push_back(l->at(file, "/largest_difference"));
        if (k.largest_difference > 0) l->add(std::move(cl));
      }
    } else {
      const char* regime = 4 * s.k * s.m == s.gamma * s.gamma ? "critically " : "over";
      md += fmt::format("Here $4 k m = {:g} \\le \\gamma^2 = {:g}$: the cube is {}damped, $\\beta$ is not real and the sheet's "
                        "form does not apply; $c_1 = m g / k = {:.6g}$ still fixes the start, and the errors below are measured "
                        "against the exact solution in its {}damped form.\n\n",
                        4 * s.k * s.m, s.gamma * s.gamma, regime, k.c1, regime);
    }
    return md;
  }
};

}  // namespace

std::unique_ptr<Section> make_sheet_section() { return std::make_unique<Sheet>(); }

}  // namespace steplab
