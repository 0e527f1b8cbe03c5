#include <cstdio>
#include <exception>

#include "reports/cli.hpp"

int main(int argc, char** argv) {
  try {
    return steplab::cli_main(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "steplab: %s\n", e.what());
    return 1;
  }
}
