// smoothVertices: moves inserted vertices to raise the worst shape of the tetrahedra around them.
#pragma once

#include <cstdint>

#include "mesh/volumes/delaunay_tets.h"

namespace geomesh {

// Sweeps the volume mesher makes (a third adds little: mean gamma 0.8028 to 0.8030 on a cube).
inline constexpr int kSmoothingPasses = 2;

// Moves each vertex numbered `firstMovable` or more, in `passes` sweeps in vertex order, to the
// mean of its neighbours when that raises the lowest mean ratio of its tetrahedra, every one
// of them staying positive (exact test). The topology does not change. Deterministic.
// Returns the number of moves.
std::size_t smoothVertices(DelaunayTets& mesh, std::uint32_t firstMovable, int passes);

}  // namespace geomesh
