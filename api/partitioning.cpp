// The session's partitioning, from its options, with a line of statistics in the log.
#include "api/partitioning.h"

#include <algorithm>
#include <chrono>
#include <sstream>

#include "mesh/partition/partition_mesh.h"
#include "stdlib/clamped_integer.h"

namespace geomesh::api {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int integerOption(const Session& session, const char* name) {
  return clampedInteger<int>(session.options().number(name));
}

PartitionTopologyOptions topologyOptions(Session& session) {
  PartitionTopologyOptions topology;
  topology.createTopology = integerOption(session, "Mesh.PartitionCreateTopology") != 0;
  topology.createPhysicals = integerOption(session, "Mesh.PartitionCreatePhysicals") != 0;
  if (integerOption(session, "Mesh.PartitionCreateGhostCells") != 0)
    session.log().warning(
        "Mesh.PartitionCreateGhostCells is not supported yet: partitions are written without "
        "ghost cells");
  if (integerOption(session, "Mesh.PartitionTopologyFile") != 0)
    session.log().warning(
        "Mesh.PartitionTopologyFile is not supported yet: no .pro file of the partition "
        "topology is written");
  return topology;
}

MetisSettings metisSettings(const Session& session) {
  MetisSettings metis;
  metis.algorithm = integerOption(session, "Mesh.MetisAlgorithm");
  metis.objective = integerOption(session, "Mesh.MetisObjective");
  metis.edgeMatching = integerOption(session, "Mesh.MetisEdgeMatching");
  metis.refinement = integerOption(session, "Mesh.MetisRefinementAlgorithm");
  metis.maxImbalance = session.options().number("Mesh.MetisMaxLoadImbalance");
  metis.minConnectivity = integerOption(session, "Mesh.MetisMinConn");
  static constexpr std::pair<ElementFamily, const char*> kWeights[] = {
      {ElementFamily::Line, "Mesh.PartitionLineWeight"},
      {ElementFamily::Triangle, "Mesh.PartitionTriWeight"},
      {ElementFamily::Quad, "Mesh.PartitionQuadWeight"},
      {ElementFamily::Tet, "Mesh.PartitionTetWeight"},
      {ElementFamily::Hex, "Mesh.PartitionHexWeight"},
      {ElementFamily::Prism, "Mesh.PartitionPrismWeight"},
      {ElementFamily::Pyramid, "Mesh.PartitionPyramidWeight"}};
  for (const auto& [family, name] : kWeights)
    metis.familyWeights[static_cast<int>(family)] = integerOption(session, name);
  return metis;
}

void logResult(Session& session, double seconds) {
  const Mesh& mesh = session.mesh();
  const PartitionStatistics stats = partitionStatistics(mesh);
  std::ostringstream line;
  line.precision(3);
  line << "Done partitioning mesh into " << mesh.partitions()->count << " parts (" << seconds
       << " s): imbalance " << 100 * stats.imbalance << "%, " << stats.cutFacets
       << " facets between parts, " << mesh.partitions()->entities.size() << " partition entities";
  session.log().info(line.str());
}

}  // namespace

void partitionMesh(Session& session, int count) {
  session.log().info("Partitioning mesh into " + std::to_string(count) + " parts...");
  const auto start = std::chrono::steady_clock::now();
  PartitionSettings settings;
  settings.count = count;
  settings.metis = metisSettings(session);
  settings.topology = topologyOptions(session);
  geomesh::partitionMesh(session.model(), session.mesh(), settings);
  logResult(session, secondsSince(start));
}

void partitionMeshBySlices(Session& session, std::array<int, 3> slices) {
  session.log().info("Partitioning mesh by slices...");
  const auto start = std::chrono::steady_clock::now();
  geomesh::partitionMeshBySlices(session.model(), session.mesh(), slices, topologyOptions(session));
  logResult(session, secondsSince(start));
}

PartitionStatistics partitionStatistics(const Mesh& mesh) {
  PartitionStatistics stats;
  const MeshPartitions* partitions = mesh.partitions();
  if (!partitions || partitions->count < 1) return stats;
  int top = 0;
  for (const PartitionEntity& piece : partitions->entities) top = std::max(top, piece.id.dim);
  std::vector<std::size_t> load(partitions->count + 1, 0);
  std::size_t total = 0;
  for (const PartitionEntity& piece : partitions->entities)
    for (const ElementBlock& b : piece.blocks) {
      // Facets between partitions are the elements of the pieces one dimension down that lie
      // in two partitions (made there by the partition topology).
      if (dimension(b.type) == top - 1 && piece.partitions.size() >= 2) stats.cutFacets += b.size();
      if (dimension(b.type) != top || piece.partitions.size() != 1) continue;
      load[piece.partitions[0]] += b.size();
      total += b.size();
    }
  const double mean = static_cast<double>(total) / partitions->count;
  const std::size_t largest = *std::max_element(load.begin(), load.end());
  stats.imbalance = mean > 0 ? largest / mean - 1 : 0;
  return stats;
}

}  // namespace geomesh::api
