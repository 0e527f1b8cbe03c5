// How every figure tells the methods apart: one style per method, the same in every figure, and
// the family panels that keep each plot to a handful of curves. Written once per report as
// figures/styles.gp, which every script loads.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace steplab {

struct MethodStyle {
  std::string colour;  // "#rrggbb"
  int point;           // gnuplot point type
  std::string dash;    // gnuplot dash type: a number (1..5) or a pattern "(8,3,2,3)"
};

// Colour: the family's hue from the Okabe-Ito palette (told apart with any colour vision),
// darker with the order. Point by the order, dash by order and family: the methods of one panel
// differ in colour and in point and dash, whatever families the panel mixes.
MethodStyle method_style(std::size_t method);

// A solver's colour on the crossover map: a method's family hue; CVODE sky blue, ARKODE's DIRK
// tables teal, RADAU5 rose; the explicit adaptive solvers (dopri5, Boost.Odeint's, ARKODE's
// explicit table) grey: its group's (solver_group, analysis/peers/peers.hpp).
std::string solver_hue(std::string_view solver);

// figures/styles.gp: `set linetype` per method (method k of the table is linetype k + 1),
//   mlt(name)            the linetype of a method by name
//   in_list(name, list)  whether a word is in a space-separated list
//   adaptive             the adaptive solvers of the work-precision study (linetypes after the table's)
// A figure's panels are its own (FigureSpec::panels, reports/document/section.hpp).
std::string styles_gp();

}  // namespace steplab
