// Triangulation2D, a corner-based 2D triangulation, and incremental Delaunay triangulation.
#pragma once

#include <span>

#include "mesh/surfaces/triangulation2d.h"

namespace geomesh {

// Delaunay triangulation of `points` (plus the three enclosing vertices) inserted in
// spatial order. Vertex k + kFirstVertex of the result is points[k]; a point equal to an
// earlier one is left out (triangleOf() is kNone for it).
Triangulation2D delaunayTriangulation(std::span<const Vec2> points);

}  // namespace geomesh
