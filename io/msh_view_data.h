// The data sections of an MSH file as read, before they become views: what the file's own
// node and element tags name in the mesh, and each section's header and entries.
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "mesh/core/mesh.h"
#include "mesh/views/view.h"

namespace geomesh {

// Tags of the mesh: node i has tag i + 1; elements are numbered from 1 over the entities in
// order (dimension, tag), each entity's blocks in order, each block's elements in order.
// These are the tags MeshData holds; the file's own tags are mapped onto them through its
// $Nodes (by position, as the MSH reader adds nodes) and $Elements (by type and nodes).
struct FileMeshTags {
  bool nodesGiven = false;  // `nodes` known beforehand: the file's $Nodes are not read
  bool hasNodes = false;
  bool hasElements = false;
  std::unordered_map<std::uint64_t, std::uint64_t> nodes;     // file tag -> mesh tag
  std::unordered_map<std::uint64_t, std::uint64_t> elements;  // file tag -> mesh tag
};

// One $NodeData, $ElementData or $ElementNodeData section, its tags already the mesh's.
struct DataSection {
  post::MeshData::Kind kind = post::MeshData::Kind::Node;
  std::string name;
  int components = 1;
  std::size_t entries = 0;
  std::size_t at = 0;  // byte offset of the data, for messages
  post::MeshData::Step step;
};

// The data sections of an MSH file held in `data`, whose mesh is `mesh`; `tags`, if given,
// starts the mapping (see nodesGiven) and receives how the file's tags map to the mesh's. Throws
// ViewReadError located at the line and column (text) or byte (binary data) at fault.
std::vector<DataSection> readMshDataSections(const std::string& data, const std::string& path,
                                             const Mesh& mesh, FileMeshTags* tags = nullptr);

}  // namespace geomesh
