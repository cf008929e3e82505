// Partitioning a session's mesh: PartitionMesh n;, -part n, Mesh.NbPartitions after meshing,
// and the SimplePartition plugin.
#pragma once

#include <array>

#include "api/session.h"

namespace geomesh::api {

// Splits the session's mesh into `count` partitions with METIS, following Mesh.MetisAlgorithm,
// MetisObjective, MetisEdgeMatching, MetisRefinementAlgorithm, MetisMaxLoadImbalance,
// MetisMinConn, Partition*Weight, PartitionCreateTopology and PartitionCreatePhysicals.
// Throws std::invalid_argument when the mesh has fewer elements than `count`, or none.
void partitionMesh(Session& session, int count);

// Plugin(SimplePartition).Run: NumSlicesX/Y/Z slices of the mesh's box.
void partitionMeshBySlices(Session& session, std::array<int, 3> slices);

// The load imbalance (largest partition over the mean, minus 1) and the number of facets
// between elements of different partitions (0 without Mesh.PartitionCreateTopology), for the
// log.
struct PartitionStatistics {
  double imbalance = 0;
  std::size_t cutFacets = 0;
};
PartitionStatistics partitionStatistics(const Mesh& mesh);

}  // namespace geomesh::api
