#include "reports/document/sections/sections.hpp"

#include <algorithm>

#include "reports/document/section.hpp"

namespace steplab {

#define STEPLAB_DECLARE_SECTION(n, full, handout) std::unique_ptr<Section> make_##n##_section();
STEPLAB_REPORT_SECTIONS(STEPLAB_DECLARE_SECTION)
#undef STEPLAB_DECLARE_SECTION

std::vector<std::string> section_names() {
#define STEPLAB_SECTION_NAME(n, full, handout) #n,
  return {STEPLAB_REPORT_SECTIONS(STEPLAB_SECTION_NAME)};
#undef STEPLAB_SECTION_NAME
}

std::vector<std::string> full_report_sections() {
  std::vector<std::string> out;
#define STEPLAB_FULL_SECTION(n, full, handout) \
  if (full) out.push_back(#n);
  STEPLAB_REPORT_SECTIONS(STEPLAB_FULL_SECTION)
#undef STEPLAB_FULL_SECTION
  return out;
}

std::vector<std::unique_ptr<Section>> report_sections(const std::vector<std::string>& chosen) {
  const auto wanted = [&](const char* n) { return std::find(chosen.begin(), chosen.end(), n) != chosen.end(); };
  std::vector<std::unique_ptr<Section>> out;
#define STEPLAB_MAKE_SECTION(n, full, shown)                                         \
  if (wanted(#n)) {                                                                   \
    out.push_back(make_##n##_section());                                              \
    out.back()->id = #n, out.back()->handout = Handout::shown;                      \
  }
  STEPLAB_REPORT_SECTIONS(STEPLAB_MAKE_SECTION)
#undef STEPLAB_MAKE_SECTION
  return out;
}

}  // namespace steplab
