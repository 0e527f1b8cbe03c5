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

// The load a measurement saw, recorded beside it: a study times each of its rows twice, in two
// passes apart in time (every row, then every row again in reverse order), keeps the smaller of
// the two minima and records their ratio, larger over smaller, as the row's spread. The spread
// decides nothing. Load only slows a run, so the smaller minimum is the one less disturbed: a
// spread says how much worse the worse pass was, not how far the kept time moves from one report
// to the next, and a margin raised by it made ties where the kept ratios had not moved
// (docs/design.md, "Timing noise"). kTieMargin alone is the margin a win needs.
inline double spread_of(double a, double b) { return a > b ? a / b : b / a; }

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
