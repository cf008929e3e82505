// mshNodesAt: node permutations between MSH and other formats, found by reference coordinates.
#include "io/node_order.h"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "mesh/high_order/reference_element.h"

namespace geomesh {

namespace {

int nodeAtCentre(const ReferenceElement& ref, const std::vector<int>& corners) {
  std::array<double, 3> centre{};
  for (int c : corners)
    for (int k = 0; k < 3; ++k) centre[k] += ref.xi[c][k] / static_cast<double>(corners.size());
  for (std::size_t n = 0; n < ref.xi.size(); ++n)
    if (std::abs(ref.xi[n][0] - centre[0]) + std::abs(ref.xi[n][1] - centre[1]) +
            std::abs(ref.xi[n][2] - centre[2]) <
        1e-12)
      return static_cast<int>(n);
  throw std::logic_error(std::string("no node of ") + elementName(ref.type) +
                         " lies at the centre of the corners given");
}

}  // namespace

std::vector<int> mshNodesAt(ElementType type, const NodePlaces& places) {
  const ReferenceElement& ref = referenceElement(type);
  std::vector<int> nodes;
  nodes.reserve(places.size());
  for (const std::vector<int>& corners : places) nodes.push_back(nodeAtCentre(ref, corners));
  return nodes;
}

NodePlaces cornersThen(ElementType type, const NodePlaces& centres) {
  NodePlaces places;
  for (int c = 0; c < vertexCount(type); ++c) places.push_back({c});
  places.insert(places.end(), centres.begin(), centres.end());
  return places;
}

NodePlaces triangleEdges() {
  return {{0, 1}, {1, 2}, {2, 0}};
}
NodePlaces quadEdges() {
  return {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
}
NodePlaces tetEdges() {
  return {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
}

NodePlaces hexEdgesBottomTopVertical() {
  return {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
          {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
}

NodePlaces prismEdgesBottomTopVertical() {
  return {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}, {0, 3}, {1, 4}, {2, 5}};
}

NodePlaces hexEdgesBottomVerticalTop() {
  return {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5},
          {2, 6}, {3, 7}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
}

NodePlaces prismEdgesBottomVerticalTop() {
  return {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 4}, {2, 5}, {3, 4}, {4, 5}, {5, 3}};
}

NodePlaces pyramidEdges() {
  return {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 4}, {2, 4}, {3, 4}};
}

void refuseElementType(std::string_view format, ElementType type, std::string_view why) {
  throw std::invalid_argument(std::string(format) + " output of " + elementName(type) +
                              " elements is not supported: " + std::string(why));
}

}  // namespace geomesh
