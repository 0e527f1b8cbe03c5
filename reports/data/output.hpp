// Every file steplab writes is written to a temporary file beside it and renamed into place, so
// a reader (or an interrupted run) never sees half a file, and a refused run leaves none.
#pragma once

#include <string>

namespace steplab {

// Throws UsageError (naming the path) if a file cannot be created in the path's directory, or if
// the path holds a file steplab did not write: a file is replaced only if it is a JSON document of
// one of steplab's schemas (`{"schema": "steplab.`...), so a user's own file is never lost. Called
// before any work, so bad output paths are refused up front.
void check_writable(const std::string& path);

// The folder `steplab report --out` writes: new, empty, or one that holds a report steplab wrote
// and nothing else (its marker, kReportMarker, lists every file the report wrote; a folder of an
// older steplab, without the marker, is recognised by its data/stamp). Anything else: UsageError
// naming what is in the way. The report is swapped in whole, so nothing of a user's may be in it.
inline constexpr const char* kReportMarker = ".steplab-report";
void check_report_folder(const std::string& path);
// The marker's text: a line saying what it is, then the files of `folder` (relative paths, sorted).
std::string report_marker(const std::string& folder);

// Writes content to path atomically (temporary file + rename). Throws std::runtime_error.
void write_atomic(const std::string& path, const std::string& content);

}  // namespace steplab
