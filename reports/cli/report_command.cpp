// `steplab report`: every study the configuration names, into one folder (reports/document/).
#include <filesystem>

#include "reports/cli/commands.hpp"
#include "reports/document/report.hpp"

namespace steplab {

int report_command(ReportArgs& a, Context& ctx) {
  const ReportConfig base = a.sheet ? sheet_report_config() : default_report_config();
  ReportConfig c = a.config.empty() ? base : read_report_config(a.config, base);
  const auto list = [](const std::string& text) { return text.empty() ? std::vector<std::string>{} : split_list(text); };
  if (a.methods_given) choose_methods(c, list(a.methods), "--methods");
  if (a.scenes_given) choose_scenes(c, list(a.scenes), "--scenes");
  if (a.sections_given) choose_sections(c, list(a.sections), "--sections");
  check_choice(c, "--methods");
  if (a.print_config) {
    std::fputs((report_config_json(c).dump(1) + "\n").c_str(), stdout);
    return 0;
  }
  if (a.out.empty()) throw UsageError("--out is empty; accepted: a folder path");
  if (ctx.dry_run) return 0;
  check_report_folder(a.out);
  check_writable((std::filesystem::path(a.out).parent_path().empty() ? std::filesystem::path(".")
                                                                     : std::filesystem::path(a.out).parent_path()) /
                 ".steplab-write-check");
  return write_report(c, a.out, a.force, ctx.progress);
}

}  // namespace steplab
