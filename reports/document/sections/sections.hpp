// THE section list of `steplab report`, in the order they appear. Adding a section: write
// reports/document/sections/<name>.cpp (a Section, see reports/document/section.hpp, and its
// `std::unique_ptr<Section> make_<name>_section()`) and add X(<name>) below.
#pragma once

#define STEPLAB_REPORT_SECTIONS(X) \
  X(summary)                       \
  X(stable)                        \
  X(families)                      \
  X(scenes)                        \
  X(convergence)                   \
  X(stability)                     \
  X(cost)                          \
  X(collision)                     \
  X(growth)                        \
  X(reproduce)
