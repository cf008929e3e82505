// Partitioning a mesh: one partition per element of the top dimension, then the pieces of
// every entity (mesh/core/mesh.h: MeshPartitions).
#pragma once

#include <array>

#include "kernel/model.h"
#include "mesh/core/mesh.h"
#include "mesh/partition/element_partition.h"
#include "mesh/partition/partition_topology.h"

namespace geomesh {

struct PartitionSettings {
  int count = 1;
  MetisSettings metis;
  PartitionTopologyOptions topology;
};

// Splits the mesh into settings.count partitions with METIS and stores the pieces in the
// mesh (replacing earlier ones). Throws std::invalid_argument when the mesh has fewer
// elements than partitions, or no element.
void partitionMesh(const Model& model, Mesh& mesh, const PartitionSettings& settings);

// The SimplePartition plugin: slices of the mesh's box along x, y and z.
void partitionMeshBySlices(const Model& model, Mesh& mesh, std::array<int, 3> slices,
                           const PartitionTopologyOptions& topology);

}  // namespace geomesh
