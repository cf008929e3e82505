#pragma once

#include "kernel/vec3.h"

namespace geomesh {

struct Interval {
  double min = 0, max = 1;
};

struct ParamBox {
  Interval u, v;
};

// The shape of a curve: a map from a parameter interval to space. Built-in and OpenCASCADE
// curves both implement it; the mesher only sees this interface.
class CurveGeometry {
 public:
  virtual ~CurveGeometry() = default;
  virtual Interval range() const = 0;
  virtual Vec3 point(double t) const = 0;
  virtual Vec3 firstDerivative(double t) const = 0;
  virtual Vec3 secondDerivative(double t) const = 0;
};

struct SurfaceDerivatives {
  Vec3 du, dv;
};

// The shape of a surface: a map from a parameter box to space.
class SurfaceGeometry {
 public:
  virtual ~SurfaceGeometry() = default;
  virtual ParamBox bounds() const = 0;
  virtual Vec3 point(Vec2 uv) const = 0;
  virtual SurfaceDerivatives firstDerivatives(Vec2 uv) const = 0;
  // Parameters of the surface point closest to p.
  virtual Vec2 project(Vec3 p) const = 0;
  virtual bool isPlane() const { return false; }
};

}  // namespace geomesh
