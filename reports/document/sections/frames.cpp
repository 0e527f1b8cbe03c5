// At a frame budget: "substeps or sweeps, XPBD or large steps, at what cost a frame?" The
// frame-budget study (analysis/studies/frames.hpp) on its rope (section `frames`) and on the cloth
// (section `cloth`, analysis/studies/defaults.hpp), every method on springs at each split of the
// budget and the ODE methods at the same substeps; the position-based family's answer to the
// sheet's "is stability correlated with the order?". On the cloth also the cheapest set-up within
// 1 % of its size and a picture of it at three frames. Every sentence is computed from the runs.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/defaults.hpp"
#include "analysis/studies/frames.hpp"
#include "reports/studies/studies.hpp"
#include "reports/document/claims.hpp"
#include "reports/document/report_text.hpp"
#include "reports/document/section.hpp"
#include "reports/document/sections/cloth.hpp"

namespace steplab {
namespace {

std::string g3(double x) { return std::isfinite(x) ? fmt::format("{:.3g}", x) : "-"; }

class Frames : public Section {
 public:
  explicit Frames(bool cloth) : cloth_(cloth) {}
  std::string title() const override {
    return cloth_ ? "At a frame budget on cloth: where the springs turn" : "At a frame budget: substeps or sweeps, XPBD or large steps";
  }
  std::string missing(const ReportConfig& c) const override { return uncovered(c, {config().scene}); }
  void study(const ReportData& d) override {
    FramesConfig c = config();
    // The cloth's set-ups untimed: no verdict rests on time (the fronts and the cheapest set-ups
    // are drawn against spring visits), and timing its 48 would add 27 s to the report.
    c.timing = d.config.timing && !cloth_;
    c.workers = d.workers;
    r_ = frames_study(c);
    if (cloth_) {
      picture_ = cloth_picture(r_);
      rope_ = rope_xpbd_study(c, d.workers);
    }
  }

  void write_data(const ReportData&, const DataDir& dat) const override {
    dat.write("frames.json", frames_json(r_).dump(1) + "\n");
    for (std::size_t m : r_.config.methods) {
      std::string s = "# substeps sweeps_or_cg seconds_per_frame spring_visits_per_frame error_max stretch energy_lost_per_s\n";
      for (const FrameRun& run : runs_of(m))
        if (run.stable)
          s += fmt::format("{} {} {} {} {} {} {}\n", run.setup.substeps, setting(run.setup), num(run.seconds), num(run.spring_visits),
                           num(run.error), num(run.stretch), num(run.energy_lost));
      dat.write(fmt::format("frames_{}.dat", name(m)), s);
    }
    write_picture(picture_, dat);
    if (cloth_) dat.write("rope_xpbd.json", frames_json(rope_).dump(1) + "\n");
  }

  std::vector<FigureSpec> figures(const ReportData&) const override {
    std::vector<std::string> drawn;
    for (std::size_t m : r_.config.methods)
      if (std::any_of(r_.runs.begin(), r_.runs.end(), [&](const FrameRun& x) { return x.setup.method == m && x.stable; }))
        drawn.push_back(name(m));
    if (drawn.empty()) return {};
    const bool timed = r_.config.timing;
    std::vector<FigureSpec> out{{"frames", fmt::format("xcol={}; xname='{}'", timed ? 3 : 4, timed ? "time a frame (s)" : "spring visits a frame"),
                                 {{"error against cost a frame", drawn}}, figure_name()}};
    if (!picture_.drawn.empty()) out.push_back(picture_figure(picture_, r_));
    return out;
  }

