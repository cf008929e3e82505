// A .geo script run with a command line's settings, as runGeomesh runs it, in two stages.
#include "app/script_run.h"

#include <chrono>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "api/meshing.h"
#include "api/options.h"
#include "api/output.h"
#include "interpreter/diagnostics.h"
#include "interpreter/run_script.h"
#include "io/formats.h"
#include "mesh/high_order/set_order.h"

namespace geomesh {

void applySettings(const CommandLine& settings, Session& session) {
  session.options().setNumber("General.Verbosity", settings.verbosity);
  session.allowSystemCalls(settings.allowSystemCalls);
  for (const auto& [name, value] : settings.setNumbers) api::setNumber(session, name, value);
  for (const auto& [name, value] : settings.setStrings) api::setString(session, name, value);
  for (const auto& [name, value] : settings.numberOptions) session.options().setNumber(name, value);
}

std::string formatSeconds(double seconds) {
  std::ostringstream os;
  os.precision(3);
  os << seconds << " s";
  return os.str();
}

bool evaluateScriptFile(const std::string& file, Session& session, ConsoleLog& log) {
  const auto start = std::chrono::steady_clock::now();
  log.info("Reading '" + file + "'...");
  try {
    runScriptFile(session, file);
  } catch (const ScriptExit&) {
    log.info("Script called Exit: stopping");
    return false;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  log.info("Done reading '" + file + "' (" + formatSeconds(seconds) + ")");
  return true;
}

void checkElementOrder(const Session& session, const MeshFormat* format, const std::string& path) {
  const int order = session.meshOptions().elementOrder;
  if (const std::string why = unsupportedOrderReason(order); !why.empty())
    throw std::invalid_argument("Mesh.ElementOrder: " + why);
  if (!format) return;
  if (const std::string why = orderUnsupportedReason(*format, order); !why.empty())
    throw std::invalid_argument("cannot write elements of order " + std::to_string(order) +
                                " to '" + path + "': " + why);
}

ScriptRun::ScriptRun(CommandLine settings, std::ostream& out, std::ostream& err)
    : settings_(std::move(settings)), log_(err, settings_.verbosity), session_(log_, out) {
  if (settings_.files.size() != 1)
    throw std::invalid_argument("a script run needs exactly one script, got " +
                                std::to_string(settings_.files.size()));
  applySettings(settings_, session_);
}

bool ScriptRun::evaluate() { return evaluateScriptFile(settings_.files.front(), session_, log_); }

void ScriptRun::meshAndWrite() {
  session_.synchronize();
  if (!settings_.dimension) return;
  const int dim = *settings_.dimension;
  const std::string& path = settings_.output;
  if (dim == 0) {
    if (!path.empty()) api::writeUnrolledGeometry(session_, path);
    return;
  }
  const MeshFormat* format =
      path.empty() ? nullptr : &api::outputFormat(session_.options(), path, settings_.format);
  checkElementOrder(session_, format, path);
  api::requireSomethingToMesh(session_, dim);
  api::generate(session_, dim);
  if (format) {
    log_.info("Writing '" + path + "'...");
    api::writeMesh(session_, path, *format);
    log_.info("Done writing '" + path + "'");
  }
}

}  // namespace geomesh
