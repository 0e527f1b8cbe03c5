#include "reports/document/sections/cloth.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "reports/studies/studies.hpp"
#include "reports/document/claims.hpp"
#include "reports/document/report_text.hpp"

namespace steplab {

void claim_least_run(Ledger& l, const FramesCited& c, std::string claim_id, std::string sentence, std::size_t i,
                     std::vector<std::size_t> among, const char* field) {
  const auto value = [&](std::size_t k) { return field == std::string("error_max") ? c.r.runs[k].error : frame_cost(c.r.runs[k]); };
  std::erase(among, i);
  std::stable_sort(among.begin(), among.end(), [&](std::size_t a, std::size_t b) { return value(a) < value(b); });
  const auto at = [&](std::size_t k) { return l.at(c.document, fmt::format("/runs/{}/{}", k, field)); };
  std::vector<Evidence> others;
  for (std::size_t k : among) others.push_back(at(k));
  const bool tie = !among.empty() && value(among.front()) == value(i);
  claim_group(l, claim_text(std::move(claim_id), c.section, std::move(sentence)),
              comparison_group(at(i), std::move(others), tie ? "tie" : "less", 1.0));
}

std::string frame_cost_text(const FramesResult& r, const FrameRun& x) {
  return r.config.timing ? fmt::format("{:.4g} spring visits a frame ({:.3g} µs)", x.spring_visits, 1e6 * x.seconds)
                         : fmt::format("{:.4g} spring visits a frame", x.spring_visits);
}

std::string visual_target(Ledger* l, const FramesCited& c) {
  const FramesResult& r_ = c.r;
  const std::string& id = c.section;
  const double target = kVisualTarget * r_.extent;
  const std::string scene(scene_name(r_.config.scene));
  const std::string within = fmt::format("within {:g} % of the {}'s size ({:.3g} m, an error the eye does not see)",
                                         100 * kVisualTarget, scene, target);
  if (target >= r_.motion) return {};  // a body at rest meets it
  std::vector<std::size_t> reach;
  for (std::size_t i = 0; i < r_.runs.size(); ++i)
    if (r_.runs[i].stable && r_.runs[i].error <= target) reach.push_back(i);
  const auto best = std::min_element(reach.begin(), reach.end(), [&](std::size_t a, std::size_t b) {
    const double ca = frame_cost(r_.runs[a]), cb = frame_cost(r_.runs[b]);
    return ca != cb ? ca < cb : r_.runs[a].error < r_.runs[b].error;
  });
  const auto at = [&](std::size_t i, const char* field) { return l->at(c.document, fmt::format("/runs/{}/{}", i, field)); };
  Claim above = claim_text(id + ".visual.cheaper_miss", id, {});
  above.kind = "threshold";
  above.rule = {{"op", ">"}, {"limit", target}};
  for (std::size_t i = 0; i < r_.runs.size() && l; ++i)  // the stable set-ups cheaper than the one named (all, where none)
    if (r_.runs[i].stable && (best == reach.end() || frame_cost(r_.runs[i]) < frame_cost(r_.runs[*best])))
      above.evidence.push_back(at(i, "error_max"));
  if (best == reach.end()) {
    above.sentence = fmt::format("No stable set-up is {}.", within);
    if (l && !above.evidence.empty()) l->add(above);
    return above.sentence + "\n\n";
  }
  const FrameRun& b = r_.runs[*best];
  above.sentence = fmt::format("The cheapest set-up {}: `{}` {}, {}, error {}.", within, method_info(b.setup.method).name,
                               frame_setup_text(b.setup), frame_cost_text(r_, b), fmt::format("{:.3g}", b.error));
  if (l) {
    if (!above.evidence.empty()) l->add(above);
    claim_group(*l, claim_text(id + ".visual.reaches", id, above.sentence),
                comparison_group(at(*best, "error_max"), {l->at(c.document, "/extent")}, "less", 1 / kVisualTarget));
    claim_least_run(*l, c, id + ".visual", above.sentence, *best, reach, "spring_visits_per_frame");
  }
  return above.sentence + "\n\n";
}

FramesResult rope_xpbd_study(const FramesConfig& cloth, const Workers& w) {
  FramesConfig c = default_frames_config();
  c.fps = cloth.fps, c.budget = cloth.budget;
  c.methods = {*find_method("xpbd")};
  c.timing = c.orders = false;
  c.workers = w;
  return frames_study(c);
}

std::string xpbd_contrast(Ledger* l, const FramesCited& cloth, const FramesResult& rope, const std::string& rope_document) {
  // XPBD's two ends in a study: its runs at one substep and at `budget`, by index
  const auto ends = [](const FramesResult& r) -> std::optional<std::pair<std::size_t, std::size_t>> {
    std::optional<std::size_t> one, many;
    for (std::size_t i = 0; i < r.runs.size(); ++i)
      if (method_info(r.runs[i].setup.method).name == "xpbd" && r.runs[i].stable) {
        if (r.runs[i].setup.substeps == 1) one = i;
        if (r.runs[i].setup.substeps == r.config.budget) many = i;
      }
    if (!one || !many) return std::nullopt;
    return std::pair{*one, *many};
  };
  const auto here = ends(cloth.r), there = ends(rope);
  if (!here || !there) return {};
  const double a = cloth.r.runs[here->first].error / cloth.r.runs[here->second].error;
  const double b = rope.runs[there->first].error / rope.runs[there->second].error;
  const std::string sentence = fmt::format(
      "XPBD gains {} from substeps here than on the {}: {} x 1 sweep is {:.3g} times as accurate as 1 x {} sweeps on the {}, "
      "{:.3g} times on the {} of {} springs at the same budget (the section before).",
      a < b ? "less" : "more", scene_name(rope.config.scene), cloth.r.config.budget, a, cloth.r.config.budget,
      scene_name(cloth.r.config.scene), b, scene_name(rope.config.scene), rope.springs);
  if (l) {
    l->document(rope_document, [&] { return frames_json(rope); });
    const auto ratio = [&](const std::string& doc, std::pair<std::size_t, std::size_t> e) {
      return Ratio{{l->at(doc, fmt::format("/runs/{}/error_max", e.first))}, {l->at(doc, fmt::format("/runs/{}/error_max", e.second))}};
    };
    claim_ratio(*l, claim_text(cloth.section + ".xpbd_contrast.here", cloth.section, sentence), ratio(cloth.document, *here), a,
                Digits{true, 3});
    claim_ratio(*l, claim_text(cloth.section + ".xpbd_contrast.rope", cloth.section, sentence), ratio(rope_document, *there), b,
                Digits{true, 3});
  }
  return sentence;
}

ClothPicture cloth_picture(const FramesResult& r) {
  ClothPicture p;
  const long long last = std::llround(r.config.t_end * r.config.fps);
  if (scene_kernel(r.config.scene).coords_per_mass != 3 || last < 3) return p;
  p.frames = {last / 3, 2 * last / 3, last};
  for (const FamilyFront& f : r.fronts) {
    p.runs.push_back(f.runs.front());
    p.drawn.push_back(std::string(method_info(r.runs[f.runs.front()].setup.method).name));
  }
  // The middle column: the masses whose rest x is nearest the middle of the sheet's x (the left
  // one of two equally near), by their rest y.
  const Eigen::VectorXd& rest = r.reference.front().x;
  const Eigen::Index masses = rest.size() / 3;
  double lo = INFINITY, hi = -INFINITY;
  for (Eigen::Index i = 0; i < masses; ++i) lo = std::min(lo, rest[3 * i]), hi = std::max(hi, rest[3 * i]);
  const double middle = 0.5 * (lo + hi);
  double nearest = INFINITY;
  for (Eigen::Index i = 0; i < masses; ++i)
    if (rest[3 * i] <= middle) nearest = std::min(nearest, middle - rest[3 * i]);
  std::vector<Eigen::Index> column;
  for (Eigen::Index i = 0; i < masses; ++i)
    if (rest[3 * i] <= middle && middle - rest[3 * i] <= nearest + 1e-12 * (hi - lo)) column.push_back(i);
  std::sort(column.begin(), column.end(), [&](Eigen::Index a, Eigen::Index b) { return rest[3 * a + 1] < rest[3 * b + 1]; });
  const auto profile = [&](const std::vector<AnyState>& states) {
    std::vector<std::vector<std::array<double, 2>>> out;
    for (long long k : p.frames) {
      out.emplace_back();
      if (static_cast<std::size_t>(k) >= states.size()) continue;  // the run ended early
      for (Eigen::Index i : column) out.back().push_back({states[k].x[3 * i + 1], states[k].x[3 * i + 2]});
    }
    return out;
  };
  p.profiles.push_back(profile(r.reference));
  for (std::size_t i : p.runs) p.profiles.push_back(profile(frame_states(r.config, r.runs[i].setup)));
  return p;
}

void write_picture(const ClothPicture& p, const DataDir& dat) {
  for (std::size_t c = 0; c < p.profiles.size(); ++c) {
    std::string s = "# y z of the middle column of masses, a block a frame drawn\n";
    for (const auto& frame : p.profiles[c]) {
      for (const auto& [y, z] : frame) s += fmt::format("{} {}\n", num(y), num(z));
      s += "\n\n";
    }
    dat.write(fmt::format("profile_{}.dat", c == 0 ? std::string("reference") : p.drawn[c - 1]), s);
  }
}

FigureSpec picture_figure(const ClothPicture& p, const FramesResult& r) {
  FigureSpec f{"cloth", {}, {}};
  for (long long k : p.frames) f.panels.push_back({fmt::format("t = {:.3g} s", static_cast<double>(k) / r.config.fps), p.drawn});
  return f;
}

std::string picture_markdown(Page& page, const ClothPicture& p, const FramesResult& r, const std::string& section,
                             const std::string& document) {
  constexpr Digits kError{true, 3};
  const auto named = [](const FrameRun& x) { return fmt::format("`{}` {}", method_info(x.setup.method).name, frame_setup_text(x.setup)); };
  std::vector<FrameRun> drawn;
  std::vector<std::string> setups;
  for (std::size_t i : p.runs) drawn.push_back(r.runs[i]), setups.push_back(named(r.runs[i]));
  const auto all = [](const FrameRun&) { return true; };
  const auto [least, most] = least_and_most(drawn, all, &FrameRun::error);
  const std::string sentence = fmt::format("Their largest errors over the frames lie from {} m ({}) to {} m ({}).", printed(least->error, kError),
                                           named(*least), printed(most->error, kError), named(*most));
  std::string md = page.figure("cloth", fmt::format("The {} seen from the side: the middle column of masses from the pinned edge (y = 0) "
                                                    "to the free one, at three frames, for the reference (black) and each family's "
                                                    "cheapest stable set-up ({}). {}",
                                                    scene_name(r.config.scene), fmt::join(setups, ", "), sentence));
  if (page.ledger)  // the drawn set-ups' errors, from the least to the greatest
    claim_range(*page.ledger, section + ".picture", section, sentence, kept_evidence(drawn, all, least, most, [&](const FrameRun&, std::size_t j) {
      return page.ledger->at(document, fmt::format("/runs/{}/error_max", p.runs[j]));
    }), kError);
  return md;
}

}  // namespace steplab
