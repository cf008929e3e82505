// The legacy VTK writer, through its row of the format table: structure, counts, cell types
// and the entity tag of each cell.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "io/formats.h"
#include "kernel/geo/geo_factory.h"
#include "tests/kernel/kernel_test_helpers.h"

namespace geomesh {
namespace {

// Unit square split into two triangles on surface 1; its four corner nodes on points 1..4 and
// the four sides as lines on curves 1..4. Optionally one tetrahedron on volume 7 and one
// quadrangle on surface 9 sharing nodes, to cover more cell types.
void buildSquare(Model& model, Mesh& mesh, bool withPhysical) {
  GeoFactory geo;
  addUnitSquareSurface(geo);
  if (withPhysical) geo.addPhysicalGroup(2, 5, "plate", {1});
  geo.synchronize(model);
  for (int p = 1; p <= 4; ++p) {
    const NodeIndex n = mesh.addNode(model.point(p)->xyz);
    mesh.entity({0, p}).nodes.push_back(n);
    mesh.entity({0, p}).block(ElementType::Point1).nodes.push_back(n);
  }
  for (int c = 1; c <= 4; ++c)
    mesh.entity({1, c}).block(ElementType::Line2).nodes = {NodeIndex(c - 1), NodeIndex(c % 4)};
  mesh.entity({2, 1}).block(ElementType::Triangle3).nodes = {0, 1, 2, 0, 2, 3};
}

std::string vtkOf(const Model& model, const Mesh& mesh, bool saveAll = false) {
  std::ostringstream out;
  findFormatByName("vtk")->write(out, model, mesh, {saveAll, false});
  return out.str();
}

// The lines after `header` up to the next line starting with an upper-case keyword.
std::vector<std::string> sectionLines(const std::string& text, const std::string& header) {
  std::istringstream in(text.substr(text.find(header)));
  std::vector<std::string> lines;
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line) && !(line[0] >= 'A' && line[0] <= 'Z')) lines.push_back(line);
  return lines;
}

TEST(VtkWriter, IsFoundByNameExtensionAndCode) {
  ASSERT_NE(findFormatByName("vtk"), nullptr);
  EXPECT_EQ(findFormatByExtension(".vtk", 4.1), findFormatByName("vtk"));
  EXPECT_EQ(findFormatByCode(16, 4.1), findFormatByName("vtk"));
  EXPECT_EQ(findReaderByExtension(".vtk"), findFormatByName("vtk"));
  EXPECT_NE(formatNameList().find("vtk"), std::string::npos);
}

TEST(VtkWriter, WritesTheLegacyUnstructuredGridLayout) {
  Model model;
  Mesh mesh;
  buildSquare(model, mesh, false);
  const std::string vtk = vtkOf(model, mesh);
  EXPECT_EQ(vtk.rfind("# vtk DataFile Version 2.0\n", 0), 0u) << vtk;
  std::istringstream in(vtk);
  std::string line;
  std::getline(in, line);
  std::getline(in, line);  // title
  std::getline(in, line);
  EXPECT_EQ(line, "ASCII");
  std::getline(in, line);
  EXPECT_EQ(line, "DATASET UNSTRUCTURED_GRID");
  std::getline(in, line);
  EXPECT_EQ(line, "POINTS 4 double");
  // 4 vertices, 4 lines, 2 triangles: 10 cells of 2 + 4 * 3 + 2 * 4 = 28 numbers.
  EXPECT_NE(vtk.find("\nCELLS 10 28\n"), std::string::npos) << vtk;
  EXPECT_NE(vtk.find("\nCELL_TYPES 10\n"), std::string::npos) << vtk;
  EXPECT_NE(vtk.find("\nCELL_DATA 10\nSCALARS CellEntityIds int 1\nLOOKUP_TABLE default\n"),
            std::string::npos)
      << vtk;
  EXPECT_EQ(sectionLines(vtk, "POINTS"),
            (std::vector<std::string>{"0 0 0", "1 0 0", "1 1 0", "0 1 0"}));
  EXPECT_EQ(sectionLines(vtk, "CELL_TYPES"),
            (std::vector<std::string>{"1", "1", "1", "1", "3", "3", "3", "3", "5", "5"}));
  const std::vector<std::string> cells = sectionLines(vtk, "CELLS");
  ASSERT_EQ(cells.size(), 10u);
  EXPECT_EQ(cells[0], "1 0");
  EXPECT_EQ(cells[7], "2 3 0");
  EXPECT_EQ(cells[9], "3 0 2 3");
  EXPECT_EQ(sectionLines(vtk, "LOOKUP_TABLE"),
            (std::vector<std::string>{"1", "2", "3", "4", "1", "2", "3", "4", "1", "1"}));
}

TEST(VtkWriter, SavesOnlyPhysicalGroupsUnlessSaveAll) {
  Model model;
  Mesh mesh;
  buildSquare(model, mesh, true);
  const std::string physical = vtkOf(model, mesh);
  EXPECT_NE(physical.find("\nCELLS 2 8\n"), std::string::npos) << physical;
  EXPECT_NE(physical.find("\nPOINTS 4 double\n"), std::string::npos) << physical;
  EXPECT_NE(vtkOf(model, mesh, true).find("\nCELLS 10 28\n"), std::string::npos);
}

