// MshReadState: what the MSH section readers build up, and the section readers' declarations.
#pragma once

#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include "io/msh_decoder.h"
#include "kernel/model.h"
#include "mesh/core/mesh.h"

namespace geomesh {

// What the section readers of an MSH file build up, turned into the model's physical groups
// once the whole file is read.
struct MshReadState {
  Model& model;
  Mesh& mesh;
  std::unordered_map<std::uint64_t, NodeIndex> nodeIndex;  // file tag -> mesh node
  std::map<EntityId, std::string> physicalNames;           // (dim, group tag) -> name
  std::map<EntityId, std::vector<int>> physicalMembers;    // (dim, group tag) -> entity tags
  // A partitioned file: its pieces as $PartitionedEntities lists them (nodes and elements are
  // read onto entities of the pieces' tags, then moved to their parents).
  int partitionCount = 0;
  std::vector<PartitionEntity> pieces;

  void addToPhysical(int dim, int group, int entity);
  NodeIndex node(MshDecoder& in, std::uint64_t tag) const;  // fails for an unknown tag
  // Element type from its MSH number; fails for types the mesh cannot hold.
  static ElementType elementType(MshDecoder& in, int number);
  static void checkDimension(MshDecoder& in, int dim);
};

void readMsh41Entities(MshDecoder& in, MshReadState& state);
// The pieces of a partitioned file; once the file is read, attachPartitions gives their nodes
// and elements to the entities they are pieces of and keeps the pieces as the mesh's
// partitions.
void readMsh41PartitionedEntities(MshDecoder& in, MshReadState& state);
void attachPartitions(MshReadState& state);
void readMsh41Nodes(MshDecoder& in, MshReadState& state);
void readMsh41Elements(MshDecoder& in, MshReadState& state);
void readMsh22Nodes(MshDecoder& in, MshReadState& state);
void readMsh22Elements(MshDecoder& in, MshReadState& state);
// MSH 1.0: $NOD (as 2.2's $Nodes) and $ELM (each element: tag, type, physical group,
// elementary entity, node count, nodes), text only.
void readMsh1Nodes(MshDecoder& in, MshReadState& state);
void readMsh1Elements(MshDecoder& in, MshReadState& state);
// $Periodic: each link is kept in the linked entity's EntityMesh::periodic.
void readMsh41Periodic(MshDecoder& in, MshReadState& state);
void readMsh22Periodic(MshDecoder& in, MshReadState& state);

// Reads the end marker of a section, after optional whitespace (a line break follows binary
// data).
void expectSectionEnd(MshDecoder& in, const char* marker);

}  // namespace geomesh
