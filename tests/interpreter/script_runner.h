// ScriptRun and CollectingSink: running a script in tests, with its output and warnings kept.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "interpreter/diagnostics.h"
#include "api/session.h"
#include "interpreter/run_script.h"
#include "kernel/messages.h"

namespace geomesh::testing {

// Keeps every message, so tests can check the warnings a script produces.
class CollectingSink final : public MessageSink {
 public:
  void info(std::string_view m) override { infos.emplace_back(m); }
  void warning(std::string_view m) override { warnings.emplace_back(m); }
  std::vector<std::string> infos, warnings;
};

// A session whose Printf output goes to a string.
struct ScriptRun {
  CollectingSink log;
  std::ostringstream out;
  Session session{log, out};

  // Runs `text` as the file "test.geo"; returns what it printed.
  std::string run(const std::string& text, const std::string& name = "test.geo") {
    runScriptText(session, text, name);
    return out.str();
  }
};

// What a script prints; throws like runScriptText.
inline std::string printed(const std::string& text) {
  ScriptRun run;
  return run.run(text);
}

// The complete diagnostic of a failing script, or "" if it does not fail.
inline std::string errorOf(const std::string& text) {
  ScriptRun run;
  try {
    run.run(text);
  } catch (const ScriptError& error) {
    return error.what();
  }
  return "";
}

// The message part of the first line of a failing script's diagnostic.
inline std::string firstLineOf(const std::string& text) {
  std::string all = errorOf(text);
  return all.substr(0, all.find('\n'));
}

}  // namespace geomesh::testing
