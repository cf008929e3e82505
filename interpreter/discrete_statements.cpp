// ClassifySurfaces, CreateTopology and CreateGeometry: merged triangulations made into
// surfaces, curves and points, and given geometry.
#include <numbers>
#include <stdexcept>

#include "api/session.h"
#include "interpreter/script_interpreter.h"

namespace geomesh {

// The numbers of `Name{a, b, ...}` (none for a bare `Name;`).
std::vector<double> Interpreter::braceNumbers(const ast::CommandStmt& command, const char* usage,
                                              const SourceLocation& where) {
  if (!command.shape) {
    if (command.argStyle != ast::CommandStmt::Args::None || command.value) fail(where, usage);
    return {};
  }
  if (command.shape->parts.size() != 1) fail(where, usage);
  return evaluateNumbers(command.shape->parts[0].items);
}

// ClassifySurfaces{angle, boundary, forReparametrization <, curveAngle>};
void Interpreter::classifySurfaces(const ast::CommandStmt& command, const SourceLocation& where) {
  const char* usage =
      "ClassifySurfaces takes an angle (radians), whether to include the boundary, whether to "
      "make surfaces fit for reparametrization and optionally a curve angle, as in "
      "ClassifySurfaces{40 * Pi / 180, 1, 0, Pi};";
  const std::vector<double> values = braceNumbers(command, usage, where);
  if (values.size() < 3 || values.size() > 4) fail(where, usage);
  const double curveAngle = values.size() == 4 ? values[3] : std::numbers::pi;
  try {
    session_.classifySurfaces(values[0], values[1] != 0, values[2] != 0, curveAngle);
  } catch (const std::runtime_error& error) {
    fail(where, error.what());
  }
}

// CreateTopology; or CreateTopology{makeSimplyConnected, exportDiscrete}; (surfaces are split
// into their connected parts either way).
void Interpreter::createTopology(const ast::CommandStmt& command, const SourceLocation& where) {
  const std::vector<double> values = braceNumbers(
      command, "CreateTopology takes at most two flags, as in CreateTopology{1, 1};", where);
  if (values.size() > 2) fail(where, "CreateTopology takes at most two flags");
  try {
    session_.createTopology();
  } catch (const std::runtime_error& error) {
    fail(where, error.what());
  }
}

void Interpreter::createGeometry(const ast::CommandStmt& command, const SourceLocation& where) {
  if (command.shape || command.argStyle != ast::CommandStmt::Args::None || command.value)
    fail(where, "CreateGeometry takes no values: CreateGeometry;");
  try {
    session_.createGeometry();
  } catch (const std::runtime_error& error) {
    fail(where, error.what());
  }
}

}  // namespace geomesh
