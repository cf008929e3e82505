// Tests of reading MSH 1.0 ($NOD/$ELM) and MSH 3.0 files, written by hand after their layouts.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "io/msh_reader.h"
#include "tests/io/msh_text_reading.h"

namespace geomesh {
namespace {

// A unit square of two triangles (surface 7, physical group 10), one edge (curve 3, physical
// group 20) and a corner (point 1, physical group 5).
const std::string kVersion1 = R"msh($NOD
4
1 0 0 0
2 1 0 0
3 1 1 0
4 0 1 0
$ENDNOD
$ELM
4
1 15 5 1 1 1
2 1 20 3 2 1 2
3 2 10 7 3 1 2 3
4 2 10 7 3 1 3 4
$ENDELM
)msh";

// The same square in MSH 3.0: a $MeshFormat, then sections laid out as in 2.x, elements with
// more tags than the physical and elementary ones (here a partition count and partition).
const std::string kVersion3 = R"msh($MeshFormat
3.0 0 8
$EndMeshFormat
$Nodes
4
1 0 0 0
2 1 0 0
3 1 1 0
4 0 1 0
$EndNodes
$Elements
4
1 15 2 5 1 1
2 1 2 20 3 1 2
3 2 4 10 7 1 1 1 2 3
4 2 4 10 7 1 1 1 3 4
$EndElements
)msh";

using testing::ReadResult;

ReadResult read(const std::string& text) { return testing::read(text, "old.msh"); }
std::string readError(const std::string& text) { return testing::readError(text, "old.msh"); }

void expectSquare(const ReadResult& r) {
  EXPECT_EQ(r.mesh.nodeCount(), 4u);
  EXPECT_EQ(r.mesh.elementCount(2), 2u);
  EXPECT_EQ(r.mesh.elementCount(1), 1u);
  EXPECT_EQ(r.mesh.elementCount(0), 1u);
  EXPECT_EQ(r.model.surfaces().size(), 1u);
  EXPECT_EQ(r.model.point(1)->xyz, (Vec3{0, 0, 0}));
  EXPECT_EQ(r.model.physicalGroups().at({2, 10}).entities, (std::vector<int>{7}));
  EXPECT_EQ(r.model.physicalGroups().at({1, 20}).entities, (std::vector<int>{3}));
  EXPECT_EQ(r.model.physicalGroups().at({0, 5}).entities, (std::vector<int>{1}));
  ASSERT_NE(r.mesh.find({2, 7}), nullptr);
  EXPECT_EQ(r.mesh.find({2, 7})->nodes.size(), 2u);  // nodes 3 and 4: 1 and 2 lie lower
}

TEST(MshOldVersions, ReadsVersion1) { expectSquare(read(kVersion1)); }

TEST(MshOldVersions, ReadsVersion3) { expectSquare(read(kVersion3)); }

TEST(MshOldVersions, Version1ErrorsAreLocated) {
  std::string bad = kVersion1;
  bad.replace(bad.find("3 2 10 7 3 1 2 3"), 16, "3 2 10 7 4 1 2 3 4");
  EXPECT_EQ(readError(bad), "old.msh:12: an element of type 2 has 3 nodes, not 4");
  bad = kVersion1;
  bad.replace(bad.find("$ENDNOD"), 7, "$EndNodes");
  EXPECT_EQ(readError(bad), "old.msh:8: expected $ENDNOD, found '$EndNodes'");
  EXPECT_EQ(readError("$NOD\n1\n1 0 0 0\n$ENDNOD\n$Elements\n0\n$EndElements\n"),
            "old.msh:6: unexpected section $Elements in an MSH 1.0 file");
}

}  // namespace
}  // namespace geomesh