  std::string markdown(Page& page) const override {
    const FramesConfig& c = r_.config;
    std::string md = "## " + title() + "\n\n";
    md += fmt::format(
        "A simulator shows the {} of {} springs ({}) at {} frames a second for {} s and has a budget of {} sweeps (or CG "
        "iterations) a frame to spend: on one substep of {} sweeps, {} substeps of one sweep, or any split between. Each method on springs runs at "
        "every split (XPBD and PBD: sweeps a substep; Baraff-Witkin: CG iterations), each ODE method at the same substeps. The "
        "error is the largest position error over the frames against the {}, which moves at most {} m from its start (a "
        "run at rest has that error); the stretch how much more (relative elongation) its springs give than the reference's "
        "at the same frame.\n\n",
        scene_name(c.scene), r_.springs, params_text(c.scene, c.params), c.fps, c.t_end, c.budget, c.budget, c.budget,
        scene_kernel(c.scene).exact ? "exact motion" : "reference", g3(r_.motion));
    if (page.ledger) page.ledger->document(doc(), [&] { return frames_json(r_); });
    md += splits("xpbd", page.ledger);
    if (const std::string contrast = cloth_ ? xpbd_contrast(page.ledger, {r_, id, doc()}, rope_, rope_doc()) : ""; !contrast.empty())
      md += "  " + contrast + "\n";  // the xpbd item's second sentence
    md += splits("pbd", page.ledger);
    md += large_steps();
    md += stability(page.ledger);
    md += fronts(page.ledger);
    const auto stable = [](const FrameRun& run) { return run.stable && run.status == RunStatus::Ok; };
    const FrameRun* best = least_and_most(r_.runs, stable, &FrameRun::error).first;  // the least error of a stable split
    constexpr Digits kError{true, 3};
    const std::string least = best ? fmt::format("The least error, {}, is `{}`'s at {} substeps a frame.", printed(best->error, kError),
                                                 name(best->setup.method), best->setup.substeps)
                                   : std::string("No split is stable.");
    md += page.figure(figure_key(), fmt::format("Error against cost a frame ({}), {} at {} frames a second: each method's splits of "
                                            "the budget {}, the stable ones. {}",
                                            c.timing ? "time" : "spring visits", scene_name(c.scene), c.fps, c.budget, least));
    if (page.ledger && best) {  // over the stable splits
      const Kept errors = kept_evidence(r_.runs, stable, best, nullptr, [&](const FrameRun&, std::size_t i) {
        return page.ledger->at(doc(), fmt::format("/runs/{}/error_max", i));
      });
      claim_extreme(*page.ledger, claim_text(id + ".least_error", id, least), errors.values, errors.least, Extreme::Least, kError);
    }
    if (!picture_.drawn.empty()) md += picture_markdown(page, picture_, r_, id, doc());
    md += family_answer();
    return md;
  }

  std::string brief(Page& page) const override {
    const std::string answer = as_accurate(page.ledger) + (cloth_ ? visual_target(page.ledger, {r_, id, doc()}) : std::string());
    if (cloth_)
      return brief_markdown(title(), fmt::format("On the {} of {} springs, falling from flat and swinging for {} s, at {} frames a second "
                                                 "and the same budget of {} sweeps a frame. {}{}",
                                                 scene_name(r_.config.scene), r_.springs, r_.config.t_end, r_.config.fps,
                                                 r_.config.budget, answer,
                                                 xpbd_contrast(page.ledger, {r_, id, doc()}, rope_, rope_doc()) + " " +
                                                     implicit_euler_one_substep()));
    return brief_markdown(title(), fmt::format("At {} frames a second on the {} of {} springs, with a budget of {} sweeps a frame (a "
                                               "sweep projects every spring once; XPBD and PBD split the budget between substeps and "
                                               "sweeps a substep, the ODE methods spend it on substeps). {}",
                                               r_.config.fps, scene_name(r_.config.scene), r_.springs, r_.config.budget, answer));
  }

 private:
  bool cloth_;
  FramesResult r_;
  ClothPicture picture_;
  FramesResult rope_;  // the cloth's: XPBD on the rope at the same budget (rope_xpbd_study)

  FramesConfig config() const { return cloth_ ? cloth_frames_config() : default_frames_config(); }
  std::string doc() const { return id + "/frames.json"; }
  std::string rope_doc() const { return id + "/rope_xpbd.json"; }
  std::string figure_name() const { return cloth_ ? id + "_frames" : std::string(); }
  std::string figure_key() const { return FigureSpec{"frames", {}, {}, figure_name()}.key(); }

