// "Is stability correlated with the method's order?", answered family by family: within explicit
// Runge-Kutta, symplectic splitting, implicit Runge-Kutta, Adams-Bashforth and BDF, how dt* moves
// with the order at every damping measured; Dahlquist's second barrier checked against the
// multistep methods; the pooled correlation (the numerical methods only); the stability regions in
// z = h lambda with the spring's eigenvalue ray; and the splitting methods, which have no region,
// on the test equation. Every sentence is computed from the thresholds and regions.
#include <algorithm>
#include <cmath>
#include <complex>
#include <numeric>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/regions.hpp"
#include "core/scenes/spring.hpp"
#include "reports/document/claims.hpp"
#include "reports/document/figure_styles.hpp"
#include "reports/document/findings.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"

namespace steplab {
namespace {

std::vector<std::size_t> every_method() {
  std::vector<std::size_t> all(method_count());
  std::iota(all.begin(), all.end(), 0);
  return all;
}

class Families : public Section {
 public:
  std::string title() const override { return "Stability and order, family by family"; }
  unsigned needs() const override { return kFindings; }
  void study(const ReportData& d) override {
    RegionConfig c;
    c.methods = d.methods;
    c.workers = d.workers;
    regions_ = stability_regions(c);
  }

  // region_<m>.dat: re im stable (0/1), the whole window (mirrored: -im_max .. im_max), a block per
  // im; mark_<m>.dat: where the spring's eigenvalue ray leaves the region (dt* lambda) and where it
  // enters it again (the predicted "stable again" step times lambda); ray.dat: the ray.
  void write_data(const ReportData& d, const DataDir& dat) const override {
    const std::complex<double> lambda = Spring(d.config.oscillator.params).eigenvalue();
    const std::size_t ni = regions_.im.size();
    for (const StabilityRegion& r : regions_.regions) {
      std::string s = "# re im stable (rho <= 1)\n";
      for (std::size_t jj = 0; jj < 2 * ni - 1; ++jj) {
        const std::size_t j = jj < ni ? ni - 1 - jj : jj - ni + 1;
        const double im = jj < ni ? -regions_.im[j] : regions_.im[j];
        for (std::size_t i = 0; i < regions_.re.size(); ++i)
          s += num(regions_.re[i]) + " " + num(im) + " " + (r.rho[j][i] <= 1 + kRegionTolerance ? "1" : "0") + "\n";
        s += "\n";
      }
      dat.write("region_" + name(r.method) + ".dat", s);
      s = "# re im of dt* lambda (leaves the region) and of the stable-again step times lambda (enters it again)\n";
      if (const ThresholdRow* t = find_threshold(d, r.method, d.config.damping()))
        for (double h : {t->dt_theory, t->again_theory})
          if (h > 0 && std::isfinite(h)) s += num((h * lambda).real()) + " " + num((h * lambda).imag()) + "\n";
      dat.write("mark_" + name(r.method) + ".dat", s);
    }
    std::string ray = "# re im: z = h lambda, h from 0 out of the window\n";
    const double reach = 20 / std::abs(lambda);
    ray += "0 0\n" + num(reach * lambda.real()) + " " + num(reach * lambda.imag()) + "\n";
    dat.write("ray.dat", ray);
  }

  // A panel per family with a scalar stability function, each method's region lightly filled and edged in its style.
  std::vector<FigureSpec> figures(const ReportData& d) const override {
    std::vector<Panel> panels = family_panels(d.methods, [&](std::size_t m) { return has_region(m); });
    if (panels.empty()) return {};
    std::string vars;
    for (const StabilityRegion& r : regions_.regions)
      vars += fmt::format("rgb_{}={}; ", name(r.method), std::stoi(method_style(r.method).colour.substr(1), nullptr, 16));
    return {{"regions", vars, std::move(panels)}};
  }

  // Whether the study found `m`'s stability region (a method with a scalar stability function).
  bool has_region(std::size_t m) const {
    return std::any_of(regions_.regions.begin(), regions_.regions.end(), [&](const StabilityRegion& r) { return r.method == m; });
  }

