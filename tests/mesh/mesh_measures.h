// What the mesher tests measure on a whole mesh: lengths, areas, volumes and element counts,
// and a message sink that keeps the log quiet.
#pragma once

#include <cstddef>
#include <string_view>

#include "kernel/messages.h"
#include "mesh/core/mesh.h"

namespace geomesh::testing {

class QuietSink final : public MessageSink {
 public:
  void info(std::string_view) override {}
  void warning(std::string_view) override {}
};

// Sum of the segment lengths of every curve's mesh.
inline double totalLength(const Mesh& mesh) {
  double length = 0;
  for (const auto& [id, em] : mesh.entities()) {
    if (id.dim != 1) continue;
    if (const ElementBlock* l = em.findBlock(ElementType::Line2))
      for (std::size_t e = 0; e < l->size(); ++e) {
        const auto n = l->element(e);
        length += norm(mesh.node(n[1]) - mesh.node(n[0]));
      }
  }
  return length;
}

// Sum of the areas of every surface's triangles and quadrangles (each cut in two).
inline double totalArea(const Mesh& mesh) {
  double area = 0;
  auto triangle = [&](NodeIndex a, NodeIndex b, NodeIndex c) {
    area += 0.5 * norm(cross(mesh.node(b) - mesh.node(a), mesh.node(c) - mesh.node(a)));
  };
  for (const auto& [id, em] : mesh.entities()) {
    if (id.dim != 2) continue;
    if (const ElementBlock* t = em.findBlock(ElementType::Triangle3))
      for (std::size_t e = 0; e < t->size(); ++e) {
        const auto n = t->element(e);
        triangle(n[0], n[1], n[2]);
      }
    if (const ElementBlock* q = em.findBlock(ElementType::Quad4))
      for (std::size_t e = 0; e < q->size(); ++e) {
        const auto n = q->element(e);
        triangle(n[0], n[1], n[2]);
        triangle(n[0], n[2], n[3]);
      }
  }
  return area;
}

// Sum of the signed volumes of every volume's tetrahedra.
inline double totalVolume(const Mesh& mesh) {
  double volume = 0;
  for (const auto& [id, em] : mesh.entities()) {
    if (id.dim != 3) continue;
    if (const ElementBlock* t = em.findBlock(ElementType::Tet4))
      for (std::size_t e = 0; e < t->size(); ++e) {
        const auto n = t->element(e);
        const Vec3 a = mesh.node(n[0]);
        volume += dot(mesh.node(n[1]) - a, cross(mesh.node(n[2]) - a, mesh.node(n[3]) - a)) / 6;
      }
  }
  return volume;
}

// The number of elements of the type over the entities of dimension `dim`.
inline std::size_t countOf(const Mesh& mesh, int dim, ElementType type) {
  std::size_t count = 0;
  for (const auto& [id, em] : mesh.entities())
    if (id.dim == dim)
      if (const ElementBlock* b = em.findBlock(type)) count += b->size();
  return count;
}

}  // namespace geomesh::testing
