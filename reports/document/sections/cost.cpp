// Cost: work-precision on the spring and the stiff chain (analysis/work_precision.hpp), with the
// adaptive peers; the cheapest method per error level, the chain's stable against accurate
// steps, and the stiffness crossover. Every sentence is computed from d.work.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analysis/kernel.hpp"
#include "analysis/peers.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"
#include "reports/data/study_output.hpp"

namespace steplab {
namespace {

std::string scene_word(const SceneWork& w) { return std::string(scene_name(w.scene)); }

// "1.2 µs" / "3.4 ms" or "812 evaluations".
std::string cost_text(bool timed, double seconds, long long evaluations) {
  if (!timed) return fmt::format("{} evaluations", evaluations);
  if (seconds < 1e-3) return fmt::format("{:.3g} µs", seconds * 1e6);
  return seconds < 1 ? fmt::format("{:.3g} ms", seconds * 1e3) : fmt::format("{:.3g} s", seconds);
}

// Runs of equal names over the error levels: "`rk4` at 1e-02 .. 1e-06, `cvode_bdf` at 1e-07".
std::string level_runs(const SceneWork& w, bool timed) {
  std::vector<std::string> parts;
  const auto& ch = w.cheapest;
  for (std::size_t i = 0; i < ch.size();) {
    const std::string& n = timed ? ch[i].by_time : ch[i].by_evaluations;
    std::size_t j = i;
    while (j + 1 < ch.size() && (timed ? ch[j + 1].by_time : ch[j + 1].by_evaluations) == n) ++j;
    const std::string who = n.empty() ? "no run" : "`" + n + "`";
    parts.push_back(j == i ? fmt::format("{} at {:.0e}", who, ch[i].error_level)
                           : fmt::format("{} at {:.0e} .. {:.0e}", who, ch[i].error_level, ch[j].error_level));
    i = j + 1;
  }
  return and_list(parts);
}

// A run's cost: seconds, or force and Jacobian evaluations untimed.
double point_cost(const WorkPoint& p, bool timed) {
  return timed ? p.seconds : static_cast<double>(p.evaluations());
}
// The cheapest run of `method` with error at most `level` (null if none reaches it).
const WorkPoint* cheapest_point(const SceneWork& w, const std::string& method, double level, bool timed) {
  const WorkPoint* best = nullptr;
  for (const WorkPoint& p : w.points)
    if (p.method == method && p.status == RunStatus::Ok && p.error <= level && (!best || point_cost(p, timed) < point_cost(*best, timed)))
      best = &p;
  return best;
}

class Cost : public Section {
 public:
  std::string title() const override { return "Cost: work against precision"; }
  unsigned needs() const override { return kWorkPrecisionStudy; }
  void write_data(const ReportData& d, const DataDir& dat) const override {
    dat.write("work_precision.json", work_precision_json(d.work).dump(1) + "\n");
    for (const SceneWork& w : d.work.scenes)
      for (const std::string& m : curve_names(d)) {
        std::string s = "# dt_or_tolerance error_max seconds evaluations\n";
        for (const WorkPoint& p : w.points)
          if (p.method == m && p.status == RunStatus::Ok && p.error > 0)
            s += fmt::format("{} {} {} {}\n", num(p.setting), num(p.error), num(p.seconds), p.evaluations());
        dat.write(fmt::format("wp_{}_{}.dat", scene_word(w), m), s);
      }
  }

