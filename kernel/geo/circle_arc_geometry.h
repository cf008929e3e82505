// CircleArcGeometry: a circle arc of at most pi, parametrized as Gmsh's built-in kernel does.
#pragma once

#include "kernel/geometry.h"

namespace geomesh {

// An arc of circle around `center` from `start` to `end`, of angle at most pi, parametrized as
// the built-in kernel does: t in [0, 1], the angle growing linearly with t, turning about
// `axis` (unit, normal to the arc's plane). When start and end are not quite at the same
// distance from the center, the radius varies linearly along the arc so that it still joins
// them exactly.
class CircleArcGeometry final : public CurveGeometry {
 public:
  CircleArcGeometry(Vec3 center, Vec3 start, Vec3 end, Vec3 axis);

  Interval range() const override { return {0, 1}; }
  Vec3 point(double t) const override;
  Vec3 firstDerivative(double t) const override;
  Vec3 secondDerivative(double t) const override;
  CurveKind kind() const override { return CurveKind::CircleArc; }
  double arcAngle() const override { return angle_; }

  double angle() const { return angle_; }
  Vec3 center() const { return center_; }
  double startRadius() const { return startRadius_; }
  double endRadius() const { return endRadius_; }

 private:
  Vec3 radial(double t) const;      // unit vector from the center at t
  Vec3 tangential(double t) const;  // radial turned a quarter further

  Vec3 center_, e1_, e2_;  // e1: towards the start; e2: a quarter turn further
  double startRadius_, endRadius_, angle_;
};

}  // namespace geomesh
