// "Is stability correlated with the method's order?", answered family by family: within explicit
// Runge-Kutta, symplectic splitting, implicit Runge-Kutta, Adams-Bashforth and BDF, how dt* moves
// with the order at every damping measured; Dahlquist's second barrier checked against the
// multistep methods; the pooled correlation as one line; and the stability regions in z = h lambda
// with the spring's eigenvalue ray. Every sentence is computed from the thresholds and regions.
#include <algorithm>
#include <numeric>
#include <cmath>
#include <complex>
#include <map>

#include <fmt/format.h>

#include "analysis/regions.hpp"
#include "analysis/kernel.hpp"
#include "core/scenes/spring.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"

namespace steplab {
namespace {

// How dt* moves along a family's orders.
enum class Trend { StaysInfinite, Rises, Falls, StaysTheSame, Mixed };

const char* to_text(Trend t) {
  switch (t) {
    case Trend::StaysInfinite: return "stays infinite";
    case Trend::Rises: return "rises";
    case Trend::Falls: return "falls";
    case Trend::StaysTheSame: return "stays the same";
    case Trend::Mixed: return "does not move one way";
  }
  return "?";
}

Trend trend(const std::vector<double>& dt) {
  if (std::all_of(dt.begin(), dt.end(), [](double x) { return std::isinf(x); })) return Trend::StaysInfinite;
  bool up = false, down = false;
  for (std::size_t i = 0; i + 1 < dt.size(); ++i) up |= dt[i + 1] > dt[i], down |= dt[i + 1] < dt[i];
  return up && down ? Trend::Mixed : up ? Trend::Rises : down ? Trend::Falls : Trend::StaysTheSame;
}

std::vector<std::size_t> every_method() {
  std::vector<std::size_t> all(method_count());
  std::iota(all.begin(), all.end(), 0);
  return all;
}

class Families : public Section {
 public:
  std::string title() const override { return "Is stability correlated with the order? Family by family"; }
  unsigned needs() const override { return kFindings; }
  void study(const ReportData& d) override {
    RegionConfig c;
    c.methods = d.methods;
    c.workers = d.workers;
    regions_ = stability_regions(c);
  }

  void write_data(const ReportData& d, const DataDir& dat) const override {
    const std::complex<double> lambda = Spring(d.config.oscillator.params).eigenvalue();
    const std::size_t ni = regions_.im.size();
    for (const StabilityRegion& r : regions_.regions) {
      std::string s = "# re im stable (rho <= 1)\n";
      for (std::size_t jj = 0; jj < 2 * ni - 1; ++jj) {  // mirrored: -im_max .. im_max
        const std::size_t j = jj < ni ? ni - 1 - jj : jj - ni + 1;
        const double im = jj < ni ? -regions_.im[j] : regions_.im[j];
        for (std::size_t i = 0; i < regions_.re.size(); ++i)
          s += num(regions_.re[i]) + " " + num(im) + " " + (r.rho[j][i] <= 1 + kRegionTolerance ? "1" : "0") + "\n";
        s += "\n";
      }
      dat.write("region_" + name(r.method) + ".dat", s);
      s = "# re im of dt* lambda, where the ray leaves the region\n";
      if (const ThresholdRow* t = find_threshold(d, r.method, d.config.damping()); t && t->dt_theory > 0 && std::isfinite(t->dt_theory)) {
        const std::complex<double> z = t->dt_theory * lambda;
        s += num(z.real()) + " " + num(z.imag()) + "\n" + num(z.real()) + " " + num(-z.imag()) + "\n";
      }
      dat.write("mark_" + name(r.method) + ".dat", s);
    }
    std::string ray = "# re im: z = h lambda, h from 0 out of the window (and its conjugate)\n";
    const double reach = 20 / std::abs(lambda);
    ray += "0 0\n" + num(reach * lambda.real()) + " " + num(reach * lambda.imag()) + "\n\n0 0\n" + num(reach * lambda.real()) + " " +
           num(-reach * lambda.imag()) + "\n";
    dat.write("ray.dat", ray);
  }

