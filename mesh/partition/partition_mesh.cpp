// partitionMesh and partitionMeshBySlices: a partition per top element, then the pieces.
#include "mesh/partition/partition_mesh.h"

#include <stdexcept>
#include <string>

namespace geomesh {

namespace {

TopElements checkedTopElements(const Mesh& mesh) {
  TopElements top = topElements(mesh);
  if (top.elements.empty()) throw std::invalid_argument("there is no mesh to partition");
  return top;
}

}  // namespace

void partitionMesh(const Model& model, Mesh& mesh, const PartitionSettings& settings) {
  const TopElements top = checkedTopElements(mesh);
  const std::vector<int> part = metisPartition(top, settings.count, settings.metis);
  MeshPartitions partitions =
      buildPartitions(model, mesh, top, part, settings.count, settings.topology);
  mesh.setPartitions(std::move(partitions));
}

void partitionMeshBySlices(const Model& model, Mesh& mesh, std::array<int, 3> slices,
                           const PartitionTopologyOptions& topology) {
  const TopElements top = checkedTopElements(mesh);
  const std::vector<int> part = slicePartition(mesh, top, slices);
  int count = 1;
  for (int s : slices) count *= std::max(1, s);
  mesh.setPartitions(buildPartitions(model, mesh, top, part, count, topology));
}

}  // namespace geomesh