  // The fitted order with the slopes between neighbouring substeps, log2(e_k / e_k+1): "0.35, 1.25,
  // 1.31" fits 1.00 but has not reached it (slopes that differ by more than kSettled: the next
  // error term still counts, pre-asymptotic); a slope near 0 does not converge.
  static constexpr double kSettled = 0.2;
  static std::string order_cell(const FrameOrder& o) {
    if (std::abs(o.order) < 0.2) return fmt::format("{:.2f}: does not converge", o.order);
    std::vector<std::string> slopes;
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t k = 0; k + 1 < o.errors.size(); ++k) {
      const double p = std::log2(o.errors[k] / o.errors[k + 1]);
      slopes.push_back(fmt::format("{:.2f}", p));
      lo = std::min(lo, p), hi = std::max(hi, p);
    }
    return fmt::format("{:.2f} ({}){}", o.order, fmt::join(slopes, ", "), hi - lo > kSettled ? ", pre-asymptotic" : "");
  }

  std::vector<FrameRun> runs_of(std::size_t m) const {
    std::vector<FrameRun> out;
    for (const FrameRun& x : r_.runs)
      if (x.setup.method == m) out.push_back(x);
    return out;
  }
  std::vector<FrameRun> runs_of(std::string_view n) const {
    const auto m = find_method(n);
    return m && std::find(r_.config.methods.begin(), r_.config.methods.end(), *m) != r_.config.methods.end() ? runs_of(*m)
                                                                                                          : std::vector<FrameRun>{};
  }
  static int setting(const FrameSetup& s) {
    return takes_sweeps(method_info(s.method)) ? s.settings.sweeps : takes_cg(method_info(s.method)) ? s.settings.cg_iterations : 0;
  }

  // Substeps against sweeps for one method: its two ends, and whether the error falls at each split.
  std::string splits(std::string_view n, Ledger* l) const {
    const std::vector<FrameRun> runs = runs_of(n);  // by substeps, ascending
    if (runs.size() < 2 || !runs.front().stable || !runs.back().stable) return {};
    const FrameRun &one = runs.front(), &many = runs.back();
    bool falls = true;
    for (std::size_t k = 1; k < runs.size(); ++k) falls = falls && runs[k].stable && runs[k].error < runs[k - 1].error;
    const double ratio = one.error / many.error;
    const std::string md = fmt::format(
        "- `{}`: {} a frame has error {} and stretch {}; {} has error {} and stretch {}: {} substeps of one sweep are {} "
        "({:.3g}x){}.\n",
        n, frame_setup_text(one.setup), g3(one.error), g3(one.stretch), frame_setup_text(many.setup), g3(many.error),
        g3(many.stretch), many.setup.substeps, ratio > 1 ? "more accurate" : "less accurate", ratio > 1 ? ratio : 1 / ratio,
        falls ? ", and the error falls at every split in between" : "; the error does not fall at every split");
    if (l && falls) {  // the error along the splits, by substeps: each one below the last (no two the same)
      Claim c = claim_text(fmt::format("{}.splits.{}", id, n), id, md);
      c.kind = "trend";
      Json along = Json::array();
      for (std::size_t i = 0; i < r_.runs.size(); ++i)  // runs_of's runs, in its order, by their index in frames.json
        if (r_.runs[i].setup.method == runs.front().setup.method) {
          along.push_back(frame_setup_text(r_.runs[i].setup));
          c.evidence.push_back(l->at(doc(), fmt::format("/runs/{}/error_max", i)));
        }
      c.rule = {{"along", std::move(along)}, {"relative", 0}, {"trend", "falls"}};
      l->add(std::move(c));
    }
    return md;
  }

