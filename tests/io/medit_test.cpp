// Medit (.mesh) through its row of the format table: sections and counts, references, node
// orders, refused types, and the reader: round trips, discrete entities and groups, errors.
#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "io/mesh_scanner.h"
#include "tests/io/format_test_meshes.h"
#include "tests/io/solver_format_meshes.h"
#include "tests/scratch.h"

namespace geomesh {
namespace {

using testing::buildMixedMesh;
using testing::writeText;

// Each keyword's rows, as numbers; the count after the keyword is checked against them.
std::map<std::string, std::vector<std::vector<double>>> sectionsOf(const std::string& text) {
  std::map<std::string, std::vector<std::vector<double>>> sections;
  std::istringstream in(text);
  const std::map<std::string, int> widths = {
      {"Vertices", 4},      {"Edges", 3},          {"EdgesP2", 4},           {"Triangles", 4},
      {"TrianglesP2", 7},   {"Quadrilaterals", 5}, {"QuadrilateralsQ2", 10}, {"Tetrahedra", 5},
      {"TetrahedraP2", 11}, {"Prisms", 7},         {"Pyramids", 6},          {"Hexahedra", 9}};
  for (std::string word; in >> word;) {
    if (word == "MeshVersionFormatted" || word == "Dimension") {
      in >> word;  // the value
      continue;
    }
    if (word == "End") break;
    std::size_t count = 0;
    in >> count;
    auto& rows = sections[word];
    for (std::size_t i = 0; i < count; ++i) {
      rows.emplace_back(widths.at(word));
      for (double& v : rows.back()) in >> v;
    }
  }
  return sections;
}

std::vector<Vec3> elementNodes(const std::vector<std::vector<double>>& vertices,
                               const std::vector<double>& row) {
  std::vector<Vec3> nodes;
  for (std::size_t k = 0; k + 1 < row.size(); ++k) {
    const auto& v = vertices.at(static_cast<std::size_t>(row[k]) - 1);
    nodes.push_back({v[0], v[1], v[2]});
  }
  return nodes;
}

TEST(Medit, IsFoundByNameExtensionAndCode) {
  const MeshFormat* format = findFormatByName("mesh");
  ASSERT_NE(format, nullptr);
  EXPECT_EQ(findFormatByExtension(".mesh", 4.1), format);
  EXPECT_EQ(findFormatByCode(30, 4.1), format);
  EXPECT_EQ(findReaderByExtension(".mesh"), format);
}

TEST(Medit, WritesHeaderVerticesAndOneSectionPerKeyword) {
  Model model;
  Mesh mesh;
  buildMixedMesh(model, mesh);
  testing::addPyramid(model, mesh);
  const std::string text = writeText("mesh", model, mesh);
  EXPECT_EQ(text.rfind("MeshVersionFormatted 2\n\nDimension 3\n", 0), 0u) << text;
  EXPECT_NE(text.find("\nEnd\n"), std::string::npos);
  const auto sections = sectionsOf(text);
  // The triangle of surface 6 is in no group: not saved, nor its nodes.
  EXPECT_EQ(sections.at("Vertices").size(), 8u + 4 + 6 + 5 + 3 + 3 + 4 + 2 + 2 + 1);
  EXPECT_EQ(sections.at("Hexahedra").size(), 1u);
  EXPECT_EQ(sections.at("Tetrahedra").size(), 1u);
  EXPECT_EQ(sections.at("Prisms").size(), 1u);
  EXPECT_EQ(sections.at("Pyramids").size(), 1u);
  EXPECT_EQ(sections.at("Triangles").size(), 2u);
  EXPECT_EQ(sections.at("Quadrilaterals").size(), 1u);
  EXPECT_EQ(sections.at("Edges").size(), 2u);
  EXPECT_EQ(text.find("Corners"), std::string::npos);  // points are vertices only
}

TEST(Medit, ReferencesArePhysicalTagsElseEntityTags) {
  Model model;
  Mesh mesh;
  buildMixedMesh(model, mesh);
  MeshWriteOptions all;
  all.saveAll = true;
  const auto sections = sectionsOf(writeText("mesh", model, mesh, all));
  EXPECT_EQ(sections.at("Hexahedra")[0].back(), 10);
  EXPECT_EQ(sections.at("Tetrahedra")[0].back(), 11);
  EXPECT_EQ(sections.at("Edges")[0].back(), 30);
  const auto& triangles = sections.at("Triangles");
  ASSERT_EQ(triangles.size(), 3u);
  EXPECT_EQ(triangles[0].back(), 20);
  EXPECT_EQ(triangles[2].back(), 6);  // surface 6 has no group
  for (const auto& vertex : sections.at("Vertices"))
    EXPECT_TRUE(vertex[0] < 50 || vertex.back() == 6) << vertex[0];  // surface 6's nodes
}

TEST(Medit, VolumeElementsKeepPositiveCorners) {
  Model model;
  Mesh mesh;
  buildMixedMesh(model, mesh);
  testing::addPyramid(model, mesh);
  const auto sections = sectionsOf(writeText("mesh", model, mesh));
  const auto& vertices = sections.at("Vertices");
  const std::map<std::string, ElementFamily> volumes = {{"Tetrahedra", ElementFamily::Tet},
                                                        {"Hexahedra", ElementFamily::Hex},
                                                        {"Prisms", ElementFamily::Prism},
                                                        {"Pyramids", ElementFamily::Pyramid}};
  for (const auto& [keyword, family] : volumes)
    EXPECT_GT(testing::cornerVolume6(family, elementNodes(vertices, sections.at(keyword)[0])), 0)
        << keyword;
}

TEST(Medit, SecondOrderNodesFollowTheCornersEdgeByEdge) {
  Model model;
  Mesh mesh;
  testing::addReferenceElement(mesh, {1, 1}, ElementType::Line3, {0, 0, 0});
  testing::addReferenceElement(mesh, {2, 1}, ElementType::Triangle6, {3, 0, 0});
  testing::addReferenceElement(mesh, {2, 1}, ElementType::Quad9, {6, 0, 0});
  testing::addReferenceElement(mesh, {3, 1}, ElementType::Tet10, {9, 0, 0});
  const auto sections = sectionsOf(writeText("mesh", model, mesh));
  const auto& v = sections.at("Vertices");
  using testing::cornersAnd;
  testing::expectLayout(elementNodes(v, sections.at("EdgesP2")[0]), cornersAnd(2, {{0, 1}}),
                        "EdgesP2");
  testing::expectLayout(elementNodes(v, sections.at("TrianglesP2")[0]),
                        cornersAnd(3, {{0, 1}, {1, 2}, {2, 0}}), "TrianglesP2");
  testing::expectLayout(elementNodes(v, sections.at("QuadrilateralsQ2")[0]),
                        cornersAnd(4, {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 1, 2, 3}}),
                        "QuadrilateralsQ2");
  const auto tet = elementNodes(v, sections.at("TetrahedraP2")[0]);
  testing::expectLayout(tet, cornersAnd(4, {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}}),
                        "TetrahedraP2");
  EXPECT_GT(testing::cornerVolume6(ElementFamily::Tet, tet), 0);
}

