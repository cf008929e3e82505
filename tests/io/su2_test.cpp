// SU2 meshes through the su2 row of the format table: NDIME, the elements of the top dimension
// with their type numbers, the points they use, one marker per boundary group, and refusals.
#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "tests/io/solver_format_meshes.h"
#include "tests/scratch.h"

namespace geomesh {
namespace {

using testing::buildMixedMesh;
using testing::writeText;

struct Su2Marker {
  std::string tag;
  std::vector<std::vector<long long>> elements;
};

struct Su2File {
  int dim = 0;
  std::vector<std::vector<long long>> elements;  // type, nodes..., index
  std::vector<std::vector<double>> points;       // coordinates..., index
  std::vector<Su2Marker> markers;
};

std::vector<long long> integers(const std::string& line) {
  std::istringstream in(line);
  std::vector<long long> values;
  for (long long v; in >> v;) values.push_back(v);
  return values;
}

Su2File parseSu2(const std::string& text) {
  Su2File file;
  const std::vector<std::string> lines = testing::linesOf(text);
  auto count = [&](std::size_t i, const std::string& key) {
    EXPECT_EQ(lines.at(i).rfind(key + "= ", 0), 0u) << lines.at(i);
    return std::stoul(lines.at(i).substr(key.size() + 2));
  };
  std::size_t i = 0;
  file.dim = static_cast<int>(count(i++, "NDIME"));
  for (std::size_t n = count(i++, "NELEM"); n > 0; --n)
    file.elements.push_back(integers(lines[i++]));
  for (std::size_t n = count(i++, "NPOIN"); n > 0; --n) {
    std::istringstream in(lines[i++]);
    file.points.emplace_back();
    for (double v; in >> v;) file.points.back().push_back(v);
  }
  for (std::size_t m = count(i++, "NMARK"); m > 0; --m) {
    EXPECT_EQ(lines[i].rfind("MARKER_TAG= ", 0), 0u);
    Su2Marker marker{lines[i++].substr(12), {}};
    for (std::size_t n = count(i++, "MARKER_ELEMS"); n > 0; --n)
      marker.elements.push_back(integers(lines[i++]));
    file.markers.push_back(marker);
  }
  EXPECT_EQ(i, lines.size());
  return file;
}

TEST(Su2, IsFoundByNameExtensionAndCodeAndIsWrittenOnly) {
  const MeshFormat* format = findFormatByName("su2");
  ASSERT_NE(format, nullptr);
  EXPECT_EQ(findFormatByExtension(".su2", 4.1), format);
  EXPECT_EQ(findFormatByCode(42, 4.1), format);
  EXPECT_EQ(findReaderByExtension(".su2"), nullptr);
}

TEST(Su2, WritesTopDimensionElementsUsedPointsAndBoundaryMarkers) {
  Model model;
  Mesh mesh;
  buildMixedMesh(model, mesh);
  testing::addPyramid(model, mesh);
  const Su2File file = parseSu2(writeText("su2", model, mesh));
  EXPECT_EQ(file.dim, 3);
  std::map<long long, int> types;
  for (std::size_t e = 0; e < file.elements.size(); ++e) {
    ++types[file.elements[e][0]];
    EXPECT_EQ(file.elements[e].back(), static_cast<long long>(e));
  }
  EXPECT_EQ(types, (std::map<long long, int>{{10, 1}, {12, 1}, {13, 1}, {14, 1}}));
  // The volumes' points and the boundary group's: not the lines', the point's or surface 6's.
  EXPECT_EQ(file.points.size(), 8u + 4 + 6 + 5 + 3 + 3 + 4);
  for (std::size_t p = 0; p < file.points.size(); ++p) {
    ASSERT_EQ(file.points[p].size(), 4u);
    EXPECT_EQ(file.points[p].back(), static_cast<double>(p));
  }
  ASSERT_EQ(file.markers.size(), 1u);
  EXPECT_EQ(file.markers[0].tag, "wall");
  std::map<long long, int> boundary;
  for (const auto& e : file.markers[0].elements) ++boundary[e[0]];
  EXPECT_EQ(boundary, (std::map<long long, int>{{5, 2}, {9, 1}}));
}

TEST(Su2, NodesAreZeroBasedIndicesOfThePointsInMshOrder) {
  Model model;
  Mesh mesh;
  buildMixedMesh(model, mesh);
  const Su2File file = parseSu2(writeText("su2", model, mesh));
  for (const auto& e : file.elements) {
    std::vector<Vec3> nodes;
    for (std::size_t k = 1; k + 1 < e.size(); ++k) {
      const auto& p = file.points.at(static_cast<std::size_t>(e[k]));
      nodes.push_back({p[0], p[1], p[2]});
    }
    const ElementFamily family = e[0] == 10   ? ElementFamily::Tet
                                 : e[0] == 12 ? ElementFamily::Hex
                                              : ElementFamily::Prism;
    EXPECT_GT(testing::cornerVolume6(family, nodes), 0) << e[0];
  }
}

TEST(Su2, TwoDimensionalMeshesHaveTwoCoordinatesAndLineMarkers) {
  Model model;
  Mesh mesh;
  testing::addReferenceElement(mesh, {2, 1}, ElementType::Triangle3, {0, 0, 0});
  testing::addReferenceElement(mesh, {2, 1}, ElementType::Quad4, {3, 0, 0});
  testing::addReferenceElement(mesh, {1, 2}, ElementType::Line2, {0, -2, 0});
  testing::addReferenceElement(mesh, {1, 3}, ElementType::Line2, {0, -4, 0});
  model.addPhysicalGroup({2, 1, "domain", {1}});
  model.addPhysicalGroup({1, 5, "", {2}});
  model.addPhysicalGroup({1, 6, "far", {3}});
  const Su2File file = parseSu2(writeText("su2", model, mesh));
  EXPECT_EQ(file.dim, 2);
  EXPECT_EQ(file.elements.size(), 2u);
  EXPECT_EQ(file.points.size(), 3u + 4 + 2 + 2);
  EXPECT_EQ(file.points[0].size(), 3u);  // x y index
  ASSERT_EQ(file.markers.size(), 2u);
  EXPECT_EQ(file.markers[0].tag, "PhysicalLine5");
  EXPECT_EQ(file.markers[1].tag, "far");
  EXPECT_EQ(file.markers[1].elements, (std::vector<std::vector<long long>>{{3, 2, 3}}));
}

TEST(Su2, RefusesWhatItCannotHoldBeforeWriting) {
  for (ElementType type : {ElementType::Tet10, ElementType::Triangle6}) {
    Model model;
    Mesh mesh;
    buildMixedMesh(model, mesh);
    testing::addReferenceElement(mesh, {dimension(type), dimension(type) == 3 ? 1 : 3}, type,
                                 {60, 0, 0});
    std::ostringstream out;
    EXPECT_THROW(findFormatByName("su2")->write(out, model, mesh, {}), std::invalid_argument);
    EXPECT_EQ(out.str(), "");
    testing::expectRefusedWithoutFile("su2", model, mesh, scratch::path("refused.su2"),
                                      std::string("SU2 output of ") + elementName(type));
  }
  Model model;
  Mesh mesh;
  testing::addReferenceElement(mesh, {1, 1}, ElementType::Line2, {0, 0, 0});
  testing::expectRefusedWithoutFile("su2", model, mesh, scratch::path("refused.su2"),
                                    "dimension 2 or 3");
  testing::addReferenceElement(mesh, {2, 1}, ElementType::Triangle3, {0, 0, 1});
  testing::expectRefusedWithoutFile("su2", model, mesh, scratch::path("refused.su2"),
                                    "plane z = 0");
}

}  // namespace
}  // namespace geomesh
