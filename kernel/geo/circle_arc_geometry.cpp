// CircleArcGeometry: points and derivatives of a circle arc, radius blended between its ends.
#include "kernel/geo/circle_arc_geometry.h"

#include <cmath>

namespace geomesh {

CircleArcGeometry::CircleArcGeometry(Vec3 center, Vec3 start, Vec3 end, Vec3 axis)
    : center_(center),
      e1_(normalized(start - center)),
      e2_(normalized(cross(axis, e1_))),
      startRadius_(distance(start, center)),
      endRadius_(distance(end, center)),
      angle_(std::atan2(dot(end - center, e2_), dot(end - center, e1_))) {
  if (angle_ < 0) angle_ += 2 * std::acos(-1.0);
  if (start == end) angle_ = 2 * std::acos(-1.0);  // a whole turn back to its start
}

Vec3 CircleArcGeometry::radial(double t) const {
  const double a = t * angle_;
  return std::cos(a) * e1_ + std::sin(a) * e2_;
}

Vec3 CircleArcGeometry::tangential(double t) const {
  const double a = t * angle_;
  return -std::sin(a) * e1_ + std::cos(a) * e2_;
}

Vec3 CircleArcGeometry::point(double t) const {
  return center_ + (startRadius_ + t * (endRadius_ - startRadius_)) * radial(t);
}

Vec3 CircleArcGeometry::firstDerivative(double t) const {
  const double r = startRadius_ + t * (endRadius_ - startRadius_);
  return (endRadius_ - startRadius_) * radial(t) + r * angle_ * tangential(t);
}

Vec3 CircleArcGeometry::secondDerivative(double t) const {
  const double r = startRadius_ + t * (endRadius_ - startRadius_);
  return 2 * (endRadius_ - startRadius_) * angle_ * tangential(t) -
         r * angle_ * angle_ * radial(t);
}

}  // namespace geomesh
