// Curves given by points (Line, Ellipse, Spline, BSpline, Bezier, Nurbs and their older
// names), the plane of a half circle, Split Curve, and PolarSphere.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iterator>

#include "interpreter/script_interpreter.h"
#include "api/session.h"
#include "kernel/geometry_error.h"

namespace geomesh {

using Words = std::vector<std::string>;

bool Interpreter::isCurveThroughPoints(const std::string& word) {
  static constexpr std::string_view kCurves[] = {"BSpline", "Bezier",  "CatmullRom", "Ellipse",
                                                 "Ellipsis", "Line", "Nurbs",      "Spline"};
  return std::find(std::begin(kCurves), std::end(kCurves), word) != std::end(kCurves);
}

// Line, Ellipse (or its older name Ellipsis), Spline (CatmullRom: the same curve), BSpline,
// Bezier and Nurbs: curves given by points, whose signs do not matter (Line(1) = {1, -2}).
void Interpreter::defineCurveThroughPoints(const ast::CommandStmt& command, int tag,
                                           std::vector<int> points) {
  for (int& p : points) p = std::abs(p);
  const std::string& kind = command.words[0];
  GeometryFactory& geo = session_.factory();
  const ast::Expr& value = *command.value;
  if (kind == "Line" && points.size() < 2)
    fail(value.loc, "Line takes 2 points or more, not " + std::to_string(points.size()));
  if (kind == "Nurbs") return defineNurbs(command, tag, points);
  if (!command.tail.empty()) fail(command.tail.front().value ? command.tail.front().value->loc
                                                             : value.loc,
                                  "unexpected words after " + kind + "(" +
                                      std::to_string(tag) + ") = {..}");
  if (kind == "Line" && points.size() == 2 && points[0] == points[1] &&
      geo.name() != "OpenCASCADE")
    warn(value.loc, "Line " + std::to_string(tag) + ": both ends are point " +
                        std::to_string(points[0]) + "; a line of no length makes no curve");
  if (kind == "Line" && points.size() == 2) return geo.addLine(tag, points[0], points[1]);
  if (kind == "Line") return geo.addPolyline(tag, points);
  if (kind == "Ellipse" || kind == "Ellipsis") {
    if (points.size() != 4)
      fail(value.loc, kind + " takes {start, center, major axis point, end}, not " +
                          std::to_string(points.size()) + " values");
    return geo.addEllipseArc(tag, points[0], points[1], points[2], points[3]);
  }
  if (kind == "Spline" || kind == "CatmullRom") return geo.addSpline(tag, points);
  if (kind == "BSpline") return geo.addBSpline(tag, points);
  geo.addBezier(tag, points);
}

// Nurbs(tag) = {points} Knots {knots} Order degree;
void Interpreter::defineNurbs(const ast::CommandStmt& command, int tag,
                              const std::vector<int>& points) {
  const ast::Expr* knots = nullptr;
  const ast::Expr* order = nullptr;
  for (const ast::TailItem& item : command.tail) {
    if (item.word == "Knots" && item.value && !knots) knots = item.value.get();
    else if (item.word == "Order" && item.value && !order) order = item.value.get();
    else fail(command.value->loc, "expected Nurbs(tag) = {points} Knots {knots} Order degree;");
  }
  if (!knots || !order)
    fail(command.value->loc, "expected Nurbs(tag) = {points} Knots {knots} Order degree;");
  const double degree = evaluateNumber(*order);
  if (degree != std::floor(degree)) fail(order->loc, "the order of a Nurbs must be an integer");
  session_.factory().addNurbs(tag, points, evaluateNumbers(*knots), clampedInteger<int>(degree));
}

// The normal of `Circle(..) = {..} Plane{nx, ny, nz};`, if given.
std::optional<Vec3> Interpreter::circlePlaneNormal(const ast::CommandStmt& command) {
  if (command.tail.empty()) return std::nullopt;
  const ast::Expr* plane = command.tail.front().value.get();
  const bool isPlane = command.tail.size() == 1 && plane && command.tail[0].word == "Plane";
  if (!isPlane)
    fail(command.value->loc, "expected Circle(tag) = {start, center, end} Plane{nx, ny, nz};");
  const std::vector<double> n = evaluateNumbers(*plane);
  if (n.size() != 3) fail(plane->loc, "Plane takes {nx, ny, nz}, not " + std::to_string(n.size()) + " values");
  return Vec3{n[0], n[1], n[2]};
}

// Split Curve{tags} Point{tags}; (Split Line: the same) cuts each curve at those of the points
// it passes through.
void Interpreter::executeSplitCurve(const ast::CommandStmt& command, const SourceLocation& where) {
  const ast::Expr* points = command.tail.empty() ? nullptr : command.tail.front().value.get();
  const bool pointShape = command.shape && command.tail.size() == 1 && points &&
                          points->kind == ast::ExprKind::Shape && points->words == Words{"Point"};
  if (!pointShape) fail(where, "expected Split Curve{curves} Point{points};");
  const std::vector<int> cuts = shapeTags(*points, 0);
  try {
    for (int curve : shapeTags(*command.shape, 1))
      session_.factory().splitCurve(std::abs(curve), cuts);
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
}

// PolarSphere(tag) = {center, point}; defines no entity: in Gmsh, a sphere that surfaces
// defined later may be projected onto. The built-in kernel recognises patches of spheres from
// their arcs alone, so the statement has nothing left to do.
void Interpreter::definePolarSphere(const ast::CommandStmt& command, const SourceLocation& where) {
  if (command.argStyle != ast::CommandStmt::Args::Paren || !command.value || command.op != "=")
    return unsupportedStatement(command, where);
  const std::vector<int> points = entityTags(*command.value);
  if (points.size() != 2)
    fail(command.value->loc, "PolarSphere takes {center point, point on the sphere}, not " +
                                 std::to_string(points.size()) + " values");
  for (int p : points)
    if (!session_.factory().hasPoint(std::abs(p)))
      fail(command.value->loc, "PolarSphere: point " + std::to_string(std::abs(p)) +
                                   " is not defined");
  session_.log().debug(where.file + ":" + std::to_string(where.line) +
                       ": PolarSphere defines no entity");
}

}  // namespace geomesh
