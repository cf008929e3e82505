// fitPlane (best-fit plane of a polygon) and PlaneGeometry (a flat parametric surface).
#pragma once

#include <span>

#include "kernel/geometry.h"

namespace geomesh {

// A best-fit plane through a set of points (Newell's method for the normal, so that the
// normal follows the right-hand rule when the points form a closed polygon).
struct PlaneFit {
  Vec3 origin;   // centroid of the points
  Vec3 normal;   // unit normal; zero when the points are (nearly) collinear
  double maxDeviation = 0;  // largest distance of a point to the plane
};
// `polygon` is a closed polygon given once around (its last point joins its first).
PlaneFit fitPlane(std::span<const Vec3> polygon);

// A flat surface: point(u, v) = origin + u * uAxis + v * vAxis, with orthonormal axes and
// uAxis x vAxis = normal. Bounds are those of the parameters of the points it was built from.
class PlaneGeometry final : public SurfaceGeometry {
 public:
  // Chooses the axes from `normal` (unit): uAxis is the projection of the coordinate axis
  // least aligned with the normal.
  PlaneGeometry(Vec3 origin, Vec3 normal);
  // Widens the parameter bounds to include the projection of p.
  void include(Vec3 p);

  ParamBox bounds() const override { return bounds_; }
  Vec3 point(Vec2 uv) const override { return origin_ + uv.u * uAxis_ + uv.v * vAxis_; }
  SurfaceDerivatives firstDerivatives(Vec2) const override { return {uAxis_, vAxis_}; }
  Vec2 project(Vec3 p) const override;
  SurfaceKind kind() const override { return SurfaceKind::Plane; }

  Vec3 origin() const { return origin_; }
  Vec3 normal() const { return cross(uAxis_, vAxis_); }
  Vec3 uAxis() const { return uAxis_; }
  Vec3 vAxis() const { return vAxis_; }

 private:
  Vec3 origin_, uAxis_, vAxis_;
  ParamBox bounds_{{1e300, -1e300}, {1e300, -1e300}};
};

}  // namespace geomesh
