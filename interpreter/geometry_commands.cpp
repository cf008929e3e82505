// Geometry statements that map onto the built-in factory: Point, Line, Curve Loop, Plane
// Surface, Surface Loop, Volume, Physical groups; and shapes used as values (Point{t}).
#include <cmath>

#include "interpreter/script_interpreter.h"
#include "interpreter/session.h"
#include "kernel/geometry_error.h"

namespace geomesh {

namespace {

using Words = std::vector<std::string>;

int physicalDimension(const Words& words) {
  if (words.size() != 2 || words[0] != "Physical") return -1;
  if (words[1] == "Point") return 0;
  if (words[1] == "Line" || words[1] == "Curve") return 1;
  if (words[1] == "Surface") return 2;
  if (words[1] == "Volume") return 3;
  return -1;
}

std::string joined(const Words& words) {
  std::string text;
  for (const auto& word : words) text += (text.empty() ? "" : " ") + word;
  return text;
}

}  // namespace

std::vector<int> Interpreter::entityTags(const ast::Expr& list) {
  std::vector<int> tags;
  for (double x : evaluateNumbers(list)) {
    if (x != std::floor(x)) fail(list.loc, "entity tag " + std::to_string(x) + " is not an integer");
    tags.push_back(static_cast<int>(x));
  }
  return tags;
}

int Interpreter::entityTag(const ast::CommandStmt& command, const SourceLocation& where) {
  if (command.args.size() != 1)
    fail(where, "'" + joined(command.words) + "' takes one tag in parentheses");
  const double tag = evaluateNumber(*command.args[0]);
  if (tag != std::floor(tag) || tag <= 0)
    fail(command.args[0]->loc, "tag of '" + joined(command.words) + "' must be a positive integer");
  return static_cast<int>(tag);
}

bool Interpreter::executeGeometry(const ast::CommandStmt& command, const SourceLocation& where) {
  const Words& w = command.words;
  if (command.argStyle != ast::CommandStmt::Args::Paren || !command.value) return false;
  const int physical = physicalDimension(w);
  if (physical >= 0) {
    definePhysical(command, physical, where);
    return true;
  }
  if (w == Words{"Circle"} && command.op == "=") return defineCircleArc(command, where);
  const bool known = w == Words{"Point"} || w == Words{"Line"} || w == Words{"Curve", "Loop"} ||
                     w == Words{"Line", "Loop"} || w == Words{"Plane", "Surface"} ||
                     w == Words{"Surface", "Loop"} || w == Words{"Volume"};
  if (!known || command.op != "=") return false;
  const int tag = entityTag(command, where);
  const ast::Expr& value = *command.value;
  std::vector<int> tags;
  try {
    if (w == Words{"Point"}) {
      std::vector<double> xs = evaluateNumbers(value);
      if (xs.size() != 3 && xs.size() != 4)
        fail(value.loc, "Point takes {x, y, z} or {x, y, z, size}, not " +
                            std::to_string(xs.size()) + " values");
      session_.geo().addPoint(tag, Vec3{xs[0], xs[1], xs[2]}, xs.size() == 4 ? xs[3] : 0.0);
      return true;
    }
    tags = entityTags(value);
    if (w == Words{"Line"}) {
      if (tags.size() != 2)
        fail(value.loc, "Line takes 2 points, not " + std::to_string(tags.size()));
      session_.geo().addLine(tag, tags[0], tags[1]);
    } else if (w[0] == "Curve" || w[0] == "Line") {
      session_.geo().addCurveLoop(tag, tags);
    } else if (w[0] == "Plane") {
      session_.geo().addPlaneSurface(tag, tags);
    } else if (w[0] == "Surface") {
      session_.geo().addSurfaceLoop(tag, tags);
    } else {
      session_.geo().addVolume(tag, tags);
    }
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
  return true;
}

// Circle(tag) = {start, center, end}: an arc of at most half a turn. Other forms (the
// OpenCASCADE {x, y, z, r} circle) are not supported by the built-in kernel.
bool Interpreter::defineCircleArc(const ast::CommandStmt& command, const SourceLocation& where) {
  const int tag = entityTag(command, where);
  const std::vector<int> points = entityTags(*command.value);
  if (points.size() != 3) return false;
  try {
    session_.geo().addCircleArc(tag, points[0], points[1], points[2]);
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
  return true;
}

// Physical X(tag) = {..};  Physical X("name") = {..};  Physical X("name", tag) = {..};
// A group given only a name reuses the tag of the group of that name, or takes the next tag
// after every physical tag used so far (all dimensions).
void Interpreter::definePhysical(const ast::CommandStmt& command, int dim,
                                 const SourceLocation& where) {
  if (command.args.empty() || command.args.size() > 2)
    fail(where, "'" + joined(command.words) + "' takes a tag, a name, or a name and a tag");
  if (command.op == "-=") {
    warn(where, "removing entities from a physical group is not supported yet; ignored");
    return;
  }
  Value first = evaluate(*command.args[0]);
  std::string name;
  int tag = 0;
  if (first.kind() == Value::Kind::String) {
    name = first.strings()[0];
    if (command.args.size() == 2) {
      tag = static_cast<int>(evaluateNumber(*command.args[1]));
    } else if (auto known = physicalNames_.find({dim, name}); known != physicalNames_.end()) {
      tag = known->second;
    } else {
      tag = maxPhysicalTag_ + 1;
    }
  } else {
    tag = entityTag(command, where);
  }
  if (tag <= 0) fail(where, "physical tag must be a positive integer");
  std::vector<int> entities = entityTags(*command.value);
  try {
    session_.geo().addPhysicalGroup(dim, tag, name, entities);
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
  if (!name.empty()) physicalNames_[{dim, name}] = tag;
  maxPhysicalTag_ = std::max(maxPhysicalTag_, tag);
}

// Point{t} is the coordinates of point t; other shapes as values are not supported yet.
Value Interpreter::shapeValue(const ast::Expr& expr) {
  if (expr.words == Words{"Point"} && expr.parts.size() == 1 && !expr.parts[0].isBlock) {
    std::vector<double> coordinates;
    for (const auto& item : expr.parts[0].items) {
      for (int tag : entityTags(*item)) {
        try {
          Vec3 p = session_.geo().pointCoordinates(tag);
          coordinates.insert(coordinates.end(), {p.x, p.y, p.z});
        } catch (const GeometryError& error) {
          fail(item->loc, error.what());
        }
      }
    }
    return Value::list(std::move(coordinates));
  }
  warn(expr.loc, "'" + joined(expr.words) + "' is not supported yet; gives an empty list");
  return Value::list({});
}

}  // namespace geomesh
