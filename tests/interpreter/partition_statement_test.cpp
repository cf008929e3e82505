// PartitionMesh n; and Plugin(SimplePartition) in scripts: the session's mesh is split, the
// count kept in Mesh.NbPartitions, and what cannot be done is reported where it is written.
#include <gtest/gtest.h>

#include <set>

#include "script_runner.h"

namespace geomesh::testing {
namespace {

constexpr const char* kSquare = R"(Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1};
Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Mesh 2;
)";

std::set<int> partitionsUsed(const Mesh& mesh) {
  std::set<int> used;
  for (const PartitionEntity& piece : mesh.partitions()->entities)
    if (piece.id.dim == 2) used.insert(piece.partitions.begin(), piece.partitions.end());
  return used;
}

TEST(PartitionStatement, SplitsTheMeshAndSetsTheOption) {
  ScriptRun run;
  run.run(std::string(kSquare) + "PartitionMesh 3;\n");
  ASSERT_NE(run.session.mesh().partitions(), nullptr);
  EXPECT_EQ(run.session.mesh().partitions()->count, 3);
  EXPECT_EQ(partitionsUsed(run.session.mesh()), (std::set<int>{1, 2, 3}));
  EXPECT_EQ(run.session.options().number("Mesh.NbPartitions"), 3);
}

TEST(PartitionStatement, TooManyPartitionsFailsAtTheStatement) {
  const std::string error = firstLineOf(std::string(kSquare) + "PartitionMesh 100000;\n");
  EXPECT_NE(error.find("test.geo:6:1"), std::string::npos) << error;
  EXPECT_NE(error.find("100000"), std::string::npos) << error;
}

TEST(PartitionStatement, NeedsAWholePositiveNumber) {
  EXPECT_NE(firstLineOf(std::string(kSquare) + "PartitionMesh 2.5;\n").find("whole number"),
            std::string::npos);
}

TEST(PartitionStatement, SimplePartitionPluginSlicesAlongX) {
  ScriptRun run;
  run.run(std::string(kSquare) +
          "Plugin(SimplePartition).NumSlicesX = 2;\nPlugin(SimplePartition).NumSlicesY = 1;\n"
          "Plugin(SimplePartition).Run;\n");
  ASSERT_NE(run.session.mesh().partitions(), nullptr);
  EXPECT_EQ(partitionsUsed(run.session.mesh()), (std::set<int>{1, 2}));
}

TEST(PartitionStatement, GhostCellsAndTopologyFilesAreNotWrittenAndSaySo) {
  ScriptRun run;
  run.run(std::string(kSquare) +
          "Mesh.PartitionCreateGhostCells = 1;\nMesh.PartitionTopologyFile = 1;\n"
          "PartitionMesh 2;\n");
  ASSERT_EQ(run.log.warnings.size(), 2u);
  EXPECT_NE(run.log.warnings[0].find("ghost cells"), std::string::npos);
  EXPECT_NE(run.log.warnings[1].find(".pro"), std::string::npos);
  EXPECT_NE(run.session.mesh().partitions(), nullptr);
}

TEST(PartitionStatement, UnknownPluginsWarnWhenRun) {
  ScriptRun run;
  run.run("Plugin(Triangulate).View = 0;\nPlugin(Triangulate).Run;\n");
  ASSERT_EQ(run.log.warnings.size(), 1u);
  EXPECT_NE(run.log.warnings[0].find("Triangulate"), std::string::npos);
}

TEST(PartitionStatement, ViewPluginsWithoutAViewAreLocatedErrors) {
  EXPECT_EQ(firstLineOf("Plugin(CutPlane).A = 1;\nPlugin(CutPlane).Run;\n"),
            "test.geo:2:1: error: Plugin(CutPlane): View = -1: there is no view");
}

}  // namespace
}  // namespace geomesh::testing
