// Stable for how long? The long-time study (analysis/studies/long_time.hpp) on Kepler's orbit and
// on the sheet's spring swinging in a plane: each method's energy error over many periods, its
// growth exponent with its interval, the angular momentum and the phase; the families' answer
// for long times: bounded or drifting is set by the structure (symplectic or not), not by the
// order. Every sentence is computed from the runs.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/defaults.hpp"
#include "analysis/studies/long_time.hpp"
#include "reports/studies/studies.hpp"
#include "reports/document/claims.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"
#include "reports/document/sections/long_time.hpp"
#include "reports/document/sections/answers.hpp"

namespace steplab {

std::string extremes_sentence(const LongTimeResult& r, Ledger* l, const std::string& section) {
  const auto last = [](const LongTimeRow& w) { return w.error.front().back(); };
  const auto ended = [&](const LongTimeRow& w) {
    return w.steps_per_period == r.config.steps_per_period.front() && w.status == RunStatus::Ok && !w.error.empty() && !w.error.front().empty();
  };
  const auto [least, most] = least_and_most(r.rows, ended, last);
  if (!most) return "No run ends well.";
  constexpr Digits kError{true, 2};
  std::vector<std::size_t> ended_early;  // the runs that diverged: no energy error to rank
  for (const LongTimeRow& w : r.rows)
    if (w.steps_per_period == r.config.steps_per_period.front() && w.status != RunStatus::Ok) ended_early.push_back(w.method);
  const std::string text =
      fmt::format("After {:g} periods the largest energy error {}is `{}`'s ({}), the least `{}`'s ({}){}.", most->times.back(),
                  ended_early.empty() ? "" : "of the runs that did not diverge ", name(most->method), printed(last(*most), kError),
                  name(least->method), printed(last(*least), kError),
                  ended_early.empty() ? "" : fmt::format("; {} diverged", method_list(ended_early)));
  if (l) {  // each run's last energy error, the two ends
    const std::string file = cite_long_time(*l, r, section);
    const Kept errors = kept_evidence(r.rows, ended, least, most, [&](const LongTimeRow& w, std::size_t i) {
      return l->at(file, fmt::format("/rows/{}/invariants/energy/relative_error/{}", i, w.error.front().size() - 1));
    });
    claim_range(*l, fmt::format("{}.energy_error.{}", section, scene_name(r.config.scene)), section, text, errors, kError);
    if (!ended_early.empty())
      claim_members(*l, claim_text(fmt::format("{}.diverged.{}", section, scene_name(r.config.scene)), section, text), file, "/rows",
                    {{"steps_per_period", r.config.steps_per_period.front()}}, "method", true, test_field("/status", "!=", "ok"),
                    method_names(ended_early));
  }
  return text;
}

// The data files of a long-time run: lt_<scene>_<method>.dat (t in periods, each invariant's
// largest relative error up to t, the position error where the scene has an exact solution):
// shared with the hand-in's paragraph (reports/document/sections/long_run.cpp).
void write_long_time_data(const LongTimeResult& r, const DataDir& dat) {
  for (const LongTimeRow& row : r.rows) {
    std::string s = "# t_periods";
    for (const std::string& n : r.invariants) s += fmt::format(" {}_error", n.substr(0, n.find(' ')));
    s += r.has_exact ? " position_error\n" : "\n";
    for (std::size_t k = 0; k < row.times.size(); ++k) {
      s += num(row.times[k]);
      for (const std::vector<double>& e : row.error) s += fmt::format(" {}", num(e[k]));
      if (r.has_exact) s += fmt::format(" {}", num(row.position_error[k]));
      s += "\n";
    }
    dat.write(fmt::format("lt_{}_{}.dat", scene_name(r.config.scene), name(row.method)), s);
  }
}

// How a run that did not reach its end stopped: "blew up" (its energy or state beyond bound) or
// "Newton gave up" (an implicit step's iteration did not converge); the text and the table alike.
std::string stop_words(const LongTimeRow& r) { return r.status == RunStatus::NoConvergence ? "Newton gave up" : "blew up"; }

// What became of a run that lost its orbit: how it ended, or its energy's change at the end.
std::string fate(const LongTimeRow& r) {
  if (r.status != RunStatus::Ok) return fmt::format("{} after {:.3g} periods", stop_words(r), r.ended);
  const double c = r.change.empty() ? 0 : r.change[0];
  if (c > 1) return fmt::format("energy error {:.2g} times its start", c);
  return fmt::format("energy {}{:.3g} % at the end", c > 0 ? "+" : "", 100 * c);
}

LongTimeSides sides(const LongTimeResult& r) {
  LongTimeSides out;
  for (const LongTimeRow& row : r.rows) switch (energy_verdict(row, kLostAt)) {
      case EnergyVerdict::Bounded: out.bounded.push_back(row.method); break;
      case EnergyVerdict::Drifting: out.drifting.push_back(row.method); break;
      case EnergyVerdict::Unclear: out.unclear.push_back(row.method); break;
      case EnergyVerdict::Lost: out.lost.push_back(row.method); break;
    }
  // the highest order that drifts against the lowest that stays bounded
  for (std::size_t m : out.drifting)
    if (!out.high_drift || method_info(m).order > method_info(*out.high_drift).order) out.high_drift = m;
  for (std::size_t m : out.bounded)
    if (!out.low_bounded || method_info(m).order < method_info(*out.low_bounded).order) out.low_bounded = m;
  const auto all = [](const std::vector<std::size_t>& ms, bool symplectic) {
    return std::all_of(ms.begin(), ms.end(), [&](std::size_t m) { return method_info(m).symplectic == symplectic; });
  };
  out.by_structure = !out.bounded.empty() && !out.drifting.empty() && all(out.bounded, true) && all(out.drifting, false);
  out.not_by_order = out.by_structure && method_info(*out.high_drift).order >= method_info(*out.low_bounded).order;
  return out;
}

std::string symmetry_note(const LongTimeResult& r) {
  return sides(r).not_by_order ? " Whether symmetry alone would do (the trapezoidal rule: symmetric, not symplectic) is not "
                                 "measured: every symmetric method here is symplectic too."
                               : "";
}

std::string structure_answer(const LongTimeResult& r, Ledger* l, const std::string& id, const std::string& section) {
  const LongTimeSides s = sides(r);
  const auto items = [](const std::vector<std::size_t>& ms) {
    std::vector<std::string> out;
    for (std::size_t m : ms)
      out.push_back(fmt::format("`{}` ({}order {})", name(m), method_info(m).symplectic ? "symplectic, " : "", method_info(m).order));
    return out.empty() ? std::string("none") : and_list(out);
  };
  std::string md = fmt::format("Bounded energy error (growth exponent's interval below 0.5): {}. Drifting (interval above 0.5): {}.",
                               items(s.bounded), items(s.drifting));
  if (!s.unclear.empty()) md += fmt::format(" Neither (interval across 0.5): {}.", items(s.unclear));
  std::vector<std::string> lost;
  for (const LongTimeRow& row : r.rows)
    if (std::find(s.lost.begin(), s.lost.end(), row.method) != s.lost.end()) lost.push_back(fmt::format("`{}` ({})", name(row.method), fate(row)));
  if (!lost.empty())
    md += fmt::format(" Lost the {} (energy error {:g} or more, or the run ended): {}.", r.has_exact ? "orbit" : "swing", kLostAt,
                      and_list(lost));
  if (s.not_by_order)
    md += fmt::format(" The bounded ones are the symplectic ones, whatever the order: `{}` of order {} drifts while `{}` of order {} "
                      "stays bounded, so the order does not decide it.",
                      name(*s.high_drift), method_info(*s.high_drift).order, name(*s.low_bounded), method_info(*s.low_bounded).order);
  else if (s.by_structure)
    md += " Every bounded one is symplectic and every drifting one is not.";
  if (l) claim_long_time_sides(*l, r, s, section, id, section, md);
  return md;
}

namespace {

std::string g2(double x) { return std::isfinite(x) ? fmt::format("{:.2g}", x) : "-"; }

class LongTime : public Section {
 public:
  std::string title() const override { return "Stable for how long? Energy, angular momentum and phase over many periods"; }
  std::string brief(Page& page) const override { return brief_markdown(title(), answer_paragraph(page.data.long_time_orbit.rows.empty() ? std::string() : long_time_answer(page))); }
  std::string missing(const ReportConfig& c) const override {
    return uncovered(c, {scene_index(kLongTimeScene), scene_index(kLongTimeSheetScene)});
  }
  unsigned needs() const override { return kLongTimeStudy; }
  void study(const ReportData& d) override { orbit_ = d.long_time_orbit, swing_ = d.long_time_swing; }
  void write_data(const ReportData&, const DataDir& dat) const override {
    dat.write(fmt::format("long_time_{}.json", scene_name(orbit_.config.scene)), long_time_json(orbit_).dump(1) + "\n");
    dat.write(fmt::format("long_time_{}.json", scene_name(swing_.config.scene)), long_time_json(swing_).dump(1) + "\n");
    write_long_time_data(orbit_, dat);
    write_long_time_data(swing_, dat);
  }
  std::vector<FigureSpec> figures(const ReportData& d) const override {
    std::vector<Panel> drawn = panels(d.methods);
    if (drawn.empty()) return {};
    return {{"long_time", fmt::format("prefix='lt_{}_'; col=2; ylab='largest relative energy error up to t'", scene_name(orbit_.config.scene)),
             std::move(drawn)}};
  }

