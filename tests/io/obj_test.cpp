// Wavefront OBJ through its row of the format table: vertices written once and exactly, an
// object per surface or physical surface, and the reader (every form of vertex reference,
// negative indices, polygons split into triangles, names as surfaces, comments and continued
// lines, errors on malformed files).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "tests/io/format_test_meshes.h"
#include "tests/scratch.h"

namespace geomesh {
namespace {

using namespace testing;

// The lines of `text` that start with `keyword` and a space, without it.
std::vector<std::string> statements(const std::string& text, const std::string& keyword) {
  std::vector<std::string> found;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(keyword + " ", 0) == 0) found.push_back(line.substr(keyword.size() + 1));
  return found;
}

// The nodes of each element of the block, as lists.
std::vector<std::vector<NodeIndex>> elementsOf(const ElementBlock* block) {
  std::vector<std::vector<NodeIndex>> elements;
  for (std::size_t i = 0; block && i < block->size(); ++i) {
    const auto nodes = block->element(i);
    elements.emplace_back(nodes.begin(), nodes.end());
  }
  return elements;
}

const ElementBlock* trianglesOf(const ReadBack& r, int surface = 1) {
  const EntityMesh* em = r.mesh.find({2, surface});
  return em ? em->findBlock(ElementType::Triangle3) : nullptr;
}

const std::string kSquare = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

TEST(Obj, IsFoundByNameAndExtensionWithoutACode) {
  const MeshFormat* obj = findFormatByName("obj");
  ASSERT_NE(obj, nullptr);
  EXPECT_EQ(findFormatByExtension(".obj", 4.1), obj);
  EXPECT_EQ(findReaderByExtension(".obj"), obj);
  EXPECT_EQ(obj->code, 0);
  EXPECT_EQ(obj->maxOrder, 1);
}

TEST(Obj, WritesVerticesOnceAndAnObjectPerSurface) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh, true);
  const std::string text = writeAs("obj", model, mesh);
  const std::vector<std::string> vertices = statements(text, "v");
  ASSERT_EQ(vertices.size(), 8u);
  std::vector<Vec3> points;
  for (const std::string& v : vertices) {
    std::istringstream in(v);
    Vec3 p;
    in >> p.x >> p.y >> p.z;
    points.push_back(p);
  }
  EXPECT_EQ(statements(text, "o"), (std::vector<std::string>{"surface1", "surface2", "surface3",
                                                             "surface4", "surface5", "surface6"}));
  const std::vector<std::string> faces = statements(text, "f");
  ASSERT_EQ(faces.size(), 9u);
  std::vector<int> last;
  std::istringstream in(faces.back());
  for (int v = 0; in >> v;) last.push_back(cornerAt(points.at(static_cast<std::size_t>(v - 1))));
  EXPECT_EQ(last, (std::vector<int>{1, 3, 7, 5}));  // the +x face, counted from 1
}

TEST(Obj, AnObjectPerPhysicalSurfaceNamedByItsGroup) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh);
  model.addPhysicalGroup({2, 3, "side walls", {3, 4, 5, 6}});
  model.addPhysicalGroup({2, 8, "", {1}});
  const std::string text = writeAs("obj", model, mesh);
  EXPECT_EQ(statements(text, "o"), (std::vector<std::string>{"side walls", "PhysicalSurface8"}));
  EXPECT_EQ(statements(text, "f").size(), 5u);
  EXPECT_EQ(statements(text, "v").size(), 8u);  // the +z face's vertices are all on others
  EXPECT_EQ(statements(writeAs("obj", model, mesh, false, true), "o").size(), 6u);  // SaveAll
}

TEST(Obj, ReadsBackWhatItWritesWithExactCoordinates) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh, true);
  const ReadBack r = readAs("obj", writeAs("obj", model, mesh));
  EXPECT_EQ(r.mesh.nodeCount(), 8u);
  EXPECT_EQ(r.model.entities(2).size(), 6u);
  const auto counts = countsByEntity(r.mesh);
  for (int s = 1; s <= 3; ++s) EXPECT_EQ((counts.at({{2, s}, ElementType::Triangle3})), 2u) << s;
  for (int s = 4; s <= 6; ++s) EXPECT_EQ((counts.at({{2, s}, ElementType::Quad4})), 1u) << s;
  EXPECT_EQ(r.mesh.node(trianglesOf(r, 1)->nodes[1]), cubeCorner(2));

  // Coordinates that take all 17 digits, tiny, huge and negative zero, read back bit for bit.
  Model odd;
  Mesh oddMesh;
  const std::vector<Vec3> points = {{1.0 / 3, 0.1, -7.25e-301}, {std::acos(-1.0), 1e300, -0.0},
                                    {-2.0 / 7, 123456789.123456789, 5e-324}};
  for (const Vec3& p : points) oddMesh.addNode(p);
  oddMesh.entity({2, 4}).block(ElementType::Triangle3).nodes = {0, 1, 2};
  addDiscreteEntities(odd, oddMesh);
  const ReadBack back = readAs("obj", writeAs("obj", odd, oddMesh));
  ASSERT_EQ(back.mesh.nodeCount(), 3u);
  const std::vector<std::vector<NodeIndex>> triangles = elementsOf(trianglesOf(back, 1));
  ASSERT_EQ(triangles.size(), 1u);
  for (int k = 0; k < 3; ++k) {
    const Vec3 p = back.mesh.node(triangles[0][k]);
    EXPECT_EQ(p, points[k]) << k;
    EXPECT_EQ(std::signbit(p.z), std::signbit(points[k].z)) << k;
  }
}

