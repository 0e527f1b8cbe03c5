#include <cstdio>
#include <exception>

#include "analysis/parallel.hpp"
#include "reports/cli.hpp"

int main(int argc, char** argv) {
  try {
    return steplab::cli_main(argc, argv);
  } catch (const steplab::Interrupted&) {
    std::fputs("steplab: interrupted; nothing was written or replaced\n", stderr);
    return 130;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "steplab: %s\n", e.what());
    return 1;
  }
}
