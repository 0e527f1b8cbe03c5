#pragma once

namespace steplab {

// The whole command line: parses, dispatches to a command, and turns bad input into one line
// on stderr and exit status 2. `dry_run`: every command checks its input and stops there,
// running nothing (the fuzzer).
int cli_main(int argc, const char* const* argv, bool dry_run = false);

// What main() does (reports/cli/main.cpp, and the main of a tool made with steplab_add_executable):
// cli_main, with an interrupt (exit 130) or an unexpected error (exit 1) reported in one line.
int program_main(int argc, char** argv);

}  // namespace steplab
