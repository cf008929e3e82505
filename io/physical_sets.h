// Physical groups as the formats that hold named sets (UNV, Abaqus, SU2, CGNS) or one number per
// element (Medit, Nastran) save them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "io/msh_content.h"

namespace geomesh {

// The number an element of `entity` is saved with by formats that hold one per element: the
// tag of its entity's first physical group, else the entity's own tag.
int physicalOrEntityTag(const Model& model, EntityId entity);

// The group's name; for an unnamed group, "Physical" + its dimension's word + its tag
// ("PhysicalSurface3"), so that groups of different dimensions never share a name.
std::string physicalGroupName(const PhysicalGroup& group);

// The indices in content.elementBlocks of the blocks of the group's entities.
std::vector<std::size_t> groupBlocks(const MshContent& content, const PhysicalGroup& group);

// The file tags of the nodes of those blocks' elements, ascending, each once.
std::vector<std::uint64_t> groupNodeTags(const MshContent& content,
                                         const std::vector<std::size_t>& blocks);

}  // namespace geomesh