  std::vector<FigureSpec> figures(const ReportData&) const override {
    std::vector<std::size_t> with_region;
    for (const StabilityRegion& r : regions_.regions) with_region.push_back(r.method);
    std::sort(with_region.begin(), with_region.end(), family_order_less);
    return {{"fig10_regions", fmt::format("regions='{}'", method_words(with_region)), {}}};
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
          "is the measured answer; across families the construction dominates. dt* measured at each damping (the largest "
          "step with every smaller one stable; inf: stable at every step tried):\n\n";
    md += family_table(d, gamma);
    std::map<Trend, std::vector<std::string>> at_gamma;  // the families by their trend at the spring's damping
    bool turns = false;
    for (Family f : kReportFamilies) {
      const std::vector<std::size_t> fam = family_members(d.methods, f);
      if (fam.size() == 1 && family_members(every_method(), f).size() > 1)  // the others not chosen
        md += fmt::format("- **{}**: only {} of it is in this report, so no trend with the order can be read.\n", to_string(f),
                          method_list(fam));
      if (fam.size() < 2) continue;
      std::string line = fmt::format("- **{}** ({}):", to_string(f), method_list(fam));
      Trend first = Trend::Mixed;
      for (std::size_t g = 0; g < dampings.size(); ++g) {
        std::vector<double> dt;
        std::string values;
        for (std::size_t m : fam) {
          const ThresholdRow* t = find_threshold(d, m, dampings[g]);
          dt.push_back(t ? t->dt_measured : NAN);
          values += fmt::format("{}{}", values.empty() ? "" : " → ", dt_text(dt.back()));
          if (t && std::isfinite(t->again_measured)) values += fmt::format(" (stable again from {})", dt_text(t->again_measured));
        }
        const Trend tr = trend(dt);
        if (g == 0) first = tr;
        else turns |= tr != first;
        if (dampings[g] == gamma) at_gamma[tr].emplace_back(to_string(f));
        line += fmt::format("{} at damping {} dt* {}: {}", g ? ";" : "", dampings[g], to_text(tr), values);
      }
      md += line + ".\n";
    }
    md += "\n";
    if (turns)
      md += "Where a family's trend changes with the damping, the spring's eigenvalues z = h lambda point another way: close "
            "to the imaginary axis when lightly damped, onto the negative real axis near critical damping; each region "
            "reaches further in some directions than others (figure " + std::to_string(page.next_figure()) + ").\n\n";
    md += dahlquist(d, dampings, page.next_figure());
    md += pooled(page.findings, gamma, at_gamma);
    md += page.figure("fig10_regions", fmt::format("stability regions in z = h lambda (shaded: |R(z)| <= 1 for one-step methods, "
                                                   "the root condition for multistep ones), from each method's own step map; the "
                                                   "spring's eigenvalue ray at damping {} (line) and predicted dt* where it leaves "
                                                   "the region (points)", gamma));
    std::vector<std::size_t> partitioned;
    for (std::size_t m : d.methods)
      if (method_info(m).family == Family::Splitting) partitioned.push_back(m);
    if (!partitioned.empty())
      md += partitioned.size() == 1
                ? fmt::format("{} has no stability region in this sense: it updates x and v by different rules, so its step "
                              "matrix is not a function R(h A) of one scalar z. Its stability is in the (dt, damping) maps "
                              "(Stability section).\n\n", method_list(partitioned))
                : fmt::format("{} have no stability region in this sense: they update x and v by different rules, so their step "
                              "matrix is not a function R(h A) of one scalar z. Their stability is in the (dt, damping) maps "
                              "(Stability section).\n\n", method_list(partitioned));
    return md;
  }

 private:
  RegionResult regions_;

  // Family x order: each cell the measured dt* undamped / at the spring's damping of the family's
  // method of that order; the family cell names its methods, in order. (The names stay out of the
  // order cells: pandoc gives pipe-table columns the widths of the separator's dashes, and a
  // method's name in code font does not wrap, so it ran into the next column.)
  static std::string family_table(const ReportData& d, double gamma) {
    int top = 0;
    for (std::size_t m : d.methods)
      if (!method_info(m).exact_flow) top = std::max(top, method_info(m).order);
    std::string md = "| family and its methods, by order |", rule = "|----------|";
    for (int p = 1; p <= top; ++p) md += fmt::format(" order {} |", p), rule += "---|";
    md += "\n" + rule + "\n";
    for (Family f : kReportFamilies) {
      std::vector<std::size_t> fam = family_members(d.methods, f);
      if (fam.empty()) continue;
      std::stable_sort(fam.begin(), fam.end(),
                       [](std::size_t a, std::size_t b) { return method_info(a).order < method_info(b).order; });
      std::string names;
      for (std::size_t m : fam) names += fmt::format("{}`{}`", names.empty() ? "" : ", ", name(m));
      md += fmt::format("| {}: {} |", to_string(f), names);
      for (int p = 1; p <= top; ++p) {
        std::string cell;
        for (std::size_t m : fam)
          if (method_info(m).order == p) {
            const ThresholdRow *u = find_threshold(d, m, 0), *g = find_threshold(d, m, gamma);
            cell += fmt::format("{}{} / {}", cell.empty() ? "" : "; ", u ? dt_text(u->dt_measured) : "-",
                                g ? dt_text(g->dt_measured) : "-");
          }
        md += " " + cell + " |";
      }
      md += "\n";
    }
    return md + fmt::format("\nEach cell: the measured dt* of the family's method of that order, undamped / at damping "
                            "{}. Fitted orders and energy growth are in the Summary.\n\n", gamma);
  }

  // Dahlquist's second barrier: an A-stable linear multistep method has order at most 2.
  std::string dahlquist(const ReportData& d, const std::vector<double>& dampings, int region_figure) const {
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
    int max_order = 0;
    for (std::size_t m : half_plane) max_order = std::max(max_order, method_info(m).order);
    std::string orders;
    for (std::size_t m : every_step) orders += fmt::format("{}`{}` (order {})", orders.empty() ? "" : ", ", name(m), method_info(m).order);
    std::string md = fmt::format(
        "Dahlquist's second barrier: an A-stable linear multistep method has order at most 2. Measured on the {} linear "
        "multistep methods (Adams-Bashforth and BDF, explicit and implicit Euler included): stable at every step at every "
        "damping tried: {}; stability region holding the whole left half-plane of figure {}: {}.",
        multistep.size(), orders.empty() ? "none" : orders, region_figure, method_list(half_plane));
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

  std::string pooled(const Findings& f, double gamma, std::map<Trend, std::vector<std::string>> at_gamma) const {
    const auto families = [&](Trend t) { return at_gamma[t].empty() ? std::string("no family") : and_list(at_gamma[t]); };
    return fmt::format("Pooled over all {} methods, Spearman's rank correlation between order and measured dt* (damping {}) is "
                       "**{:.2f}**. It misleads: it mixes families in which dt* rises with the order ({}), falls ({}) or stays "
                       "infinite ({}), so one number answers none of them.\n\n",
                       f.rows.size(), gamma, f.spearman, families(Trend::Rises), families(Trend::Falls),
                       families(Trend::StaysInfinite));
  }
};

}  // namespace

std::unique_ptr<Section> make_families_section() { return std::make_unique<Families>(); }

}  // namespace steplab
