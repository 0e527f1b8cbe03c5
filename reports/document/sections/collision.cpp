// Collision: the undamped bounce's energy per method and step, orders against the exact bounce
// (those that are findings), and the falling triangle's penetration.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "reports/studies/studies.hpp"
#include "reports/document/claims.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"

namespace steplab {
namespace {

class Collision : public Section {
 public:
  std::string title() const override { return "Collision"; }
  unsigned needs() const override { return kCollisionStudy | kConvergenceStudy; }
  // The hand-in shows the falling triangle alone, with the sheet's methods: it needs that scene only.
  std::string missing(const ReportConfig& c) const override {
    return c.hand_in() ? uncovered(c, {c.body.scene}) : uncovered_for(c, needs());
  }
  void write_data(const ReportData& d, const DataDir& dat) const override {
    dat.write("collision.json", collision_json(d.collision).dump(1) + "\n");
    for (std::size_t m : d.collision.config.methods) {
      std::string s = "# dt energy_ratio_after_last_bounce\n";
      for (const CollisionRun& r : d.collision.bounce)
        if (r.method == m && !r.bounces.empty()) s += num(r.dt) + " " + num(r.bounces.back().energy_ratio) + "\n";
      dat.write("bounce_" + name(m) + ".dat", s);
    }
    // The triangle's path with the sheet's methods: its lowest corner (the least of the three
    // particles' heights) and its energy over the first sample's.
    for (const CollisionRun* run : sheet_triangles(d)) {
      std::string s = "# t lowest_y energy_ratio\n";
      for (const auto& p : run->path)
        s += num(p.t) + " " + num(std::min({p.x[1], p.x[3], p.x[5]})) + " " + num(p.energy / run->path.front().energy) + "\n";
      dat.write("triangle_" + name(run->method) + ".dat", s);
    }
  }

  std::vector<FigureSpec> figures(const ReportData& d) const override {
    const auto bounced = [&](std::size_t m) {  // a run with a bounce to draw
      return std::any_of(d.collision.bounce.begin(), d.collision.bounce.end(),
                         [&](const CollisionRun& r) { return r.method == m && !r.bounces.empty(); });
    };
    std::vector<FigureSpec> out;
    std::vector<std::string> sheet;
    for (const CollisionRun* run : sheet_triangles(d)) sheet.push_back(name(run->method));
    if (!sheet.empty()) out.push_back({"triangle", "", {{"lowest corner", sheet}, {"energy", sheet}}});
    std::vector<Panel> panels = family_panels(d.collision.config.methods, bounced);
    if (!panels.empty() && !d.config.hand_in()) out.push_back({"bounce_energy", "", std::move(panels)});
    return out;
  }

  std::string markdown(Page& page) const override {
    const ReportData& d = page.data;
    const ReportConfig& c = d.config;
    const CollisionResult& r = d.collision;
    std::string md = "## " + title() + "\n\n";
    if (c.hand_in()) return md + "The slides' contact: a penalty spring pushes a body back above the ground y = -1. " + triangle(page);
    md += fmt::format("The slides' contact: a penalty spring pushes a body back above the ground y = -1. The undamped bounce ({}; "
                      "dropped from y = 0) should keep its energy from bounce to bounce; over {} s, by method and step:\n\n",
                      params_text(c.rebound.scene, c.rebound.params), c.collision.t_end);
    md += "| method | bounces |";
    std::string rule = "|------------|--|";
    for (double dt : r.config.dts) md += fmt::format(" E/E0 after the last, dt {} |", dt), rule += "-----|";
    md += " deepest penetration |\n" + rule + "-----|\n";
    // the hand-out's rows: the sheet's methods where it has any (the atlas has every method's)
    const std::vector<std::size_t> sheet = sheet_methods();
    const auto on_sheet = [&](std::size_t m) { return std::find(sheet.begin(), sheet.end(), m) != sheet.end(); };
    const bool sheet_only = page.handout && std::any_of(r.config.methods.begin(), r.config.methods.end(), on_sheet);
    for (std::size_t m : r.config.methods) {
      if (sheet_only && !on_sheet(m)) continue;
      std::string cells;
      std::size_t bounces = 0;
      double deepest = 0;
      for (const CollisionRun& run : r.bounce)
        if (run.method == m) {
          cells += run.status != RunStatus::Ok ? " diverged |"
                   : run.bounces.empty()       ? " - |"
                                               : fmt::format(" {:.4f} |", run.bounces.back().energy_ratio);
          if (run.dt == r.config.dts.front()) bounces = run.bounces.size(), deepest = run.max_penetration;
        }
      md += fmt::format("| `{}` | {} |{} {:.4f} |\n", name(m), bounces, cells, deepest);
    }
    md += fmt::format("\n{}Bounces and penetration at dt {}. {}\n\n",
                      sheet_only ? fmt::format("The sheet's methods; [the atlas]({}) has every method's row. ", Page::atlas_link(title())) : "",
                      r.config.dts.front(), bounce_orders(d, page.ledger));
    md += triangle(page);
    if (page.has("bounce_energy") && !page.handout)
      md += page.figure("bounce_energy", "The bounce: E/E0 after the last bounce against dt, a panel per family. " + bounce_spread(r, page.ledger));
    return md;
  }

