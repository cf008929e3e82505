// PLY through its row of the format table: header, vertices and faces in ASCII and
// binary_little_endian, the refusal of meshes without surface elements, and the reader (its
// three encodings, properties and elements it reads past, errors on malformed files).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "tests/io/format_test_meshes.h"
#include "tests/scratch.h"

namespace geomesh {
namespace {

using namespace testing;

const char* kCubeHeader =
    "ply\nformat ascii 1.0\ncomment geomesh mesh\nelement vertex 8\nproperty double x\n"
    "property double y\nproperty double z\nelement face 9\n"
    "property list uchar int vertex_indices\nend_header\n";

TEST(Ply, IsFoundByNameAndExtensionWithoutACode) {
  const MeshFormat* ply = findFormatByName("ply");
  ASSERT_NE(ply, nullptr);
  EXPECT_EQ(findFormatByExtension(".ply", 4.1), ply);
  EXPECT_EQ(findReaderByExtension(".ply"), ply);
  EXPECT_EQ(ply->code, 0);
  EXPECT_EQ(formatCodeList().find("(ply)"), std::string::npos) << formatCodeList();
}

TEST(Ply, AsciiHoldsTheVerticesUsedAndOneFacePerElement) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh, true);
  mesh.addNode({5, 5, 5});  // used by no element: not written
  const std::string text = writeAs("ply", model, mesh);
  ASSERT_EQ(text.rfind(kCubeHeader, 0), 0u) << text;
  std::istringstream in(text.substr(std::strlen(kCubeHeader)));
  std::vector<Vec3> vertices(8);
  for (Vec3& p : vertices) in >> p.x >> p.y >> p.z;
  // Each face as the corners of the cube its vertices are at.
  std::vector<std::vector<int>> faces;
  for (int n = 0; in >> n;) {
    faces.emplace_back();
    for (int k = 0; k < n; ++k) {
      int v = 0;
      in >> v;
      faces.back().push_back(cornerAt(vertices.at(static_cast<std::size_t>(v))));
    }
  }
  ASSERT_EQ(faces.size(), 9u);
  EXPECT_EQ(faces[0], (std::vector<int>{0, 2, 3}));
  EXPECT_EQ(faces[1], (std::vector<int>{0, 3, 1}));
  EXPECT_EQ(faces[8], (std::vector<int>{1, 3, 7, 5}));
  std::sort(vertices.begin(), vertices.end(), [](Vec3 a, Vec3 b) {
    return cornerAt(a) < cornerAt(b);
  });
  for (int i = 0; i < 8; ++i) EXPECT_EQ(vertices[i], cubeCorner(i));
}

TEST(Ply, BinaryIsLittleEndianDoublesAndIntLists) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh, true);
  const std::string bytes = writeAs("ply", model, mesh, true);
  const std::string header = "ply\nformat binary_little_endian 1.0\n";
  ASSERT_EQ(bytes.rfind(header, 0), 0u);
  const std::size_t body = bytes.find("end_header\n") + 11;
  ASSERT_EQ(bytes.size(), body + 8 * 24 + 6 * (1 + 12) + 3 * (1 + 16));
  const std::size_t lastFace = bytes.size() - 17;
  EXPECT_EQ(bytes[lastFace], 4);
  std::int32_t indices[4];
  std::memcpy(indices, bytes.data() + lastFace + 1, 16);
  std::vector<int> corners;
  for (std::int32_t v : indices) {
    double xyz[3];
    std::memcpy(xyz, bytes.data() + body + 24 * static_cast<std::size_t>(v), 24);
    corners.push_back(cornerAt({xyz[0], xyz[1], xyz[2]}));
  }
  EXPECT_EQ(corners, (std::vector<int>{1, 3, 7, 5}));
}

TEST(Ply, BinaryAndAsciiReadBackAlike) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh, true);
  for (bool binary : {false, true}) {
    const ReadBack r = readAs("ply", writeAs("ply", model, mesh, binary));
    EXPECT_EQ(r.mesh.nodeCount(), 8u);
    const auto counts = countsByEntity(r.mesh);
    EXPECT_EQ((counts.at({{2, 1}, ElementType::Triangle3})), 6u) << binary;
    EXPECT_EQ((counts.at({{2, 1}, ElementType::Quad4})), 3u) << binary;
    const ElementBlock* quads = r.mesh.find({2, 1})->findBlock(ElementType::Quad4);
    const int corners[] = {1, 3, 7, 5};
    for (int k = 0; k < 4; ++k) EXPECT_EQ(r.mesh.node(quads->nodes[8 + k]), cubeCorner(corners[k]));
    EXPECT_NE(r.model.surface(1), nullptr);
  }
}

