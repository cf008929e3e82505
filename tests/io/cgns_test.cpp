// CGNS through the cgns row of the format table (a path writer): base, zone, coordinates,
// element sections and their node orders, boundary conditions and families, refusals that
// leave no file, read back through libcgns.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "io/cgns_summary.h"
#include "tests/io/solver_format_meshes.h"
#include "tests/scratch.h"

namespace geomesh {
namespace {

using testing::buildMixedMesh;

CgnsSummary writeAndSummarize(const Model& model, const Mesh& mesh, const std::string& name,
                              const MeshWriteOptions& options = {}) {
  const std::filesystem::path path = scratch::path(name);
  writeMeshFile(path.string(), *findFormatByName("cgns"), model, mesh, options);
  EXPECT_FALSE(std::filesystem::exists(path.string() + ".partial"));
  CgnsSummary summary = summarizeCgnsFile(path.string());
  std::filesystem::remove(path);
  return summary;
}

const CgnsSectionSummary& sectionOfType(const CgnsSummary& s, const std::string& type) {
  for (const CgnsSectionSummary& section : s.sections)
    if (section.type == type) return section;
  throw std::runtime_error("no section of " + type);
}

// The nodes of element `e` of a section, in CGNS's order.
std::vector<Vec3> nodesOf(const CgnsSummary& s, const CgnsSectionSummary& section, std::size_t e,
                          std::size_t count) {
  std::vector<Vec3> nodes;
  for (std::size_t k = 0; k < count; ++k) {
    const auto n = static_cast<std::size_t>(section.connectivity.at(e * count + k) - 1);
    nodes.push_back({s.x.at(n), s.y.at(n), s.z.at(n)});
  }
  return nodes;
}

TEST(Cgns, IsFoundByNameExtensionAndCodeAndIsWrittenToAPath) {
  const MeshFormat* format = findFormatByName("cgns");
  ASSERT_NE(format, nullptr);
  EXPECT_EQ(findFormatByExtension(".cgns", 4.1), format);
  EXPECT_EQ(findFormatByCode(32, 4.1), format);
  EXPECT_EQ(format->write, nullptr);
  EXPECT_NE(format->writeFile, nullptr);
  EXPECT_TRUE(format->writes());
  EXPECT_NE(writtenExtensionList().find(".cgns"), std::string::npos);
}

TEST(Cgns, WritesOneUnstructuredZoneWithASectionPerEntityAndType) {
  Model model;
  Mesh mesh;
  buildMixedMesh(model, mesh);
  testing::addPyramid(model, mesh);
  const CgnsSummary s = writeAndSummarize(model, mesh, "sections.cgns");
  EXPECT_EQ(s.base, "Base");
  EXPECT_EQ(s.zone, "Zone1");
  EXPECT_EQ(s.cellDim, 3);
  EXPECT_EQ(s.physicalDim, 3);
  EXPECT_TRUE(s.unstructured);
  EXPECT_EQ(s.vertices, 8 + 4 + 6 + 5 + 3 + 3 + 4 + 2 + 2 + 1);
  EXPECT_EQ(s.cells, 4);
  EXPECT_EQ(s.x.size(), static_cast<std::size_t>(s.vertices));
  // The volumes first, then the surfaces, curves and points; element numbers run on.
  std::vector<std::tuple<std::string, std::string, long long, long long>> sections;
  for (const CgnsSectionSummary& section : s.sections)
    sections.emplace_back(section.name, section.type, section.first, section.last);
  using S = std::tuple<std::string, std::string, long long, long long>;
  EXPECT_EQ(
      sections,
      (std::vector<S>{S{"Volume1_HEXA_8", "HEXA_8", 1, 1}, S{"Volume2_TETRA_4", "TETRA_4", 2, 2},
                      S{"Volume2_PENTA_6", "PENTA_6", 3, 3}, S{"Volume7_PYRA_5", "PYRA_5", 4, 4},
                      S{"Surface3_TRI_3", "TRI_3", 5, 6}, S{"Surface3_QUAD_4", "QUAD_4", 7, 7},
                      S{"Curve4_BAR_2", "BAR_2", 8, 9}, S{"Point5_NODE", "NODE", 10, 10}}));
}

TEST(Cgns, BoundaryAndCellGroupsBecomeFamiliesAndBoundaryConditions) {
  Model model;
  Mesh mesh;
  buildMixedMesh(model, mesh);
  MeshWriteOptions all;
  all.saveAll = true;
  const CgnsSummary s = writeAndSummarize(model, mesh, "boundaries.cgns", all);
  EXPECT_EQ(s.families, (std::vector<std::string>{"wall", "solid", "PhysicalVolume11"}));
  ASSERT_EQ(s.boundaries.size(), 3u);
  EXPECT_EQ(s.boundaries[0].name, "wall");
  EXPECT_EQ(s.boundaries[0].family, "wall");
  EXPECT_EQ(s.boundaries[0].location, "FaceCenter");
  // Surface 3's two triangles and quadrangle, not surface 6's triangle.
  EXPECT_EQ(s.boundaries[0].elements, (std::vector<long long>{4, 5, 6}));
  // Groups of cells are listed too, at cell centres, as the reference writes them.
  EXPECT_EQ(s.boundaries[1].family, "solid");
  EXPECT_EQ(s.boundaries[1].location, "CellCenter");
  EXPECT_EQ(s.boundaries[1].elements.size(), 1u);
  EXPECT_EQ(s.boundaries[2].family, "PhysicalVolume11");
  EXPECT_EQ(s.boundaries[2].elements.size(), 2u);  // the prism and the tetrahedron of volume 2
  EXPECT_EQ(sectionOfType(s, "TRI_3").last, 5);
}

TEST(Cgns, VolumeElementsKeepPositiveCorners) {
  Model model;
  Mesh mesh;
  buildMixedMesh(model, mesh);
  testing::addPyramid(model, mesh);
  const CgnsSummary s = writeAndSummarize(model, mesh, "corners.cgns");
  const std::vector<std::tuple<std::string, std::size_t, ElementFamily>> volumes = {
      {"HEXA_8", 8, ElementFamily::Hex},
      {"TETRA_4", 4, ElementFamily::Tet},
      {"PENTA_6", 6, ElementFamily::Prism},
      {"PYRA_5", 5, ElementFamily::Pyramid}};
  for (const auto& [type, count, family] : volumes)
    EXPECT_GT(testing::cornerVolume6(family, nodesOf(s, sectionOfType(s, type), 0, count)), 0)
        << type;
}

TEST(Cgns, SecondOrderNodesFollowTheSidsNumbering) {
  Model model;
  Mesh mesh;
  using T = ElementType;
  const std::vector<T> types = {T::Line3,   T::Triangle6, T::Quad8,     T::Quad9,
                                T::Tet10,   T::Pyramid13, T::Pyramid14, T::Prism15,
                                T::Prism18, T::Hex20,     T::Hex27};
  for (T type : types)
    testing::addReferenceElement(mesh, {dimension(type), 1}, type,
                                 {5.0 * static_cast<int>(type), 0, 0});
  const CgnsSummary s = writeAndSummarize(model, mesh, "second-order.cgns");
  using testing::cornersAnd;
  using P = std::vector<std::vector<int>>;
  const P quadEdges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  P pyramid = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 4}, {2, 4}, {3, 4}};
  P prism = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 4}, {2, 5}, {3, 4}, {4, 5}, {5, 3}};
  P hex = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5},
           {2, 6}, {3, 7}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
  P quad9 = quadEdges, pyramid14 = pyramid, prism18 = prism, hex27 = hex;
  quad9.push_back({0, 1, 2, 3});
  pyramid14.push_back({0, 1, 2, 3});
  prism18.insert(prism18.end(), {{0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}});
  hex27.insert(hex27.end(), {{0, 3, 2, 1},
                             {0, 1, 5, 4},
                             {1, 2, 6, 5},
                             {2, 3, 7, 6},
                             {0, 4, 7, 3},
                             {4, 5, 6, 7},
                             {0, 1, 2, 3, 4, 5, 6, 7}});
  const std::vector<std::tuple<std::string, std::size_t, P>> layouts = {
      {"BAR_3", 3, cornersAnd(2, {{0, 1}})},
      {"TRI_6", 6, cornersAnd(3, {{0, 1}, {1, 2}, {2, 0}})},
      {"QUAD_8", 8, cornersAnd(4, quadEdges)},
      {"QUAD_9", 9, cornersAnd(4, quad9)},
      {"TETRA_10", 10, cornersAnd(4, {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}})},
      {"PYRA_13", 13, cornersAnd(5, pyramid)},
      {"PYRA_14", 14, cornersAnd(5, pyramid14)},
      {"PENTA_15", 15, cornersAnd(6, prism)},
      {"PENTA_18", 18, cornersAnd(6, prism18)},
      {"HEXA_20", 20, cornersAnd(8, hex)},
      {"HEXA_27", 27, cornersAnd(8, hex27)}};
  for (const auto& [type, count, places] : layouts)
    testing::expectLayout(nodesOf(s, sectionOfType(s, type), 0, count), places, type);
}

