// LineGeometry::project: the parameter of the closest point on a straight line.
#include "kernel/geo/line_geometry.h"

namespace geomesh {

double LineGeometry::project(Vec3 p) const {
  const Vec3 d = end_ - start_;
  const double len2 = dot(d, d);
  return len2 > 0 ? dot(p - start_, d) / len2 : 0.0;
}

}  // namespace geomesh
