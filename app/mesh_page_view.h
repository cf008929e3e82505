// The HTML page of a mesh (io/html_writer.cpp) written for `geomesh view` and -view, and
// opened in a browser when there is a display to show it on.
#pragma once

#include <string>

#include "api/session.h"
#include "app/console_log.h"

namespace geomesh {

// The page beside a mesh file: its path with the extension replaced by ".html".
std::string pagePathBeside(const std::string& meshPath);

// Writes the session's mesh as a page at `path` (nothing is left there on failure: the
// error is thrown), then opens it (openPage).
void writeMeshPage(const Session& session, const std::string& path, ConsoleLog& log);

// With DISPLAY or WAYLAND_DISPLAY set, hands the page to xdg-open without waiting for the
// browser; otherwise, or when xdg-open cannot be run, logs where the page is.
void openPage(const std::string& path, ConsoleLog& log);

}  // namespace geomesh
