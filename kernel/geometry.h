// CurveGeometry and SurfaceGeometry: the parametric shapes meshers see, from either kernel.
#pragma once

#include <optional>

#include "kernel/bounding_box.h"
#include "kernel/vec3.h"

namespace geomesh {

struct Interval {
  double min = 0, max = 1;
};

struct ParamBox {
  Interval u, v;
};

// What a curve is, as the script or the CAD model defined it. Other: none of these (or not
// known), to be recognised from its shape if it matters.
enum class CurveKind { Line, CircleArc, EllipseArc, Spline, BSpline, Bezier, Other };

// The shape of a curve: a map from a parameter interval to space. Built-in and OpenCASCADE
// curves both implement it; the mesher only sees this interface.
class CurveGeometry {
 public:
  virtual ~CurveGeometry() = default;
  virtual Interval range() const = 0;
  virtual Vec3 point(double t) const = 0;
  virtual Vec3 firstDerivative(double t) const = 0;
  virtual Vec3 secondDerivative(double t) const = 0;

  virtual CurveKind kind() const { return CurveKind::Other; }
  // The angle an arc of circle or ellipse spans (for an ellipse, its parametric angle). The
  // default, the length of the parameter range, is that angle for a curve parametrized by
  // its angle.
  virtual double arcAngle() const { return range().max - range().min; }
  // Whether the curve is a single point of space over its whole range (a CAD model's edge at
  // the pole of a sphere or the apex of a cone): its mesh is its one vertex, no segment.
  virtual bool isDegenerate() const { return false; }

  // curveBoundingBox(*this), computed on first use and kept: a geometry never changes once
  // made (a transformed curve gets a new geometry).
  const BoundingBox& boundingBox() const;

 private:
  mutable std::optional<BoundingBox> box_;
};

struct SurfaceDerivatives {
  Vec3 du, dv;
};

// What a surface is, as the script or the CAD model defined it; Other when none of these.
enum class SurfaceKind { Plane, Cylinder, Cone, Sphere, Torus, BSpline, Bezier, Other };

// The shape of a surface: a map from a parameter box to space.
class SurfaceGeometry {
 public:
  virtual ~SurfaceGeometry() = default;
  virtual ParamBox bounds() const = 0;
  virtual Vec3 point(Vec2 uv) const = 0;
  virtual SurfaceDerivatives firstDerivatives(Vec2 uv) const = 0;
  // Parameters of the surface point closest to p.
  virtual Vec2 project(Vec3 p) const = 0;
  virtual SurfaceKind kind() const { return SurfaceKind::Other; }
  virtual bool isPlane() const { return kind() == SurfaceKind::Plane; }
  // Where the point at parameter t of the boundary curve `signedCurve` (as it appears in one
  // of the surface's loops, negative when used against its direction) lies in the parameter
  // plane. A seam of a periodic surface appears twice, once per direction: each sign gives its
  // side of the parameter box. A degenerate curve (a pole) gives a segment. nullopt when the
  // surface does not know the curve: the point is then projected.
  virtual std::optional<Vec2> curveParameters(int signedCurve, double t) const {
    (void)signedCurve, (void)t;
    return std::nullopt;
  }
  // The largest principal curvature at uv when the surface knows it better than finite
  // differences of its normals would (a piecewise-linear surface, whose normal jumps across its
  // triangles); nullopt otherwise.
  virtual std::optional<double> curvature(Vec2 uv) const {
    (void)uv;
    return std::nullopt;
  }
};

}  // namespace geomesh
