// When two timings are told apart. A header of its own, apart from the timing loop that every
// kernel compiles (timing.hpp), so that the rule can change without rebuilding the kernels.
#pragma once

#include <algorithm>
#include <vector>

namespace steplab {

// A margin of one solver's time over another's below this is within the noise of a report's
// timings: a tie, not a win. Measured between two full reports on a 2-core machine, one of them
// beside the test suite: the ratio of two solvers' best times at an error level moved by up to
// 1.40x (a 90th percentile 1.19x), and at 1.2 one timed comparison in 14 and 8 of 24
// crossover-map cells changed verdict (docs/design.md, "Timing noise", with what still changes
// at 1.5; tools/compare_verdicts.py compares two reports' verdicts). Exact counts (an untimed
// study) tie only when equal.
inline constexpr double kTieMargin = 1.5;

// The timing noise of one measurement, measured in the same run: a study times each of its rows
// twice, in two passes apart in time (every row, then every row again in reverse order), keeps
// the smaller of the two minima and records their ratio, larger over smaller, as the row's
// spread: how far the machine's load moved its time between the passes. Two rows are told apart
// only where one's time is below the other's by more than kTieMargin and by more than the product
// of their spreads (the worst case: one timed at its high, the other at its low): noise_margin.
inline double spread_of(double a, double b) { return a > b ? a / b : b / a; }
inline double noise_margin(double spread_a, double spread_b) {
  const double noise = spread_a * spread_b;
  return noise > kTieMargin ? noise : kTieMargin;
}

// The two passes over a study's rows (each with `seconds` and `spread`): `time(row)` is one
// timing of the row's run (the minimum of its repeats).
template <class Row, class Time> void time_in_two_passes(const std::vector<Row*>& rows, Time&& time) {
  for (Row* r : rows) r->seconds = time(*r);
  for (auto r = rows.rbegin(); r != rows.rend(); ++r) {
    const double again = time(**r);
    (*r)->spread = spread_of((*r)->seconds, again), (*r)->seconds = std::min((*r)->seconds, again);
  }
}

}  // namespace steplab