  std::string markdown(Page& page) const override {
    const LongTimeConfig& c = orbit_.config;
    std::string md = fmt::format("## {}\n\n", title());
    if (page.ledger) {
      page.ledger->theory("long_time", "On the linear spring a method's energy is a quadratic form its step maps exactly: it damps, "
                                       "stays bounded or grows geometrically, and nothing else can happen.");
      page.ledger->theory("long_time", "The position error's growth exponent, theory: 1 for symplectic and symmetric methods, 2 "
                                       "otherwise (Hairer, Lubich and Wanner, ch. X).");
    }
    md += fmt::format(
        "On the linear spring a method's energy is a quadratic form its step maps exactly: it damps, stays bounded or grows "
        "geometrically, and nothing else can happen. A nonlinear system asks more: whether a bounded error stays bounded where "
        "no such form is kept. {} ({}, {} steps a period) and the sheet's spring swinging in a plane ({}, {} steps a period) run "
        "for {:g} periods with each method; every step's energy (and the orbit's angular momentum) is read, and the largest "
        "relative error up to t is fitted against t on log-log axes from {:g} periods on: the growth exponent with its 95 % "
        "interval (near 0: bounded; near 1: a drift linear in t; near 0.5: round-off's random walk).\n\n",
        scene_kernel(c.scene).title, params_text(c.scene, c.params), c.steps_per_period.front(),
        params_text(swing_.config.scene, swing_.config.params), swing_.config.steps_per_period.front(), c.periods, c.fit_from);
    md += fmt::format("- **{}.** {}\n- **The swinging spring.** {}\n", scene_kernel(c.scene).title, structure_answer(orbit_, page.ledger, "long_time.orbit", "long_time"),
                      structure_answer(swing_, page.ledger, "long_time.swing", "long_time") + symmetry_note(swing_));
    md += angular_momentum(page.ledger) + phase() + crossing() + "\n";
    if (!panels(page.data.methods).empty())
      md += page.figure("long_time", fmt::format("{}, {} steps a period: the largest relative energy error up to t (in "
                                               "periods), a panel per family. {}",
                                               scene_kernel(c.scene).title, c.steps_per_period.front(),
                                               extremes_sentence(orbit_, page.ledger, "long_time")));
    md += table();
    return md;
  }

