// Measures and element counts of a mesh, as tests of merged meshes check them.
#pragma once

#include <cstddef>

#include "mesh/core/mesh.h"
#include "mesh/core/quality.h"

namespace geomesh::testing {

// The total length, area or volume of the elements of dimension `dim` (of entity `only`
// alone when it is given).
inline double measure(const Mesh& mesh, int dim, EntityId only = {-1, 0}) {
  double total = 0;
  for (const auto& [id, em] : mesh.entities()) {
    if (id.dim != dim || (only.dim >= 0 && !(id == only))) continue;
    for (const ElementBlock& block : em.blocks)
      for (std::size_t e = 0; e < block.size(); ++e)
        total += elementMeasure(mesh, block.type, block.element(e));
  }
  return total;
}

inline std::size_t count(const Mesh& mesh, ElementType type) {
  std::size_t n = 0;
  for (const auto& [id, em] : mesh.entities())
    if (const ElementBlock* b = em.findBlock(type)) n += b->size();
  return n;
}

}  // namespace geomesh::testing
