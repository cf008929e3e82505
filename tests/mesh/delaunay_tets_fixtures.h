// Helpers for the Delaunay kernel's tests: the volume of a tetrahedralization.
#pragma once

#include <cstdint>

#include "mesh/volumes/delaunay_tets.h"

namespace geomesh::testing {

// The signed volume of the alive tetrahedra.
inline double volumeOf(const DelaunayTets& mesh) {
  double volume = 0;
  for (std::uint32_t t = 0; t < mesh.slotCount(); ++t) {
    if (!mesh.alive(t)) continue;
    const std::uint32_t* v = &mesh.vertices[4 * t];
    const Vec3 a = mesh.points[v[0]];
    volume += dot(cross(mesh.points[v[1]] - a, mesh.points[v[2]] - a), mesh.points[v[3]] - a) / 6;
  }
  return volume;
}

}  // namespace geomesh::testing