TEST(Medit, TypesWithoutAKeywordAreRefusedBeforeAnythingIsWritten) {
  for (ElementType type : {ElementType::Quad8, ElementType::Hex27, ElementType::Tet20}) {
    Model model;
    Mesh mesh;
    buildMixedMesh(model, mesh);
    testing::addReferenceElement(mesh, {3, 1}, type, {60, 0, 0});
    std::ostringstream out;
    try {
      findFormatByName("mesh")->write(out, model, mesh, {});
      ADD_FAILURE() << elementName(type);
    } catch (const std::invalid_argument& error) {
      EXPECT_NE(std::string(error.what())
                    .find(std::string("Medit output of ") + elementName(type) + " elements"),
                std::string::npos)
          << error.what();
    }
    EXPECT_EQ(out.str(), "");
    testing::expectRefusedWithoutFile("mesh", model, mesh, scratch::path("refused.mesh"),
                                      elementName(type));
  }
}

TEST(Medit, ReadsBackTypesCountsNodeOrdersAndGroups) {
  Model model;
  Mesh mesh;
  buildMixedMesh(model, mesh);
  testing::addPyramid(model, mesh);
  testing::addReferenceElement(mesh, {3, 1}, ElementType::Tet10, {70, 0, 0});
  MeshWriteOptions all;
  all.saveAll = true;
  const testing::ReadBack back = testing::readAs("mesh", writeText("mesh", model, mesh, all));
  auto expected = testing::elementsByType(mesh);
  expected.erase(ElementType::Point1);
  EXPECT_EQ(testing::elementsByType(back.mesh), expected);
  // One entity and one unnamed group per (dimension, reference).
  using G = std::tuple<int, int, std::string, std::vector<int>>;
  std::vector<G> groups;
  for (const auto& [id, g] : back.model.physicalGroups())
    groups.emplace_back(g.dim, g.tag, g.name, g.entities);
  EXPECT_EQ(groups, (std::vector<G>{G{1, 30, "", {30}}, G{2, 6, "", {6}}, G{2, 20, "", {20}},
                                    G{3, 10, "", {10}}, G{3, 11, "", {11}}}));
  EXPECT_TRUE(back.model.contains({3, 11}));
  EXPECT_EQ(back.mesh.find({3, 11})->elementCount(), 3u);  // tetrahedron, prism, pyramid
  EXPECT_EQ(back.mesh.nodeCount(), 8u + 4 + 6 + 5 + 3 * 3 + 4 + 2 * 2 + 10);  // point dropped
}

