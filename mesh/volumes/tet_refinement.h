// refineToSizes: Delaunay refinement of a boundary-conforming tetrahedralization to a size map.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "mesh/volumes/delaunay_tets.h"

namespace geomesh {

// Where the sizes inside the volume come from.
struct RefinementSizes {
  // Size at each vertex present before refinement (its boundary size, bounded by the field's
  // when there is one); refinement appends one per vertex it inserts.
  std::vector<double> atVertex;
  // The size field inside the volume (factor and bounds applied), or empty.
  std::function<double(Vec3)> field;
  // Whether sizes interpolated from the boundary bound the field's (Mesh.MeshSizeExtendFromBoundary);
  // without a field they are the only sizes.
  bool extendFromBoundary = true;
  // Called after each round of insertion, with the number of tetrahedra then (progress).
  std::function<void(std::size_t tetrahedra)> afterRound;
};

struct RefinementStats {
  int rounds = 0;
  std::size_t inserted = 0;
  std::size_t refusedTooClose = 0;  // a vertex nearer than the spacing asked for
  std::size_t refusedOther = 0;     // outside, behind a kept face, or degenerate
};

// Inserts points into the tetrahedra (Bowyer-Watson, kept faces respected) until every
// tetrahedron's circumradius fits the local size: in rounds, the circumcentres of the
// tetrahedra too large for the size interpolated at their vertices (their centroids when the
// circumcentre lies outside the domain), sorted along a Hilbert curve, each refused when an
// existing vertex is nearer than a fraction of the size there. Deterministic.
RefinementStats refineToSizes(DelaunayTets& mesh, RefinementSizes& sizes);

}  // namespace geomesh
