// Feeds arbitrary bytes to the script front end (lexer, parser, evaluator) and the built-in
// kernel. Any outcome but a success or a script diagnostic is a bug: an uncaught exception,
// a crash, a hang or a sanitizer report.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "interpreter/diagnostics.h"
#include "api/session.h"
#include "interpreter/run_script.h"
#include "kernel/geometry_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  geomesh::SilentSink log;
  std::ostringstream out;
  geomesh::Session session(log, out);
  session.setSandboxed(true);  // arbitrary scripts must not write files or mesh for minutes
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    geomesh::runScriptText(session, text, "fuzz.geo");
    session.synchronize();
  } catch (const geomesh::ScriptError&) {
  } catch (const geomesh::ScriptExit&) {
  } catch (const geomesh::GeometryError&) {
  }
  return 0;
}
