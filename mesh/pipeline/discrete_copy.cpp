// Copying the discrete entities' elements from the merged file's mesh; closed shells.
#include "mesh/pipeline/discrete_copy.h"

#include <cstdlib>
#include <limits>
#include <map>
#include <sstream>
#include <vector>

#include "mesh/core/mesh_error.h"
#include "mesh/quads/recombine.h"

namespace geomesh {

namespace {

constexpr NodeIndex kNoNode = std::numeric_limits<NodeIndex>::max();

// Copies entity `id` of `from`, elements of dimension `dim` only, reusing the nodes already
// copied; adds each element edge's length to both its ends.
class EntityCopier {
 public:
  EntityCopier(const Mesh& from, Mesh& to)
      : from_(from), to_(to), copied_(from.nodeCount(), kNoNode), lengths_(from.nodeCount(), 0),
        edges_(from.nodeCount(), 0) {}

  void copy(EntityId id, int dim) {
    const EntityMesh* source = from_.find(id);
    if (!source) throw MeshError(id, "the merged mesh file holds no elements of it");
    EntityMesh& em = to_.entity(id);
    for (const ElementBlock& block : source->blocks) {
      if (dimension(block.type) != dim) continue;
      ElementBlock& into = em.block(block.type);
      const std::size_t corners = static_cast<std::size_t>(vertexCount(family(block.type)));
      for (std::size_t e = 0; e < block.size(); ++e) {
        const auto nodes = block.element(e);
        for (std::size_t k = 0; k < nodes.size(); ++k) {
          into.nodes.push_back(node(nodes[k], em));
          if (dim == 0 || k >= corners || (dim == 1 && k + 1 == corners)) continue;
          addEdge(nodes[k], nodes[(k + 1) % corners]);
        }
      }
    }
  }

  // Each copied node's size: the mean length of its edges.
  void setSizes() const {
    for (NodeIndex n = 0; n < from_.nodeCount(); ++n)
      if (copied_[n] != kNoNode && edges_[n] > 0)
        to_.setNodeSize(copied_[n], lengths_[n] / edges_[n]);
  }

 private:
  NodeIndex node(NodeIndex n, EntityMesh& em) {
    NodeIndex& c = copied_[n];
    if (c == kNoNode) {
      c = to_.addNode(from_.node(n));
      em.nodes.push_back(c);
    }
    return c;
  }

  void addEdge(NodeIndex a, NodeIndex b) {
    const double l = distance(from_.node(a), from_.node(b));
    lengths_[a] += l;
    lengths_[b] += l;
    ++edges_[a];
    ++edges_[b];
  }

  const Mesh& from_;
  Mesh& to_;
  std::vector<NodeIndex> copied_;
  std::vector<double> lengths_;
  std::vector<int> edges_;
};

}  // namespace

void copyDiscreteEntities(const Model& model, const Mesh& from, int dim, Mesh& mesh) {
  EntityCopier copier(from, mesh);
  for (const auto& [tag, point] : model.points())
    if (point.discrete && from.find({0, tag})) copier.copy({0, tag}, 0);
  for (const auto& [tag, curve] : model.curves())
    if (curve.discrete) copier.copy({1, tag}, 1);
  if (dim >= 2)
    for (const auto& [tag, surface] : model.surfaces())
      if (surface.discrete) copier.copy({2, tag}, 2);
  copier.setSizes();
}

void checkDiscreteShells(const Model& model, const Mesh& mesh) {
  for (const auto& [tag, volume] : model.volumes()) {
    bool discrete = false;
    for (const std::vector<int>& shell : volume.shells)
      for (int s : shell)
        if (const ModelSurface* surface = model.surface(std::abs(s)); surface && surface->discrete)
          discrete = true;
    if (!discrete) continue;
    for (const std::vector<int>& shell : volume.shells) {
      std::map<std::uint64_t, int> uses;
      for (int s : shell) {
        const EntityMesh* em = mesh.find({2, std::abs(s)});
        const ElementBlock* triangles = em ? em->findBlock(ElementType::Triangle3) : nullptr;
        if (!triangles) continue;
        for (std::size_t e = 0; e < triangles->size(); ++e) {
          const auto t = triangles->element(e);
          for (std::size_t k = 0; k < 3; ++k) ++uses[edgeKey(t[k], t[(k + 1) % 3])];
        }
      }
      std::size_t open = 0;
      std::uint64_t first = 0;
      for (const auto& [edge, count] : uses)
        if (count != 2 && open++ == 0) first = edge;
      if (open == 0) continue;
      const Vec3 a = mesh.node(static_cast<NodeIndex>(first >> 32));
      const Vec3 b = mesh.node(static_cast<NodeIndex>(first & 0xffffffffu));
      std::ostringstream why;
      why << "the triangles of its surface loop do not close: " << open
          << " edges are not shared by exactly two of them, the first from (" << a.x << ", "
          << a.y << ", " << a.z << ") to (" << b.x << ", " << b.y << ", " << b.z << ")";
      throw MeshError({3, tag}, why.str());
    }
  }
}

}  // namespace geomesh
