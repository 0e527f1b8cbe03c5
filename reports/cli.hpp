#pragma once

namespace steplab {

// The whole command line: parses, dispatches to a command, and turns bad input into one line
// on stderr and exit status 2.
int cli_main(int argc, const char* const* argv);

}  // namespace steplab