  // Where implicit Euler at one substep a frame is not stable: what it does there, and from how
  // many substeps it is stable ("" where it is stable at one).
  std::string implicit_euler_one_substep() const {
    const std::vector<FrameRun> ie = runs_of("implicit_euler");
    if (ie.empty() || ie.front().stable) return {};
    const auto from = std::find_if(ie.begin(), ie.end(), [](const FrameRun& x) { return x.stable; });
    return fmt::format("Implicit Euler at one substep a frame {}{}.",
                       ie.front().status == RunStatus::NoConvergence ? "does not converge (its Newton iteration gives up)" : "is unstable",
                       from == ie.end() ? std::string(", nor at any split") : fmt::format(", and is stable from {}", frame_setup_text(from->setup)));
  }

  std::string large_steps() const {
    const std::vector<FrameRun> bw = runs_of("baraff_witkin"), ie = runs_of("implicit_euler");
    if (bw.empty() || ie.empty() || !bw.front().stable) return {};
    const std::string bw_one = fmt::format("- `baraff_witkin` (one Newton step of implicit Euler, solved by CG): {} has error {}",
                                           frame_setup_text(bw.front().setup), g3(bw.front().error));
    if (!ie.front().stable) return fmt::format("{}. {}\n\n", bw_one, implicit_euler_one_substep());
    return fmt::format("{}, implicit Euler's step at one substep (factorised) {}; with fewer CG iterations on more substeps ({}) "
                       "the error is {}.\n\n", bw_one, g3(ie.front().error),
                       frame_setup_text(bw.back().setup), g3(bw.back().error));
  }

  std::string stability(Ledger* l) const {
    std::vector<std::size_t> every, some, none;
    for (std::size_t m : r_.config.methods) {
      const std::vector<FrameRun> runs = runs_of(m);
      const auto stable = std::count_if(runs.begin(), runs.end(), [](const FrameRun& x) { return x.stable; });
      (stable == static_cast<long>(runs.size()) ? every : stable == 0 ? none : some).push_back(m);
    }
    std::string md = fmt::format("Stable at every split: {}.", method_list(every));
    if (!some.empty()) {
      std::vector<std::string> from;
      for (std::size_t m : some)
        for (const FrameRun& x : runs_of(m))
          if (x.stable) {
            from.push_back(fmt::format("`{}` from {} substeps", name(m), x.setup.substeps));
            break;
          }
      md += fmt::format(" Stable only with enough substeps: {}.", and_list(from));
    }
    if (!none.empty()) md += fmt::format(" Unstable at every split: {}.", method_list(none));
    if (l) {  // which methods have a stable run and which an unstable one: every, some and none between them
      std::vector<std::string> with_stable = method_names(every), with_unstable = method_names(none);
      for (std::size_t m : some) with_stable.push_back(name(m)), with_unstable.push_back(name(m));
      claim_members(*l, claim_text(id + ".stable_runs", id, md), doc(), "/runs", Json::object(), "method", true,
                    test_field("/stable", "==", true), with_stable);
      claim_members(*l, claim_text(id + ".unstable_runs", id, md), doc(), "/runs", Json::object(), "method", true,
                    test_field("/stable", "==", false), with_unstable);
    }
    return md + "\n\n";
  }

  // "runs[i] is the least of `among` by `field`" (others ascending; tied where the next is equal).
  void least(Ledger* l, std::string claim_id, std::string sentence, std::size_t i, std::vector<std::size_t> among, const char* field) const {
    if (l) claim_least_run(*l, {r_, id, doc()}, std::move(claim_id), std::move(sentence), i, std::move(among), field);
  }
  std::string cost(const FrameRun& x) const { return frame_cost_text(r_, x); }

