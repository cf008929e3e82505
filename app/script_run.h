// ScriptRun: a .geo script run as the geomesh command runs it, the session kept afterwards.
#pragma once

#include <iosfwd>
#include <string>

#include "api/session.h"
#include "app/command_line.h"
#include "app/console_log.h"

namespace geomesh {

struct MeshFormat;

// What the command and ScriptRun share.
// The command line's settings applied to a session: -v, -allow_system, -setnumber,
// -setstring, and options such as -clscale.
void applySettings(const CommandLine& settings, Session& session);
// Reads and evaluates the script, with the "Reading"/"Done reading" lines; false when it
// stopped at `Exit;`.
bool evaluateScriptFile(const std::string& file, Session& session, ConsoleLog& log);
// Throws std::invalid_argument when the session's element order cannot be made, or (when
// `format` is given) cannot be written to `path` in it.
void checkElementOrder(const Session& session, const MeshFormat* format, const std::string& path);
// "0.0123 s"
std::string formatSeconds(double seconds);

// One script run with the settings of a command line (-v, -setnumber, -setstring, options
// such as -clscale, -<dim>, -o, -format), in two stages so that a front end can tell a
// script's errors from meshing's: evaluate(), then meshAndWrite(). The session and its mesh
// stay for the caller to read. Unlike the command, nothing is written unless `output` names
// a file. Not copyable or movable: the session refers to the log.
class ScriptRun {
 public:
  // Makes the session and applies the settings; `settings.files` holds the one script.
  // Script output (Printf) goes to `out`, log lines to `err`.
  ScriptRun(CommandLine settings, std::ostream& out, std::ostream& err);
  ScriptRun(const ScriptRun&) = delete;
  ScriptRun& operator=(const ScriptRun&) = delete;

  // Reads and evaluates the script; false when it stopped at `Exit;`. Throws ScriptError
  // (and MeshError, std::runtime_error... for what the script's own statements run).
  bool evaluate();
  // Without a dimension: synchronizes only. Dimension 0: synchronizes, and writes the
  // unrolled geometry to `output` when given. Dimensions 1 to 3: meshes, then writes the
  // mesh to `output` when given, in the format that -format or the file name says (the
  // format and the element order are checked first). Throws MeshError, or ScriptError for
  // a meshing failure located at the statement that defined the entity.
  void meshAndWrite();

  Session& session() { return session_; }
  const Session& session() const { return session_; }
  const CommandLine& settings() const { return settings_; }

 private:
  CommandLine settings_;
  ConsoleLog log_;
  Session session_;
};

}  // namespace geomesh
