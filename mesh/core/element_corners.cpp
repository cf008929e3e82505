// The corner tables of volume elements.
#include "mesh/core/element_corners.h"

namespace geomesh {

std::span<const std::array<int, 4>> cornerNeighbours(ElementType type) {
  static constexpr std::array<int, 4> tet[] = {{0, 1, 2, 3}, {1, 0, 3, 2}, {2, 3, 0, 1},
                                               {3, 2, 1, 0}};
  static constexpr std::array<int, 4> prism[] = {{0, 1, 2, 3}, {1, 2, 0, 4}, {2, 0, 1, 5},
                                                 {3, 5, 4, 0}, {4, 3, 5, 1}, {5, 4, 3, 2}};
  static constexpr std::array<int, 4> hex[] = {{0, 1, 3, 4}, {1, 2, 0, 5}, {2, 3, 1, 6},
                                               {3, 0, 2, 7}, {4, 7, 5, 0}, {5, 4, 6, 1},
                                               {6, 5, 7, 2}, {7, 6, 4, 3}};
  switch (type) {
    case ElementType::Tet4: return tet;
    case ElementType::Prism6: return prism;
    case ElementType::Hex8: return hex;
    default: return {};
  }
}

}  // namespace geomesh
