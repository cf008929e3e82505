// BoundingBox: an axis-aligned box, and the smallest one holding a curve.
#pragma once

#include "kernel/vec3.h"

namespace geomesh {

class CurveGeometry;

struct BoundingBox {
  Vec3 min{1e300, 1e300, 1e300};
  Vec3 max{-1e300, -1e300, -1e300};
  bool empty() const { return min.x > max.x; }
  void include(Vec3 p);
  void include(const BoundingBox& b);
};

// The smallest box holding the curve (its coordinates' extremes, found to rounding).
// CurveGeometry::boundingBox() keeps it once computed.
BoundingBox curveBoundingBox(const CurveGeometry& curve);

}  // namespace geomesh
