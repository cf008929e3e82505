// The CGNS element types geomesh writes and reads, with their node orders: shared by the CGNS
// writer and reader without the library's header (the CGNS type is its ElementType_t value).
#pragma once

#include <vector>

#include "mesh/core/element_type.h"

namespace geomesh {

// A CGNS element type and, for each node it lists, the index (in MSH order) of the element's
// node that goes there: corners, edge middles (around the bottom face, along the vertical
// edges, around the top face), face centres, then the centre.
struct CgnsElement {
  ElementType type;
  int cgnsType;  // CGNS's ElementType_t
  std::vector<int> fromMsh;
};

const std::vector<CgnsElement>& cgnsElements();

// The row of `type`; refuses (std::invalid_argument) the types CGNS files cannot hold.
const CgnsElement& cgnsElementOf(ElementType type);

// The row of CGNS's element type `cgnsType`, null for types geomesh does not read.
const CgnsElement* cgnsElementFor(int cgnsType);

}  // namespace geomesh
