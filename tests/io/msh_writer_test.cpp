// Tests of the MSH writer: Gmsh's 4.1 and 2.2 layouts, physical groups, binary, safe replace.
#include "io/msh_writer.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <cstring>
#include <string>

using namespace std::string_literals;

#include "kernel/geo/geo_factory.h"
#include "tests/scratch.h"

namespace geomesh {
namespace {


// The triangle (0,0)-(1,0)-(0,1): points 1..3, lines 1..3, surface 1. Curve 2 has one interior
// node at (0.5, 0.5); the surface has two triangles. Physical groups as asked.
void buildTriangle(Model& model, Mesh& mesh, bool withPhysicals) {
  GeoFactory geo;
  geo.addPoint(1, {0, 0, 0}, 1);
  geo.addPoint(2, {1, 0, 0}, 1);
  geo.addPoint(3, {0, 1, 0}, 1);
  geo.addLine(1, 1, 2);
  geo.addLine(2, 2, 3);
  geo.addLine(3, 3, 1);
  geo.addCurveLoop(1, {1, 2, 3});
  geo.addPlaneSurface(1, {1});
  if (withPhysicals) {
    geo.addPhysicalGroup(1, 4, "", {1});
    geo.addPhysicalGroup(2, 9, "", {1});
  }
  geo.synchronize(model);
  mesh.clear();
  for (int p = 1; p <= 3; ++p) {
    const NodeIndex n = mesh.addNode(model.point(p)->xyz);
    EntityMesh& em = mesh.entity({0, p});
    em.nodes.push_back(n);
    em.block(ElementType::Point1).nodes.push_back(n);
  }
  const NodeIndex mid = mesh.addNode({0.5, 0.5, 0});
  mesh.entity({1, 2}).nodes.push_back(mid);
  mesh.entity({1, 1}).block(ElementType::Line2).nodes = {0, 1};
  mesh.entity({1, 2}).block(ElementType::Line2).nodes = {1, mid, mid, 2};
  mesh.entity({1, 3}).block(ElementType::Line2).nodes = {2, 0};
  mesh.entity({2, 1}).block(ElementType::Triangle3).nodes = {1, mid, 0, mid, 2, 0};
}


std::string written(const Model& model, const Mesh& mesh, MshWriteOptions options = {}) {
  std::ostringstream out;
  writeMsh(out, model, mesh, options);
  return out.str();
}

TEST(MshWriter, PhysicalOnlyLayoutMatchesGmsh) {
  Model model;
  Mesh mesh;
  buildTriangle(model, mesh, true);
  const std::string expected =
      "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
      "$Entities\n3 3 1 0\n"
      "1 0 0 0 0 \n2 1 0 0 0 \n3 0 1 0 0 \n"
      "1 0 0 0 1 0 0 1 4 2 1 -2 \n"
      "2 0 0 0 1 1 0 0 2 2 -3 \n"
      "3 0 0 0 0 1 0 0 2 3 -1 \n"
      "1 0 0 0 1 1 0 1 9 3 1 2 3 \n"
      "$EndEntities\n"
      "$Nodes\n6 4 1 4\n"
      "0 1 0 1\n1\n0 0 0\n"
      "0 2 0 1\n2\n1 0 0\n"
      "0 3 0 1\n3\n0 1 0\n"
      "1 1 0 0\n"
      "1 2 0 1\n4\n0.5 0.5 0\n"
      "2 1 0 0\n"
      "$EndNodes\n"
      "$Elements\n2 3 1 3\n"
      "1 1 1 1\n1 1 2 \n"
      "2 1 2 2\n2 2 4 1 \n3 4 3 1 \n"
      "$EndElements\n";
  EXPECT_EQ(written(model, mesh), expected);
}

TEST(MshWriter, WithoutPhysicalsEverythingIsSaved) {
  Model model;
  Mesh mesh;
  buildTriangle(model, mesh, false);
  const std::string text = written(model, mesh);
  EXPECT_NE(text.find("$Nodes\n7 4 1 4\n"), std::string::npos) << text;  // every entity
  EXPECT_NE(text.find("1 3 0 0\n"), std::string::npos);  // curve 3: empty block
  EXPECT_NE(text.find("$Elements\n7 9 1 9\n"), std::string::npos);
  EXPECT_EQ(text.find("$PhysicalNames"), std::string::npos);
}

TEST(MshWriter, SaveAllKeepsEverythingAndPhysicalTags) {
  Model model;
  Mesh mesh;
  buildTriangle(model, mesh, true);
  const std::string text = written(model, mesh, {.saveAll = true});
  EXPECT_NE(text.find("$Elements\n7 9 1 9\n"), std::string::npos) << text;
  EXPECT_NE(text.find("1 0 0 0 1 0 0 1 4 2 1 -2 \n"), std::string::npos);
}

TEST(MshWriter, RenumbersNodesAndElementsConsecutively) {
  Model model;
  Mesh mesh;
  buildTriangle(model, mesh, false);
  // Only curve 2 is physical: its end points and interior node become nodes 1..3.
  model.addPhysicalGroup({1, 7, "edge", {2}});
  const std::string expected =
      "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
      "$PhysicalNames\n1\n1 7 \"edge\"\n$EndPhysicalNames\n";
  const std::string text = written(model, mesh);
  EXPECT_EQ(text.substr(0, expected.size()), expected);
  EXPECT_NE(text.find("$Nodes\n3 3 1 3\n0 2 0 1\n1\n1 0 0\n0 3 0 1\n2\n0 1 0\n"
                      "1 2 0 1\n3\n0.5 0.5 0\n$EndNodes\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("$Elements\n1 2 1 2\n1 2 1 2\n1 1 3 \n2 3 2 \n$EndElements\n"),
            std::string::npos)
      << text;
}

TEST(MshWriter, Version22LayoutMatchesGmsh) {
  Model model;
  Mesh mesh;
  buildTriangle(model, mesh, true);
  const std::string expected =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
      "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0.5 0.5 0\n$EndNodes\n"
      "$Elements\n3\n"
      "1 1 2 4 1 1 2\n"
      "2 2 2 9 1 2 4 1\n"
      "3 2 2 9 1 4 3 1\n"
      "$EndElements\n";
  EXPECT_EQ(written(model, mesh, {.version = 2.2}), expected);
}

TEST(MshWriter, Version22WritesOneLinePerPhysicalGroup) {
  Model model;
  Mesh mesh;
  buildTriangle(model, mesh, true);
  model.addPhysicalGroup({2, 10, "again", {1}});
  const std::string text = written(model, mesh, {.version = 2.2});
  EXPECT_NE(text.find("$Elements\n5\n"), std::string::npos) << text;
  // Each copy follows its element, as Gmsh writes them.
  EXPECT_NE(text.find("2 2 2 9 1 2 4 1\n3 2 2 10 1 2 4 1\n4 2 2 9 1 4 3 1\n"),
            std::string::npos)
      << text;
}

template <class T>
T readRaw(const std::string& s, std::size_t& pos) {
  T v;
  std::memcpy(&v, s.data() + pos, sizeof(T));
  pos += sizeof(T);
  return v;
}

TEST(MshWriter, BinaryNodesUseSizeTTagsAndDoubles) {
  Model model;
  Mesh mesh;
  buildTriangle(model, mesh, true);
  const std::string text = written(model, mesh, {.binary = true});
  ASSERT_EQ(text.substr(0, 29), "$MeshFormat\n4.1 1 8\n\x01\0\0\0\n$End"s.substr(0, 29));
  std::size_t pos = text.find("$Nodes\n") + 7;
  EXPECT_EQ(readRaw<std::uint64_t>(text, pos), 6u);  // blocks
  EXPECT_EQ(readRaw<std::uint64_t>(text, pos), 4u);  // nodes
  EXPECT_EQ(readRaw<std::uint64_t>(text, pos), 1u);
  EXPECT_EQ(readRaw<std::uint64_t>(text, pos), 4u);
  EXPECT_EQ(readRaw<int>(text, pos), 0);  // dim
  EXPECT_EQ(readRaw<int>(text, pos), 1);  // tag
  EXPECT_EQ(readRaw<int>(text, pos), 0);  // parametric
  EXPECT_EQ(readRaw<std::uint64_t>(text, pos), 1u);
  EXPECT_EQ(readRaw<std::uint64_t>(text, pos), 1u);  // node tag
  EXPECT_EQ(readRaw<double>(text, pos), 0.0);
  EXPECT_NE(text.find("\n$EndNodes\n$Elements\n"), std::string::npos);
  EXPECT_NE(text.find("\n$EndElements\n"), std::string::npos);
}

TEST(MshWriter, RejectsUnknownVersionAndDanglingNodes) {
  Model model;
  Mesh mesh;
  buildTriangle(model, mesh, false);
  EXPECT_THROW(written(model, mesh, {.version = 3.0}), std::invalid_argument);
  mesh.entity({2, 1}).block(ElementType::Triangle3).nodes.back() = 99;
  EXPECT_THROW(written(model, mesh), std::invalid_argument);
}

TEST(MshWriter, FileIsReplacedOnlyOnSuccess) {
  Model model;
  Mesh mesh;
  buildTriangle(model, mesh, true);
  const auto dir = scratch::path("msh-writer");
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "out.msh").string();
  writeMshFile(path, model, mesh, {});
  std::ifstream in(path);
  std::stringstream content;
  content << in.rdbuf();
  EXPECT_EQ(content.str(), written(model, mesh));
  mesh.entity({2, 1}).block(ElementType::Triangle3).nodes.back() = 99;
  EXPECT_THROW(writeMshFile(path, model, mesh, {}), std::runtime_error);
  std::ifstream again(path);
  std::stringstream kept;
  kept << again.rdbuf();
  EXPECT_EQ(kept.str(), content.str());  // the old file is intact
  EXPECT_FALSE(std::filesystem::exists(path + ".partial"));
  EXPECT_THROW(writeMshFile((dir / "missing" / "x.msh").string(), model, mesh, {}),
               std::runtime_error);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace geomesh