TEST(Obj, EveryFormOfVertexReferenceIsRead) {
  const ReadBack r = readAs("obj", kSquare +
                                       "vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\n"
                                       "f 1 2 3\nf 1/1 2/2 3/3\nf 1//1 2//1 3//1\n"
                                       "f 1/1/1 2/2/1 3/3/1\nf 1/1 2/2 3/3 4/3\n");
  const std::vector<std::vector<NodeIndex>> triangles = elementsOf(trianglesOf(r));
  ASSERT_EQ(triangles.size(), 4u);
  for (const auto& t : triangles) {
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(r.mesh.node(t[0]), (Vec3{0, 0, 0}));
    EXPECT_EQ(r.mesh.node(t[1]), (Vec3{1, 0, 0}));
    EXPECT_EQ(r.mesh.node(t[2]), (Vec3{1, 1, 0}));
  }
  const auto counts = countsByType(r.mesh);
  EXPECT_EQ(counts.at(ElementType::Quad4), 1u);
  EXPECT_EQ(r.mesh.nodeCount(), 4u);
}

TEST(Obj, NegativeIndicesCountBackFromTheLastVertexRead) {
  const ReadBack r = readAs("obj",
                            "v 0 0 0\nv 1 0 0\nv 1 1 0\nf -3 -2 -1\n"
                            "v 0 1 0\nf -4/1 -2//1 -1/1/1\n");
  const std::vector<std::vector<NodeIndex>> triangles = elementsOf(trianglesOf(r));
  ASSERT_EQ(triangles.size(), 2u);
  const std::vector<Vec3> expected = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0},
                                      {0, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (std::size_t k = 0; k < 6; ++k)
    EXPECT_EQ(r.mesh.node(triangles[k / 3][k % 3]), expected[k]) << k;
}

TEST(Obj, AHexagonIsAFanOfFourTrianglesOfTheSameArea) {
  std::string text;
  for (int k = 0; k < 6; ++k) {
    const double angle = k * std::acos(-1.0) / 3;
    std::ostringstream v;
    v.precision(17);
    v << "v " << 2 * std::cos(angle) << ' ' << 2 * std::sin(angle) << " 1\n";
    text += v.str();
  }
  const ReadBack r = readAs("obj", text + "f 1 2 3 4 5 6\n");
  const std::vector<std::vector<NodeIndex>> triangles = elementsOf(trianglesOf(r));
  ASSERT_EQ(triangles.size(), 4u);
  double area = 0;
  for (const auto& t : triangles) {
    EXPECT_EQ(r.mesh.node(t[0]), r.mesh.node(triangles[0][0]));  // all from the first vertex
    const Vec3 a = r.mesh.node(t[0]), b = r.mesh.node(t[1]), c = r.mesh.node(t[2]);
    const Vec3 normal = cross(b - a, c - a);
    EXPECT_GT(normal.z, 0);  // the face's orientation kept
    area += 0.5 * norm(normal);
  }
  EXPECT_NEAR(area, 3 * std::sqrt(3.0) / 2 * 4, 1e-12);
  EXPECT_EQ(r.mesh.nodeCount(), 6u);
}

TEST(Obj, EachNameIsASurfaceNumberedInTheOrderOfItsFirstFace) {
  const std::string text = kSquare +
                           "f 1 2 3\n"                         // before any name: surface 1
                           "o wall\nf 1 2 3 4\n"               // surface 2
                           "g empty\n"                         // no face: no surface
                           "g roof tiles\nf 1 3 4\nf 2 3 4\n"  // surface 3
                           "o wall\nf 2 3 4\n"                 // surface 2 again
                           "g\nf 1 2 4\n";                     // no name: surface 1 again
  const ReadBack r = readAs("obj", text);
  const auto counts = countsByEntity(r.mesh);
  EXPECT_EQ((counts.at({{2, 1}, ElementType::Triangle3})), 2u);
  EXPECT_EQ((counts.at({{2, 2}, ElementType::Quad4})), 1u);
  EXPECT_EQ((counts.at({{2, 2}, ElementType::Triangle3})), 1u);
  EXPECT_EQ((counts.at({{2, 3}, ElementType::Triangle3})), 2u);
  EXPECT_EQ(counts.size(), 4u);
  EXPECT_EQ(r.model.entities(2).size(), 3u);
  EXPECT_TRUE(r.model.physicalGroups().empty());  // as for STL solids, names are not kept
}

