// EllipseArcGeometry, and makeEllipseArc: the ellipse through both ends of Ellipse(t).
#include "kernel/geo/ellipse_arc_geometry.h"

#include <cmath>
#include <string>

#include "kernel/geometry_error.h"

namespace geomesh {

EllipseArcGeometry::EllipseArcGeometry(Vec3 center, Vec3 major, Vec3 minor, double a, double b,
                                       double startAngle, double endAngle)
    : center_(center), major_(major), minor_(minor), a_(a), b_(b), start_(startAngle),
      end_(endAngle) {}

Vec3 EllipseArcGeometry::point(double t) const {
  const double phi = start_ + t * (end_ - start_);
  return center_ + a_ * std::cos(phi) * major_ + b_ * std::sin(phi) * minor_;
}

Vec3 EllipseArcGeometry::firstDerivative(double t) const {
  const double phi = start_ + t * (end_ - start_), w = end_ - start_;
  return w * (-a_ * std::sin(phi) * major_ + b_ * std::cos(phi) * minor_);
}

Vec3 EllipseArcGeometry::secondDerivative(double t) const {
  const double w = end_ - start_;
  return -w * w * (point(t) - center_);
}

namespace {

[[noreturn]] void failEllipse(const std::string& what, const std::string& reason) {
  throw GeometryError(what + ": " + reason);
}

}  // namespace

EllipseArcGeometry makeEllipseArc(Vec3 start, Vec3 center, Vec3 majorPoint, Vec3 end,
                                  const std::string& what) {
  // A major-axis point at the center (as in Ellipse(1) = {2, 1, 1, 3};, often written for
  // circles) puts the axis through the start.
  const Vec3 towards = norm(majorPoint - center) == 0 ? start : majorPoint;
  if (norm(towards - center) == 0) failEllipse(what, "its start is the center");
  const Vec3 major = normalized(towards - center);
  // The plane of the arc holds the major axis and both ends.
  Vec3 normal = cross(major, start - center);
  if (norm(normal) < 1e-12 * norm(start - center)) normal = cross(major, end - center);
  if (norm(normal) == 0) failEllipse(what, "its points are collinear");
  const Vec3 minor = normalized(cross(normalized(normal), major));
  const double x1 = dot(start - center, major), y1 = dot(start - center, minor);
  const double x2 = dot(end - center, major), y2 = dot(end - center, minor);
  // Both ends on x^2 / a^2 + y^2 / b^2 = 1: linear in (1 / a^2, 1 / b^2); with a single
  // equation (an end on the major axis), the other end fixes the remaining semi-axis.
  double ia = 0, ib = 0;
  const double det = x1 * x1 * y2 * y2 - x2 * x2 * y1 * y1;
  if (std::abs(det) > 1e-14 * std::pow(norm(start - center) * norm(end - center), 2)) {
    ia = (y2 * y2 - y1 * y1) / det;
    ib = (x1 * x1 - x2 * x2) / det;
  } else if (std::abs(y1) < std::abs(y2)) {
    ia = 1 / (x1 * x1);
    ib = (1 - x2 * x2 * ia) / (y2 * y2);
  } else {
    ia = 1 / (x2 * x2);
    ib = (1 - x1 * x1 * ia) / (y1 * y1);
  }
  if (!(ia > 0) || !(ib > 0) || !std::isfinite(ia) || !std::isfinite(ib))
    failEllipse(what, "no ellipse with this major axis passes through both ends");
  const double a = 1 / std::sqrt(ia), b = 1 / std::sqrt(ib);
  const double phi1 = std::atan2(y1 / b, x1 / a);
  double phi2 = std::atan2(y2 / b, x2 / a);
  const double pi = std::acos(-1.0);
  while (phi2 - phi1 > pi) phi2 -= 2 * pi;
  while (phi2 - phi1 < -pi) phi2 += 2 * pi;
  return EllipseArcGeometry(center, major, minor, a, b, phi1, phi2);
}

}  // namespace geomesh