 private:
  // The falling triangle: its sentence and its figure.
  static std::string triangle(Page& page) {
    std::string md = triangle_sentence(page.data, page.ledger);
    if (page.has("triangle")) {
      const auto [low, high] = energy_extremes(page.data.collision);
      md += page.figure("triangle", fmt::format("The falling triangle at dt = {} with the sheet's methods: its lowest corner "
                                                "against the ground y = -1 (left) and E/E0 (right) over t; each contact dips the "
                                                "corner below the ground by the penetration above. {}",
                                                page.data.collision.config.triangle_dt,
                                                low ? fmt::format("E/E0 ends at {:.3g} with `{}` and at {:.3g} with `{}`.",
                                                                  low->energy_ratio_final, name(low->method),
                                                                  high->energy_ratio_final, name(high->method))
                                                    : std::string("No run ends well.")));
    }
    return md;
  }

  // The triangle's runs of the sheet's methods, in the sheet's order, with a path to draw.
  static std::vector<const CollisionRun*> sheet_triangles(const ReportData& d) {
    std::vector<const CollisionRun*> out;
    for (std::size_t m : sheet_methods())
      for (const CollisionRun& run : d.collision.triangle)
        if (run.method == m && run.path.size() > 1) out.push_back(&run);
    return out;
  }