TEST(VtkWriter, VolumeCellTypes) {
  Model model;
  Mesh mesh;
  buildSquare(model, mesh, false);
  const NodeIndex apex = mesh.addNode({0, 0, 1});
  const NodeIndex top[4] = {mesh.addNode({0, 0, 2}), mesh.addNode({1, 0, 2}),
                            mesh.addNode({1, 1, 2}), mesh.addNode({0, 1, 2})};
  EntityMesh& volume = mesh.entity({3, 7});
  volume.nodes = {apex, top[0], top[1], top[2], top[3]};
  volume.block(ElementType::Tet4).nodes = {0, 1, 2, apex};
  volume.block(ElementType::Pyramid5).nodes = {0, 1, 2, 3, apex};
  volume.block(ElementType::Prism6).nodes = {0, 1, 2, top[0], top[1], top[2]};
  volume.block(ElementType::Hex8).nodes = {0, 1, 2, 3, top[0], top[1], top[2], top[3]};
  const std::string vtk = vtkOf(model, mesh);
  const std::vector<std::string> types = sectionLines(vtk, "CELL_TYPES");
  ASSERT_EQ(types.size(), 14u) << vtk;
  std::vector<std::string> volumeTypes(types.end() - 4, types.end());
  std::sort(volumeTypes.begin(), volumeTypes.end());
  EXPECT_EQ(volumeTypes, (std::vector<std::string>{"10", "12", "13", "14"}));
  EXPECT_EQ(sectionLines(vtk, "LOOKUP_TABLE").back(), "7");
  EXPECT_NE(vtk.find("\nPOINTS 9 double\n"), std::string::npos) << vtk;
}

TEST(VtkWriter, ElementsAboveOrderTwoAreRefusedBeforeAnythingIsWritten) {
  Model model;
  Mesh mesh;
  buildSquare(model, mesh, false);
  const NodeIndex a = mesh.addNode({1.0 / 3, 0, 0});
  const NodeIndex b = mesh.addNode({2.0 / 3, 0, 0});
  mesh.entity({1, 1}).nodes.insert(mesh.entity({1, 1}).nodes.end(), {a, b});
  mesh.entity({1, 1}).block(ElementType::Line4).nodes = {0, 1, a, b};
  std::ostringstream out;
  EXPECT_THROW(findFormatByName("vtk")->write(out, model, mesh, {}), std::invalid_argument);
  EXPECT_EQ(out.str(), "");
}

// The big-endian value of type T at `at` in `bytes`.
template <class T>
T bigEndianAt(const std::string& bytes, std::size_t at) {
  unsigned char raw[sizeof(T)];
  for (std::size_t k = 0; k < sizeof(T); ++k)
    raw[k] = static_cast<unsigned char>(bytes.at(at + sizeof(T) - 1 - k));
  T v;
  std::memcpy(&v, raw, sizeof(T));
  return v;
}

// The `count` big-endian values of type T after the line `header` (which must end the line).
template <class T>
std::vector<T> binarySection(const std::string& bytes, const std::string& header,
                             std::size_t count) {
  const std::size_t start = bytes.find(header);
  EXPECT_NE(start, std::string::npos) << header;
  std::vector<T> values;
  for (std::size_t i = 0; i < count; ++i)
    values.push_back(bigEndianAt<T>(bytes, start + header.size() + i * sizeof(T)));
  EXPECT_EQ(bytes.at(start + header.size() + count * sizeof(T)), '\n') << header;
  return values;
}

std::vector<std::string> words(const std::vector<std::string>& lines) {
  std::vector<std::string> out;
  for (const std::string& line : lines) {
    std::istringstream in(line);
    for (std::string w; in >> w;) out.push_back(w);
  }
  return out;
}

TEST(VtkWriter, BinaryFormHoldsTheAsciiNumbersBigEndian) {
  Model model;
  Mesh mesh;
  buildSquare(model, mesh, false);
  mesh.setNode(2, {1.25, 1e-7, -3});
  const std::string ascii = vtkOf(model, mesh);
  std::ostringstream out;
  findFormatByName("vtk")->write(out, model, mesh, {true, true});
  const std::string binary = out.str();
  EXPECT_EQ(binary.rfind("# vtk DataFile Version 2.0\ngeomesh mesh\nBINARY\n"
                         "DATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n",
                         0),
            0u);
  const std::vector<double> points = binarySection<double>(binary, "POINTS 4 double\n", 12);
  std::vector<std::string> asciiPoints = words(sectionLines(ascii, "POINTS"));
  ASSERT_EQ(asciiPoints.size(), 12u);
  for (std::size_t i = 0; i < 12; ++i) EXPECT_EQ(points[i], std::stod(asciiPoints[i])) << i;
  const auto asInts = [](const std::vector<std::string>& w) {
    std::vector<std::int32_t> v;
    for (const std::string& s : w) v.push_back(std::stoi(s));
    return v;
  };
  EXPECT_EQ(binarySection<std::int32_t>(binary, "\nCELLS 10 28\n", 28),
            asInts(words(sectionLines(ascii, "CELLS"))));
  EXPECT_EQ(binarySection<std::int32_t>(binary, "\nCELL_TYPES 10\n", 10),
            asInts(sectionLines(ascii, "CELL_TYPES")));
  EXPECT_EQ(binarySection<std::int32_t>(
                binary, "CELL_DATA 10\nSCALARS CellEntityIds int 1\nLOOKUP_TABLE default\n", 10),
            asInts(sectionLines(ascii, "LOOKUP_TABLE")));
}

}  // namespace
}  // namespace geomesh
