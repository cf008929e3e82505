// The Nastran bulk data element cards of geomesh's element types and their node orders: shared
// by the BDF writer and reader.
#pragma once

#include <string_view>
#include <vector>

#include "mesh/core/element_type.h"

namespace geomesh {

// An element type as Nastran cards hold it: the card's name and, for each grid point it lists,
// the index (in MSH order) of the element's node that goes there.
struct BdfElement {
  ElementType type = ElementType::Line2;
  std::string_view card;
  std::vector<int> fromMsh;
};

// Throws std::invalid_argument for the types Nastran cannot hold.
const BdfElement& bdfElementForWriting(ElementType type);

// The element a card with `nodes` grid points is read as (CBAR and CBEAM too, as lines); null
// for a card geomesh has no element for, or a node count that does not fit it.
const BdfElement* bdfElementForReading(std::string_view card, std::size_t nodes);

// Whether `card` names an element card the reader knows, and how many of its fields after the
// property id are grid points at most (the others hold orientations, thicknesses...).
std::size_t bdfNodeFields(std::string_view card);

}  // namespace geomesh