  // The orders against the exact bounce, each against its declared order: kept where the bound
  // holds it or the fit is within kKeptOrder of it; lost where neither, with a bound at most +-0.5
  // wide or one however wide that lies wholly below it (a finding either way). A wider bound that
  // holds the order, or lies above it, is not a finding.
  static constexpr double kKeptOrder = 0.15;
  static std::string bounce_orders(const ReportData& d, Ledger* l) {
    const ConvergenceResult& conv = d.convergence_on(d.config.rebound.scene);
    std::vector<std::string> kept, lost, loose, kept_names, lost_names, loose_names;
    for (const ConvergenceFit& f : conv.fits) {
      if (method_info(f.method).exact_flow || !f.fit.fitted) continue;
      const int p = method_info(f.method).order;
      const bool holds = std::abs(f.fit.order - p) <= kKeptOrder || (f.fit.bound_lo <= p && p <= f.fit.bound_hi);
      const bool wide = f.fit.bound_hi - f.fit.bound_lo > 1;
      if (wide && (holds || f.fit.bound_hi >= p)) {
        loose.push_back(fmt::format("`{}` {:.2f} (order {})", name(f.method), f.fit.order, p));
        loose_names.push_back(name(f.method));
      } else if (holds) {
        kept.push_back(fmt::format("`{}` {:.2f} (order {})", name(f.method), f.fit.order, p));
        kept_names.push_back(name(f.method));
      } else {
        lost.push_back(fmt::format("`{}` {:.2f} [{:.2f}, {:.2f}] (order {})", name(f.method), f.fit.order, f.fit.bound_lo,
                                   f.fit.bound_hi, p));
        lost_names.push_back(name(f.method));
      }
    }
    std::string md = "Against the exact bounce, fitted over the dt sweep: ";
    if (kept.empty() && lost.empty()) md += "no method's order is pinned down";
    if (!lost.empty()) md += fmt::format("the contact costs order to {}", and_list(lost));
    if (!kept.empty()) md += fmt::format("{}{} keep their order", lost.empty() ? "" : "; ", and_list(kept));
    if (!loose.empty())
      md += fmt::format("; the fits of {} have bounds wider than +-0.5 that hold their order or lie above it: not findings either way",
                        and_list(loose));
    md += ".";
    if (l) {  // the same three classes over the bounce's convergence document
      const std::string file = cite_convergence(*l, conv);
      const Json fitted = test_field("/order", "!=", nullptr);
      const Json wide = test_difference("/order_bound/1", "/order_bound/0", ">", 1);
      const Json holds = test_any({test_difference("/order", "/declared_order", "<=", kKeptOrder),
                                   test_all({test_scaled("/order_bound/0", "<=", 1, "/declared_order"),
                                             test_scaled("/declared_order", "<=", 1, "/order_bound/1")})});
      const auto members = [&](const char* what, Json test, const std::vector<std::string>& set) {
        claim_members(*l, claim_text(fmt::format("collision.bounce_order.{}", what), "collision", md), file, "/fits", Json::object(),
                      "method", true, test_all({fitted, std::move(test)}), set);
      };
      members("kept", test_all({test_not(wide), holds}), kept_names);
      const Json below = test_scaled("/order_bound/1", "<", 1, "/declared_order");
      members("lost", test_all({test_not(holds), test_any({test_not(wide), below})}), lost_names);
      members("not_a_finding", test_all({wide, test_any({holds, test_not(below)})}), loose_names);
    }
    return md;
  }

  // The bounce figure's sentence of what to see: at the largest step, the least and the most
  // energy left after the last bounce.
  static std::string bounce_spread(const CollisionResult& r, Ledger* l) {
    const double dt = *std::max_element(r.config.dts.begin(), r.config.dts.end());
    const auto bounced = [&](const CollisionRun& run) { return run.dt == dt && run.status == RunStatus::Ok && !run.bounces.empty(); };
    const auto [low, high] = least_and_most(r.bounce, bounced, [](const CollisionRun& run) { return run.bounces.back().energy_ratio; });
    if (!low) return fmt::format("At dt {} no run bounces.", dt);
    constexpr Digits kRatio{false, 4};
    const std::string text = fmt::format("At dt {}, E/E0 after the last bounce runs from {} (`{}`) to {} (`{}`).", dt,
                                         printed(low->bounces.back().energy_ratio, kRatio), name(low->method),
                                         printed(high->bounces.back().energy_ratio, kRatio), name(high->method));
    if (l) {  // the two ends over the runs that bounced at that step
      l->document(kCollisionDocument, [&] { return collision_json(r); });
      const Kept ratios = kept_evidence(r.bounce, bounced, low, high, [&](const CollisionRun&, std::size_t i) {
        return l->at(kCollisionDocument, fmt::format("/bounce/{}/energy_ratio_last_bounce", i));
      });
      claim_range(*l, "collision.bounce_energy", "collision", text, ratios, kRatio);
    }
    return text;
  }

  // The triangle's runs that ended well with the least and the most energy at the end (null if none).
  static std::pair<const CollisionRun*, const CollisionRun*> energy_extremes(const CollisionResult& r) {
    return least_and_most(r.triangle, [](const CollisionRun& run) { return run.status == RunStatus::Ok; },
                          &CollisionRun::energy_ratio_final);
  }

