// Tests of the MSH reader: 4.1 and 2.2 round trips, located errors, corrupt, truncated input.
#include "io/msh_reader.h"
#include "tests/io/msh_text_reading.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "io/msh_writer.h"
#include "mesh/pipeline/generate.h"
#include "mesh/checks/mesh_check.h"
#include "tests/mesh/mesh_test_models.h"

namespace geomesh {
namespace {

// Two unit squares side by side, meshed with physical groups on the left surface, the right
// square's outer edge and one corner: the layout Gmsh writes when saving physical groups only.
const std::string kTwoSquares = R"msh($MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
2
0 6 "p"
2 1 "left"
$EndPhysicalNames
$Entities
6 7 2 0
1 0 0 0 0 
2 1 0 0 0 
3 1 1 0 0 
4 0 1 0 0 
5 2 0 0 1 6 
6 2 1 0 0 
1 0 0 0 1 0 0 0 2 1 -2 
2 1 0 0 1 1 0 0 2 2 -3 
3 0 1 0 1 1 0 0 2 3 -4 
4 0 0 0 0 1 0 0 2 4 -1 
5 1 0 0 2 0 0 0 2 2 -5 
6 2 0 0 2 1 0 1 5 2 5 -6 
7 1 1 0 2 1 0 0 2 6 -3 
1 0 0 0 1 1 0 1 1 4 1 2 3 4 
2 1 0 0 2 1 0 0 4 5 6 7 -2 
$EndEntities
$Nodes
12 15 1 15
0 1 0 1
1
0 0 0
0 2 0 1
2
1 0 0
0 3 0 1
3
1 1 0
0 4 0 1
4
0 1 0
0 5 0 1
5
2 0 0
0 6 0 1
6
2 1 0
1 1 0 1
7
0.4999999999986942 0 0
1 2 0 1
8
1 0.4999999999986942 0
1 3 0 1
9
0.500000000002059 1 0
1 4 0 1
10
0 0.500000000002059 0
1 6 0 1
11
2 0.4999999999986942 0
2 1 0 4
12
13
14
15
0.2937500000004588 0.7062500000004164 0
0.3749999999995795 0.3750000000004207 0
0.6479166666669072 0.6437499999998404 0
0.7187499999993463 0.2812499999995111 0
$EndNodes
$Elements
3 17 1 17
0 5 15 1
1 5 
1 6 1 2
2 5 11 
3 11 6 
2 1 2 14
4 8 3 14 
5 10 1 13 
6 1 7 13 
7 3 9 14 
8 7 2 15 
9 2 8 15 
10 9 4 12 
11 4 10 12 
12 8 14 15 
13 12 10 13 
14 12 13 14 
15 13 7 15 
16 14 13 15 
17 9 12 14 
$EndElements
)msh";

using testing::read;
using testing::ReadResult;
using testing::readError;

std::string write(const ReadResult& r, MshWriteOptions options = {}) {
  std::ostringstream out;
  writeMsh(out, r.model, r.mesh, options);
  return out.str();
}

TEST(MshReader, ReadsEntitiesPhysicalGroupsAndMesh) {
  const ReadResult r = read(kTwoSquares);
  EXPECT_EQ(r.model.points().size(), 6u);
  EXPECT_EQ(r.model.curves().size(), 7u);
  EXPECT_EQ(r.model.surfaces().size(), 2u);
  EXPECT_EQ(r.model.curve(5)->startPoint, 2);
  EXPECT_EQ(r.model.curve(5)->endPoint, 5);
  EXPECT_EQ(r.model.boundary({2, 2}), (std::vector<int>{5, 6, 7, -2}));
  EXPECT_EQ(r.model.point(6)->xyz, (Vec3{2, 1, 0}));
  EXPECT_EQ(r.model.physicalGroups().at({2, 1}).name, "left");
  EXPECT_EQ(r.model.physicalGroups().at({2, 1}).entities, (std::vector<int>{1}));
  EXPECT_EQ(r.model.physicalGroups().at({1, 5}).entities, (std::vector<int>{6}));
  EXPECT_EQ(r.model.physicalGroups().at({0, 6}).name, "p");
  EXPECT_EQ(r.mesh.nodeCount(), 15u);
  EXPECT_EQ(r.mesh.elementCount(2), 14u);
  EXPECT_EQ(r.mesh.elementCount(1), 2u);
  EXPECT_EQ(r.mesh.find({2, 1})->nodes.size(), 4u);
  EXPECT_EQ(r.mesh.find({1, 5}), nullptr);
}

TEST(MshReader, Version41RoundTripIsByteIdentical) {
  const ReadResult r = read(kTwoSquares);
  EXPECT_EQ(write(r), kTwoSquares);
  const std::string binary = write(r, {.binary = true});
  EXPECT_EQ(write(read(binary)), kTwoSquares);
}

TEST(MshReader, Version22RoundTripKeepsNodesElementsAndGroups) {
  const ReadResult original = read(kTwoSquares);
  for (bool binary : {false, true}) {
    const ReadResult r = read(write(original, {.binary = binary, .version = 2.2}));
    EXPECT_EQ(r.mesh.nodeCount(), 15u);
    EXPECT_EQ(r.mesh.elementCount(-1), 17u);
    EXPECT_EQ(r.model.physicalGroups().at({2, 1}).name, "left");
    EXPECT_EQ(r.model.physicalGroups().at({1, 5}).entities, (std::vector<int>{6}));
    EXPECT_EQ(r.model.point(5)->xyz, (Vec3{2, 0, 0}));
    // Rewriting as 2.2 gives the same file again.
    const std::string again = write(r, {.binary = binary, .version = 2.2});
    EXPECT_EQ(write(read(again), {.binary = binary, .version = 2.2}), again);
  }
}

TEST(MshReader, Version22ElementsInSeveralGroupsAreReadOnce) {
  ReadResult r = read(kTwoSquares);
  r.model.addPhysicalGroup({2, 8, "", {1}});
  const ReadResult back = read(write(r, {.version = 2.2}));
  EXPECT_EQ(back.mesh.elementCount(2), 14u);
  EXPECT_EQ(back.model.physicalTagsOf({2, 1}), (std::vector<int>{1, 8}));
}

TEST(MshReader, Version22MeshesPassTheCheckThatStillFindsDefects) {
  // MSH 2.2 carries no topology: the check cannot know a surface's boundary or a curve's end
  // points, but must still find an edge shared by three triangles.
  testing::PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.2), b.circle({0.5, 0.5}, 0.2, 0.1)});
  ReadResult generated{b.model, {}};
  SilentSink log;
  generateMesh(generated.model, {}, 2, generated.mesh, log);
  ReadResult r = read(write(generated, {.version = 2.2}));
  const MeshCheckReport report = checkMesh(r.model, r.mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
  ElementBlock& triangles = r.mesh.entity({2, 1}).block(ElementType::Triangle3);
  const std::vector<NodeIndex> first(triangles.nodes.begin(), triangles.nodes.begin() + 3);
  triangles.nodes.insert(triangles.nodes.end(), first.begin(), first.end());
  const MeshCheckReport broken = checkMesh(r.model, r.mesh);
  ASSERT_FALSE(broken.ok());
  EXPECT_NE(broken.summary().find("triangles instead of 2"), std::string::npos)
      << broken.summary();
}

