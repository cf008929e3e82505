// simplify: fewer triangles for a dense merged triangulation (scan, STL), by quadric-error edge
// collapses.
#pragma once

#include <cstddef>

#include "mesh/discrete/triangulation.h"

namespace geomesh {

struct SimplifyOptions {
  std::size_t targetTriangles = 0;  // stop at or below this many triangles (0: no count target)
  // Stop when the next collapse's quadric error (a squared distance) exceeds this (0: no bound).
  double maxError = 0;
  bool keepBoundary = true;  // boundary and non-manifold edges' vertices stay put
};

// Garland–Heckbert edge collapses with quadric error metrics (optimal placement solving the 3x3
// system, the edge's midpoint or an end when singular), in a priority queue with lazy
// invalidation; a collapse that would flip a triangle's normal (by more than 90 degrees) or make
// the mesh non-manifold (link condition) is refused. Returns the simplified triangulation
// (unused vertices removed).
//
// The error of a position is the sum of its squared distances to the planes of the original
// triangles merged into the collapsed vertices. Without keepBoundary, boundary edges add
// heavily weighted planes through them, perpendicular to their triangle, and the vertices of
// non-manifold edges still stay put. With neither a count target nor an error bound nothing is
// collapsed. Triangles with a repeated vertex are dropped.
Triangulation simplify(const Triangulation& t, const SimplifyOptions& options);

}  // namespace geomesh
