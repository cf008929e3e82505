// Mesh: one node array; per entity its nodes, parameters, element blocks and periodic links.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "kernel/model.h"
#include "mesh/core/element_type.h"

namespace geomesh {

using NodeIndex = std::uint32_t;

// Elements of one type on one entity: connectivity flattened, nodeCount(type) indices each.
struct ElementBlock {
  ElementType type = ElementType::Triangle3;
  std::vector<NodeIndex> nodes;

  std::size_t size() const { return nodes.size() / nodeCount(type); }
  std::span<const NodeIndex> element(std::size_t i) const {
    const std::size_t n = nodeCount(type);
    return {nodes.data() + i * n, n};
  }
};

// A periodic entity's mesh is the image of its master's by `affine` (row-major 4x4); `nodes`
// pairs each node of the entity's closure with the master node it is the image of.
struct PeriodicLink {
  int master = 0;
  std::vector<double> affine;
  std::vector<std::pair<NodeIndex, NodeIndex>> nodes;  // (node here, node of the master)
};

// The mesh of one model entity: the nodes classified on it (not those of its boundary) and its
// elements, which may use boundary nodes too.
struct EntityMesh {
  EntityId entity;
  std::vector<NodeIndex> nodes;
  // Parametric coordinates of `nodes`: 1 value per node on curves, 2 on surfaces; empty on
  // points and volumes, or when the entity has no parametrization.
  std::vector<double> parametric;
  std::vector<ElementBlock> blocks;
  std::optional<PeriodicLink> periodic;
  // A 2D boundary layer's share of a surface's mesh: its nodes are the first `nodes` of
  // `nodes`, its elements the first `triangles` and `quadrangles` of those blocks. Meshers
  // that rewrite the surface's elements afterwards keep that order or drop the record.
  struct LayerPart {
    std::size_t nodes = 0, triangles = 0, quadrangles = 0;
  };
  std::optional<LayerPart> layer;

  ElementBlock& block(ElementType type);  // finds or appends
  const ElementBlock* findBlock(ElementType type) const;
  std::size_t elementCount() const;
};

// A piece of a model entity inside one or more partitions, as a partitioned mesh file holds
// it: the pieces form a boundary representation of the partitions of their own.
struct PartitionEntity {
  EntityId id;                   // numbered after the tags of the model's entities of id.dim
  EntityId parent;               // the model entity it is a piece of, of id.dim or higher
  std::vector<int> partitions;   // ascending, numbered from 1
  std::vector<int> physicals;    // physical tags it is written under
  std::vector<int> boundary;     // tags of pieces of dimension id.dim - 1 that bound it
  std::vector<NodeIndex> nodes;  // the nodes classified on it
  std::vector<ElementBlock> blocks;
};

// A partitioned mesh: every node and element of the entity meshes, placed on the pieces.
struct MeshPartitions {
  int count = 0;
  std::vector<PartitionEntity> entities;      // ordered by (dim, tag)
  std::vector<PhysicalGroup> physicalGroups;  // one per partition set (PartitionCreatePhysicals)
};

// A mesh: node coordinates in one contiguous array, per-node attributes beside it, and a
// mesh per model entity.
class Mesh {
 public:
  NodeIndex addNode(Vec3 xyz) {
    coords_.insert(coords_.end(), {xyz.x, xyz.y, xyz.z});
    if (!sizes_.empty()) sizes_.push_back(0);
    return static_cast<NodeIndex>(coords_.size() / 3 - 1);
  }
  Vec3 node(NodeIndex i) const { return {coords_[3 * i], coords_[3 * i + 1], coords_[3 * i + 2]}; }
  void setNode(NodeIndex i, Vec3 p) {
    coords_[3 * i] = p.x;
    coords_[3 * i + 1] = p.y;
    coords_[3 * i + 2] = p.z;
  }
  std::size_t nodeCount() const { return coords_.size() / 3; }
  std::span<const double> coordinates() const { return coords_; }
  void reserveNodes(std::size_t n) {
    coords_.reserve(3 * n);
    if (!sizes_.empty()) sizes_.reserve(n);
  }

  // Target sizes: the element size the mesher of a node's entity aimed at there, which the
  // meshers of the next dimension extend inwards; 0 where none was set. The array exists
  // once a size is set, and then grows with the nodes (one value per node).
  double nodeSize(NodeIndex i) const { return i < sizes_.size() ? sizes_[i] : 0; }
  void setNodeSize(NodeIndex i, double size) {
    if (sizes_.empty()) sizes_.assign(nodeCount(), 0);
    sizes_[i] = size;
  }
  // All of them at once, for loops over many nodes (empty if none was set).
  std::span<const double> nodeSizes() const { return sizes_; }

  EntityMesh& entity(EntityId e);  // finds or creates
  void eraseEntity(EntityId e) { entities_.erase(e); }
  const EntityMesh* find(EntityId e) const;
  EntityMesh* findMutable(EntityId e) {
    const auto it = entities_.find(e);
    return it == entities_.end() ? nullptr : &it->second;
  }
  const std::map<EntityId, EntityMesh>& entities() const { return entities_; }
  std::size_t elementCount(int dim) const;  // dim -1: all
  void clear();

  // Set by partitioning; any change of the mesh afterwards must drop them (clearPartitions).
  const MeshPartitions* partitions() const { return partitions_ ? &*partitions_ : nullptr; }
  void setPartitions(MeshPartitions p) { partitions_ = std::move(p); }
  void clearPartitions() { partitions_.reset(); }
  // Drops the nodes no entity holds (left over when a mesher removes a node it had added),
  // renumbering the others in their order everywhere they appear. Returns how many went.
  std::size_t dropUnheldNodes();

 private:
  std::vector<double> coords_;
  std::vector<double> sizes_;  // empty, or one per node
  std::map<EntityId, EntityMesh> entities_;
  std::optional<MeshPartitions> partitions_;
};

}  // namespace geomesh