  // The regions figure's sentence of what to see: along the spring's ray at `gamma`, the region left
  // first (the least predicted dt*) and the methods whose region holds the whole ray.
  // Each a claim over the thresholds' predicted dt* at `gamma`, where `l` is given.
  std::string ray_sentence(const ReportData& d, double gamma, Ledger* l) const {
    const ThresholdRow* first = nullptr;
    std::vector<std::size_t> whole;
    std::vector<Json> regions;  // the thresholds rows of the methods with a region, by their fields
    std::size_t a = 0;
    for (const ThresholdRow& r : d.thresholds) {
      if (!has_region(r.method) || r.damping != gamma) continue;
      if (std::isinf(r.dt_theory)) whole.push_back(r.method);
      else if (!first || r.dt_theory < first->dt_theory) first = &r, a = regions.size();
      regions.push_back({{"method", name(r.method)}, {"damping", gamma}});
    }
    constexpr Digits kDt{true, 4};
    std::string out;
    if (first) out = fmt::format("The ray leaves `{}`'s region first, at dt* = {}", name(first->method), printed(first->dt_theory, kDt));
    if (!whole.empty()) out += fmt::format("{} stays inside the regions of {}", out.empty() ? "The ray" : ", and", method_list(whole));
    if (out.empty()) return out;
    out += ".";
    if (l && first)
      claim_stability_extreme(*l, {d}, claim_text("families.ray_leaves_first", "families", out), "thresholds", regions, a, "dt_theory",
                              Extreme::Least, kDt);
    if (l && !whole.empty()) claim_unbounded_at(*l, {d}, "families.ray_inside", "families", out, gamma, whole);
    return out;
  }

  std::string markdown(Page& page) const override {
    const ReportData& d = page.data;
    const ReportConfig& c = d.config;
    const double gamma = c.damping();
    std::vector<double> dampings;
    for (const ThresholdRow& r : d.thresholds)
      if (std::find(dampings.begin(), dampings.end(), r.damping) == dampings.end()) dampings.push_back(r.damping);
    std::sort(dampings.begin(), dampings.end());

    std::string md = "## " + title() + "\n\n";
    md += "Within a family the methods share their construction and differ in order, so a family's dt* against its orders "
          "is the measured answer to the sheet's question; across families the construction dominates. ";
    md += trend_table(d, dampings, page.ledger);
    md += dahlquist(d, dampings);
    if (page.ledger) page.ledger->theory("families", "Dahlquist's second barrier: an A-stable linear multistep method has order at most 2.");
    md += pooled(page.findings, gamma);
    if (page.has("regions")) {
      md += fmt::format("The stability regions (figure {}) show why the trends differ: the spring's eigenvalues z = h lambda lie "
                        "near the imaginary axis when it is lightly damped, and each region reaches further along some "
                        "directions than others.\n\n",
                        page.number("regions"));
      md += page.figure("regions", fmt::format("Stability regions in z = h lambda: where |R(z)| <= 1 (a one-step method) or the "
                                               "root condition holds (a multistep one), from each method's own step map, each "
                                               "lightly filled and edged in its colour and dash; red line with crosses: the "
                                               "spring's eigenvalue ray at damping {}; "
                                               "points: where it leaves a region at the predicted dt* and where it enters it "
                                               "again. {}", gamma, ray_sentence(d, gamma, page.ledger)));
    }
    md += by_hand(d, page.findings, page.ledger);
    md += splitting(d, page.findings, page.ledger);
    return md;
  }

 private:
  RegionResult regions_;

  // A row per family, a column per damping: how dt* moves with the order.
  static std::string trend_table(const ReportData& d, const std::vector<double>& dampings, Ledger* ledger) {
    std::string md = "How the measured dt* (the summary's, and at further dampings) moves along each family's orders:\n\n| family |", rule = "|--------|";
    for (double g : dampings) md += fmt::format(" damping {} |", g), rule += "------|";
    md += "\n" + rule + "\n";
    std::vector<std::vector<FamilyTrend>> at;
    for (double g : dampings) at.push_back(family_trends(d, g));
    for (std::size_t i = 0; !at.empty() && i < at.front().size(); ++i) {
      md += fmt::format("| {} |", to_string(at.front()[i].family));
      for (std::size_t g = 0; g < at.size(); ++g) {
        const FamilyTrend& t = at[g][i];
        md += fmt::format(" {} |", to_text(t.trend));
        if (ledger)
          claim_family_trend(*ledger, {d}, fmt::format("families.trend.{}.damping_{}", id_word(to_string(t.family)), dampings[g]), "families",
                             fmt::format("the family table's {} row at damping {}: {}", to_string(t.family), dampings[g], to_text(t.trend)),
                             t, dampings[g]);
      }
      md += "\n";
    }
    std::vector<std::string> first;  // a method another family counts as its first member (AB1 is explicit Euler)
    for (Family f : kReportFamilies)
      for (std::size_t m : family_members(d.methods, f))
        if (method_info(m).family != f) first.push_back(fmt::format("{} from `{}`", to_string(f), name(m)));
    if (!first.empty())
      md += fmt::format("\nA family's orders start at its order-1 member, another family's method: {}.\n", and_list(first));
    std::vector<std::string> lone;  // a family of several methods of which the report has one
    for (Family f : kReportFamilies) {
      const std::vector<std::size_t> fam = family_members(d.methods, f);
      if (fam.size() == 1 && family_members(every_method(), f).size() > 1)
        lone.push_back(fmt::format("{} ({})", to_string(f), method_list(fam)));
    }
    if (!lone.empty()) md += fmt::format("\nNo trend is read where the report has one method of a family: {}.\n", and_list(lone));
    return md + "\n";
  }

