// The element shapes of views as MSH element types, and back.
#include "io/view_file_parts.h"

namespace geomesh {

using post::ElementShape;

namespace {

constexpr ElementType kFirstOrder[post::kShapeCount] = {
    ElementType::Point1, ElementType::Line2, ElementType::Triangle3, ElementType::Quad4,
    ElementType::Tet4,   ElementType::Hex8,  ElementType::Prism6,    ElementType::Pyramid5};
// Points have no second order: a point list of order 2 is written as points.
constexpr ElementType kSecondOrder[post::kShapeCount] = {
    ElementType::Point1, ElementType::Line3, ElementType::Triangle6, ElementType::Quad9,
    ElementType::Tet10,  ElementType::Hex27, ElementType::Prism18,   ElementType::Pyramid14};

}  // namespace

ElementType listElementType(ElementShape shape, int order) {
  return (order == 2 ? kSecondOrder : kFirstOrder)[static_cast<int>(shape)];
}

int listNodeCount(ElementShape shape, int order) {
  return nodeCount(listElementType(shape, order));
}

ElementShape shapeOfType(ElementType type) { return post::shapeOfFamily(family(type)); }

int listOrderOfType(ElementType type) {
  const ElementShape shape = shapeOfType(type);
  return shape != ElementShape::Point && listElementType(shape, 2) == type ? 2 : 1;
}

}  // namespace geomesh
