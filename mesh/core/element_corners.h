// The corners of volume elements with their neighbours along edges.
#pragma once

#include <array>
#include <span>

#include "mesh/core/element_type.h"

namespace geomesh {

// For each corner of a tetrahedron, prism or hexahedron (MSH order): (corner, a, b, c), its
// three neighbours along edges in right-handed order, so that the edge vectors to a, b and c
// have a positive triple product in a valid element. Empty for other types.
std::span<const std::array<int, 4>> cornerNeighbours(ElementType type);

}  // namespace geomesh
