// Partitioned MSH files: $PartitionedEntities and per-piece blocks in 4.1, partition tags in
// 2.2, one file per partition when asked, and the 4.1 reader taking pieces as entities.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "io/formats.h"
#include "io/msh_reader.h"
#include "io/msh_writer.h"
#include "mesh/partition/partition_mesh.h"
#include "mesh/pipeline/generate.h"
#include "tests/mesh/mesh_test_models.h"
#include "tests/scratch.h"

namespace geomesh {
namespace {

struct Partitioned {
  Model model;
  Mesh mesh;
};

Partitioned partitionedSquare(int parts, bool physicals = false) {
  testing::PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.1)});
  Partitioned p{std::move(b.model), {}};
  p.model.addPhysicalGroup({2, 5, "plate", {1}});
  SilentSink log;
  generateMesh(p.model, {}, 2, p.mesh, log);
  PartitionSettings settings;
  settings.count = parts;
  settings.topology.createPhysicals = physicals;
  partitionMesh(p.model, p.mesh, settings);
  return p;
}

std::string mshText(const Partitioned& p, double version, bool binary = false,
                    bool saveAll = false) {
  std::ostringstream out;
  writeMsh(out, p.model, p.mesh, {saveAll, binary, version});
  return out.str();
}

std::string section(const std::string& text, const std::string& name) {
  const std::size_t begin = text.find("$" + name + "\n");
  const std::size_t end = text.find("$End" + name);
  if (begin == std::string::npos || end == std::string::npos) return "";
  return text.substr(begin + name.size() + 2, end - begin - name.size() - 2);
}

TEST(MshPartitions, Version41ListsThePiecesAfterTheEntities) {
  const Partitioned p = partitionedSquare(3);
  const std::string text = mshText(p, 4.1);
  ASSERT_LT(text.find("$EndEntities"), text.find("$PartitionedEntities"));
  std::istringstream in(section(text, "PartitionedEntities"));
  std::size_t partitions = 0, ghosts = 0, counts[4];
  in >> partitions >> ghosts >> counts[0] >> counts[1] >> counts[2] >> counts[3];
  EXPECT_EQ(partitions, 3u);
  EXPECT_EQ(ghosts, 0u);
  std::size_t pieces[4] = {};
  for (const PartitionEntity& piece : p.mesh.partitions()->entities) ++pieces[piece.id.dim];
  for (int d = 0; d < 4; ++d) EXPECT_EQ(counts[d], pieces[d]) << "dimension " << d;
  // The first point piece: tag, parent (0, tag), one partition.
  int tag = 0, parentDim = -1, parentTag = 0, partitionCount = 0;
  in >> tag >> parentDim >> parentTag >> partitionCount;
  EXPECT_GT(tag, p.model.maxTag(0));
  EXPECT_EQ(parentDim, 0);
  EXPECT_EQ(partitionCount, 1);
}

TEST(MshPartitions, ReadingKeepsThePartitionsAndWritingAgainGivesTheSameFile) {
  const Partitioned p = partitionedSquare(4);
  for (bool binary : {false, true}) {
    const std::string first = mshText(p, 4.1, binary, true);
    std::istringstream in(first);
    Partitioned read;
    readMsh(in, read.model, read.mesh, "part.msh");
    // The model's entities hold the nodes and elements again; the pieces are partitions.
    EXPECT_EQ(read.mesh.nodeCount(), p.mesh.nodeCount());
    for (int d = 0; d <= 2; ++d) EXPECT_EQ(read.mesh.elementCount(d), p.mesh.elementCount(d));
    ASSERT_NE(read.mesh.partitions(), nullptr);
    EXPECT_EQ(read.mesh.partitions()->count, 4);
    const auto& pieces = p.mesh.partitions()->entities;
    const auto& again = read.mesh.partitions()->entities;
    ASSERT_EQ(again.size(), pieces.size());
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      EXPECT_EQ(again[i].id, pieces[i].id);
      EXPECT_EQ(again[i].parent, pieces[i].parent);
      EXPECT_EQ(again[i].partitions, pieces[i].partitions);
      EXPECT_EQ(again[i].boundary, pieces[i].boundary);
      EXPECT_EQ(again[i].nodes.size(), pieces[i].nodes.size());
    }
    if (binary) continue;
    const std::string second = mshText(read, 4.1, false, true);
    for (const char* name : {"PartitionedEntities", "Nodes", "Elements"})
      EXPECT_EQ(section(second, name), section(first, name)) << name;
  }
}

TEST(MshPartitions, PhysicalGroupsPerPartitionAreNamed) {
  const Partitioned p = partitionedSquare(2, true);
  const std::string names = section(mshText(p, 4.1), "PhysicalNames");
  EXPECT_NE(names.find("\"_part{1}_physical{5}_dim{2}\""), std::string::npos) << names;
  EXPECT_NE(names.find("\"plate\""), std::string::npos) << names;
}

TEST(MshPartitions, Version22ElementsCarryTheirPartitions) {
  const Partitioned p = partitionedSquare(3);
  std::istringstream in(section(mshText(p, 2.2), "Elements"));
  std::size_t count = 0;
  in >> count;
  ASSERT_EQ(count, p.mesh.elementCount(2));  // only the triangles are in a physical group
  int tag, type, tags, physical, entity, partitions, partition;
  in >> tag >> type >> tags >> physical >> entity >> partitions >> partition;
  EXPECT_EQ(tags, 4);
  EXPECT_EQ(physical, 5);
  EXPECT_EQ(entity, 1);  // old style: the model surface's tag
  EXPECT_EQ(partitions, 1);
  EXPECT_GE(partition, 1);
  EXPECT_LE(partition, 3);
}

TEST(MshPartitions, SplitFilesHoldOnePartitionEach) {
  const Partitioned p = partitionedSquare(3);
  const auto dir = scratch::path("split-test");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  MeshWriteOptions options;
  options.splitPartitions = true;
  writeMeshFile((dir / "plate.msh").string(), *findFormatByName("msh41"), p.model, p.mesh, options);
  EXPECT_FALSE(std::filesystem::exists(dir / "plate.msh"));
  std::size_t triangles = 0;
  for (int k = 1; k <= 3; ++k) {
    const auto path = dir / ("plate_" + std::to_string(k) + ".msh");
    ASSERT_TRUE(std::filesystem::exists(path)) << path;
    Model model;
    Mesh mesh;
    readMshFile(path.string(), model, mesh);
    triangles += mesh.elementCount(2);
  }
  EXPECT_EQ(triangles, p.mesh.elementCount(2));
  std::filesystem::remove_all(dir);
}

TEST(MshPartitions, OtherFormatsSaveTheModelEntitiesAndTheirGroups) {
  const Partitioned p = partitionedSquare(3);
  std::ostringstream out;
  findFormatByName("vtk")->write(out, p.model, p.mesh, {});
  const std::string text = out.str();
  std::istringstream cells(text.substr(text.find("CELLS ")));
  std::string word;
  std::size_t count = 0;
  cells >> word >> count;
  EXPECT_EQ(count, p.mesh.elementCount(2)) << "the triangles of the plate, its only group";
  std::istringstream ids(text.substr(text.find("LOOKUP_TABLE default")));
  std::getline(ids, word);
  int id = 0;
  while (ids >> id) EXPECT_EQ(id, 1) << "each cell carries the model surface's tag";
}

}  // namespace
}  // namespace geomesh
