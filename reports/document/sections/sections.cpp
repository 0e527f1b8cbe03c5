#include "reports/document/sections/sections.hpp"

#include "reports/document/section.hpp"

namespace steplab {

#define STEPLAB_DECLARE_SECTION(n) std::unique_ptr<Section> make_##n##_section();
STEPLAB_REPORT_SECTIONS(STEPLAB_DECLARE_SECTION)
#undef STEPLAB_DECLARE_SECTION

std::vector<std::unique_ptr<Section>> report_sections() {
  std::vector<std::unique_ptr<Section>> out;
#define STEPLAB_MAKE_SECTION(n) out.push_back(make_##n##_section());
  STEPLAB_REPORT_SECTIONS(STEPLAB_MAKE_SECTION)
#undef STEPLAB_MAKE_SECTION
  return out;
}

}  // namespace steplab
