// OFF through its row of the format table: counts, vertices and faces, the refusal of meshes
// without surface elements, and the reader (comments, variants, errors on malformed files).
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "tests/io/format_test_meshes.h"
#include "tests/scratch.h"

namespace geomesh {
namespace {

using namespace testing;

TEST(Off, IsFoundByNameAndExtensionWithoutACode) {
  const MeshFormat* off = findFormatByName("off");
  ASSERT_NE(off, nullptr);
  EXPECT_EQ(findFormatByExtension(".off", 4.1), off);
  EXPECT_EQ(findReaderByExtension(".off"), off);
  EXPECT_EQ(off->code, 0);
  EXPECT_EQ(off->maxOrder, 1);
}

TEST(Off, WritesCountsVerticesAndFaces) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh, true);
  const std::string text = writeAs("off", model, mesh);
  std::istringstream in(text);
  std::string keyword;
  int vertices = 0, faces = 0, edges = -1;
  in >> keyword >> vertices >> faces >> edges;
  EXPECT_EQ(keyword, "OFF");
  EXPECT_EQ(vertices, 8);
  EXPECT_EQ(faces, 9);
  EXPECT_EQ(edges, 0);
  std::vector<Vec3> points(8);
  for (Vec3& p : points) in >> p.x >> p.y >> p.z;
  std::vector<int> sizes;
  std::vector<int> last;
  for (int n = 0; in >> n;) {
    sizes.push_back(n);
    last.clear();
    for (int k = 0; k < n; ++k) {
      int v = 0;
      in >> v;
      last.push_back(cornerAt(points.at(static_cast<std::size_t>(v))));
    }
  }
  EXPECT_EQ(sizes, (std::vector<int>{3, 3, 3, 3, 3, 3, 4, 4, 4}));
  EXPECT_EQ(last, (std::vector<int>{1, 3, 7, 5}));
}

TEST(Off, ReadsBackWhatItWrites) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh, true);
  const ReadBack r = readAs("off", writeAs("off", model, mesh));
  EXPECT_EQ(r.mesh.nodeCount(), 8u);
  const auto counts = countsByEntity(r.mesh);
  EXPECT_EQ((counts.at({{2, 1}, ElementType::Triangle3})), 6u);
  EXPECT_EQ((counts.at({{2, 1}, ElementType::Quad4})), 3u);
  const ElementBlock* triangles = r.mesh.find({2, 1})->findBlock(ElementType::Triangle3);
  EXPECT_EQ(r.mesh.node(triangles->nodes[1]), cubeCorner(2));
}

TEST(Off, ReadsCommentsColoursAndCountsOnTheKeywordLine) {
  const ReadBack r = readAs("off",
                            "# a comment\nCOFF 4 2 0\n"
                            "0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n\n1 1 0 0 0 255 255\n"
                            "0 1 0 1 1 1 1 # last vertex\n"
                            "3 0 1 2 0.5 0.5 0.5\n3 0 2 3\n");
  EXPECT_EQ(r.mesh.nodeCount(), 4u);
  EXPECT_EQ(r.mesh.elementCount(2), 2u);
}

TEST(Off, MalformedFilesAreErrorsNamingTheFileAndLine) {
  const std::string head = "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n";
  EXPECT_EQ(readErrorOf("off", head + "5 0 1 2 3 0\n", "o.off"),
            "o.off:7: face 0 has 5 vertices: triangles and quadrangles are read");
  EXPECT_EQ(readErrorOf("off", head + "3 0 1 7\n", "o.off"),
            "o.off:7: face 0 uses vertex 7, but the file has 4 vertices");
  EXPECT_EQ(readErrorOf("off", head + "4 0 1 2\n", "o.off"),
            "o.off:7: face 0 lists fewer than 4 vertices");
  EXPECT_EQ(readErrorOf("off", head, "o.off"), "o.off:7: unexpected end of file");
  EXPECT_EQ(readErrorOf("off", "OFF\n4 1 0\n0 0 0\n1 0\n", "o.off"),
            "o.off:4: vertex 1 has fewer than 3 coordinates");
  EXPECT_EQ(readErrorOf("off", "OFF\n1 0 0\n0 0 x\n", "o.off"),
            "o.off:3: expected a coordinate, found 'x'");
  EXPECT_EQ(readErrorOf("off", "PLY\n", "o.off"),
            "o.off:1: not an OFF file: expected 'OFF', found 'PLY'");
  EXPECT_EQ(readErrorOf("off", "OFF\n99999 1 0\n0 0 0\n", "o.off"),
            "o.off:2: the counts exceed the size of the file");
}

TEST(Off, AVolumeMeshIsRefusedAndNoFileIsLeft) {
  expectVolumeMeshRefused("off", ": the mesh to save has 1 hexahedron elements");
}

TEST(Off, DamagedFilesAreErrorsNeverCrashes) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh, true);
  expectDamageIsReported("off", writeAs("off", model, mesh));
}

}  // namespace
}  // namespace geomesh
