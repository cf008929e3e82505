// The interpreter's one entry point: running a .geo script in a session.
#pragma once

#include <string>

namespace geomesh {

class Session;

// Reads, parses and evaluates a .geo script in `session`. Throws ScriptError for any error
// (syntax or evaluation) and ScriptExit when the script says `Exit;`.
void runScriptFile(Session& session, const std::string& path);

// Same, for script text given directly; `name` is used in diagnostics and to resolve Include
// paths (relative to its directory).
void runScriptText(Session& session, const std::string& text, const std::string& name);

}  // namespace geomesh
