// Curves of the built-in kernel: their definitions and the geometry built from their points.
#include <cmath>
#include <optional>

#include "kernel/geo/circle_arc_geometry.h"
#include "kernel/geo/ellipse_arc_geometry.h"
#include "kernel/geo/geo_factory.h"
#include "kernel/geo/geo_detail.h"
#include "kernel/geo/line_geometry.h"
#include "kernel/geo/polyline_geometry.h"
#include "kernel/geo/spline_geometry.h"

namespace geomesh {

using geo_detail::fail;
using geo_detail::requireNew;

void GeoFactory::addCircleArc(int tag, int startPoint, int centerPoint, int endPoint) {
  requireNew(curves_, tag, "Curve");
  for (int p : {startPoint, centerPoint, endPoint})
    if (!hasPoint(p)) fail("Circle ", tag, ": point ", p, " is not defined");
  const Vec3 start = points_.at(startPoint).xyz, center = points_.at(centerPoint).xyz;
  const Vec3 end = points_.at(endPoint).xyz;
  const double r1 = distance(start, center), r2 = distance(end, center);
  const double tolerance = absoluteTolerance();
  if (r1 <= tolerance || r2 <= tolerance)
    fail("Circle ", tag, ": its center, point ", centerPoint, ", is one of its ends");
  // From a point back to itself: a whole circle (the reference warns that the arc is more
  // than half a turn, and builds it).
  if (startPoint != endPoint && distance(start, end) <= tolerance)
    fail("Circle ", tag, ": points ", startPoint, " and ", endPoint, " coincide");
  if (std::abs(r1 - r2) > 0.1 * std::max(r1, r2))
    fail("Circle ", tag, ": points ", startPoint, " and ", endPoint,
         " are not on one circle around point ", centerPoint, " (radii ", r1, " and ", r2, ")");
  curves_[tag] = Curve{tag, CurveKind::CircleArc, {startPoint, centerPoint, endPoint}};
  noteTag(1, tag);
}

void GeoFactory::addCircleArcAbout(int tag, int startPoint, int centerPoint, int endPoint,
                                   Vec3 normal) {
  if (!(norm(normal) > 0)) fail("Circle ", tag, ": its plane's normal is zero");
  addCircleArc(tag, startPoint, centerPoint, endPoint);
  curves_.at(tag).normal = normalized(normal);
}

void GeoFactory::addPolyline(int tag, const std::vector<int>& points) {
  if (points.size() == 2) return addLine(tag, points[0], points[1]);
  addControlPointCurve(tag, CurveKind::Line, points, "Line");
  for (std::size_t i = 1; i < points.size(); ++i)
    if (distance(points_.at(points[i - 1]).xyz, points_.at(points[i]).xyz) <= absoluteTolerance())
      fail("Line ", tag, ": points ", points[i - 1], " and ", points[i], " coincide");
}

void GeoFactory::addNurbs(int tag, const std::vector<int>& points,
                          const std::vector<double>& knots, int degree) {
  if (degree < 1) fail("Nurbs ", tag, ": its order must be at least 1, not ", degree);
  if (points.size() < static_cast<std::size_t>(degree) + 1)
    fail("Nurbs ", tag, ": order ", degree, " needs at least ", degree + 1, " points");
  if (knots.size() != points.size() + degree + 1)
    fail("Nurbs ", tag, ": ", points.size(), " points of order ", degree, " need ",
         points.size() + degree + 1, " knots, not ", knots.size());
  for (std::size_t i = 1; i < knots.size(); ++i)
    if (!(knots[i] >= knots[i - 1])) fail("Nurbs ", tag, ": its knots decrease");
  if (!(knots[points.size()] > knots[degree])) fail("Nurbs ", tag, ": its knot span is empty");
  addControlPointCurve(tag, CurveKind::BSpline, points, "Nurbs");
  curves_.at(tag).knots = knots;
  curves_.at(tag).degree = degree;
}

void GeoFactory::addEllipseArc(int tag, int startPoint, int centerPoint, int majorAxisPoint,
                               int endPoint) {
  requireNew(curves_, tag, "Curve");
  for (int p : {startPoint, centerPoint, majorAxisPoint, endPoint})
    if (!hasPoint(p)) fail("Ellipse ", tag, ": point ", p, " is not defined");
  if (distance(points_.at(startPoint).xyz, points_.at(endPoint).xyz) <= absoluteTolerance())
    fail("Ellipse ", tag, ": points ", startPoint, " and ", endPoint, " coincide");
  Curve curve{tag, CurveKind::EllipseArc, {startPoint, centerPoint, majorAxisPoint, endPoint}};
  curveGeometry(curve);  // throws when no ellipse fits
  curves_[tag] = std::move(curve);
  noteTag(1, tag);
}

void GeoFactory::addSpline(int tag, const std::vector<int>& points) {
  addControlPointCurve(tag, CurveKind::Spline, points, "Spline");
}

void GeoFactory::addBSpline(int tag, const std::vector<int>& points) {
  addControlPointCurve(tag, CurveKind::BSpline, points, "BSpline");
}

void GeoFactory::addBezier(int tag, const std::vector<int>& points) {
  addControlPointCurve(tag, CurveKind::Bezier, points, "Bezier");
}

void GeoFactory::addControlPointCurve(int tag, CurveKind kind, const std::vector<int>& points,
                                      const char* what) {
  requireNew(curves_, tag, "Curve");
  if (points.size() < 2) fail(what, " ", tag, ": needs at least 2 points, not ", points.size());
  for (int p : points)
    if (!hasPoint(p)) fail(what, " ", tag, ": point ", p, " is not defined");
  curves_[tag] = Curve{tag, kind, points};
  noteTag(1, tag);
}

namespace {

// The axis an arc turns about: normal to its ends' radii, or for a half circle (where they are
// opposite), the normal given with it, else the coordinate axis most normal to them, z first.
Vec3 arcAxis(Vec3 center, Vec3 start, Vec3 end, std::optional<Vec3> given) {
  const Vec3 v1 = start - center, v2 = end - center;
  const Vec3 n = cross(v1, v2);
  if (norm(n) > 1e-10 * norm(v1) * norm(v2)) return normalized(n);
  const Vec3 e1 = normalized(v1);
  if (given) {
    const Vec3 across = *given - dot(*given, e1) * e1;
    if (norm(across) > 1e-10) return normalized(across);
  }
  Vec3 best{0, 0, 1};
  for (Vec3 axis : {Vec3{0, 1, 0}, Vec3{1, 0, 0}})
    if (std::abs(dot(axis, e1)) < std::abs(dot(best, e1)) - 1e-12) best = axis;
  return normalized(best - dot(best, e1) * e1);
}

}  // namespace

std::shared_ptr<const CurveGeometry> GeoFactory::curveGeometry(const Curve& c) const {
  std::vector<Vec3> xyz;
  for (int p : c.points) xyz.push_back(points_.at(p).xyz);
  const bool closed = c.points.size() > 2 && c.start() == c.end();
  switch (c.kind) {
    case CurveKind::Line:
      if (xyz.size() > 2) return std::make_shared<PolylineGeometry>(std::move(xyz));
      return std::make_shared<LineGeometry>(xyz.front(), xyz.back());
    case CurveKind::CircleArc:
      return std::make_shared<CircleArcGeometry>(xyz[1], xyz[0], xyz[2],
                                                 arcAxis(xyz[1], xyz[0], xyz[2], c.normal));
    case CurveKind::EllipseArc:
      return std::make_shared<EllipseArcGeometry>(
          makeEllipseArc(xyz[0], xyz[1], xyz[2], xyz[3], "Ellipse " + std::to_string(c.tag)));
    case CurveKind::Spline: return std::make_shared<CatmullRomGeometry>(std::move(xyz));
    case CurveKind::BSpline:
      if (!c.knots.empty())
        return std::make_shared<BSplineGeometry>(std::move(xyz), c.degree, c.knots);
      return std::make_shared<BSplineGeometry>(BSplineGeometry::uniform(std::move(xyz), closed));
    case CurveKind::Bezier:
      return std::make_shared<BSplineGeometry>(BSplineGeometry::bezier(std::move(xyz)));
    case CurveKind::Other:
      if (!c.trace.empty()) return std::make_shared<PolylineGeometry>(c.trace);
      break;
  }
  fail("Curve ", c.tag, ": unknown kind");
}

}  // namespace geomesh
