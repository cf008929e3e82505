// PlanarMesh: the triangles a 2D algorithm leaves in a surface's work plane.
#pragma once

#include <cstdint>
#include <vector>

#include "kernel/vec3.h"

namespace geomesh {

// A triangulated part of a work plane: triangle t has the counter-clockwise vertices
// triangles[3t..3t+2], indices into `points`. Points no triangle uses are left over.
struct PlanarMesh {
  std::vector<Vec2> points;
  std::vector<std::uint32_t> triangles;
  std::vector<double> sizes;  // per point: the target size extended from the boundary
};

}  // namespace geomesh
