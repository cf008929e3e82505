// MeshSize{points} = size; and its old spelling Characteristic Length{points} = size;
#include <cmath>

#include "interpreter/script_interpreter.h"
#include "interpreter/session.h"
#include "kernel/geometry_error.h"

namespace geomesh {

bool Interpreter::executeMeshSize(const ast::CommandStmt& command, const SourceLocation& where) {
  if (!command.shape || command.op != "=" || !command.value) return false;
  const std::vector<std::string>& words = command.shape->words;
  const bool isMeshSize = words == std::vector<std::string>{"MeshSize"} ||
                          words == std::vector<std::string>{"Characteristic", "Length"};
  if (!isMeshSize) return false;
  if (command.shape->parts.size() != 1 || command.shape->parts[0].isBlock)
    fail(where, "MeshSize takes point tags, as in MeshSize{1, 2} = 0.1;");
  std::vector<int> points;
  for (double x : evaluateNumbers(command.shape->parts[0].items)) {
    if (x != std::floor(x) || x <= 0)
      fail(command.shape->loc, "point tag " + std::to_string(x) + " is not a positive integer");
    points.push_back(static_cast<int>(x));
  }
  const double size = evaluateNumber(*command.value);
  if (!std::isfinite(size) || size < 0)
    fail(command.value->loc, "mesh size must be a finite number >= 0");
  try {
    session_.geo().setMeshSize(points, size);
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
  return true;
}

}  // namespace geomesh