TEST(Obj, CommentsContinuedLinesAndOtherStatementsAreRead) {
  const ReadBack r = readAs("obj",
                            "# a comment\r\nmtllib box.mtl\r\n"
                            "v 0 0 0 1 # a weight\r\nv 1 0 0 0.5 0.2 0.1\r\n"
                            "v 1 \\\n 1 0\nv 0 1 0\n"
                            "vt 0 0\nvn 0 0 1\nvp 0.5\ns off\nusemtl red\nl 1 2 3\np 1\n"
                            "f 1 2 \\   \n3 # a continued face \\\n"
                            "f 1 3 4\n");
  EXPECT_EQ(r.mesh.nodeCount(), 4u);
  const std::vector<std::vector<NodeIndex>> triangles = elementsOf(trianglesOf(r));
  ASSERT_EQ(triangles.size(), 2u);
  EXPECT_EQ(r.mesh.node(triangles[0][2]), (Vec3{1, 1, 0}));
  EXPECT_EQ(r.mesh.elementCount(1), 0u);  // l lines are not read
  EXPECT_EQ(readAs("obj", "").mesh.nodeCount(), 0u);
}

TEST(Obj, MalformedFilesAreErrorsNamingTheFileAndLine) {
  EXPECT_EQ(readErrorOf("obj", kSquare + "f 1 2 5\n", "o.obj"),
            "o.obj:5: face uses vertex 5, but 4 vertices come before it");
  EXPECT_EQ(readErrorOf("obj", kSquare + "f 1 2 -5\n", "o.obj"),
            "o.obj:5: face uses vertex -5, but 4 vertices come before it");
  EXPECT_EQ(readErrorOf("obj", "v 0 0 0\nf 1 2 3\nv 1 0 0\nv 0 1 0\n", "o.obj"),
            "o.obj:2: face uses vertex 2, but 1 vertex comes before it");
  EXPECT_EQ(readErrorOf("obj", kSquare + "f 0 1 2\n", "o.obj"),
            "o.obj:5: face uses vertex 0, but vertices are numbered from 1 (or back from -1)");
  EXPECT_EQ(readErrorOf("obj", kSquare + "\nf 1 2\n", "o.obj"),
            "o.obj:6: face has 2 vertices: at least 3 are needed");
  EXPECT_EQ(readErrorOf("obj", kSquare + "f\n", "o.obj"),
            "o.obj:5: face has 0 vertices: at least 3 are needed");
  EXPECT_EQ(readErrorOf("obj", "v 0 0 x\n", "o.obj"), "o.obj:1: expected a coordinate, found 'x'");
  EXPECT_EQ(readErrorOf("obj", "v 0 0 inf\n", "o.obj"), "o.obj:1: non-finite number 'inf'");
  EXPECT_EQ(readErrorOf("obj", "v 0 0 0\nv 1 0\n", "o.obj"),
            "o.obj:2: vertex 2 has fewer than 3 coordinates");
  EXPECT_EQ(readErrorOf("obj", kSquare + "f 1 2 3x\n", "o.obj"),
            "o.obj:5: expected a vertex index, found '3x'");
  EXPECT_EQ(readErrorOf("obj", kSquare + "f 1 2/a 3\n", "o.obj"),
            "o.obj:5: expected a texture index, found 'a'");
  EXPECT_EQ(readErrorOf("obj", kSquare + "f 1 2 3//n\n", "o.obj"),
            "o.obj:5: expected a normal index, found 'n'");
  for (const char* reference : {"3/", "3//", "3/1/"})
    EXPECT_EQ(readErrorOf("obj", kSquare + "f 1 2 " + reference + "\n", "o.obj"),
              "o.obj:5: expected a vertex reference (i, i/t, i//n or i/t/n), found '" +
                  std::string(reference) + "'");
  // A continued statement is told of at the line where it ends.
  EXPECT_EQ(readErrorOf("obj", kSquare + "f 1 \\\n2 \\\n9\n", "o.obj"),
            "o.obj:7: face uses vertex 9, but 4 vertices come before it");
}

TEST(Obj, AVolumeMeshIsRefusedAndNoFileIsLeft) {
  expectVolumeMeshRefused("obj", ": the mesh to save has 1 hexahedron elements");
}

TEST(Obj, AWrittenFileIsReadThroughTheTable) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh);
  const std::filesystem::path path = scratch::path("cube.obj");
  writeMeshFile(path.string(), *findFormatByName("obj"), model, mesh, {});
  Model readModel;
  Mesh readMesh;
  readMeshFile(path.string(), *findReaderByExtension(".obj"), readModel, readMesh);
  EXPECT_EQ(readMesh.elementCount(2), 6u);
  EXPECT_EQ(readModel.entities(2).size(), 6u);
  std::filesystem::remove(path);
}

TEST(Obj, DamagedFilesAreErrorsNeverCrashes) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh, true);
  expectDamageIsReported("obj", writeAs("obj", model, mesh));
  expectDamageIsReported("obj", kSquare + "vt 0 0\nvn 0 0 1\ng a\nf 1/1/1 -3//1 3/1 \\\n4\n");
}

}  // namespace
}  // namespace geomesh