  // The falling triangle (the slides' problem 3): how deep it sinks into the ground and what
  // becomes of its energy, over the methods.
  static std::string triangle_sentence(const ReportData& d, Ledger* l) {
    const CollisionResult& r = d.collision;
    const CollisionRun *shallow = nullptr, *deep = nullptr;
    std::vector<std::size_t> diverged;
    for (const CollisionRun& run : r.triangle) {
      if (run.status != RunStatus::Ok) {
        diverged.push_back(run.method);
        continue;
      }
      if (!shallow || run.max_penetration < shallow->max_penetration) shallow = &run;
      if (!deep || run.max_penetration > deep->max_penetration) deep = &run;
    }
    if (!shallow) return {};
    const auto [low, high] = energy_extremes(r);
    std::string md = fmt::format(
        "The falling triangle ({}; the slides' problem 3) at dt {} over {} s: its deepest point goes {:.3g} m into the ground "
        "with `{}` and {:.3g} m with `{}`; E/E0 at the end is {:.3g} with `{}` and {:.3g} with `{}`",
        params_text(d.config.body.scene, d.config.body.params), r.config.triangle_dt, d.config.collision.t_end,
        shallow->max_penetration, name(shallow->method), deep->max_penetration, name(deep->method), low->energy_ratio_final,
        name(low->method), high->energy_ratio_final, name(high->method));
    if (!diverged.empty()) md += fmt::format("; {} diverge", method_list(diverged));
    md += ".";
    // The converged motion: the reference runs coarse to fine, the finest checked against the first.
    const auto& ref = r.triangle_reference;
    const bool converged = ref.size() >= 2 && std::all_of(ref.begin(), ref.end(), [](const CollisionRun& x) { return x.status == RunStatus::Ok; });
    const std::size_t coarse = 0, fine = ref.size() - 1;
    double within = 0;  // their E/E0 at the end apart, rounded up to one digit so that it bounds the difference
    if (converged) {
      const double diff = std::abs(ref[fine].energy_ratio_final - ref[coarse].energy_ratio_final);
      const double unit = diff > 0 ? std::pow(10.0, std::floor(std::log10(diff))) : 1e-16;
      within = std::ceil(diff / unit) * unit;
      md += fmt::format(" Converged (RK4 at dt {:g}; at dt {:g} its E/E0 at the end is within {:.1g} of it), the deepest point "
                        "goes {:.3g} m in and E/E0 ends at {:.3g}.",
                        ref[fine].dt, ref[coarse].dt, within, ref[fine].max_penetration, ref[fine].energy_ratio_final);
    }
    md += "\n\n";
    if (l) {  // the shallowest and the deepest of the runs that ended well
      l->document(kCollisionDocument, [&] { return collision_json(r); });
      const auto extreme = [&](const char* what, const char* field, const char* op, double limit) {
        Claim c = claim_text(fmt::format("collision.triangle.{}", what), "collision", md);
        c.kind = "threshold", c.rule = {{"op", op}, {"limit", limit}};
        for (std::size_t i = 0; i < r.triangle.size(); ++i)
          if (r.triangle[i].status == RunStatus::Ok) c.evidence.push_back(l->at(kCollisionDocument, fmt::format("/triangle/{}/{}", i, field)));
        l->add(std::move(c));
      };
      extreme("shallowest", "max_penetration", ">=", shallow->max_penetration);
      extreme("deepest", "max_penetration", "<=", deep->max_penetration);
      extreme("least_energy", "energy_ratio_final", ">=", low->energy_ratio_final);
      extreme("most_energy", "energy_ratio_final", "<=", high->energy_ratio_final);
      if (converged) {
        const auto at = [&](std::size_t i, const char* field) {
          return l->at(kCollisionDocument, fmt::format("/triangle_reference/{}/{}", i, field));
        };
        claim_equal(*l, claim_text("collision.triangle.reference_check", "collision", md),
                    {{at(fine, "energy_ratio_final"), at(coarse, "energy_ratio_final")}}, 0, within);
        claim_ratio(*l, claim_text("collision.triangle.reference_depth", "collision", md), {{at(fine, "max_penetration")}, {}},
                    ref[fine].max_penetration, {true, 3});
        claim_ratio(*l, claim_text("collision.triangle.reference_energy", "collision", md), {{at(fine, "energy_ratio_final")}, {}},
                    ref[fine].energy_ratio_final, {true, 3});
      }
    }
    return md;
  }
};

}  // namespace

std::unique_ptr<Section> make_collision_section() { return std::make_unique<Collision>(); }

}  // namespace steplab
