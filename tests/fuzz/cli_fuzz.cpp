// libFuzzer target over steplab's input handling: the command line and the report's JSON
// configuration. An input starting with '{' or '[' is a configuration file's text; anything
// else is a command line, one argument per line. Commands run in dry-run mode (they check their
// input and stop), so the fuzzer explores parsing, not simulations.
//
// Any exception that escapes cli_main (it must turn every bad input into exit status 2) or the
// configuration reader (it must throw UsageError and nothing else), and any sanitizer report,
// is a crash.
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "reports/cli/cli.hpp"
#include "reports/data/inputs.hpp"
#include "reports/document/report_config.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  if (!text.empty() && (text[0] == '{' || text[0] == '[')) {
    nlohmann::ordered_json j;
    try {
      j = nlohmann::ordered_json::parse(text);
    } catch (const nlohmann::json::exception&) {
      return 0;  // read_report_config turns this into a UsageError
    }
    try {
      steplab::report_config_from_json(j);
    } catch (const steplab::UsageError&) {
    }
    return 0;
  }
  std::vector<std::string> args{"steplab"};
  std::string arg;
  for (char c : text) {
    if (c == '\n') {
      args.push_back(arg);
      arg.clear();
    } else {
      arg += c;
    }
  }
  if (!arg.empty()) args.push_back(arg);
  if (args.size() > 64) return 0;
  std::vector<const char*> argv;
  for (const auto& a : args) argv.push_back(a.c_str());
  const int status = steplab::cli_main(static_cast<int>(argv.size()), argv.data(), /*dry_run=*/true);
  if (status != 0 && status != 2) std::abort();  // bad input is exit 2, never anything else
  return 0;
}
