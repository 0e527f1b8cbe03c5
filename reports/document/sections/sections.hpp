// THE section list of `steplab report`, in the order they appear. Adding a section: write
// reports/document/sections/<name>.cpp (a Section, see reports/document/section.hpp, and its
// `std::unique_ptr<Section> make_<name>_section()`) and add X(<name>, <in the full report>) below.
// The hand-in's own sections (`steplab report --sheet`) are not in the full report, which has
// the longer versions of what they say.
#pragma once

#define STEPLAB_REPORT_SECTIONS(X) \
  X(answers, true)                 \
  X(sheet, false)                  \
  X(summary, true)                 \
  X(stable, false)                 \
  X(order, false)                  \
  X(families, true)                \
  X(energy, true)                  \
  X(scenes, false)                 \
  X(convergence, true)             \
  X(long_run, false)               \
  X(stiff_order, true)             \
  X(dense_output, true)            \
  X(stability, true)               \
  X(cost, true)                    \
  X(collision, true)               \
  X(scaling, true)                 \
  X(frames, true)                  \
  X(long_time, true)               \
  X(advice, true)                  \
  X(physics, true)                 \
  X(reproduce, true)
