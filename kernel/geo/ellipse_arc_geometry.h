// EllipseArcGeometry: an arc of ellipse over its parametric angles, and makeEllipseArc.
#pragma once

#include <cmath>
#include <string>

#include "kernel/geometry.h"

namespace geomesh {

// An arc of ellipse: center + a cos(phi) major + b sin(phi) minor, phi growing linearly from
// the start angle to the end angle as t goes from 0 to 1 (the angles are the ellipse's
// parametric angles, not polar ones). `major` and `minor` are orthonormal.
class EllipseArcGeometry final : public CurveGeometry {
 public:
  EllipseArcGeometry(Vec3 center, Vec3 major, Vec3 minor, double a, double b, double startAngle,
                     double endAngle);

  Interval range() const override { return {0, 1}; }
  Vec3 point(double t) const override;
  Vec3 firstDerivative(double t) const override;
  Vec3 secondDerivative(double t) const override;
  CurveKind kind() const override { return CurveKind::EllipseArc; }
  double arcAngle() const override { return std::abs(sweep()); }

  double sweep() const { return end_ - start_; }

 private:
  Vec3 center_, major_, minor_;
  double a_, b_, start_, end_;
};

// The arc of Ellipse(t) = {start, center, major-axis point, end}: the major axis points from
// the center towards `majorPoint`; the semi-axes are those of the ellipse through both ends;
// the arc turns the short way (less than half a turn). Throws GeometryError (with `what` in
// the message) when no such ellipse exists.
EllipseArcGeometry makeEllipseArc(Vec3 start, Vec3 center, Vec3 majorPoint, Vec3 end,
                                  const std::string& what);

}  // namespace geomesh