 private:
  LongTimeResult orbit_, swing_;

  // A panel per family, of the methods with samples to draw (none where every run ended at once).
  std::vector<Panel> panels(const std::vector<std::size_t>& methods) const {
    return family_panels(methods, [&](std::size_t m) {
      return std::any_of(orbit_.rows.begin(), orbit_.rows.end(), [&](const LongTimeRow& r) { return r.method == m && !r.times.empty(); });
    });
  }

  // The first sample from which the growth is fitted (fit_from periods): "early" in a long run.
  std::size_t early_sample() const {
    for (const LongTimeRow& row : orbit_.rows)
      for (std::size_t k = 0; k < row.times.size(); ++k)
        if (row.times[k] >= orbit_.config.fit_from * (1 - 1e-12)) return k;
    return 0;
  }

  // Angular momentum (the orbit's second invariant) kept to round-off, against the symplectic claim.
  std::string angular_momentum(Ledger* l) const {
    if (orbit_.invariants.size() < 2) return {};
    std::vector<std::size_t> keep;
    double others = INFINITY;
    for (const LongTimeRow& row : orbit_.rows) {
      if (row.status != RunStatus::Ok || row.error.size() < 2) continue;
      if (row.round_off[1]) keep.push_back(row.method);
      else others = std::min(others, row.error[1].back());
    }
    const double floor2 = two_digits(others, false);  // "by X or more": a lower bound as printed
    const std::string md = fmt::format("- **Angular momentum** stays within round-off ({:g} u sqrt(steps)) with {}; every other method "
                                       "that kept running changed it by {} or more.\n",
                                       kRoundOff, method_list(keep), g2(floor2));
    if (l) {
      const std::string file = cite_long_time(*l, orbit_, "long_time");
      const std::string inv = "/invariants/" + orbit_.invariants[1];
      claim_members(*l, claim_text("long_time.angular_momentum.round_off", "long_time", md), file, "/rows", Json::object(), "method",
                    true, test_all({test_field("/status", "==", "ok"), test_field(inv + "/round_off", "==", true)}), method_names(keep));
      std::vector<std::size_t> rest;  // the others that kept running: changed by `others` or more
      for (const LongTimeRow& row : orbit_.rows)
        if (row.status == RunStatus::Ok && row.error.size() >= 2 && !row.round_off[1]) rest.push_back(row.method);
      if (!rest.empty())
        claim_members(*l, claim_text("long_time.angular_momentum.changed", "long_time", md), file, "/rows", Json::object(), "method",
                    true, test_all({test_field("/status", "==", "ok"), test_field(inv + "/round_off", "==", false),
                                    test_field(inv + "/error_at_end", ">=", floor2)}),
                    method_names(rest));
    }
    return md;
  }

