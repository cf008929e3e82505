// The unit square built by the built-in kernel (points, lines, a plane surface), for tests.
#pragma once

#include "kernel/geo/geo_factory.h"
#include "kernel/model.h"

namespace geomesh {

// Points 1..4 at the corners with mesh size h, lines 1..4 round it, plane surface 1.
inline Model geoUnitSquare(double h) {
  GeoFactory geo;
  geo.addPoint(1, {0, 0, 0}, h);
  geo.addPoint(2, {1, 0, 0}, h);
  geo.addPoint(3, {1, 1, 0}, h);
  geo.addPoint(4, {0, 1, 0}, h);
  for (int k = 1; k <= 4; ++k) geo.addLine(k, k, k % 4 + 1);
  geo.addCurveLoop(1, {1, 2, 3, 4});
  geo.addPlaneSurface(1, {1});
  Model model;
  geo.synchronize(model);
  return model;
}

}  // namespace geomesh
