// The I-DEAS universal file's finite element descriptors (dataset 2412) of geomesh's element
// types, and their node orders: shared by the UNV writer and reader.
#pragma once

#include <vector>

#include "mesh/core/element_type.h"

namespace geomesh {

// An element type as UNV files hold it: its FE descriptor id and, for each node the file lists,
// the index (in MSH order) of the element's node that goes there. Second-order elements list
// their nodes around the element: corner, edge middle, corner...
struct UnvElement {
  ElementType type = ElementType::Line2;
  int descriptor = 0;
  std::vector<int> fromMsh;
};

// The descriptor written for `type`: beams for lines, thin shells for triangles and
// quadrangles, solids for the rest. Throws std::invalid_argument for the types UNV cannot hold.
const UnvElement& unvElementForWriting(ElementType type);

// How elements of a descriptor are read (the other 1D, plane, plate, membrane and
// axisymmetric descriptors too); null for a descriptor geomesh has no element for.
const UnvElement* unvElementForReading(int descriptor);

// Whether the elements of a descriptor have the beam record (orientation node and cross
// sections) before their nodes: the one-dimensional ones.
constexpr bool unvHasBeamRecord(int descriptor) {
  return descriptor >= 11 && descriptor <= 32;
}

}  // namespace geomesh