TEST(Medit, ReadsTwoDimensionalFilesCommentsAndSkippedKeywords) {
  const std::string text =
      "# a comment\nMeshVersionFormatted 1\nDimension\n2\nVertices\n3\n0 0 1\n1 0 1\n0 1 2\n"
      "Corners\n1\n1\nTriangles\n1\n1 2 3 0\nEdges 1\n1 2 5\nEnd\n";
  const testing::ReadBack back = testing::readAs("mesh", text);
  EXPECT_EQ(back.mesh.nodeCount(), 3u);
  EXPECT_EQ(back.mesh.find({2, 0})->elementCount(), 1u);
  EXPECT_EQ(back.mesh.find({1, 5})->elementCount(), 1u);
  EXPECT_EQ(back.model.physicalGroups().size(), 1u);  // reference 0 is no group
  EXPECT_EQ(back.mesh.node(2).y, 1);
}

TEST(Medit, MalformedFilesAreErrorsNamingTheFileAndLine) {
  const std::string head = "MeshVersionFormatted 2\nDimension 3\nVertices\n2\n0 0 0 0\n1 0 0 0\n";
  EXPECT_EQ(testing::readErrorOf("mesh", head + "Edges\n1\n1 3 7\n", "bad.mesh"),
            "bad.mesh:9: vertex 3 does not exist (2 vertices)");
  EXPECT_EQ(testing::readErrorOf("mesh", head + "Bogus\n1\n", "bad.mesh"),
            "bad.mesh:7: unsupported keyword 'Bogus'");
  EXPECT_EQ(testing::readErrorOf("mesh", head + "Edges\n1\n1 2\n\n\n", "bad.mesh"),
            "bad.mesh:12: unexpected end of file");
  EXPECT_EQ(
      testing::readErrorOf("mesh", "MeshVersionFormatted 2\nVertices\n1\n0 0 0 0\n", "bad.mesh"),
      "bad.mesh:2: Vertices before Dimension");
  EXPECT_EQ(testing::readErrorOf("mesh", head + "Edges\n99999999\n1 2 0\n", "bad.mesh"),
            "bad.mesh:8: count 99999999 exceeds the size of the file");
  EXPECT_EQ(testing::readErrorOf("mesh", head + "Edges\n1\n1 x 0\n", "bad.mesh"),
            "bad.mesh:9: expected a vertex number, found 'x'");
}

TEST(Medit, AWrittenFileReadsBackThroughTheTable) {
  Model model;
  Mesh mesh;
  buildMixedMesh(model, mesh);
  const std::filesystem::path path = scratch::path("roundtrip.mesh");
  writeMeshFile(path.string(), *findFormatByName("mesh"), model, mesh, {});
  Model readModel;
  Mesh readMesh;
  readMeshFile(path.string(), *findReaderByExtension(".mesh"), readModel, readMesh);
  EXPECT_EQ(readMesh.elementCount(3), 3u);
  EXPECT_EQ(readMesh.elementCount(2), 3u);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace geomesh
