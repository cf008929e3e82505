// The lookup of element blocks and entity meshes in a Mesh.
#include "mesh/core/mesh.h"

#include <algorithm>

namespace geomesh {

ElementBlock& EntityMesh::block(ElementType type) {
  for (ElementBlock& b : blocks)
    if (b.type == type) return b;
  blocks.push_back({type, {}});
  return blocks.back();
}

const ElementBlock* EntityMesh::findBlock(ElementType type) const {
  for (const ElementBlock& b : blocks)
    if (b.type == type) return &b;
  return nullptr;
}

std::size_t EntityMesh::elementCount() const {
  std::size_t n = 0;
  for (const ElementBlock& b : blocks) n += b.size();
  return n;
}

EntityMesh& Mesh::entity(EntityId e) {
  auto [it, inserted] = entities_.try_emplace(e);
  if (inserted) it->second.entity = e;
  return it->second;
}

const EntityMesh* Mesh::find(EntityId e) const {
  auto it = entities_.find(e);
  return it == entities_.end() ? nullptr : &it->second;
}

std::size_t Mesh::elementCount(int dim) const {
  std::size_t n = 0;
  for (const auto& [id, em] : entities_)
    for (const ElementBlock& b : em.blocks)
      if (dim == -1 || dimension(b.type) == dim) n += b.size();
  return n;
}

std::size_t Mesh::dropUnheldNodes() {
  constexpr NodeIndex kNone = ~NodeIndex{0};
  const std::size_t count = nodeCount();
  std::size_t held = 0;  // a node belongs to one entity at most
  for (const auto& [id, em] : entities_) held += em.nodes.size();
  if (held == count) return 0;
  std::vector<NodeIndex> renumbered(count, kNone);
  for (const auto& [id, em] : entities_)
    for (NodeIndex n : em.nodes) renumbered[n] = 0;
  NodeIndex next = 0;
  for (std::size_t n = 0; n < count; ++n)
    if (renumbered[n] != kNone) {
      const std::size_t to = next;
      for (int c = 0; c < 3; ++c) coords_[3 * to + c] = coords_[3 * n + c];
      if (!sizes_.empty()) sizes_[to] = sizes_[n];
      renumbered[n] = next++;
    }
  if (next == count) return 0;
  coords_.resize(3 * static_cast<std::size_t>(next));
  if (!sizes_.empty()) sizes_.resize(next);
  for (auto& [id, em] : entities_) {
    for (NodeIndex& n : em.nodes) n = renumbered[n];
    for (ElementBlock& b : em.blocks)
      for (NodeIndex& n : b.nodes) n = renumbered[n];
    if (em.periodic)
      for (auto& [here, there] : em.periodic->nodes)
        here = renumbered[here], there = renumbered[there];
  }
  return count - next;
}

void Mesh::clear() {
  coords_.clear();
  sizes_.clear();
  entities_.clear();
  partitions_.reset();
}

}  // namespace geomesh
