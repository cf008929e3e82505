// Fixtures and checks the kernel tests share.
#pragma once
#include <gtest/gtest.h>

#include "kernel/geo/geo_factory.h"
#include "kernel/geometry_factory.h"
#include "kernel/vec3.h"

namespace geomesh {

inline void expectNear(Vec3 a, Vec3 b, double tolerance = 1e-12) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

// Plane surface 1: the unit square in z = 0, points 1..4 counter-clockwise, lines 1..4 around
// it, curve loop 1; mesh size `size` at its corners.
inline void addUnitSquareSurface(GeometryFactory& geo, double size = 1) {
  geo.addPoint(1, {0, 0, 0}, size);
  geo.addPoint(2, {1, 0, 0}, size);
  geo.addPoint(3, {1, 1, 0}, size);
  geo.addPoint(4, {0, 1, 0}, size);
  for (int i = 1; i <= 4; ++i) geo.addLine(i, i, i % 4 + 1);
  geo.addCurveLoop(1, {1, 2, 3, 4});
  geo.addPlaneSurface(1, {1});
}

}  // namespace geomesh