  // A column per scene, with common axes down it: the ranges from the data.
  std::vector<FigureSpec> figures(const ReportData& d) const override {
    const bool timed = d.config.timing;
    std::string vars = fmt::format("xcol={}; xname='{}'; ", timed ? 3 : 4, timed ? "run time (s)" : "force + Jacobian evaluations");
    for (std::size_t k = 0; k < d.work.scenes.size(); ++k) {
      double x0 = INFINITY, x1 = 0, y0 = INFINITY, y1 = 0;
      for (const WorkPoint& p : d.work.scenes[k].points) {
        if (p.status != RunStatus::Ok || !(p.error > 0)) continue;
        const double x = point_cost(p, timed);
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, p.error), y1 = std::max(y1, p.error);
      }
      if (!(x0 <= x1)) x0 = 1, x1 = 10, y0 = 1e-10, y1 = 1;
      vars += fmt::format("scene{}='{}'; xlo{}={}; xhi{}={}; ylo{}={}; yhi{}={}; ", k + 1, scene_word(d.work.scenes[k]), k + 1,
                          num(x0 / 1.5), k + 1, num(x1 * 1.5), k + 1, num(y0 / 3), k + 1, num(std::min(y1 * 3, 1e3)));
    }
    // a row per family and one of the adaptive solvers, each of the solvers with a point to draw
    const auto has_points = [&](std::string_view solver) {
      for (const SceneWork& w : d.work.scenes)
        for (const WorkPoint& p : w.points)
          if (p.method == solver && p.status == RunStatus::Ok && p.error > 0) return true;
      return false;
    };
    std::vector<Panel> panels = family_panels(d.work.config.methods, [&](std::size_t m) { return has_points(name(m)); });
    Panel adaptive{"adaptive solvers", {}};
    for (const std::string& a : d.work.config.adaptive)
      if (has_points(a)) adaptive.solvers.push_back(a);
    if (!adaptive.solvers.empty()) panels.push_back(std::move(adaptive));
    return {{"fig7_work_precision", vars, std::move(panels)}};
  }

  std::string markdown(Page& page) const override {
    const ReportData& d = page.data;
    const WorkPrecisionResult& r = d.work;
    const bool timed = d.config.timing;
    const std::string by = timed ? "run time (the minimum of repeated timings, integration only)" : "force and Jacobian evaluations";
    std::string md = "## " + title() + "\n\n";
    md += fmt::format(
        "Each point is one run to t = {}: its largest position error against the exact solution at its steps, and its cost "
        "in {}. The fixed-step methods run over dt sweeps, the adaptive solvers over tolerances {:.0e} .. {:.0e} "
        "(rtol = atol): steplab's `dopri5`, Boost.Odeint's controlled Dormand-Prince (`odeint_dopri5`) and SUNDIALS CVODE "
        "({}) with Adams-Moulton (`cvode_adams_dense`), with BDF (`cvode_bdf_dense`) and with BDF capped at order 2 "
        "(`cvode_bdf_max2_dense`: A-stable, for the eigenvalues near the imaginary axis), each with Newton on the analytic "
        "Jacobian and dense LU, as CVODE's guide advises for non-stiff, stiff and oscillatory problems. Every solver is timed alike: the "
        "scene made outside, the solver's set-up, run and clean-up inside.",
        r.config.t_end, by, r.config.tolerances.front(), r.config.tolerances.back(), cvode_build_text());
    if (r.stiff >= 0 && scene_kernel(r.scenes[static_cast<std::size_t>(r.stiff)].scene).modes) {
      const SceneWork& stiff = r.scenes[static_cast<std::size_t>(r.stiff)];
      md += fmt::format(" The {} ({}) has a slow mode near the sheet's spring and a stiff, damped one about {:.0f} times faster.",
                        scene_word(stiff), params_text(stiff.scene, stiff.params), fast_over_slow(stiff));
    }
    md += "\n\n";
    md += page.figure("fig7_work_precision",
                      fmt::format("work-precision on the spring (left) and the stiff chain (right): largest error along the run "
                                  "against {}; a row per family, the adaptive solvers in the last",
                                  timed ? "run time" : "evaluations"));
    md += cheapest_table(r, timed);
    for (const SceneWork& w : r.scenes)
      md += fmt::format("- Cheapest on the {} by {}: {}.\n", scene_word(w), timed ? "run time" : "evaluations", level_runs(w, timed));
    md += peer_sentences(r, timed);
    md += '\n';
    if (r.stiff >= 0) md += limits_text(r) + stiffness_text(r, timed);
    return md;
  }

 private:
  static std::vector<std::string> curve_names(const ReportData& d) {
    std::vector<std::string> out;
    for (std::size_t m : d.work.config.methods) out.push_back(name(m));
    for (const std::string& p : d.work.config.adaptive) out.push_back(p);
    return out;
  }

