// formatDiagnostic, ScriptError (a script's located error) and ScriptExit (Exit;).
#pragma once

#include <exception>

#include "grammar/diagnostic.h"

namespace geomesh {

// Script errors (ScriptError, formatDiagnostic) are in grammar/diagnostic.h, so that the
// library layer under the interpreter reports located errors too.

// Thrown by `Exit;`: evaluation stops successfully, and nothing is meshed.
class ScriptExit : public std::exception {
 public:
  const char* what() const noexcept override { return "Exit"; }
};

}  // namespace geomesh
