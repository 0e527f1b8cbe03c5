#include "reports/cli/cli.hpp"

int main(int argc, char** argv) { return steplab::program_main(argc, argv); }
