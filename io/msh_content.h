// MshContent: the nodes and elements an MSH file holds, chosen once for every version.
#pragma once

#include <cstdint>
#include <set>
#include <vector>

#include "kernel/model.h"
#include "mesh/core/mesh.h"

namespace geomesh {

// What an MSH file holds, decided once for every format version: which nodes and elements are
// saved, in which order, and the tag each node gets in the file.
struct MshNodeBlock {
  EntityId entity;
  std::vector<NodeIndex> nodes;
};

// In a partitioned file, blocks belong to pieces of the partitions (`piece`), whose tags are
// those of `entity`.
struct MshElementBlock {
  EntityId entity;
  const ElementBlock* block = nullptr;
  const PartitionEntity* piece = nullptr;
};

struct MshContent {
  std::vector<std::uint64_t> nodeTag;  // per mesh node: its tag in the file, 0 if not saved
  std::vector<MshNodeBlock> nodeBlocks;
  std::vector<MshElementBlock> elementBlocks;  // by (dim, tag), then element type
  std::size_t nodeCount = 0;
  std::size_t elementCount = 0;
  std::set<EntityId> entities;                 // of the model and of the mesh
  bool physicalOnly = false;                   // only the elements of physical groups are saved
  const MeshPartitions* partitions = nullptr;  // set when the file is partitioned
  std::vector<const PartitionEntity*> pieces;  // saved pieces, ordered by (dim, tag)
};

// The entities that physical groups of the model hold.
std::set<EntityId> physicalEntities(const Model& model);
// Those of them that the model or the mesh has (a group may name an entity that is missing).
std::set<EntityId> presentPhysicalEntities(const Model& model, const Mesh& mesh);
// Whether only the elements of physical groups are saved: not with saveAll, nor when no
// entity of the model or the mesh is in a group (the groups named only entities missing),
// as the reference decides.
bool savesPhysicalsOnly(const Model& model, const Mesh& mesh, bool saveAll);

// With physical groups and !saveAll, only elements of entities in a physical group are saved;
// an entity's node block is then written when the entity is in a group or has a node used by a
// saved element. Otherwise every entity has a node block, possibly empty. Throws
// std::invalid_argument when an element uses a node that no entity holds.
// Partitions play no part: the entity meshes are saved (what every format but MSH writes).
MshContent selectMshContent(const Model& model, const Mesh& mesh, bool saveAll);
// For a partitioned mesh: the same choice over its pieces, a piece being in the groups of
// PartitionEntity::physicals; `onlyPartition` > 0 keeps the pieces of that partition only (one
// file per partition).
MshContent selectPartitionedContent(const Model& model, const Mesh& mesh, bool saveAll,
                                    int onlyPartition);

}  // namespace geomesh
