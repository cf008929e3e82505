// UNV finite element descriptors and node orders.
#include "io/unv_elements.h"

#include <map>

#include "io/node_order.h"

namespace geomesh {

namespace {

// A face's nodes in I-DEAS order: around it, corner, edge middle, corner...
NodePlaces around(const std::vector<int>& corners) {
  NodePlaces places;
  for (std::size_t i = 0; i < corners.size(); ++i)
    places.insert(places.end(), {{corners[i]}, {corners[i], corners[(i + 1) % corners.size()]}});
  return places;
}

NodePlaces joined(std::initializer_list<NodePlaces> parts) {
  NodePlaces places;
  for (const NodePlaces& part : parts) places.insert(places.end(), part.begin(), part.end());
  return places;
}

// The written descriptors. Second-order elements list the bottom face's nodes around it, the
// middles of the vertical edges, then the top face's nodes (a tetrahedron's apex).
const std::vector<UnvElement>& writtenElements() {
  using T = ElementType;
  auto at = [](ElementType type, const NodePlaces& places) { return mshNodesAt(type, places); };
  auto linear = [](ElementType type) { return mshNodesAt(type, cornersThen(type, {})); };
  const NodePlaces tet10 = joined({around({0, 1, 2}), {{0, 3}, {1, 3}, {2, 3}, {3}}});
  const NodePlaces prism15 =
      joined({around({0, 1, 2}), {{0, 3}, {1, 4}, {2, 5}}, around({3, 4, 5})});
  const NodePlaces hex20 =
      joined({around({0, 1, 2, 3}), {{0, 4}, {1, 5}, {2, 6}, {3, 7}}, around({4, 5, 6, 7})});
  static const std::vector<UnvElement> elements = {
      {T::Line2, 21, linear(T::Line2)},
      {T::Line3, 24, at(T::Line3, {{0}, {0, 1}, {1}})},
      {T::Triangle3, 91, linear(T::Triangle3)},
      {T::Triangle6, 92, at(T::Triangle6, around({0, 1, 2}))},
      {T::Quad4, 94, linear(T::Quad4)},
      {T::Quad8, 95, at(T::Quad8, around({0, 1, 2, 3}))},
      {T::Tet4, 111, linear(T::Tet4)},
      {T::Tet10, 118, at(T::Tet10, tet10)},
      {T::Prism6, 112, linear(T::Prism6)},
      {T::Prism15, 113, at(T::Prism15, prism15)},
      {T::Hex8, 115, linear(T::Hex8)},
      {T::Hex20, 116, at(T::Hex20, hex20)},
  };
  return elements;
}

const UnvElement* written(ElementType type) {
  for (const UnvElement& e : writtenElements())
    if (e.type == type) return &e;
  return nullptr;
}

// Other descriptors of the same shapes: rod, tapered beam and pipe; plane stress, plane
// strain, flat plate, membrane and axisymmetric solid triangles and quadrangles.
std::map<int, ElementType> readAliases() {
  using T = ElementType;
  std::map<int, ElementType> aliases = {{11, T::Line2}, {22, T::Line2}, {31, T::Line2}};
  for (int base : {40, 50, 60, 70, 80}) {
    aliases[base + 1] = T::Triangle3;
    aliases[base + 2] = T::Triangle6;
    aliases[base + 4] = T::Quad4;
    aliases[base + 5] = T::Quad8;
  }
  return aliases;
}

std::map<int, UnvElement> buildReadTable() {
  std::map<int, UnvElement> table;
  for (const UnvElement& e : writtenElements()) table[e.descriptor] = e;
  for (const auto& [descriptor, type] : readAliases()) {
    UnvElement e = *written(type);
    e.descriptor = descriptor;
    table[descriptor] = e;
  }
  return table;
}

}  // namespace

const UnvElement& unvElementForWriting(ElementType type) {
  if (const UnvElement* e = written(type)) return *e;
  refuseElementType("UNV", type,
                    order(type) > 2 ? "UNV files hold elements up to order 2"
                                    : "UNV has no finite element descriptor for them");
}

const UnvElement* unvElementForReading(int descriptor) {
  static const std::map<int, UnvElement> table = buildReadTable();
  const auto it = table.find(descriptor);
  return it == table.end() ? nullptr : &it->second;
}

}  // namespace geomesh