  // omega_fast / omega_slow of a scene's modes (core/scene.hpp).
  static double fast_over_slow(const SceneWork& w) {
    const std::vector<Mode> modes = scene_kernel(w.scene).modes(w.params);
    return modes.back().omega / modes.front().omega;
  }

  static std::string cheapest_table(const WorkPrecisionResult& r, bool timed) {
    std::string md = "| error at most |";
    for (const SceneWork& w : r.scenes)
      md += timed ? fmt::format(" {0}: by run time | {0}: by evaluations |", scene_word(w)) : fmt::format(" {}: by evaluations |", scene_word(w));
    md += "\n|---|" + std::string(timed ? "---|---|---|---|" : "---|---|") + "\n";
    for (std::size_t i = 0; i < r.config.error_levels.size(); ++i) {
      md += fmt::format("| {:.0e} |", r.config.error_levels[i]);
      for (const SceneWork& w : r.scenes) {
        const Cheapest& c = w.cheapest[i];
        if (timed) md += c.by_time.empty() ? " none |" : fmt::format(" `{}` {} |", c.by_time, cost_text(true, c.seconds, 0));
        md += c.by_evaluations.empty() ? " none |" : fmt::format(" `{}` {} |", c.by_evaluations, c.evaluations);
      }
      md += "\n";
    }
    return md + "\n";
  }

  // steplab's dopri5 against odeint's, and steplab's best implicit method against each CVODE
  // configuration on the chain: the ratios at equal error in time and in force evaluations.
  static std::string peer_sentences(const WorkPrecisionResult& r, bool timed) {
    std::string md;
    for (const SceneWork& w : r.scenes) {
      double lo = INFINITY, hi = 0, flo = INFINITY, fhi = 0;
      for (const double level : r.config.error_levels) {
        const WorkPoint *a = cheapest_point(w, "dopri5", level, timed), *b = cheapest_point(w, "odeint_dopri5", level, timed);
        if (!a || !b || !(point_cost(*b, timed) > 0)) continue;
        const double ratio = point_cost(*a, timed) / point_cost(*b, timed), f = double(a->force_evaluations) / double(b->force_evaluations);
        lo = std::min(lo, ratio), hi = std::max(hi, ratio), flo = std::min(flo, f), fhi = std::max(fhi, f);
      }
      if (hi > 0)
        md += fmt::format("- On the {}, steplab's `dopri5` costs {:.2f} .. {:.2f} times what `odeint_dopri5` costs at equal error "
                          "in {}, and {:.2f} .. {:.2f} times its force evaluations (at the error levels both reach).\n",
                          scene_word(w), lo, hi, timed ? "run time" : "evaluations", flo, fhi);
    }
    if (r.stiff < 0) return md;
    const SceneWork& chain = r.scenes[static_cast<std::size_t>(r.stiff)];
    for (const double level : {r.config.crossover_error, r.config.error_levels.back()}) {
      const WorkPoint* best = nullptr;
      for (std::size_t m : r.config.methods)
        if (method_info(m).implicit)
          if (const WorkPoint* p = cheapest_point(chain, name(m), level, timed); p && (!best || point_cost(*p, timed) < point_cost(*best, timed)))
            best = p;
      if (!best) continue;
      for (const std::string& solver : r.config.adaptive) {
        const PeerInfo* peer = find_peer(solver);
        const WorkPoint* cv = peer && peer->is_cvode() ? cheapest_point(chain, solver, level, timed) : nullptr;
        if (!cv) continue;
        md += fmt::format("- On the chain at error {:.0e}: steplab's cheapest implicit method, `{}`, costs {} ({}); CVODE with {} "
                          "(`{}`) {} ({}): {:.3g} times as much {} and {:.3g} times the force evaluations.\n",
                          level, best->method, cost_text(timed, best->seconds, best->evaluations()), counts_text(best->counts()),
                          cvode_method_words(*peer), solver, cost_text(timed, cv->seconds, cv->evaluations()),
                          counts_text(cv->counts()), point_cost(*cv, timed) / point_cost(*best, timed), timed ? "in run time" : "in evaluations",
                          double(cv->force_evaluations) / double(best->force_evaluations));
      }
    }
    return md;
  }

