// ElementType, numbered as in MSH files, with each type's family, order, node count and name.
#pragma once

#include <cstdint>
#include <optional>
#include <span>

namespace geomesh {

// Element types, numbered as in the MSH file format so that writers need no table. The
// serendipity ("incomplete") types have nodes on vertices and edges only.
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
  Triangle9 = 20,
  Triangle10 = 21,
  Triangle12 = 22,
  Triangle15 = 23,
  Line4 = 26,
  Line5 = 27,
  Tet20 = 29,
  Tet35 = 30,
  Tet22 = 32,
  Quad16 = 36,
  Quad25 = 37,
  Quad12 = 39,
  Quad16Serendipity = 40,
  Hex64 = 92,
  Hex125 = 93,
  Hex32 = 99,
  Hex44 = 100,
  Pyramid30 = 118,
  Pyramid55 = 119,
  Pyramid21 = 125,
  Pyramid29 = 126,
  Tet16 = 137,
};

// The shape of an element, whatever its order.
enum class ElementFamily : std::uint8_t { Point, Line, Triangle, Quad, Tet, Hex, Prism, Pyramid };

struct ElementTypeInfo {
  ElementType type;
  ElementFamily family;
  std::uint8_t order;
  std::uint8_t nodes;
  bool serendipity;  // nodes on vertices and edges only
  const char* name;
};

// One row per type; the types of one family follow each other by increasing order.
inline constexpr ElementTypeInfo kElementTypes[] = {
    {ElementType::Point1, ElementFamily::Point, 1, 1, false, "point"},
    {ElementType::Line2, ElementFamily::Line, 1, 2, false, "line"},
    {ElementType::Line3, ElementFamily::Line, 2, 3, false, "line3"},
    {ElementType::Line4, ElementFamily::Line, 3, 4, false, "line4"},
    {ElementType::Line5, ElementFamily::Line, 4, 5, false, "line5"},
    {ElementType::Triangle3, ElementFamily::Triangle, 1, 3, false, "triangle"},
    {ElementType::Triangle6, ElementFamily::Triangle, 2, 6, false, "triangle6"},
    {ElementType::Triangle9, ElementFamily::Triangle, 3, 9, true, "triangle9"},
    {ElementType::Triangle10, ElementFamily::Triangle, 3, 10, false, "triangle10"},
    {ElementType::Triangle12, ElementFamily::Triangle, 4, 12, true, "triangle12"},
    {ElementType::Triangle15, ElementFamily::Triangle, 4, 15, false, "triangle15"},
    {ElementType::Quad4, ElementFamily::Quad, 1, 4, false, "quadrangle"},
    {ElementType::Quad8, ElementFamily::Quad, 2, 8, true, "quadrangle8"},
    {ElementType::Quad9, ElementFamily::Quad, 2, 9, false, "quadrangle9"},
    {ElementType::Quad12, ElementFamily::Quad, 3, 12, true, "quadrangle12"},
    {ElementType::Quad16, ElementFamily::Quad, 3, 16, false, "quadrangle16"},
    {ElementType::Quad16Serendipity, ElementFamily::Quad, 4, 16, true, "quadrangle16s"},
    {ElementType::Quad25, ElementFamily::Quad, 4, 25, false, "quadrangle25"},
    {ElementType::Tet4, ElementFamily::Tet, 1, 4, false, "tetrahedron"},
    {ElementType::Tet10, ElementFamily::Tet, 2, 10, false, "tetrahedron10"},
    {ElementType::Tet16, ElementFamily::Tet, 3, 16, true, "tetrahedron16"},
    {ElementType::Tet20, ElementFamily::Tet, 3, 20, false, "tetrahedron20"},
    {ElementType::Tet22, ElementFamily::Tet, 4, 22, true, "tetrahedron22"},
    {ElementType::Tet35, ElementFamily::Tet, 4, 35, false, "tetrahedron35"},
    {ElementType::Hex8, ElementFamily::Hex, 1, 8, false, "hexahedron"},
    {ElementType::Hex20, ElementFamily::Hex, 2, 20, true, "hexahedron20"},
    {ElementType::Hex27, ElementFamily::Hex, 2, 27, false, "hexahedron27"},
    {ElementType::Hex32, ElementFamily::Hex, 3, 32, true, "hexahedron32"},
    {ElementType::Hex64, ElementFamily::Hex, 3, 64, false, "hexahedron64"},
    {ElementType::Hex44, ElementFamily::Hex, 4, 44, true, "hexahedron44"},
    {ElementType::Hex125, ElementFamily::Hex, 4, 125, false, "hexahedron125"},
    {ElementType::Prism6, ElementFamily::Prism, 1, 6, false, "prism"},
    {ElementType::Prism15, ElementFamily::Prism, 2, 15, true, "prism15"},
    {ElementType::Prism18, ElementFamily::Prism, 2, 18, false, "prism18"},
    {ElementType::Pyramid5, ElementFamily::Pyramid, 1, 5, false, "pyramid"},
    {ElementType::Pyramid13, ElementFamily::Pyramid, 2, 13, true, "pyramid13"},
    {ElementType::Pyramid14, ElementFamily::Pyramid, 2, 14, false, "pyramid14"},
    {ElementType::Pyramid21, ElementFamily::Pyramid, 3, 21, true, "pyramid21"},
    {ElementType::Pyramid30, ElementFamily::Pyramid, 3, 30, false, "pyramid30"},
    {ElementType::Pyramid29, ElementFamily::Pyramid, 4, 29, true, "pyramid29"},
    {ElementType::Pyramid55, ElementFamily::Pyramid, 4, 55, false, "pyramid55"},
};

