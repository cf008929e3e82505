// ElementType, numbered as in MSH files, with each type's node count, dimension and order.
#pragma once

#include <cstdint>

namespace geomesh {

// Element types, numbered as in the MSH file format so that writers need no table.
enum class ElementType : std::uint8_t {
  Line2 = 1,
  Triangle3 = 2,
  Quad4 = 3,
  Tet4 = 4,
  Hex8 = 5,
  Prism6 = 6,
  Pyramid5 = 7,
  Line3 = 8,
  Triangle6 = 9,
  Quad9 = 10,
  Tet10 = 11,
  Hex27 = 12,
  Prism18 = 13,
  Pyramid14 = 14,
  Point1 = 15,
  Quad8 = 16,
  Hex20 = 17,
  Prism15 = 18,
  Pyramid13 = 19,
};

constexpr int nodeCount(ElementType t) {
  switch (t) {
    case ElementType::Point1: return 1;
    case ElementType::Line2: return 2;
    case ElementType::Line3: return 3;
    case ElementType::Triangle3: return 3;
    case ElementType::Triangle6: return 6;
    case ElementType::Quad4: return 4;
    case ElementType::Quad8: return 8;
    case ElementType::Quad9: return 9;
    case ElementType::Tet4: return 4;
    case ElementType::Tet10: return 10;
    case ElementType::Hex8: return 8;
    case ElementType::Hex20: return 20;
    case ElementType::Hex27: return 27;
    case ElementType::Prism6: return 6;
    case ElementType::Prism15: return 15;
    case ElementType::Prism18: return 18;
    case ElementType::Pyramid5: return 5;
    case ElementType::Pyramid13: return 13;
    case ElementType::Pyramid14: return 14;
  }
  return 0;
}

constexpr int dimension(ElementType t) {
  switch (t) {
    case ElementType::Point1: return 0;
    case ElementType::Line2:
    case ElementType::Line3: return 1;
    case ElementType::Triangle3:
    case ElementType::Triangle6:
    case ElementType::Quad4:
    case ElementType::Quad8:
    case ElementType::Quad9: return 2;
    default: return 3;
  }
}

constexpr int order(ElementType t) {
  switch (t) {
    case ElementType::Point1:
    case ElementType::Line2:
    case ElementType::Triangle3:
    case ElementType::Quad4:
    case ElementType::Tet4:
    case ElementType::Hex8:
    case ElementType::Prism6:
    case ElementType::Pyramid5: return 1;
    default: return 2;
  }
}

const char* elementName(ElementType t);

}  // namespace geomesh
