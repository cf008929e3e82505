// MeshSize{points} = size; and its old spelling Characteristic Length{points} = size;
#include <cmath>

#include "interpreter/script_interpreter.h"
#include "api/session.h"
#include "kernel/geometry_error.h"

namespace geomesh {

void Interpreter::executeMeshSize(const ast::CommandStmt& command, const SourceLocation& where) {
  if (!command.shape || command.op != "=" || !command.value)
    return unsupportedStatement(command, where);
  if (command.shape->parts.size() != 1 || command.shape->parts[0].isBlock)
    fail(where, "MeshSize takes point tags, as in MeshSize{1, 2} = 0.1;");
  std::vector<int> points;
  for (const auto& item : command.shape->parts[0].items) {
    if (item->kind == ast::ExprKind::All) {  // MeshSize{:}: every point
      const std::vector<int> all = allTags(0);
      points.insert(points.end(), all.begin(), all.end());
      continue;
    }
    for (double x : evaluateNumbers(*item)) {
      if (x != std::floor(x) || x <= 0)
        fail(item->loc, "point tag " + std::to_string(x) + " is not a positive integer");
      points.push_back(clampedInteger<int>(x));
    }
  }
  // Like Gmsh, tags of no point are skipped (scripts often give a whole range of tags).
  std::vector<int> missing;
  std::erase_if(points, [&](int tag) {
    if (session_.factory().hasPoint(tag)) return false;
    missing.push_back(tag);
    return true;
  });
  if (!missing.empty())
    warn(where, "MeshSize: " + std::to_string(missing.size()) + " of the tags name no point (" +
                    std::to_string(missing.front()) + (missing.size() > 1 ? ", ..." : "") +
                    "); skipped");
  const double size = evaluateNumber(*command.value);
  if (!std::isfinite(size) || size < 0)
    fail(command.value->loc, "mesh size must be a finite number >= 0");
  try {
    session_.factory().setMeshSize(points, size);
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
}

}  // namespace geomesh