  static std::string limits_text(const WorkPrecisionResult& r) {
    std::string md = fmt::format(
        "On the chain an explicit method's step is bounded by the stiff mode's stability as well as by accuracy. The largest "
        "stable step of each (in the dt sweep) against the step at which it reaches error {:.0e} on the slow mode alone "
        "(the masses moving as one, the limit of an infinitely stiff link):\n\n"
        "| method | largest stable dt | dt for {:.0e} on the slow mode | ratio |\n|---|---|---|---|\n",
        kLimitErrorLevel, kLimitErrorLevel);
    std::vector<std::string> held;
    const StableStep* most = nullptr;
    for (const StableStep& l : r.limits) {
      const bool reached = l.accuracy_dt > 0;
      md += fmt::format("| `{}` | {} | {} | {} |\n", l.method, dt_text(l.largest_stable_dt),
                        reached ? dt_text(l.accuracy_dt) : "below the sweep",
                        reached ? fmt::format("{:.3g}", l.accuracy_dt / l.largest_stable_dt) : "-");
      if (reached && l.accuracy_dt > l.largest_stable_dt) {
        held.push_back("`" + l.method + "`");
        if (!most || l.accuracy_dt / l.largest_stable_dt > most->accuracy_dt / most->largest_stable_dt) most = &l;
      }
    }
    md += "\n";
    if (most)
      md += fmt::format("- Held below the step accuracy would allow by stability: {} of {} explicit methods ({}); the most, `{}`, "
                        "stable to dt {} where {} would do ({:.3g} times larger).\n",
                        held.size(), r.limits.size(), and_list(held), most->method, dt_text(most->largest_stable_dt),
                        dt_text(most->accuracy_dt), most->accuracy_dt / most->largest_stable_dt);
    else
      md += "- No explicit method's stable step is below the step its accuracy alone would need.\n";
    return md;
  }

  static std::string stiffness_text(const WorkPrecisionResult& r, bool timed) {
    std::string md = fmt::format(
        "\nThe stiffness sweep: the chain with k2 from {:g} to {:g}, run to t = {}; for each method the first step of a "
        "falling sweep (or tolerance) reaching error {:.0e}, and the cheapest explicit and implicit of those by {}:\n\n"
        "| k2 | k2 / k1 | cheapest explicit | cost | cheapest implicit | cost |\n|---|---|---|---|---|---|\n",
        r.config.stiffnesses.front(), r.config.stiffnesses.back(), r.config.sweep_t_end, r.config.crossover_error,
        timed ? "run time" : "evaluations");
    for (const StiffnessRow& s : r.stiffness)
      md += fmt::format("| {:g} | {:g} | {} | {} | {} | {} |\n", s.stiffness2, s.ratio,
                        s.best_explicit.empty() ? "none" : "`" + s.best_explicit + "`",
                        s.best_explicit.empty() ? "-" : cost_text(timed, s.explicit_seconds, s.explicit_evaluations),
                        s.best_implicit.empty() ? "none" : "`" + s.best_implicit + "`",
                        s.best_implicit.empty() ? "-" : cost_text(timed, s.implicit_seconds, s.implicit_evaluations));
    md += "\n";
    if (r.crossover_ratio > 0)
      md += fmt::format("- The crossover: from stiffness ratio k2 / k1 = {:g} on, an implicit method is cheaper than every "
                        "explicit one at error {:.0e} (by {}).\n\n",
                        r.crossover_ratio, r.config.crossover_error, timed ? "run time" : "evaluations");
    else
      md += fmt::format("- No stiffness ratio of the sweep makes an implicit method cheaper than every explicit one at error "
                        "{:.0e}.\n\n", r.config.crossover_error);
    return md;
  }
};

}  // namespace

std::unique_ptr<Section> make_cost_section() { return std::make_unique<Cost>(); }

}  // namespace steplab
