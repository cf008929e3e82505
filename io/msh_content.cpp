// selectMshContent: which nodes and elements an MSH file saves, and the tag of each node.
#include "io/msh_content.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace geomesh {

namespace {

std::string describe(EntityId e) {
  static constexpr const char* kNames[] = {"point", "curve", "surface", "volume"};
  const char* name = e.dim >= 0 && e.dim <= 3 ? kNames[e.dim] : "entity";
  return std::string(name) + " " + std::to_string(e.tag);
}

std::vector<const ElementBlock*> blocksByType(const std::vector<ElementBlock>& blocks) {
  std::vector<const ElementBlock*> out;
  for (const ElementBlock& b : blocks)
    if (b.size() > 0) out.push_back(&b);
  std::sort(out.begin(), out.end(), [](const ElementBlock* a, const ElementBlock* b) {
    return static_cast<int>(a->type) < static_cast<int>(b->type);
  });
  return out;
}

void checkNodeIndices(const Mesh& mesh, EntityId e, std::span<const NodeIndex> nodes) {
  for (NodeIndex n : nodes)
    if (n >= mesh.nodeCount())
      throw std::invalid_argument("the mesh of " + describe(e) + " refers to node " +
                                  std::to_string(n) + ", which does not exist");
}

// Every node of a saved element has a tag in the file.
void checkElementNodesSaved(const MshContent& content, const char* otherwise) {
  for (const MshElementBlock& b : content.elementBlocks)
    for (NodeIndex n : b.block->nodes)
      if (content.nodeTag[n] == 0)
        throw std::invalid_argument("node " + std::to_string(n) + " of an element of " +
                                    describe(b.entity) + " " + otherwise);
}

}  // namespace

std::set<EntityId> physicalEntities(const Model& model) {
  std::set<EntityId> out;
  for (const auto& [id, group] : model.physicalGroups())
    for (int tag : group.entities) out.insert({id.dim, std::abs(tag)});
  return out;
}

std::set<EntityId> presentPhysicalEntities(const Model& model, const Mesh& mesh) {
  std::set<EntityId> present;
  for (EntityId e : physicalEntities(model))
    if (model.contains(e) || mesh.find(e)) present.insert(e);
  return present;
}

bool savesPhysicalsOnly(const Model& model, const Mesh& mesh, bool saveAll) {
  return !saveAll && !presentPhysicalEntities(model, mesh).empty();
}

MshContent selectMshContent(const Model& model, const Mesh& mesh, bool saveAll) {
  MshContent content;
  for (EntityId e : model.entities(-1)) content.entities.insert(e);
  for (const auto& [id, em] : mesh.entities()) content.entities.insert(id);
  content.physicalOnly = savesPhysicalsOnly(model, mesh, saveAll);
  const bool physicalOnly = content.physicalOnly;
  const std::set<EntityId> physical = physicalEntities(model);

  std::vector<char> used(mesh.nodeCount(), physicalOnly ? 0 : 1);
  for (EntityId e : content.entities) {
    const EntityMesh* em = mesh.find(e);
    if (!em || (physicalOnly && !physical.contains(e))) continue;
    for (const ElementBlock* b : blocksByType(em->blocks)) {
      checkNodeIndices(mesh, e, b->nodes);
      content.elementBlocks.push_back({e, b});
      content.elementCount += b->size();
      for (NodeIndex n : b->nodes) used[n] = 1;
    }
  }

  content.nodeTag.assign(mesh.nodeCount(), 0);
  for (EntityId e : content.entities) {
    MshNodeBlock block{e, {}};
    if (const EntityMesh* em = mesh.find(e)) {
      checkNodeIndices(mesh, e, em->nodes);
      for (NodeIndex n : em->nodes) {
        if (!used[n]) continue;
        if (content.nodeTag[n] != 0)
          throw std::invalid_argument("node " + std::to_string(n) + " is held by two entities");
        content.nodeTag[n] = ++content.nodeCount;
        block.nodes.push_back(n);
      }
    }
    if (!physicalOnly || physical.contains(e) || !block.nodes.empty())
      content.nodeBlocks.push_back(std::move(block));
  }

  checkElementNodesSaved(content, "is held by no entity");
  return content;
}

MshContent selectPartitionedContent(const Model& model, const Mesh& mesh, bool saveAll,
                                    int onlyPartition) {
  const MeshPartitions& partitions = *mesh.partitions();
  MshContent content;
  content.partitions = &partitions;
  for (EntityId e : model.entities(-1)) content.entities.insert(e);
  for (const auto& [id, em] : mesh.entities()) content.entities.insert(id);
  content.physicalOnly =
      savesPhysicalsOnly(model, mesh, saveAll) || (!saveAll && !partitions.physicalGroups.empty());
  const bool physicalOnly = content.physicalOnly;
  for (const PartitionEntity& piece : partitions.entities) {
    const auto& parts = piece.partitions;
    if (onlyPartition > 0 && std::find(parts.begin(), parts.end(), onlyPartition) == parts.end())
      continue;
    content.pieces.push_back(&piece);
  }

  std::vector<char> used(mesh.nodeCount(), physicalOnly ? 0 : 1);
  for (const PartitionEntity* piece : content.pieces) {
    if (physicalOnly && piece->physicals.empty()) continue;
    for (const ElementBlock* b : blocksByType(piece->blocks)) {
      checkNodeIndices(mesh, piece->id, b->nodes);
      content.elementBlocks.push_back({piece->id, b, piece});
      content.elementCount += b->size();
      for (NodeIndex n : b->nodes) used[n] = 1;
    }
  }
  content.nodeTag.assign(mesh.nodeCount(), 0);
  for (const PartitionEntity* piece : content.pieces) {
    MshNodeBlock block{piece->id, {}};
    checkNodeIndices(mesh, piece->id, piece->nodes);
    for (NodeIndex n : piece->nodes)
      if (used[n] && content.nodeTag[n] == 0) {
        content.nodeTag[n] = ++content.nodeCount;
        block.nodes.push_back(n);
      }
    if (!physicalOnly || !piece->physicals.empty() || !block.nodes.empty())
      content.nodeBlocks.push_back(std::move(block));
  }
  checkElementNodesSaved(content, "is in no saved piece");
  return content;
}

}  // namespace geomesh