// The row of a type (every enumerator has one).
constexpr const ElementTypeInfo& elementInfo(ElementType t) {
  for (const ElementTypeInfo& info : kElementTypes)
    if (info.type == t) return info;
  return kElementTypes[0];
}

constexpr int nodeCount(ElementType t) { return elementInfo(t).nodes; }
constexpr ElementFamily family(ElementType t) { return elementInfo(t).family; }
constexpr int order(ElementType t) { return elementInfo(t).order; }
constexpr bool isSerendipity(ElementType t) { return elementInfo(t).serendipity; }

constexpr int dimension(ElementFamily f) {
  switch (f) {
    case ElementFamily::Point: return 0;
    case ElementFamily::Line: return 1;
    case ElementFamily::Triangle:
    case ElementFamily::Quad: return 2;
    default: return 3;
  }
}
constexpr int dimension(ElementType t) { return dimension(family(t)); }

// Corner nodes of a family: the first nodes of every element of it.
constexpr int vertexCount(ElementFamily f) {
  constexpr int counts[] = {1, 2, 3, 4, 4, 8, 6, 5};
  return counts[static_cast<int>(f)];
}
constexpr int vertexCount(ElementType t) { return vertexCount(family(t)); }

// The type of a family at an order; nullopt when there is none (above order 4, or a point of
// order above 1 which is still a point). A serendipity type is asked for with `serendipity`;
// families without one at that order (triangles, tetrahedra, lines of order 2) give the
// complete type.
constexpr std::optional<ElementType> elementTypeOf(ElementFamily f, int order,
                                                   bool serendipity = false) {
  if (f == ElementFamily::Point) return ElementType::Point1;
  std::optional<ElementType> complete;
  for (const ElementTypeInfo& info : kElementTypes)
    if (info.family == f && info.order == order) {
      if (info.serendipity == serendipity) return info.type;
      if (!info.serendipity) complete = info.type;
    }
  return complete;
}

// The first-order type of a family (Triangle3 for triangles of any order).
constexpr ElementType linearType(ElementFamily f) { return *elementTypeOf(f, 1); }

// The type numbered `number` in MSH files, nullopt when geomesh does not know it.
constexpr std::optional<ElementType> elementTypeFromNumber(int number) {
  for (const ElementTypeInfo& info : kElementTypes)
    if (static_cast<int>(info.type) == number) return info.type;
  return std::nullopt;
}

inline const char* elementName(ElementType t) { return elementInfo(t).name; }

}  // namespace geomesh