  // Dahlquist's second barrier: an A-stable linear multistep method has order at most 2.
  std::string dahlquist(const ReportData& d, const std::vector<double>& dampings) const {
    std::vector<std::size_t> multistep, every_step, half_plane;
    for (Family f : {Family::AdamsBashforth, Family::Bdf})
      for (std::size_t m : family_members(d.methods, f)) multistep.push_back(m);
    for (std::size_t m : multistep) {
      bool all = true;
      for (double g : dampings)
        if (const ThresholdRow* t = find_threshold(d, m, g); !t || !std::isinf(t->dt_measured)) all = false;
      if (all) every_step.push_back(m);
      for (const StabilityRegion& r : regions_.regions)
        if (r.method == m && left_half_plane_stable(regions_, r)) half_plane.push_back(m);
    }
    if (multistep.empty()) return {};
    int max_order = 0;
    for (std::size_t m : half_plane) max_order = std::max(max_order, method_info(m).order);
    std::string orders;
    for (std::size_t m : every_step) orders += fmt::format("{}`{}` (order {})", orders.empty() ? "" : ", ", name(m), method_info(m).order);
    std::string md = fmt::format(
        "Dahlquist's second barrier: an A-stable linear multistep method has order at most 2. Of the {} linear multistep "
        "methods here (Adams-Bashforth and BDF, explicit and implicit Euler included), stable at every step at every damping "
        "tried: {}; with a stability region holding the whole left half-plane: {}.",
        multistep.size(), orders.empty() ? "none" : orders, method_list(half_plane));
    if (half_plane.empty()) return md + "\n\n";
    md += max_order <= 2 ? fmt::format(" The highest order among them is {}: the data agree with the barrier.", max_order)
                         : fmt::format(" The highest order among them is {}, above the barrier: a defect in the method or in "
                                       "the measurement.", max_order);
    std::vector<std::size_t> beyond;
    for (std::size_t m : multistep)
      if (method_info(m).order > 2) beyond.push_back(m);
    if (!beyond.empty()) md += fmt::format(" Of order 3 and more: {}, not A-stable.", method_list(beyond));
    return md + "\n\n";
  }

  // The pooled correlation over the numerical methods, and why it misleads.
  static std::string pooled(const Findings& f, double gamma) {
    if (f.spearman_n < 3) return {};
    return fmt::format("Pooled over the {} ODE methods, Spearman's rank correlation between order and measured dt* "
                       "(damping {}) is **{:.2f}**, {}, {}. One number mixes families whose dt* moves in different directions "
                       "with the order (the table above), so it answers none of them.\n\n",
                       f.spearman_n, gamma, f.spearman, correlation_words(f.spearman), chance_words(f.spearman, f.spearman_n));
  }

