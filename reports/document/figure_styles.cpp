#include "reports/document/figure_styles.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "analysis/studies/work_precision.hpp"
#include "analysis/kernel/kernel.hpp"
#include "analysis/peers/peers.hpp"
#include "reports/document/report_text.hpp"

namespace steplab {
namespace {

// Okabe & Ito (2008), "Color Universal Design": distinguishable under every common colour-vision
// deficiency.
std::string_view family_hue(Family f) {
  switch (f) {
    case Family::ExplicitRungeKutta: return "#0072B2";  // blue
    case Family::Splitting: return "#D55E00";           // vermillion
    case Family::ImplicitRungeKutta: return "#009E73";  // bluish green
    case Family::AdamsBashforth: return "#CC79A7";      // reddish purple
    case Family::Bdf: return "#E69F00";                 // orange
    case Family::PositionBased: return "#882255";       // wine (Paul Tol's; Okabe-Ito's last, yellow, is unreadable on white)
    default: return "#000000";
  }
}

// The hue scaled towards black by the order: 1, 0.8, 0.62, 0.48, 0.38 of its brightness; a
// second member of a family with the same order is the hue's tint instead (halfway to white).
std::string shade(std::string_view hue, int order, bool tint) {
  constexpr double scale[] = {1.0, 1.0, 0.8, 0.62, 0.48, 0.38};
  const auto channel = [&](int at) {
    const int c = std::stoi(std::string(hue.substr(at, 2)), nullptr, 16);
    return static_cast<int>(std::lround(tint ? c + 0.5 * (255 - c) : scale[order] * c));
  };
  return fmt::format("#{:02X}{:02X}{:02X}", channel(1), channel(3), channel(5));
}

}  // namespace

// The adaptive implicit peers by library (Paul Tol's colours the families leave free): CVODE sky
// blue, ARKODE teal, RADAU5 rose; the explicit adaptive solvers grey.
std::string solver_hue(std::string_view solver) {
  if (const auto m = find_method(solver)) return std::string(family_hue(method_info(*m).family));
  const PeerInfo* p = find_peer(solver);
  return p && p->implicit ? std::string(p->lib->hue) : "#999999";
}

// Point by the order: filled circle, square, triangle, diamond, triangle down (gnuplot's filled
// points; open is the filled point - 1); the exact flow (order 0) a star. Dash: the (order + family)-th of six patterns, so the
// members of a family differ in dash as in point, and two methods of one order from different
// families (a panel of the sheet's methods, the explicit fixed-step ones) differ in dash: no two
// methods share both point and dash, and a panel reads in grey scale, with lines or with points.
MethodStyle method_style(std::size_t method) {
  constexpr int points[] = {3, 7, 5, 9, 13, 11};
  constexpr std::string_view dashes[] = {"1", "2", "4", "3", "5", "(8,3,2,3,2,3)"};
  constexpr int kDashes = 6;
  const MethodInfo& info = method_info(method);
  // order 0 is the exact flow's; a method that claims none (PBD) is styled as a first-order one
  const auto order_of = [](const MethodInfo& i) { return std::clamp(i.exact_flow ? 0 : std::max(i.order, 1), 0, 5); };
  const auto dash_of = [&](const MethodInfo& i) { return (order_of(i) + static_cast<int>(i.family)) % kDashes; };
  const int o = order_of(info);
  // A method after another of the same family and order (Baraff-Witkin beside implicit Euler, PBD
  // beside XPBD, a plug-in's: steplab_add_executable) gets the open point, its hue's tint and the
  // first dash no other member of its family has.
  bool shares = false;
  std::array<bool, kDashes> used{};
  for (std::size_t m = 0; m < method_count(); ++m)
    if (m != method && method_info(m).family == info.family) {
      used[static_cast<std::size_t>(dash_of(method_info(m)))] = true;
      shares = shares || (m < method && order_of(method_info(m)) == o);
    }
  int dash = dash_of(info);
  if (shares)
    for (int d = 0; d < kDashes; ++d)
      if (!used[static_cast<std::size_t>((dash + d) % kDashes)]) {
        dash = (dash + d) % kDashes;
        break;
      }
  return {shade(family_hue(info.family), std::max(o, 1), shares), shares ? points[o] - 1 : points[o],
          std::string(dashes[dash])};
}

std::string styles_gp() {
  std::string out =
      "# The methods' styles, the same in every figure (written by steplab report from\n"
      "# reports/document/figure_styles.cpp): colour by family (Okabe-Ito), darker, another point and another\n"
      "# dash with each order.\n";
  std::string names;
  for (std::size_t m = 0; m < method_count(); ++m) {
    const MethodStyle s = method_style(m);
    out += fmt::format("set linetype {} lc rgb \"{}\" pt {} dt {} lw 1.5 ps 0.6  # {}\n", m + 1, s.colour, s.point,
                       s.dash, name(m));
    if (!names.empty()) names += ' ';
    names += name(m);
  }
  // the adaptive solvers, each in its row's style (analysis/peers/peers.cpp)
  std::string adaptive;
  std::size_t lt = method_count();
  for (const PeerInfo& p : peers()) {
    const PeerStyle& st = p.style;
    out += fmt::format("set linetype {} lc rgb \"{}\" pt {} dt {} lw 1.5 ps 0.6  # {}\n", ++lt, st.colour, st.point, st.dash, p.name);
    names += fmt::format(" {}", p.name);
  }
  for (const std::string& a : adaptive_solvers()) adaptive += (adaptive.empty() ? "" : " ") + a;
  out += fmt::format("style_names = \"{}\"\n", names);
  out += fmt::format("adaptive = \"{}\"\n", adaptive);
  out += "mlt(m) = sum [k=1:words(style_names)] (word(style_names, k) eq m ? k : 0)\n";
  out += "in_list(m, list) = strstrt(\" \".list.\" \", \" \".m.\" \") > 0\n";
  // The terminal of `format` (set by steplab report) for a figure h pixels high on screen (png,
  // svg: 1100 wide, fonts 12 and keys 11) or cm centimetres high in print (pdf: 16 cm wide, fonts
  // 10 pt and keys 8 pt, the least a printed page may carry): `eval terminal(h, cm)`.
  out += "terminal(h, cm) = format eq \"pdf\" ? sprintf(\"set terminal pdfcairo enhanced size 16cm,%.1fcm font ',10'\", cm) : "
         "sprintf(\"set terminal %s enhanced size 1100,%d font ',12'%s\", format eq \"svg\" ? \"svg\" : \"pngcairo\", int(h), "
         "format eq \"svg\" ? \" background rgb 'white'\" : \"\")\n";
  out += "kfont = format eq \"pdf\" ? \",8\" : \",11\"  # the keys and labels\n";
  // The figure rules' ticks (docs/design.md): at most six labelled ones an axis. Over [lo, hi]
  // a step s puts at most (hi - lo)/s + 1 labels: on a log axis every ceil(decades / 5)-th decade
  // (a minor tick at the others), on a linear one the least of 1, 2, 2.5, 5 x 10^p at least
  // (hi - lo)/5. A script that lets gnuplot pick a range draws its panels twice: pass 1 into a
  // table (nothing drawn; `eval keep_ranges(k)` after panel k's plot keeps the ranges gnuplot
  // picked), pass 2 for real (`eval tics("y", k, log)` before it fixes that range and its ticks).
  // `eval span_tics("y", lo, hi)`: a linear axis over data from lo to hi, its range widened to
  // the step's multiples.
  out += "log_step(lo, hi) = hi > lo ? ceil(log10(hi / lo) / 5.0 - 1e-9) : 1\n"
         "nice(s) = s > 0 ? (tp = 10**floor(log10(s)), ts = s / tp, (ts <= 1 ? 1 : ts <= 2 ? 2 : ts <= 2.5 ? 2.5 : ts <= 5 ? 5 : 10) * tp) : 1\n"
         "axis_tics(a, lo, hi, log) = sprintf(\"set %srange [%.17g:%.17g]; \", a, lo, hi) . (log ? "
         "sprintf(\"set %stics 1e%d; set m%stics %s\", a, log_step(lo, hi), a, log_step(lo, hi) > 1 ? sprintf(\"%d\", log_step(lo, hi)) : \"default\") : "
         "sprintf(\"set %stics %.17g\", a, nice((hi - lo) / 5.0)))\n"
         "keep_ranges(k) = sprintf(\"xlo_%d = GPVAL_X_MIN; xhi_%d = GPVAL_X_MAX; ylo_%d = GPVAL_Y_MIN; yhi_%d = GPVAL_Y_MAX\", k, k, k, k)\n"
         "tics(a, k, log) = axis_tics(a, value(sprintf(\"%slo_%d\", a, k)), value(sprintf(\"%shi_%d\", a, k)), log)\n"
         "span_tics(a, lo, hi) = (ts_ = nice((hi - lo) / 5.0), axis_tics(a, ts_ * floor(lo / ts_), ts_ * ceil(hi / ts_), 0))\n";
  return out;
}

}  // namespace steplab
