// Tests of the report's findings (reports/document/report_studies.cpp, reports/document/report.cpp): the sentences
// follow the data, also when the parameters change. Each check recomputes what the sentence
// claims from the study data themselves, not from the Findings that produced the sentence.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <set>

#include <fmt/format.h>

#include "analysis/kernel.hpp"
#include "analysis/scaling.hpp"
#include "reports/data/inputs.hpp"
#include "reports/data/study_output.hpp"
#include "reports/document/report.hpp"
#include "small_report.hpp"

namespace steplab {
namespace {

// A parameter of one of the report's scenes, by name.
double& param(ReportScene& s, std::string_view name) {
  return s.params[static_cast<std::size_t>(param_index(scene_kernel(s.scene).params, name))];
}


// The backticked names in `line` between `from` and `to` (to the end if `to` is empty).
std::set<std::string> names_between(const std::string& line, const std::string& from, const std::string& to) {
  const std::size_t a = line.find(from);
  if (a == std::string::npos) return {};
  const std::size_t b = to.empty() ? std::string::npos : line.find(to, a);
  const std::string part = line.substr(a + from.size(), b == std::string::npos ? std::string::npos : b - a - from.size());
  std::set<std::string> out;
  static const std::regex name("`([a-z_0-9]+)`");
  for (auto it = std::sregex_iterator(part.begin(), part.end(), name); it != std::sregex_iterator(); ++it) out.insert((*it)[1]);
  return out;
}

std::string line_starting(const std::string& md, const std::string& prefix) {
  const std::size_t a = md.find(prefix);
  return a == std::string::npos ? "" : md.substr(a, md.find('\n', a) - a);
}

void expect_family_sentences_follow_data(const ReportData& d, const std::string& md);
void expect_cost_sentences_follow_data(const ReportData& d, const std::string& md);

void expect_sentences_follow_data(const ReportConfig& c) {
  const Report report = build_report(c);
  const ReportData& d = report.data;
  const std::string md = report_markdown(report, "png", "footer");
  const double gamma = c.damping();

  std::set<std::string> stable_large, unstable_large, stable_undamped, unstable_undamped;
  for (const SweepRow& r : d.sweep) {
    const std::string n(method_info(r.method).name);
    if (r.dt == c.large_dt && r.damping == gamma) (r.run.stable() ? stable_large : unstable_large).insert(n);
    if (r.dt == c.small_dt && r.damping == 0) (r.run.stable() ? stable_undamped : unstable_undamped).insert(n);
  }
  ASSERT_EQ(stable_large.size() + unstable_large.size(), method_count());
  const std::string large = line_starting(md, "- At the sheet's large step");
  ASSERT_FALSE(large.empty()) << md;
  EXPECT_EQ(names_between(large, "stable:", "; unstable:"), stable_large) << large;
  EXPECT_EQ(names_between(large, "; unstable:", ""), unstable_large) << large;
  const std::string undamped = line_starting(md, "- Without damping (dt");
  EXPECT_EQ(names_between(undamped, "stable:", "; unstable:"), stable_undamped) << undamped;
  EXPECT_EQ(names_between(undamped, "; unstable:", ""), unstable_undamped) << undamped;

  // "Stable at every step" names exactly the methods whose predicted dt* is infinite.
  std::set<std::string> always;
  for (const ThresholdRow& r : d.thresholds)
    if (r.damping == gamma && std::isinf(r.dt_theory)) always.insert(std::string(method_info(r.method).name));
  EXPECT_EQ(names_between(line_starting(md, "- Stable at every step"), ":", ""), always);

  // The correlation sentence carries the Spearman value of (order, measured dt*) and names the
  // methods whose ranks lie a third of the table apart.
  std::vector<double> order, dt;
  for (std::size_t m = 0; m < method_count(); ++m) {
    order.push_back(method_info(m).exact_flow ? INFINITY : method_info(m).order);
    for (const ThresholdRow& r : d.thresholds)
      if (r.method == m && r.damping == gamma) dt.push_back(r.dt_measured);
  }
  ASSERT_EQ(dt.size(), method_count());
  const double rho = spearman(order, dt);
  EXPECT_NE(md.find(fmt::format("is **{:.2f}**", rho)), std::string::npos) << rho;

  expect_family_sentences_follow_data(d, md);
  expect_cost_sentences_follow_data(d, md);
}

// Each family's sentence says, at every damping measured, whether dt* rises, falls or stays
// infinite along the family's orders; recomputed here from the thresholds. Dahlquist's sentence
// names the multistep methods measured stable at every step at every damping.
// The cost section (timing off: costs are evaluations): the cheapest run per error level in the
// table, and the crossover, recomputed from the work-precision points and stiffness rows.
void expect_cost_sentences_follow_data(const ReportData& d, const std::string& md) {
  const WorkPrecisionResult& r = d.work;
  ASSERT_EQ(r.scenes.size(), 2u);
  for (const double level : r.config.error_levels) {
    std::string row = fmt::format("| {:.0e} |", level);
    for (const SceneWork& w : r.scenes) {
      std::string best;
      long long cost = 0;
      for (const WorkPoint& p : w.points)
        if (p.status == RunStatus::Ok && p.error <= level && (best.empty() || p.force_evaluations + p.jacobian_evaluations < cost))
          best = p.method, cost = p.force_evaluations + p.jacobian_evaluations;
      row += best.empty() ? " none |" : fmt::format(" `{}` {} |", best, cost);
    }
    EXPECT_NE(md.find(row + "\n"), std::string::npos) << row;
  }
  // the crossover: the smallest ratio from which on the cheapest implicit run beats every explicit one
  double crossover = -1;
  for (std::size_t i = r.stiffness.size(); i-- > 0;) {
    const StiffnessRow& s = r.stiffness[i];
    if (s.best_implicit.empty() || (!s.best_explicit.empty() && s.implicit_evaluations >= s.explicit_evaluations)) break;
    crossover = s.ratio;
  }
  const std::string line = line_starting(md, "- The crossover:");
  if (crossover > 0) {
    EXPECT_NE(line.find(fmt::format("k2 / k1 = {:g} on", crossover)), std::string::npos) << line;
  } else {
    EXPECT_NE(md.find("- No stiffness ratio of the sweep"), std::string::npos);
  }
}

void expect_family_sentences_follow_data(const ReportData& d, const std::string& md) {
  std::vector<double> dampings;
  for (const ThresholdRow& r : d.thresholds)
    if (std::find(dampings.begin(), dampings.end(), r.damping) == dampings.end()) dampings.push_back(r.damping);
  std::sort(dampings.begin(), dampings.end());
  ASSERT_GE(dampings.size(), 2u);  // undamped and the spring's damping
  const auto dt_measured = [&](std::size_t m, double g) {
    for (const ThresholdRow& r : d.thresholds)
      if (r.method == m && r.damping == g) return r.dt_measured;
    ADD_FAILURE() << "no threshold for " << method_info(m).name << " at " << g;
    return std::nan("");
  };
  std::set<std::string> every_step;
  int families = 0;
  for (Family f : {Family::ExplicitRungeKutta, Family::Splitting, Family::ImplicitRungeKutta, Family::AdamsBashforth, Family::Bdf}) {
    std::vector<std::size_t> fam;
    for (std::size_t m = 0; m < method_count(); ++m)
      if (method_info(m).family == f || method_info(m).first_of == f) fam.push_back(m);
    // std::sort, not stable_sort: GCC 12's stable_sort buffer trips ASan's new/free check
    std::sort(fam.begin(), fam.end(), [](auto a, auto b) { return std::pair(method_info(a).order, a) < std::pair(method_info(b).order, b); });
    ASSERT_GE(fam.size(), 3u) << to_string(f);  // every family spans at least three orders
    ++families;
    const std::string line = line_starting(md, fmt::format("- **{}**", to_string(f)));
    ASSERT_FALSE(line.empty()) << to_string(f) << "\n" << md;
    for (double g : dampings) {
      bool up = false, down = false, inf = true;
      for (std::size_t i = 0; i < fam.size(); ++i) {
        const double x = dt_measured(fam[i], g);
        inf &= std::isinf(x);
        if (i > 0) up |= x > dt_measured(fam[i - 1], g), down |= x < dt_measured(fam[i - 1], g);
      }
      const char* tr = inf ? "stays infinite" : up && !down ? "rises" : down && !up ? "falls" : !up && !down ? "stays the same" : "does not move one way";
      EXPECT_NE(line.find(fmt::format("at damping {} dt* {}:", g, tr)), std::string::npos) << tr << " at " << g << ": " << line;
    }
    if (f == Family::AdamsBashforth || f == Family::Bdf)
      for (std::size_t m : fam) {
        bool all = true;
        for (double g : dampings) all &= std::isinf(dt_measured(m, g));
        if (all) every_step.insert(std::string(method_info(m).name));
      }
  }
  EXPECT_EQ(families, 5);
  const std::string dahlquist = line_starting(md, "Dahlquist's second barrier");
  const std::size_t a = dahlquist.find("at every damping tried:"), b = dahlquist.find("; stability region");
  ASSERT_TRUE(a != std::string::npos && b != std::string::npos) << dahlquist;
  std::set<std::string> named;
  static const std::regex word("`([a-z_0-9]+)` \\(order");
  const std::string part = dahlquist.substr(a, b - a);
  for (auto it = std::sregex_iterator(part.begin(), part.end(), word); it != std::sregex_iterator(); ++it) named.insert((*it)[1]);
  EXPECT_EQ(named, every_step) << dahlquist;
}

TEST(ReportFindings, FollowTheDataWithDefaults) { expect_sentences_follow_data(small_config()); }

TEST(ReportFindings, FollowTheDataWithoutDamping) {
  ReportConfig c = small_config();
  param(c.oscillator, "damping") = 0;  // damping 0: explicit Euler and midpoint are unstable at every step
  expect_sentences_follow_data(c);
}

TEST(ReportFindings, FollowTheDataWithAStiffSpringAndALargeStep) {
  ReportConfig c = small_config();
  param(c.oscillator, "stiffness") = 50;  // omega = 7.1
  c.large_dt = 0.3;    // beyond symplectic Euler's 2/omega = 0.28
  expect_sentences_follow_data(c);
}

TEST(ReportFindings, ChangedParametersChangeTheSentences) {
  const auto markdown = [](const ReportConfig& c) {
    return report_markdown(build_report(c), "png", "");
  };
  ReportConfig c = small_config();
  const std::string a = markdown(c);
  param(c.oscillator, "stiffness") = 50;
  c.large_dt = 0.3;
  const std::string b = markdown(c);
  EXPECT_NE(line_starting(a, "- At the sheet's large step"), line_starting(b, "- At the sheet's large step"));
}

TEST(Spearman, KnownValues) {
  EXPECT_DOUBLE_EQ(spearman({1, 2, 3, 4}, {10, 20, 30, 40}), 1.0);
  EXPECT_DOUBLE_EQ(spearman({1, 2, 3, 4}, {4, 3, 2, 1}), -1.0);
  // ties and infinities: ranks (1.5, 1.5, 3, 4) against (1, 2, 3.5, 3.5)
  const double rho = spearman({1, 1, 2, INFINITY}, {0.1, 0.2, INFINITY, INFINITY});
  // Pearson of the ranks about their mean 2.5: deviations (-1, -1, 0.5, 1.5) and (-1.5, -0.5, 1, 1);
  // products 1.5 + 0.5 + 0.5 + 1.5 = 4; sums of squares 4.5 and 4.5: rho = 4 / 4.5
  EXPECT_NEAR(rho, 4.0 / 4.5, 1e-12);
}

TEST(ReportConfigJson, DefaultsRoundTripAndOverrides) {
  const auto defaults = report_config_json(default_report_config());
  EXPECT_EQ(report_config_json(report_config_from_json(defaults)).dump(), defaults.dump());
  const ReportConfig c = report_config_from_json(nlohmann::ordered_json::parse(R"({"spring": {"damping": 0.3}, "threads": 1})"));
  EXPECT_DOUBLE_EQ(c.damping(), 0.3);
  EXPECT_EQ(c.threads, 1u);
  EXPECT_DOUBLE_EQ(c.oscillator.params[1], 5.0);  // the stiffness, as the rest, stays default
}

TEST(ReportConfigJson, RefusesBadConfigs) {
  for (const char* bad : {R"({"spring": {"stifness": 3}})", R"({"sprung": {}})", R"({"spring": {"damping": "a lot"}})",
                          R"({"spring": {"mass": 0}})", R"({"stability": {"sweep_dts": []}})", R"({"convergence": {"points": 2.5}})",
                          R"({"convergence": {"dt_min": 0.5, "dt_max": 0.1}})", R"([1, 2])", R"({"work_precision": {"timing": 1}})"}) {
    EXPECT_THROW(report_config_from_json(nlohmann::ordered_json::parse(bad)), UsageError) << bad;
  }
}

}  // namespace
}  // namespace steplab