  // Two of the sheet's methods by hand, beside their measured dt*. On m y'' = -k u - gamma u' the
  // eigenvalues are lambda = -gamma / (2m) +- i beta, |lambda|^2 = k / m = omega^2.
  //   Explicit Euler multiplies an eigencomponent by 1 + h lambda, and
  //     |1 + h lambda|^2 = 1 + 2 h Re(lambda) + h^2 |lambda|^2 <= 1  <=>  h <= -2 Re(lambda) / |lambda|^2 = gamma / k;
  //   undamped (Re(lambda) = 0) it is 1 + omega^2 h^2 > 1 at every h > 0: dt* = 0.
  //   Symplectic Euler (v+ = v - h omega^2 x, x+ = x + h v+) has the step matrix
  //     M = [[1 - h^2 omega^2, h], [-h omega^2, 1]],  det M = 1,  tr M = 2 - h^2 omega^2;
  //   its eigenvalues are on the unit circle, distinct, while |tr M| < 2: h omega < 2, dt* = 2 / omega.
  static std::string by_hand(const ReportData& d, const Findings& f, Ledger* l) {
    const Spring s(d.config.oscillator.params);
    const double omega = std::sqrt(s.k / s.m), gamma = d.config.damping();
    const MethodFinding *euler = nullptr, *symplectic = nullptr;
    for (const MethodFinding& r : f.rows) {
      if (name(r.method) == "explicit_euler") euler = &r;
      if (name(r.method) == "symplectic_euler") symplectic = &r;
    }
    if (!euler && !symplectic) return {};
    std::string md = fmt::format("Two of the sheet's methods by hand, on the spring's $u'' = -\\omega^2 u - (\\gamma/m) u'$ with "
                                 "eigenvalues $\\lambda = -\\gamma/2m \\pm i\\beta$, $|\\lambda| = \\omega = \\sqrt{{k/m}} = {:.4g}$:\n\n",
                                 omega);
    const std::string euler_theory =
        "Explicit Euler multiplies each eigencomponent by $1 + h\\lambda$, and $|1 + h\\lambda|^2 = 1 + 2h\\,\\mathrm{Re}\\,\\lambda + "
        "h^2\\omega^2 \\le 1$ exactly when $h \\le -2\\,\\mathrm{Re}\\,\\lambda/\\omega^2 = \\gamma/k$; undamped, $|1 + i\\omega h|^2 = "
        "1 + \\omega^2 h^2 > 1$ at every $h > 0$";
    const std::string symplectic_theory =
        "Symplectic Euler ($v_{n+1} = v_n - h\\omega^2 x_n$, $x_{n+1} = x_n + h v_{n+1}$) has the step matrix "
        "$M = \\begin{pmatrix} 1 - h^2\\omega^2 & h \\\\ -h\\omega^2 & 1 \\end{pmatrix}$ with $\\det M = 1$ and "
        "$\\mathrm{tr}\\, M = 2 - h^2\\omega^2$: its eigenvalues stay on the unit circle while $|\\mathrm{tr}\\, M| < 2$, that is "
        "$h\\omega < 2$";
    if (euler) {
      const std::string line = fmt::format("- {}: predicted dt* = 0 undamped and $\\gamma/k$ = {:.4g} at damping {}; measured {} and {:.4g}.\n",
                                           euler_theory, gamma / s.k, gamma, dt_text(euler->dt_undamped_measured), euler->dt_measured);
      md += line;
      if (l) {
        l->theory("families", euler_theory);
        claim_measured_as_predicted(*l, {d}, "families.by_hand.explicit_euler.damping_0", "families", line, {euler->method}, 0, 5e-4);
        claim_measured_as_predicted(*l, {d}, "families.by_hand.explicit_euler", "families", line, {euler->method}, gamma, 5e-4);
      }
    }
    if (symplectic) {
      const std::string line = fmt::format("- {}: predicted dt* = $2/\\omega$ = {:.4g} undamped; measured {:.4g}.\n", symplectic_theory,
                                           2 / omega, symplectic->dt_undamped_measured);
      md += line;
      if (l) {
        l->theory("families", symplectic_theory);
        claim_measured_as_predicted(*l, {d}, "families.by_hand.symplectic_euler", "families", line, {symplectic->method}, 0, 5e-4);
      }
    }
    return md + "\n";
  }

  // The splitting methods have no scalar R(z); on the test equation x'' = -omega^2 x their step
  // maps give a limit on h omega, which the undamped spring measures.
  static std::string splitting(const ReportData& d, const Findings& f, Ledger* l) {
    const Spring s(d.config.oscillator.params);
    const double omega = std::sqrt(s.k / s.m);
    std::vector<std::string> limits;
    std::vector<std::size_t> methods;
    for (const MethodFinding& r : f.rows)
      if (method_info(r.method).family == Family::Splitting && std::isfinite(r.dt_undamped_theory)) {
        limits.push_back(fmt::format("`{}` h omega < {:.4g} (measured on the spring: dt* omega = {:.4g})", name(r.method),
                                     r.dt_undamped_theory * omega, r.dt_undamped_measured * omega));
        methods.push_back(r.method);
      }
    if (limits.empty()) return {};
    const std::string md = fmt::format("The splitting methods update x and v by different rules, so their step is not a function "
                                       "R(h A) of one scalar z and they have no region above. On the test equation x'' = -omega^2 x "
                                       "their step maps give a limit on h omega instead: {}.\n\n",
                                       and_list(limits));
    // as printed, to 4 digits: the measured dt* within 5e-4 of the predicted one, relative
    if (l) claim_measured_as_predicted(*l, {d}, "families.splitting_limits", "families", md, methods, 0, 5e-4);
    return md;
  }
};

}  // namespace

std::unique_ptr<Section> make_families_section() { return std::make_unique<Families>(); }

}  // namespace steplab
