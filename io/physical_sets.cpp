// Element numbers, names and members of physical groups for the formats that save sets.
#include "io/physical_sets.h"

#include <algorithm>
#include <cstdlib>

namespace geomesh {

int physicalOrEntityTag(const Model& model, EntityId entity) {
  const std::vector<int> groups = model.physicalTagsOf(entity);
  return groups.empty() ? entity.tag : groups.front();
}

std::string physicalGroupName(const PhysicalGroup& group) {
  if (!group.name.empty()) return group.name;
  static constexpr const char* kWords[] = {"Point", "Line", "Surface", "Volume"};
  const char* word = group.dim >= 0 && group.dim <= 3 ? kWords[group.dim] : "";
  return "Physical" + std::string(word) + std::to_string(group.tag);
}

std::vector<std::size_t> groupBlocks(const MshContent& content, const PhysicalGroup& group) {
  std::vector<std::size_t> blocks;
  for (std::size_t i = 0; i < content.elementBlocks.size(); ++i) {
    const EntityId e = content.elementBlocks[i].entity;
    if (e.dim != group.dim) continue;
    for (int member : group.entities)
      if (std::abs(member) == e.tag) {
        blocks.push_back(i);
        break;
      }
  }
  return blocks;
}

std::vector<std::uint64_t> groupNodeTags(const MshContent& content,
                                         const std::vector<std::size_t>& blocks) {
  std::vector<std::uint64_t> tags;
  for (std::size_t i : blocks)
    for (NodeIndex n : content.elementBlocks[i].block->nodes) tags.push_back(content.nodeTag[n]);
  std::sort(tags.begin(), tags.end());
  tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
  return tags;
}

}  // namespace geomesh