namespace steplab {
namespace {

// "As the system grows": its table and sentences are the scaling study's, run here again with the
// same settings (not timed: evaluations, the same numbers every time), under two settings.
// The markdown of "As the system grows" alone.
std::string growth_section(const ReportConfig& c) {
  const std::string md = report_markdown(build_report(c), "png", "");
  const std::size_t a = md.find("## As the system grows");
  return a == std::string::npos ? "" : md.substr(a, md.find("\n## ", a + 1) - a);
}

// Returns the section's text.
std::string expect_growth_follows_data(ReportConfig& c) {
  const std::string md = growth_section(c);
  EXPECT_FALSE(md.empty());
  ScalingConfig s;
  s.params = default_param_values(*find_scene("rope"));
  s.sizes = sizes_of(c, "rope");
  s.targets = {{c.scaling_error, false}};
  s.t_end = c.scaling_t_end;
  for (std::size_t m = 0; m < method_count(); ++m)
    if (!method_info(m).exact_flow) s.methods.push_back(m);
  s.timing = false;
  const ScalingResult r = scaling_study(s);
  for (const ScalingFit& f : r.fits) {
    const std::string row = line_starting(md.substr(0, md.find("**When does implicit pay?**")), "| `" + f.solver + "` |");
    EXPECT_FALSE(row.empty()) << f.solver;
    EXPECT_NE(row.find("| " + exponent_text(f.run) + " |"), std::string::npos) << row;
  }
  if (r.blocks.front().crossover == 0) {
    EXPECT_NE(md.find("- At none of these sizes is an implicit method"), std::string::npos);
  } else {
    EXPECT_NE(md.find(fmt::format("- From N = {} on (of these sizes), `{}`", r.blocks.front().crossover,
                                  r.blocks.front().crossover_method)),
              std::string::npos);
  }
  EXPECT_NE(md.find(fmt::format("to N = {}", sizes_of(c, "rope").front())), std::string::npos);
  // the map: the rope at the map's sizes, stiffened, at the report's error and the visual one;
  // at each target, the cells where an implicit fixed-step method is the cheapest, counted here
  ScalingConfig m = s;
  for (const std::string& a : scaling_adaptive_solvers("rope"))  // the map's peers: CVODE's BDF of orders 1-2, not 1-5
    if (a != "cvode_bdf_band") m.adaptive.push_back(a);
  m.sizes = c.scaling_map_sizes;
  for (double f : c.scaling_stiffening) m.stiffnesses.push_back(f * s.params[2]);
  m.targets.push_back({c.scaling_visual, true});
  m.max_steps = 200'000;
  const ScalingResult map = scaling_study(m);
  for (int t = 0; t < 2; ++t) {
    int implicit = 0;
    for (const ScalingBlock& b : map.blocks)
      for (const ScalingCell& cell : b.cells) implicit += b.target == t && !cell.cheapest.empty() && cell.cheapest == cell.best_implicit;
    const std::string line = line_starting(md, fmt::format("- At error {}:", target_text(m, map.blocks[static_cast<std::size_t>(t + 1) * m.stiffnesses.size() - 1])));
    EXPECT_FALSE(line.empty()) << t;
    EXPECT_NE(line.find(implicit == 0 ? std::string("No implicit fixed-step method is the cheapest anywhere")
                                      : fmt::format("An implicit fixed-step method is the cheapest in {} of them", implicit)),
              std::string::npos)
        << line;
  }
  // the soft body's paragraph: its sentences from its own study
  s.scene = "softbody";
  s.params = default_param_values(*find_scene("softbody"));
  s.sizes = sizes_of(c, "softbody");
  s.max_steps = 200'000;
  const ScalingResult soft = scaling_study(s);
  const std::string tail = md.substr(md.find("Soft body of N"));
  for (const ScalingFit& f : soft.fits) {
    const std::string row = line_starting(tail, "| `" + f.solver + "` |");
    EXPECT_FALSE(row.empty()) << f.solver;
    EXPECT_NE(row.find("| " + exponent_text(f.run) + " |"), std::string::npos) << row;
  }
  const int largest = sizes_of(c, "softbody").back() * sizes_of(c, "softbody").back();
  const ScalingBlock& b = soft.blocks.front();
  EXPECT_NE(tail.find(b.crossover == 0 ? std::string("- At none of these sizes")
                                       : fmt::format("- From N = {} on (of these sizes), `{}`", b.crossover * b.crossover,
                                                     b.crossover_method)),
            std::string::npos);
  EXPECT_NE(tail.find(fmt::format("- At N = {}, steplab's cheapest", largest)), std::string::npos) << tail;
  for (const char* cvode : {"Adams-Moulton and its KLU solver (`cvode_adams_klu`)", "BDF and its KLU solver (`cvode_bdf_klu`)",
                            "BDF of orders 1-2 and its KLU solver (`cvode_bdf_max2_klu`)"})
    EXPECT_NE(tail.find(std::string("what CVODE with ") + cvode + " costs"), std::string::npos) << cvode;
  return md;
}

TEST(ReportGrowth, FollowsTheDataUnderChangedParameters) {
  ReportConfig c = small_config();
  const std::string a = expect_growth_follows_data(c);
  sizes_of(c, "rope") = {4, 16, 128};  // 1.5 decades: the exponents fitted
  sizes_of(c, "softbody") = {3, 4};
  c.scaling_error = 1e-3;
  c.scaling_stiffening = {1, 30, 1000};
  const std::string b = expect_growth_follows_data(c);
  EXPECT_NE(line_starting(a, "| `rk4` |"), line_starting(b, "| `rk4` |"));
  EXPECT_NE(line_starting(a, "- At error"), line_starting(b, "- At error"));
}

}  // namespace
}  // namespace steplab