  // The cheapest set-up of all that reaches the error of the most accurate position-based one,
  // claimed; "" where none does.
  // Where that error is not below the body's motion, a run at rest meets it: no set-up is the
  // cheapest, and the sentence says so instead.
  std::string as_accurate(Ledger* l) const {
    double target = INFINITY;
    std::size_t at_target = 0;
    for (std::size_t i = 0; i < r_.runs.size(); ++i)
      if (const FrameRun& x = r_.runs[i]; x.stable && method_info(x.setup.method).family == Family::PositionBased && x.error < target)
        target = x.error, at_target = i;
    const auto at = [&](const std::string& pointer) {
      l->document(doc(), [&] { return frames_json(r_); });
      return l->at(doc(), pointer);
    };
    if (std::isfinite(target) && target >= r_.motion) {
      const std::string sentence = fmt::format(
          "The best position-based set-up's error, {}, is not below how far the {} moves from its start, {}, so a {} at "
          "rest meets it: no set-up is the cheapest to reach it.",
          g3(target), scene_name(r_.config.scene), g3(r_.motion), scene_name(r_.config.scene));
      if (l)
        claim_group(*l, claim_text(id + ".as_accurate.at_rest", id, sentence),
                    comparison_group(at("/motion"), {at(fmt::format("/runs/{}/error_max", at_target))},
                                     target == r_.motion ? "tie" : "less", 1.0));
      return sentence + "\n\n";
    }
    std::vector<std::size_t> reach;  // the stable set-ups as accurate as that
    for (std::size_t i = 0; i < r_.runs.size(); ++i)
      if (r_.runs[i].stable && r_.runs[i].error <= target) reach.push_back(i);
    const auto best = std::min_element(reach.begin(), reach.end(), [&](std::size_t a, std::size_t b) {
      const double ca = frame_cost(r_.runs[a]), cb = frame_cost(r_.runs[b]);
      return ca != cb ? ca < cb : r_.runs[a].error < r_.runs[b].error;
    });
    if (best == reach.end() || !std::isfinite(target)) return {};
    const FrameRun& b = r_.runs[*best];
    const std::string sentence = fmt::format("The cheapest set-up as accurate as the best position-based one (error {}): `{}` {}, {}.",
                                             g3(target), name(b.setup.method), frame_setup_text(b.setup), cost(b));
    if (l)  // the error it reaches is below the motion
      claim_group(*l, claim_text(id + ".as_accurate.moves", id, sentence),
                  comparison_group(at(fmt::format("/runs/{}/error_max", at_target)), {at("/motion")}, "less", 1.0));
    least(l, id + ".as_accurate", sentence, *best, reach, "spring_visits_per_frame");
    return sentence + "\n\n";
  }

  // Each family's cheapest stable set-up and its most accurate, and the cheapest set-up of all that
  // reaches the error of the most accurate position-based one; each a claim. The cost is the spring
  // visits a frame (frame_cost: a count, the same on every machine), the time beside it.
  std::string fronts(Ledger* l) const {
    const auto stable_of = [&](Family f) {
      std::vector<std::size_t> out;
      for (std::size_t i = 0; i < r_.runs.size(); ++i)
        if (r_.runs[i].stable && method_info(r_.runs[i].setup.method).family == f) out.push_back(i);
      return out;
    };
    std::string md = "| family | cheapest stable set-up | its error | most accurate on the front | its error |\n|---|---|---|---|---|\n";
    for (const FamilyFront& f : r_.fronts) {
      const FrameRun &lo = r_.runs[f.runs.front()], &hi = r_.runs[f.runs.back()];
      const std::string row = fmt::format("| {} | `{}` {}, {} | {} | `{}` {}, {} | {} |\n", to_string(f.family), name(lo.setup.method),
                                          frame_setup_text(lo.setup), cost(lo), g3(lo.error), name(hi.setup.method),
                                          frame_setup_text(hi.setup), cost(hi), g3(hi.error));
      least(l, fmt::format("{}.cheapest.{}", id, id_word(to_string(f.family))), row, f.runs.front(), stable_of(f.family),
            "spring_visits_per_frame");
      least(l, fmt::format("{}.most_accurate.{}", id, id_word(to_string(f.family))), row, f.runs.back(), stable_of(f.family), "error_max");
      md += row;
    }
    md += "\n" + as_accurate(l) + (cloth_ ? visual_target(l, {r_, id, doc()}) : std::string());
    md += "The cost is the spring visits a frame, the same on every machine: a projection visits one spring; a force evaluation, "
          "a Jacobian, a factorisation, a linear solve or a CG product all of them (each a pass over the springs). A set-up is on its family's front where none of the family with as many visits or fewer has a smaller error; "
          "of set-ups with the same visits (every split of the budget of XPBD or PBD) the most accurate stands for them."
          + std::string(r_.config.timing ? " The time a frame stands beside it: a verdict on it would change with the machine's load.\n\n"
                                         : "\n\n");
    return md;
  }

