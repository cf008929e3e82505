// The table of CGNS element types and node orders (io/cgns_elements.h).
#include "io/cgns_elements.h"

#include <cgnslib.h>

#include "io/node_order.h"

namespace geomesh {

namespace {

NodePlaces joined(NodePlaces a, const NodePlaces& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

}  // namespace

const std::vector<CgnsElement>& cgnsElements() {
  using T = ElementType;
  auto at = [](ElementType type, const NodePlaces& centres) {
    return mshNodesAt(type, cornersThen(type, centres));
  };
  const NodePlaces quadCentre = {{0, 1, 2, 3}};
  const NodePlaces prismFaces = {{0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}};
  const NodePlaces hexFaces = {{0, 3, 2, 1},
                               {0, 1, 5, 4},
                               {1, 2, 6, 5},
                               {2, 3, 7, 6},
                               {0, 4, 7, 3},
                               {4, 5, 6, 7},
                               {0, 1, 2, 3, 4, 5, 6, 7}};
  static const std::vector<CgnsElement> elements = {
      {T::Point1, CGNS_ENUMV(NODE), {0}},
      {T::Line2, CGNS_ENUMV(BAR_2), at(T::Line2, {})},
      {T::Line3, CGNS_ENUMV(BAR_3), at(T::Line3, {{0, 1}})},
      {T::Triangle3, CGNS_ENUMV(TRI_3), at(T::Triangle3, {})},
      {T::Triangle6, CGNS_ENUMV(TRI_6), at(T::Triangle6, triangleEdges())},
      {T::Quad4, CGNS_ENUMV(QUAD_4), at(T::Quad4, {})},
      {T::Quad8, CGNS_ENUMV(QUAD_8), at(T::Quad8, quadEdges())},
      {T::Quad9, CGNS_ENUMV(QUAD_9), at(T::Quad9, joined(quadEdges(), quadCentre))},
      {T::Tet4, CGNS_ENUMV(TETRA_4), at(T::Tet4, {})},
      {T::Tet10, CGNS_ENUMV(TETRA_10), at(T::Tet10, tetEdges())},
      {T::Pyramid5, CGNS_ENUMV(PYRA_5), at(T::Pyramid5, {})},
      {T::Pyramid13, CGNS_ENUMV(PYRA_13), at(T::Pyramid13, pyramidEdges())},
      {T::Pyramid14, CGNS_ENUMV(PYRA_14), at(T::Pyramid14, joined(pyramidEdges(), quadCentre))},
      {T::Prism6, CGNS_ENUMV(PENTA_6), at(T::Prism6, {})},
      {T::Prism15, CGNS_ENUMV(PENTA_15), at(T::Prism15, prismEdgesBottomVerticalTop())},
      {T::Prism18, CGNS_ENUMV(PENTA_18),
       at(T::Prism18, joined(prismEdgesBottomVerticalTop(), prismFaces))},
      {T::Hex8, CGNS_ENUMV(HEXA_8), at(T::Hex8, {})},
      {T::Hex20, CGNS_ENUMV(HEXA_20), at(T::Hex20, hexEdgesBottomVerticalTop())},
      {T::Hex27, CGNS_ENUMV(HEXA_27), at(T::Hex27, joined(hexEdgesBottomVerticalTop(), hexFaces))},
  };
  return elements;
}

const CgnsElement& cgnsElementOf(ElementType type) {
  for (const CgnsElement& e : cgnsElements())
    if (e.type == type) return e;
  refuseElementType("CGNS", type,
                    order(type) > 2 ? "geomesh writes CGNS elements up to order 2"
                                    : "CGNS has no element type with these nodes");
}

const CgnsElement* cgnsElementFor(int cgnsType) {
  for (const CgnsElement& e : cgnsElements())
    if (e.cgnsType == cgnsType) return &e;
  return nullptr;
}

}  // namespace geomesh