  // The phase: the position error's growth exponent, symplectic methods against the others.
  std::string phase() const {
    std::vector<std::string> sym, other;
    for (const LongTimeRow& row : orbit_.rows)
      if (row.position_growth.fitted)
        (method_info(row.method).symplectic ? sym : other)
            .push_back(fmt::format("`{}` {:.2f}", name(row.method), row.position_growth.exponent));
    if (sym.empty() && other.empty()) return {};
    return fmt::format("- **The phase.** The position error's growth exponent (fitted while below a tenth of the orbit's size; theory: "
                       "1 for symplectic and symmetric methods, 2 otherwise): symplectic {}; the others {}.\n",
                       sym.empty() ? "none" : and_list(sym), other.empty() ? "none" : and_list(other));
  }

  // A non-symplectic method ahead early and behind at the end of a symplectic one: the pair
  // whose order changes most.
  std::string crossing() const {
    const LongTimeRow *best_a = nullptr, *best_b = nullptr;
    double best = 1;
    const std::size_t early = early_sample();
    for (const LongTimeRow& a : orbit_.rows)
      for (const LongTimeRow& b : orbit_.rows) {
        if (method_info(a.method).symplectic || !method_info(b.method).symplectic || energy_verdict(a, kLostAt) == EnergyVerdict::Lost ||
            energy_verdict(b, kLostAt) == EnergyVerdict::Lost)
          continue;
        if (a.times.size() != b.times.size() || early >= a.times.size() || a.error[0][early] >= b.error[0][early] || a.error[0].back() <= b.error[0].back()) continue;
        const double swing = (a.error[0].back() / b.error[0].back()) * (b.error[0][early] / a.error[0][early]);
        if (swing > best) best = swing, best_a = &a, best_b = &b;
      }
    if (!best_a) return {};
    return fmt::format("- **Short runs mislead.** After {:g} periods `{}` (order {}) has the smaller energy error, {} against `{}`'s {} "
                       "(order {}); after {:g} periods it has the larger, {} against {}.\n",
                       best_a->times[early], name(best_a->method), method_info(best_a->method).order, g2(best_a->error[0][early]),
                       name(best_b->method), g2(best_b->error[0][early]), method_info(best_b->method).order, best_a->times.back(),
                       g2(best_a->error[0].back()), g2(best_b->error[0].back()));
  }

