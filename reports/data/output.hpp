// Every file steplab writes is written to a temporary file beside it and renamed into place, so
// a reader (or an interrupted run) never sees half a file, and a refused run leaves none.
#pragma once

#include <string>

namespace steplab {

// Throws UsageError (naming the path) if a file cannot be created in the path's directory.
// Called before any work, so bad output paths are refused up front.
void check_writable(const std::string& path);

// Writes content to path atomically (temporary file + rename). Throws std::runtime_error.
void write_atomic(const std::string& path, const std::string& content);

}  // namespace steplab
