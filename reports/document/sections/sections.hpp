// THE section list of `steplab report`, in the order they appear. Adding a section: write
// reports/document/sections/<name>.cpp (a Section, see reports/document/section.hpp, and its
// `std::unique_ptr<Section> make_<name>_section()`) and add X(<name>, <in the full report>,
// <in the hand-out>) below. The full report's sections all go into the atlas (atlas.html); the
// hand-out (report.pdf, report.md) shows each Whole, Brief (its answer and a link to the atlas)
// or not at all (Atlas). The hand-in's own sections (`steplab report --sheet`) are not in the full
// report, which has the longer versions of what they say.
#pragma once

#define STEPLAB_REPORT_SECTIONS(X)       \
  X(answers, true, Whole)                \
  X(sheet, true, Whole)                  \
  X(summary, true, Whole)                \
  X(stable, false, Whole)                \
  X(order, false, Whole)                 \
  X(families, true, Whole)               \
  X(energy, true, Whole)                 \
  X(scenes, false, Whole)                \
  X(convergence, true, Whole)            \
  X(long_run, false, Whole)              \
  X(stiff_order, true, Brief)            \
  X(dense_output, true, Atlas)           \
  X(stability, true, Atlas)              \
  X(cost, true, Brief)                   \
  X(collision, true, Whole)              \
  X(scaling, true, Brief)                \
  X(frames, true, Brief)                 \
  X(cloth, true, Brief)                  \
  X(long_time, true, Brief)              \
  X(advice, true, Atlas)                 \
  X(physics, true, Atlas)                \
  X(reproduce, true, Whole)
