// runGeomesh: the whole geomesh command, with its output and error streams given.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace geomesh {

// Runs the geomesh command: `args` without the program name. Script output (Printf) goes to
// `out`, log lines and diagnostics to `err`. Returns the exit status.
// `terminal`: `err` is a terminal, where long stages draw a progress bar.
int runGeomesh(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
               bool terminal = false);

}  // namespace geomesh
