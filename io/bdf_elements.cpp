// Nastran element cards and node orders.
#include "io/bdf_elements.h"

#include "io/node_order.h"

namespace geomesh {

namespace {

// Corners first, then the middles of the edges: around the bottom face, along the vertical
// edges, around the top face; a pyramid's base, then the edges to its apex.
const std::vector<BdfElement>& bdfElements() {
  using T = ElementType;
  auto layout = [](ElementType type, const NodePlaces& centres) {
    return mshNodesAt(type, cornersThen(type, centres));
  };
  static const std::vector<BdfElement> elements = {
      {T::Line2, "CROD", layout(T::Line2, {})},
      {T::Triangle3, "CTRIA3", layout(T::Triangle3, {})},
      {T::Triangle6, "CTRIA6", layout(T::Triangle6, triangleEdges())},
      {T::Quad4, "CQUAD4", layout(T::Quad4, {})},
      {T::Quad8, "CQUAD8", layout(T::Quad8, quadEdges())},
      {T::Tet4, "CTETRA", layout(T::Tet4, {})},
      {T::Tet10, "CTETRA", layout(T::Tet10, tetEdges())},
      {T::Prism6, "CPENTA", layout(T::Prism6, {})},
      {T::Prism15, "CPENTA", layout(T::Prism15, prismEdgesBottomVerticalTop())},
      {T::Pyramid5, "CPYRAM", layout(T::Pyramid5, {})},
      {T::Pyramid13, "CPYRAM", layout(T::Pyramid13, pyramidEdges())},
      {T::Hex8, "CHEXA", layout(T::Hex8, {})},
      {T::Hex20, "CHEXA", layout(T::Hex20, hexEdgesBottomVerticalTop())},
  };
  return elements;
}

}  // namespace

const BdfElement& bdfElementForWriting(ElementType type) {
  for (const BdfElement& e : bdfElements())
    if (e.type == type) return e;
  if (type == ElementType::Line3)
    refuseElementType("Nastran", type, "Nastran has no three-node rod or bar");
  refuseElementType("Nastran", type,
                    order(type) > 2 ? "Nastran elements are at most of order 2"
                                    : "Nastran has no element card with these nodes");
}

const BdfElement* bdfElementForReading(std::string_view card, std::size_t nodes) {
  if (card == "CBAR" || card == "CBEAM") card = "CROD";
  // Second-order shells whose middle grid points are left blank are first-order ones.
  if (card == "CTRIA6" && nodes == 3) card = "CTRIA3";
  if (card == "CQUAD8" && nodes == 4) card = "CQUAD4";
  for (const BdfElement& e : bdfElements())
    if (e.card == card && static_cast<std::size_t>(nodeCount(e.type)) == nodes) return &e;
  return nullptr;
}

std::size_t bdfNodeFields(std::string_view card) {
  if (card == "CROD" || card == "CBAR" || card == "CBEAM") return 2;
  if (card == "CTRIA3") return 3;
  if (card == "CQUAD4") return 4;
  if (card == "CTRIA6") return 6;
  if (card == "CQUAD8") return 8;
  if (card == "CTETRA") return 10;
  if (card == "CPYRAM") return 13;
  if (card == "CPENTA") return 15;
  if (card == "CHEXA") return 20;
  return 0;
}

}  // namespace geomesh