  std::string table() const {
    // the rule's dashes set pandoc's column widths: the method names and the intervals whole on a line
    std::string md = "\n| method | order | sym. | energy growth, orbit | energy error | ang. mom. error | phase growth | out of phase "
                     "(periods) | energy growth, swing |\n|------------------|---|----|----------------|-------|---------|--------------|---------|"
                     "----------------|\n";
    for (const LongTimeRow& row : orbit_.rows) {
      const MethodInfo& i = method_info(row.method);
      const LongTimeRow* sw = nullptr;
      for (const LongTimeRow& s : swing_.rows)
        if (s.method == row.method) sw = &s;
      const bool ok = row.status == RunStatus::Ok && !row.error.empty() && !row.error[0].empty();
      const std::string blew = row.status == RunStatus::Ok ? "-" : fmt::format("{} at {:.3g}", stop_words(row), row.ended);
      // an error that has saturated (the orbit lost) grows no more: its exponent is no measure
      const auto growth = [](const LongTimeRow& r) {
        return energy_verdict(r, kLostAt) == EnergyVerdict::Lost ? std::string("lost") : growth_text(r.growth[0]);
      };
      md += fmt::format("| `{}` | {} | {} | {} | {} | {} | {} | {} | {} |\n", i.name, i.order, i.symplectic ? "yes" : "no",
                        ok ? growth(row) : blew, ok ? fmt::format("{}{}", g2(row.error[0].back()), row.round_off[0] ? " (R)" : "") : "-",
                        ok && row.error.size() > 1 ? fmt::format("{}{}", g2(row.error[1].back()), row.round_off[1] ? " (R)" : "") : "-",
                        growth_text(row.position_growth),
                        row.out_of_phase > 0 ? fmt::format("{:.3g}{}", row.out_of_phase, row.out_of_phase_extrapolated ? " (extr.)" : "") : "-",
                        sw && sw->status == RunStatus::Ok ? growth(*sw) : sw ? fmt::format("{} at {:.3g}", stop_words(*sw), sw->ended) : "-");
    }
    return md + fmt::format("\nGrowth: exponent [95 % interval] from {:g} periods on; lost: energy error {:g} or more, where the error has "
                            "saturated and its exponent measures nothing. Sym.: symplectic. (R): within round-off's level. Out of phase: when the "
                            "position error reaches the orbit's semi-major axis ({}: extrapolated from the fitted growth past the run).\n\n",
                            orbit_.config.fit_from, kLostAt, "extr.");
  }
};

}  // namespace

std::unique_ptr<Section> make_long_time_section() { return std::make_unique<LongTime>(); }

}  // namespace steplab