TEST(Cgns, TypesItCannotHoldAreRefusedBeforeTheFileIsCreated) {
  for (ElementType type : {ElementType::Tet20, ElementType::Triangle10, ElementType::Hex64}) {
    Model model;
    Mesh mesh;
    buildMixedMesh(model, mesh);
    testing::addReferenceElement(mesh, {3, 1}, type, {60, 0, 0});  // in group 10
    testing::expectRefusedWithoutFile("cgns", model, mesh, scratch::path("refused.cgns"),
                                      std::string("CGNS output of ") + elementName(type));
  }
}

TEST(Cgns, AMissingDirectoryIsAnErrorNamingTheFileAndLeavesNothing) {
  Model model;
  Mesh mesh;
  buildMixedMesh(model, mesh);
  const std::filesystem::path path = scratch::path("cgns-no-dir") / "sub" / "m.cgns";
  try {
    writeMeshFile(path.string(), *findFormatByName("cgns"), model, mesh, {});
    FAIL() << "no error";
  } catch (const std::runtime_error& error) {
    EXPECT_EQ(std::string(error.what()).rfind("cannot write '" + path.string() + "': ", 0), 0u)
        << error.what();
  }
  EXPECT_FALSE(std::filesystem::exists(path.parent_path()));
}

}  // namespace
}  // namespace geomesh
