// Curves of the built-in kernel: their definitions and the geometry built from their points.
#include <cmath>

#include "kernel/geo/circle_arc_geometry.h"
#include "kernel/geo/ellipse_arc_geometry.h"
#include "kernel/geo/geo_factory.h"
#include "kernel/geo/geo_detail.h"
#include "kernel/geo/line_geometry.h"
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
  if (distance(start, end) <= tolerance)
    fail("Circle ", tag, ": points ", startPoint, " and ", endPoint, " coincide");
  if (std::abs(r1 - r2) > 0.1 * std::max(r1, r2))
    fail("Circle ", tag, ": points ", startPoint, " and ", endPoint,
         " are not on one circle around point ", centerPoint, " (radii ", r1, " and ", r2, ")");
  curves_[tag] = Curve{tag, CurveKind::CircleArc, {startPoint, centerPoint, endPoint}};
  noteTag(1, tag);
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
// opposite), the coordinate axis most normal to them, z first.
Vec3 arcAxis(Vec3 center, Vec3 start, Vec3 end) {
  const Vec3 v1 = start - center, v2 = end - center;
  const Vec3 n = cross(v1, v2);
  if (norm(n) > 1e-10 * norm(v1) * norm(v2)) return normalized(n);
  const Vec3 e1 = normalized(v1);
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
    case CurveKind::Line: return std::make_shared<LineGeometry>(xyz.front(), xyz.back());
    case CurveKind::CircleArc:
      return std::make_shared<CircleArcGeometry>(xyz[1], xyz[0], xyz[2],
                                                 arcAxis(xyz[1], xyz[0], xyz[2]));
    case CurveKind::EllipseArc:
      return std::make_shared<EllipseArcGeometry>(
          makeEllipseArc(xyz[0], xyz[1], xyz[2], xyz[3], "Ellipse " + std::to_string(c.tag)));
    case CurveKind::Spline: return std::make_shared<CatmullRomGeometry>(std::move(xyz));
    case CurveKind::BSpline:
      return std::make_shared<BSplineGeometry>(BSplineGeometry::uniform(std::move(xyz), closed));
    case CurveKind::Bezier:
      return std::make_shared<BSplineGeometry>(BSplineGeometry::bezier(std::move(xyz)));
    case CurveKind::Other: break;
  }
  fail("Curve ", c.tag, ": unknown kind");
}

}  // namespace geomesh