  // The position-based family (and the large steps) in the families' terms: order in h, stable at
  // every step tried, energy; and the sheet's question for them.
  std::string family_answer() const {
    const std::string scene(scene_name(r_.config.scene));
    std::string md = r_.orders.empty() ? std::string() : fmt::format(
                     "\nThe methods on springs in the families' terms, on this {} with their settings fixed (order: the slope "
                     "of the error against h with the substeps doubled from 128 to 1024 a frame, and the slopes between "
                     "neighbours; pre-asymptotic where those differ by more than 0.2, the order not yet reached; stable: at "
                     "every split tried; energy: lost per second against the reference by the budget's split with the same "
                     "settings, negative where it gained):\n\n"
                     "| method | settings | order in h (slopes) | stable at every split | energy lost per second |\n|---|---|---|---|---|\n", scene);
    for (const FrameOrder& o : r_.orders) {
      const std::vector<FrameRun> runs = runs_of(o.setup.method);
      const bool every = std::all_of(runs.begin(), runs.end(), [](const FrameRun& x) { return x.stable; });
      const auto same = std::find_if(runs.begin(), runs.end(), [&](const FrameRun& x) { return setting(x.setup) == setting(o.setup); });
      md += fmt::format("| `{}` | {} | {} | {} | {} |\n", name(o.setup.method), frame_settings_text(o.setup), order_cell(o),
                        every ? "yes" : "no", same == runs.end() ? "-" : g3(same->energy_lost));
    }
    // Stability against order, over the methods of the study: stable at every split or not, with each one's order.
    std::vector<std::string> stable, unstable;
    bool stable_solve = true, unstable_explicit = true;  // each stable one solves its springs; each unstable one does not
    int stable_top = 0, unstable_top = 0;                // the highest order on each side
    for (std::size_t m : r_.config.methods) {
      const std::vector<FrameRun> runs = runs_of(m);
      const bool every = std::all_of(runs.begin(), runs.end(), [](const FrameRun& x) { return x.stable; });
      const MethodInfo& i = method_info(m);
      const bool solves = i.implicit || i.on_springs;
      (every ? stable : unstable).push_back(fmt::format("`{}` ({})", i.name, i.converges ? fmt::format("order {}", i.order) : "no order"));
      (every ? stable_solve : unstable_explicit) = (every ? stable_solve && solves : unstable_explicit && !solves);
      (every ? stable_top : unstable_top) = std::max(every ? stable_top : unstable_top, i.order);
    }
    md += fmt::format("\nIs stability correlated with the order here? Stable at every split: {}; not: {}.",
                      stable.empty() ? "none" : and_list(stable), unstable.empty() ? "none" : and_list(unstable));
    if (!stable.empty() && !unstable.empty() && stable_solve && unstable_explicit)
      md += fmt::format(" Every stable one solves for its springs at the step's end (a constraint projection or a linear system) "
                        "and every unstable one evaluates them at known states; {}.",
                        unstable_top > stable_top ? fmt::format("the unstable side has the higher orders. On this {} the "
                                                                "solve separates them and the order does not; with {} explicit "
                                                                "method{} on the unstable side, that is this {}'s answer, "
                                                                "not a rule", scene, unstable.size(), unstable.size() == 1 ? "" : "s", scene)
                                                  : std::string("the order does not separate them either way"));
    return md + "\n\n";
  }
};

}  // namespace

std::unique_ptr<Section> make_frames_section() { return std::make_unique<Frames>(false); }
std::unique_ptr<Section> make_cloth_section() { return std::make_unique<Frames>(true); }

}  // namespace steplab
