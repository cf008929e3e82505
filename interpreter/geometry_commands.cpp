// Geometry statements that map onto the selected factory: Point, Line, Curve Loop, Plane
// Surface, Surface Loop, Volume, Box, Physical groups.
#include <algorithm>
#include <cmath>
#include <iterator>

#include "interpreter/script_interpreter.h"
#include "api/session.h"
#include "kernel/geometry_error.h"
#include "stdlib/format.h"

namespace geomesh {

namespace {

using Words = std::vector<std::string>;

// Entities are defined as in Point(1) = {0, 0, 0};
bool isDefinition(const ast::CommandStmt& command) {
  return command.argStyle == ast::CommandStmt::Args::Paren && command.value && command.op == "=";
}

// Physical Point, Physical Line or Curve, Physical Surface, Physical Volume.
int physicalDimension(const Words& words) {
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
    if (x != std::floor(x))
      fail(list.loc, "entity tag " + std::to_string(x) + " is not an integer");
    tags.push_back(clampedInteger<int>(x));
  }
  return tags;
}

int Interpreter::entityTag(const ast::CommandStmt& command, const SourceLocation& where) {
  if (command.args.size() != 1)
    fail(where, "'" + joined(command.words) + "' takes one tag in parentheses");
  const double tag = evaluateNumber(*command.args[0]);
  if (tag != std::floor(tag))
    fail(command.args[0]->loc, "tag of '" + joined(command.words) + "' must be an integer");
  if (tag >= 0) return clampedInteger<int>(tag);
  // As in Gmsh: a negative tag is the next free one, or for a physical group its opposite.
  if (command.words[0] == "Physical") return clampedInteger<int>(-tag);
  return session_.factory().maxTag(tagKind(command.words)) + 1;
}

// The numbering a definition's tag belongs to: a dimension, or one of the two kinds of loops.
int Interpreter::tagKind(const std::vector<std::string>& words) {
  if (words.size() == 2 && words[1] == "Loop")
    return words[0] == "Surface" ? GeometryFactory::kSurfaceLoop : GeometryFactory::kCurveLoop;
  if (words.back() == "Point") return 0;
  if (words.back() == "Surface" || words.back() == "Sphere") return 2;
  if (words.back() == "Volume") return 3;
  return 1;
}

// Line(t) = {..}; and the other entities given by their tag and a list of tags: Curve Loop,
// Plane Surface, Surface Loop, Volume, Ellipse, Spline, BSpline, Bezier, Surface, Ruled Surface.
// What follows a surface definition: `Using Point{..}` (points an OpenCASCADE filling passes
// through) and `In Sphere{c}` (the built-in kernel recognises a patch of sphere from its arcs
// alone). Returns the points; anything else warns and is ignored.
std::vector<int> Interpreter::fillingPoints(const ast::CommandStmt& command,
                                           const SourceLocation& where) {
  std::vector<int> points;
  for (const ast::TailItem& item : command.tail) {
    const ast::Expr* shape = item.value.get();
    const bool isShape = shape && shape->kind == ast::ExprKind::Shape && shape->words.size() == 1;
    const bool filling = command.words.back() == "Surface" && command.words.size() == 1;
    if (filling && isShape && item.word == "Using" && shape->words[0] == "Point") {
      for (double t : shapeArguments(*shape)) points.push_back(clampedInteger<int>(t));
      if (session_.factory().name() != "OpenCASCADE")
        warn(where, "'Using Point' constrains OpenCASCADE fillings only; ignored here");
    } else if (!(filling && isShape && item.word == "In" && shape->words[0] == "Sphere")) {
      warn(where, "'" + item.word + "' after " + joined(command.words) +
                      " is not supported; ignored");
    }
  }
  return points;
}

void Interpreter::defineEntity(const ast::CommandStmt& command, const SourceLocation& where) {
  const Words& w = command.words;
  if (!isDefinition(command)) return embedEntities(command, where);
  const int tag = entityTag(command, where);
  const ast::Expr& value = *command.value;
  const std::vector<int> tags = entityTags(value);
  if (w.size() == 1 && isCurveThroughPoints(w[0])) {
    try {
      defineCurveThroughPoints(command, tag, tags);
    } catch (const GeometryError& error) {
      fail(where, error.what());
    }
    return session_.recordOrigin({1, tag}, where);
  }
  const std::vector<int> through = fillingPoints(command, where);
  GeometryFactory& geo = session_.factory();
  auto requireCount = [&](std::size_t count, const char* what) {
    if (tags.size() != count)
      fail(value.loc, joined(w) + " takes " + what + ", not " + std::to_string(tags.size()) +
                          " values");
  };
  try {
    if (w.size() == 2 && w[1] == "Loop") {
      if (w[0] == "Surface")
        geo.addSurfaceLoop(tag, tags);
      else
        geo.addCurveLoop(tag, tags);
    } else if (w == Words{"BSpline", "Surface"} || w == Words{"Bezier", "Surface"}) {
      requireCount(1, "one curve loop");
      if (SolidModeling* solids = solidModeling(joined(w), where))
        solids->addCurveFilling(tag, tags[0], w[0] == "Bezier");
    } else if (w == Words{"Plane", "Surface"}) {
      geo.addPlaneSurface(tag, tags);
      warnIfNearlyPlane(tag, where);
    } else if (w.back() == "Surface") {
      geo.addFillingSurface(tag, tags, through);
    } else {
      geo.addVolume(tag, tags);
    }
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
  if (w.back() != "Loop") {
    const int dim = w.back() == "Surface" ? 2 : w.back() == "Volume" ? 3 : 1;
    session_.recordOrigin({dim, tag}, where);
  }
}

// A plane surface whose loops are a little off their mean plane is meshed on that plane.
void Interpreter::warnIfNearlyPlane(int tag, const SourceLocation& where) {
  const double deviation = session_.factory().planeDeviation(tag);
  if (deviation == 0) return;
  const std::vector<FormatArgument> shown{deviation};
  warn(where, "Plane Surface " + std::to_string(tag) + ": its loops are not exactly plane (up to " +
                  formatPrintf("%g", shown) +
                  " off their mean plane); meshed on that plane");
}

void Interpreter::definePoint(const ast::CommandStmt& command, const SourceLocation& where) {
  if (!isDefinition(command)) return embedEntities(command, where);
  const int tag = entityTag(command, where);
  const ast::Expr& value = *command.value;
  std::vector<double> xs = evaluateNumbers(value);
  if (xs.size() < 3 || xs.size() > 5)
    fail(value.loc, "Point takes {x, y, z}, {x, y, z, size} or {x, y, z, size, weight}, not " +
                        std::to_string(xs.size()) + " values");
  // Older scripts give Nurbs control points a weight; the reference ignores it, and so does
  // geomesh, saying so.
  if (xs.size() == 5)
    warn(value.loc, "Point " + std::to_string(tag) + ": its weight (fifth value) is ignored");
  try {
    session_.factory().addPoint(tag, Vec3{xs[0], xs[1], xs[2]}, xs.size() == 4 ? xs[3] : 0.0);
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
}

// Box(tag) = {x, y, z, dx, dy, dz}; a box of the OpenCASCADE factory (a negative tag: the
// next free volume tag). The built-in factory has none: there it warns and is ignored.
void Interpreter::defineBox(const ast::CommandStmt& command, const SourceLocation& where) {
  if (!isDefinition(command)) return unsupportedStatement(command, where);
  if (command.args.size() != 1) fail(where, "'Box' takes one tag in parentheses");
  const double tag = evaluateNumber(*command.args[0]);
  if (tag != std::floor(tag) || tag == 0)
    fail(command.args[0]->loc, "tag of 'Box' must be a non-zero integer");
  const std::vector<double> xs = evaluateNumbers(*command.value);
  if (xs.size() != 6)
    fail(command.value->loc,
         "Box takes {x, y, z, dx, dy, dz}, not " + std::to_string(xs.size()) + " values");
  int made = 0;
  try {
    made = session_.factory().addBox(clampedInteger<int>(tag), Vec3{xs[0], xs[1], xs[2]},
                                     Vec3{xs[3], xs[4], xs[5]});
  } catch (const UnsupportedOperation&) {
    warn(where, "'Box' needs SetFactory(\"OpenCASCADE\"); ignored");
    return;
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
  session_.recordOrigin({3, made}, where);
}

// The selected factory handed an operation over to the built-in kernel: said once per kind of
// operation, at the statement that first needed it.
void Interpreter::reportHandover(const UnsupportedOperation& unsupported) {
  if (!handedOver_.insert(unsupported.operation()).second) return;
  static constexpr const char* kDefinitions[] = {
      "Point",         "Line",    "Circle",       "Ellipse", "Spline",    "BSpline", "Bezier",
      "Curve Loop",    "Surface", "Surface Loop", "Volume",  "Duplicata", "Extrude",
      "Plane Surface"};
  const bool defines = std::find(std::begin(kDefinitions), std::end(kDefinitions),
                                 unsupported.operation()) != std::end(kDefinitions);
  warn(statementLocation_ ? *statementLocation_ : SourceLocation{},
       "'" + unsupported.operation() + "' is not supported by the " + unsupported.factory() +
           " factory yet; the built-in kernel " + (defines ? "builds it" : "carries it out"));
}

// Circle(tag) = {start, center, end}: an arc of at most half a turn. Other forms (the
// OpenCASCADE {x, y, z, r} circle) are not supported by the built-in kernel.
void Interpreter::defineCircleArc(const ast::CommandStmt& command, const SourceLocation& where) {
  if (!isDefinition(command)) return unsupportedStatement(command, where);
  if (defineConic(command, where)) return;  // OpenCASCADE's {x, y, z, r <, a1, a2>}
  const int tag = entityTag(command, where);
  if (evaluateNumbers(*command.value).size() != 3) return unsupportedStatement(command, where);
  std::vector<int> points = entityTags(*command.value);
  for (int& p : points) p = std::abs(p);
  const std::optional<Vec3> normal = circlePlaneNormal(command);
  if (points[0] == points[2] && points[0] != points[1])
    warn(where, "Circle " + std::to_string(tag) + " goes a whole turn from point " +
                    std::to_string(points[0]) + " back to it: arcs of more than half a turn "
                    "are better split in two");
  try {
    if (normal)
      session_.factory().addCircleArcAbout(tag, points[0], points[1], points[2], *normal);
    else
      session_.factory().addCircleArc(tag, points[0], points[1], points[2]);
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
  session_.recordOrigin({1, tag}, where);
}

void Interpreter::executePhysical(const ast::CommandStmt& command, const SourceLocation& where) {
  if (command.argStyle != ast::CommandStmt::Args::Paren || !command.value)
    return unsupportedStatement(command, where);
  definePhysical(command, physicalDimension(command.words), where);
}

// Physical X(tag) = {..};  Physical X("name") = {..};  Physical X("name", tag) = {..};
// A group given only a name reuses the tag of the group of that name, or takes the next tag
// after every physical tag used so far (all dimensions).
void Interpreter::definePhysical(const ast::CommandStmt& command, int dim,
                                 const SourceLocation& where) {
  if (command.args.empty() || command.args.size() > 2)
    fail(where, "'" + joined(command.words) + "' takes a tag, a name, or a name and a tag");
  GeometryFactory& geo = session_.factory();
  Value first = evaluate(*command.args[0]);
  std::string name;
  int tag = 0;
  if (first.kind() == Value::Kind::String) {
    name = first.strings()[0];
    tag = command.args.size() == 2 ? clampedInteger<int>(evaluateNumber(*command.args[1]))
                                   : physicalTagFor(dim, name);
  } else {
    tag = entityTag(command, where);
  }
  tag = std::abs(tag);  // Physical Point(-5) is group 5, as in Gmsh
  std::vector<int> entities = entityTags(*command.value);
  try {
    if (command.op == "-=")
      geo.removeFromPhysicalGroup(dim, tag, entities);
    else
      geo.addPhysicalGroup(dim, tag, name, entities);
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
}

// The tag of the group of that name and dimension, else the next after every physical tag
// in use (all dimensions), as Gmsh numbers them.
int Interpreter::physicalTagFor(int dim, const std::string& name) const {
  int largest = 0;
  for (const auto& [id, group] : session_.factory().physicalGroups()) {
    if (id.dim == dim && group.name == name) return id.tag;
    largest = std::max(largest, id.tag);
  }
  return largest + 1;
}

}  // namespace geomesh
