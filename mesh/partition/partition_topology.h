// The pieces of a partitioned mesh: every model entity split by the partitions that hold its
// elements, with the interfaces between partitions as entities of their own.
#pragma once

#include <vector>

#include "kernel/model.h"
#include "mesh/core/mesh.h"
#include "mesh/partition/element_partition.h"

namespace geomesh {

struct PartitionTopologyOptions {
  // Mesh.PartitionCreateTopology: interfaces between partitions become entities (curves
  // between the partitions of a surface, ...) with line, triangle or point elements; without
  // it, only the pieces holding the model's elements are made, and a node shared by
  // partitions goes to the piece of the lowest of them.
  bool createTopology = true;
  // Mesh.PartitionCreatePhysicals: one physical group per dimension, partition set and
  // physical group of the parent, named "_part{1,2}_physical{200}_dim{1}"; the pieces are
  // then in those groups only.
  bool createPhysicals = false;
};

// Every element of dimension below top.dim goes to the partitions of the top-dimensional
// elements it is a facet (or edge, or corner) of; every node to the partitions of the
// elements around it. A node on a model entity of dimension d around which the partitions are
// more than around the entity's elements lies on an interface of a lower dimension: d minus
// the number of partitions beyond theirs.
MeshPartitions buildPartitions(const Model& model, const Mesh& mesh, const TopElements& top,
                               const std::vector<int>& topPartition, int count,
                               const PartitionTopologyOptions& options);

}  // namespace geomesh