TEST(MshReader, ErrorsNameFileAndLine) {
  EXPECT_EQ(readError(""), "test.msh:1: not an MSH file: no $MeshFormat");
  EXPECT_EQ(readError("$MeshFormat\n5.0 0 8\n$EndMeshFormat\n"),
            "test.msh:2: unsupported MSH version 5.0 (4.1, 3.0, 2.x and 1.0 are supported)");
  std::string bad = kTwoSquares;
  bad.replace(bad.find("0.4999999999986942 0 0"), 6, "0.4x99");
  EXPECT_EQ(readError(bad), "test.msh:49: expected a number, found '0.4x99999999986942'");
  bad = kTwoSquares;
  bad.replace(bad.find("4 8 3 14"), 8, "4 8 3 99");
  EXPECT_EQ(readError(bad), "test.msh:80: node 99 is not defined");
  bad = kTwoSquares;
  bad.replace(bad.find("2 1 2 14"), 8, "2 1 77 14");
  EXPECT_EQ(readError(bad), "test.msh:79: unsupported element type 77");
  bad = kTwoSquares;
  bad.replace(bad.find("3 17 1 17"), 9, "3 18 1 17");
  EXPECT_EQ(readError(bad), "test.msh:93: the element blocks hold 17 elements, not 18");
  EXPECT_EQ(readError(kTwoSquares.substr(0, kTwoSquares.size() - 13)),
            "test.msh:94: missing $EndElements");
}

TEST(MshReader, FailedReadLeavesNothingBehind) {
  ReadResult r = read(kTwoSquares);
  std::istringstream in(kTwoSquares.substr(0, 600));
  EXPECT_THROW(readMsh(in, r.model, r.mesh, "cut.msh"), MshReadError);
  EXPECT_EQ(r.mesh.nodeCount(), 0u);
  EXPECT_TRUE(r.model.entities(-1).empty());
}

// Every truncation and many corruptions of valid files must end in MshReadError or a
// successful read: never a crash, a hang or another exception.
void expectRobust(const std::string& valid) {
  auto attempt = [](const std::string& text) {
    try {
      read(text);
    } catch (const MshReadError&) {
    }
  };
  for (std::size_t n = 0; n < valid.size(); ++n) attempt(valid.substr(0, n));
  for (std::size_t i = 0; i < valid.size(); ++i)
    for (char c : {'\0', '9', '-', '\xff', ' ', '$', '"'}) {
      std::string corrupt = valid;
      corrupt[i] = c;
      attempt(corrupt);
    }
}

TEST(MshReader, SurvivesTruncationAndCorruption) {
  const ReadResult r = read(kTwoSquares);
  expectRobust(kTwoSquares);
  expectRobust(write(r, {.binary = true}));
  expectRobust(write(r, {.version = 2.2}));
  expectRobust(write(r, {.binary = true, .version = 2.2}));
}

TEST(MshReader, AcceptsWindowsLineEnds) {
  std::string crlf;
  for (char c : kTwoSquares) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  const ReadResult r = read(crlf);
  EXPECT_EQ(r.mesh.nodeCount(), 15u);
  EXPECT_EQ(write(r), kTwoSquares);
}

TEST(MshReader, SkipsUnknownSections) {
  std::string text = kTwoSquares;
  text.insert(text.find("$Entities"), "$Comments\nanything $Nodes\n$EndComments\n");
  EXPECT_EQ(read(text).mesh.nodeCount(), 15u);
}

}  // namespace
}  // namespace geomesh
