// The unit square built by the built-in kernel (points, lines, a plane surface), for tests.
#pragma once

#include "kernel/geo/geo_factory.h"
#include "kernel/model.h"
#include "tests/kernel/kernel_test_helpers.h"

namespace geomesh {

// Points 1..4 at the corners with mesh size h, lines 1..4 round it, plane surface 1.
inline Model geoUnitSquare(double h) {
  GeoFactory geo;
  addUnitSquareSurface(geo, h);
  Model model;
  geo.synchronize(model);
  return model;
}

}  // namespace geomesh
