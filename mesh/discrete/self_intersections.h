// selfIntersections: the pairs of triangles of a triangulation that cross each other, as a
// scan or an STL file with a fold or two parts pushed into each other has them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "mesh/discrete/triangulation.h"

namespace geomesh {

struct SelfIntersections {
  std::size_t count = 0;  // pairs of triangles that intersect
  // The first pairs found (ascending by first triangle, then second), at most the limit asked.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  std::vector<Vec3> points;  // per pair in `pairs`: a point where the two meet
};

// The pairs of triangles sharing no vertex whose closed triangles intersect (exact predicates),
// found by intersecting their bounding boxes first; triangles that share a vertex or an edge
// are neighbours, not crossings, and are not tested. Deterministic.
SelfIntersections selfIntersections(const Triangulation& t, std::size_t keep = 10);

}  // namespace geomesh