TEST(Ply, ReadsBigEndianFilesAndReadsPastOtherData) {
  std::string bytes =
      "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property uchar red\nproperty float y\nproperty float z\nelement edge 1\n"
      "property int vertex1\nproperty int vertex2\nelement face 1\n"
      "property list uchar uint vertex_index\nproperty list uchar float texcoord\nend_header\n";
  const auto add = [&](auto v) {
    char raw[sizeof v];
    std::memcpy(raw, &v, sizeof v);
    for (std::size_t k = sizeof v; k-- > 0;) bytes += raw[k];
  };
  const float xyz[3][3] = {{0, 0, 0}, {2, 0, 0}, {0, 3, 0}};
  for (const auto& p : xyz) {
    add(p[0]);
    add(std::uint8_t{200});
    add(p[1]);
    add(p[2]);
  }
  add(std::int32_t{0});
  add(std::int32_t{1});
  add(std::uint8_t{3});
  for (std::uint32_t v : {0u, 1u, 2u}) add(v);
  add(std::uint8_t{2});
  add(0.5f);
  add(0.25f);
  const ReadBack r = readAs("ply", bytes);
  ASSERT_EQ(r.mesh.nodeCount(), 3u);
  EXPECT_EQ(r.mesh.node(1), (Vec3{2, 0, 0}));
  EXPECT_EQ(r.mesh.node(2), (Vec3{0, 3, 0}));
  EXPECT_EQ(r.mesh.elementCount(2), 1u);
}

TEST(Ply, MalformedFilesAreErrorsNamingTheFileAndLine) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n1 1 0\n0 1 0\n";
  EXPECT_EQ(readErrorOf("ply", header + "5 0 1 2 3 0\n", "p.ply"),
            "p.ply:14: face 0 has 5 vertices: triangles and quadrangles are read");
  EXPECT_EQ(readErrorOf("ply", header + "3 0 1 4\n", "p.ply"),
            "p.ply:14: face 0 uses vertex 4, but the file has 4 vertices");
  EXPECT_EQ(readErrorOf("ply", header + "3 0 1\n", "p.ply"), "p.ply:15: unexpected end of file");
  EXPECT_EQ(readErrorOf("ply", "ply\nformat ascii 2.0\n", "p.ply"),
            "p.ply:2: expected 'format <encoding> 1.0'");
  EXPECT_EQ(readErrorOf("ply", "PLY\n", "p.ply"), "p.ply:1: not a PLY file: no 'ply' line");
  EXPECT_EQ(readErrorOf("ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                               "property float y\nend_header\n0 0\n",
                        "p.ply"),
            "p.ply:6: the vertex element has no 'z' property");
  EXPECT_EQ(readErrorOf("ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\n",
                        "p.ply"),
            "p.ply:4: unknown property type 'quad'");
  EXPECT_EQ(readErrorOf("ply", "ply\nformat ascii 1.0\nelement vertex 1\n", "p.ply"),
            "p.ply:4: unexpected end of file");
}

TEST(Ply, ATruncatedBinaryFileIsAnError) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh);
  const std::string bytes = writeAs("ply", model, mesh, true);
  for (std::size_t cut : {bytes.size() - 3, bytes.find("end_header") + 11 + 100}) {
    const std::string error = readErrorOf("ply", bytes.substr(0, cut), "t.ply");
    EXPECT_EQ(error.rfind("t.ply:", 0), 0u) << error;
    EXPECT_TRUE(error.find("exceed") != std::string::npos ||
                error.find("unexpected end of binary data") != std::string::npos)
        << error;
  }
}

TEST(Ply, AVolumeMeshIsRefusedAndNoFileIsLeft) {
  expectVolumeMeshRefused("ply", "");
}

TEST(Ply, DamagedFilesAreErrorsNeverCrashes) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh, true);
  expectDamageIsReported("ply", writeAs("ply", model, mesh));
  expectDamageIsReported("ply", writeAs("ply", model, mesh, true));
}

}  // namespace
}  // namespace geomesh
