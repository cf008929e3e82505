// I-DEAS universal files through the unv row of the format table: datasets 2411, 2412 and 2477,
// FE descriptors and node orders, groups as Mesh.SaveGroupsOf* select them, refused types, and
// the reader: round trips, entities split by groups, errors.
#include <gtest/gtest.h>

#include <algorithm>
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

struct UnvElementRow {
  long long label, descriptor, property, material, colour;
  std::vector<long long> nodes;
  bool beamRecord = false;
};

struct UnvGroupRow {
  long long number;
  std::string name;
  std::vector<std::pair<int, long long>> entries;  // (7 node | 8 element, label)
};

struct UnvFile {
  std::map<long long, Vec3> nodes;
  std::vector<UnvElementRow> elements;
  std::vector<UnvGroupRow> groups;
  std::vector<int> datasets;
};

double fortranReal(std::string text) {
  std::replace(text.begin(), text.end(), 'D', 'E');
  return std::stod(text);
}

// The datasets as the writer lays them out, one record per line.
UnvFile parseUnv(const std::string& text) {
  UnvFile file;
  const std::vector<std::string> lines = testing::linesOf(text);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    EXPECT_EQ(lines[i], "    -1");
    const int id = std::stoi(lines[++i]);
    file.datasets.push_back(id);
    for (++i; lines[i] != "    -1"; ++i) {
      std::istringstream record(lines[i]);
      if (id == 2411) {
        long long label;
        record >> label;
        std::istringstream xyz(lines[++i]);
        std::string x, y, z;
        xyz >> x >> y >> z;
        file.nodes[label] = {fortranReal(x), fortranReal(y), fortranReal(z)};
      } else if (id == 2412) {
        UnvElementRow e{};
        std::size_t count;
        record >> e.label >> e.descriptor >> e.property >> e.material >> e.colour >> count;
        e.beamRecord = e.descriptor == 21 || e.descriptor == 24;
        if (e.beamRecord) {
          EXPECT_EQ(lines[++i], "         0         0         0");
        }
        while (e.nodes.size() < count) {
          std::istringstream nodes(lines[++i]);
          for (long long n; nodes >> n;) e.nodes.push_back(n);
        }
        file.elements.push_back(e);
      } else if (id == 2477) {
        UnvGroupRow g{};
        long long zero;
        std::size_t count;
        record >> g.number;
        for (int k = 0; k < 6; ++k) record >> zero;
        record >> count;
        g.name = lines[++i];
        while (g.entries.size() < count) {
          std::istringstream entries(lines[++i]);
          for (int type; entries >> type;) {
            long long label, a, b;
            entries >> label >> a >> b;
            g.entries.emplace_back(type, label);
          }
        }
        file.groups.push_back(g);
      }
    }
  }
  return file;
}

std::vector<Vec3> nodesOf(const UnvFile& file, const UnvElementRow& e) {
  std::vector<Vec3> out;
  for (long long n : e.nodes) out.push_back(file.nodes.at(n));
  return out;
}

const UnvElementRow& elementWith(const UnvFile& file, long long descriptor) {
  for (const UnvElementRow& e : file.elements)
    if (e.descriptor == descriptor) return e;
  throw std::runtime_error("no element of descriptor " + std::to_string(descriptor));
}

TEST(Unv, IsFoundByNameExtensionAndCode) {
  const MeshFormat* format = findFormatByName("unv");
  ASSERT_NE(format, nullptr);
  EXPECT_EQ(findFormatByExtension(".unv", 4.1), format);
  EXPECT_EQ(findFormatByCode(2, 4.1), format);
  EXPECT_EQ(findReaderByExtension(".unv"), format);
}

TEST(Unv, WritesNodesElementsAndGroupsDatasets) {
  Model model;
  Mesh mesh;
  buildMixedMesh(model, mesh);
  const UnvFile file = parseUnv(writeText("unv", model, mesh));
  EXPECT_EQ(file.datasets, (std::vector<int>{2411, 2412, 2477}));
  EXPECT_EQ(file.nodes.size(), 8u + 4 + 6 + 3 + 3 + 4 + 2 + 2 + 1);
  EXPECT_EQ(file.nodes.at(1).x, 40);  // point 5 comes first; its node is saved, not its element
  std::map<long long, int> descriptors;
  for (const UnvElementRow& e : file.elements) ++descriptors[e.descriptor];
  EXPECT_EQ(descriptors,
            (std::map<long long, int>{{21, 2}, {91, 2}, {94, 1}, {111, 1}, {112, 1}, {115, 1}}));
  for (std::size_t i = 0; i < file.elements.size(); ++i) {
    EXPECT_EQ(file.elements[i].label, static_cast<long long>(i + 1));
    EXPECT_EQ(file.elements[i].material, 0);
    EXPECT_EQ(file.elements[i].colour, 7);
  }
  EXPECT_EQ(elementWith(file, 115).property, 1);  // the entity's tag
  EXPECT_EQ(elementWith(file, 111).property, 2);
}

TEST(Unv, VolumeElementsKeepPositiveCorners) {
  Model model;
  Mesh mesh;
  buildMixedMesh(model, mesh);
  const UnvFile file = parseUnv(writeText("unv", model, mesh));
  EXPECT_GT(testing::cornerVolume6(ElementFamily::Hex, nodesOf(file, elementWith(file, 115))), 0);
  EXPECT_GT(testing::cornerVolume6(ElementFamily::Tet, nodesOf(file, elementWith(file, 111))), 0);
  EXPECT_GT(testing::cornerVolume6(ElementFamily::Prism, nodesOf(file, elementWith(file, 112))), 0);
}

TEST(Unv, SecondOrderNodesGoAroundTheElement) {
  Model model;
  Mesh mesh;
  using T = ElementType;
  for (T type : {T::Line3, T::Triangle6, T::Quad8, T::Tet10, T::Prism15, T::Hex20})
    testing::addReferenceElement(mesh, {dimension(type), 1}, type,
                                 {5.0 * static_cast<int>(type), 0, 0});
  const UnvFile file = parseUnv(writeText("unv", model, mesh));
  // I-DEAS numbers corner, edge middle, corner... around each face: position k of `places`
  // is at the centre of the listed positions.
  const std::map<long long, std::vector<std::vector<int>>> layouts = {
      {24, {{0}, {0, 2}, {2}}},
      {92, {{0}, {0, 2}, {2}, {2, 4}, {4}, {4, 0}}},
      {95, {{0}, {0, 2}, {2}, {2, 4}, {4}, {4, 6}, {6}, {6, 0}}},
      {118, {{0}, {0, 2}, {2}, {2, 4}, {4}, {4, 0}, {0, 9}, {2, 9}, {4, 9}, {9}}},
      {113,
       {{0},
        {0, 2},
        {2},
        {2, 4},
        {4},
        {4, 0},
        {0, 9},
        {2, 11},
        {4, 13},
        {9},
        {9, 11},
        {11},
        {11, 13},
        {13},
        {13, 9}}},
      {116, {{0},     {0, 2},  {2},  {2, 4},   {4},  {4, 6},   {6},  {6, 0},   {0, 12}, {2, 14},
             {4, 16}, {6, 18}, {12}, {12, 14}, {14}, {14, 16}, {16}, {16, 18}, {18},    {18, 12}}}};
  for (const auto& [descriptor, places] : layouts)
    testing::expectLayout(nodesOf(file, elementWith(file, descriptor)), places,
                          "descriptor " + std::to_string(descriptor));
  const auto tet = nodesOf(file, elementWith(file, 118));
  EXPECT_GT(testing::tetVolume6(tet[0], tet[2], tet[4], tet[9]), 0);
}

TEST(Unv, GroupsHoldElementsAndNodesAsTheOptionsSelect) {
  Model model;
  Mesh mesh;
  buildMixedMesh(model, mesh);
  UnvFile file = parseUnv(writeText("unv", model, mesh));
  // By default, element groups only; the group of points has no element to list.
  std::vector<std::tuple<long long, std::string, std::size_t>> groups;
  for (const UnvGroupRow& g : file.groups) groups.emplace_back(g.number, g.name, g.entries.size());
  using G = std::tuple<long long, std::string, std::size_t>;
  EXPECT_EQ(groups, (std::vector<G>{G{30, "PhysicalLine30", 2}, G{20, "wall", 3}, G{10, "solid", 1},
                                    G{11, "PhysicalVolume11", 2}}));
  for (const auto& [type, label] : file.groups[2].entries) {
    EXPECT_EQ(type, 8);
    EXPECT_EQ(file.elements.at(label - 1).descriptor, 115);
  }
  MeshWriteOptions options;
  options.saveGroupsOfNodes = 1;
  options.saveGroupsOfElements = -1000;  // volumes only
  file = parseUnv(writeText("unv", model, mesh, options));
  ASSERT_EQ(file.groups.size(), 5u);
  EXPECT_EQ(file.groups[0].name, "tip");
  EXPECT_EQ(file.groups[0].entries, (std::vector<std::pair<int, long long>>{{7, 1}}));
  EXPECT_EQ(file.groups[1].entries.size(), 4u);      // the nodes of the two lines
  EXPECT_EQ(file.groups[3].entries.size(), 8u + 1);  // solid: 8 nodes, then the hexahedron
  EXPECT_EQ(file.groups[3].entries.back().first, 8);
  options.saveGroupsOfNodes = 0;
  options.saveGroupsOfElements = 0;
  EXPECT_EQ(parseUnv(writeText("unv", model, mesh, options)).datasets,
            (std::vector<int>{2411, 2412}));
}

TEST(Unv, TypesWithoutADescriptorAreRefusedBeforeAnythingIsWritten) {
  for (ElementType type :
       {ElementType::Pyramid5, ElementType::Quad9, ElementType::Hex27, ElementType::Triangle10}) {
    Model model;
    Mesh mesh;
    buildMixedMesh(model, mesh);
    testing::addReferenceElement(mesh, {3, 1}, type, {60, 0, 0});  // in group 10
    std::ostringstream out;
    EXPECT_THROW(findFormatByName("unv")->write(out, model, mesh, {}), std::invalid_argument);
    EXPECT_EQ(out.str(), "");
    testing::expectRefusedWithoutFile("unv", model, mesh, scratch::path("refused.unv"),
                                      std::string("UNV output of ") + elementName(type));
  }
}

TEST(Unv, ReadsBackTypesNodeOrdersEntitiesAndGroups) {
  Model model;
  Mesh mesh;
  buildMixedMesh(model, mesh);
  for (ElementType type : {ElementType::Tet10, ElementType::Hex20, ElementType::Prism15})
    testing::addReferenceElement(mesh, {3, 2}, type, {5.0 * static_cast<int>(type), 9, 0});
  const testing::ReadBack back = testing::readAs("unv", writeText("unv", model, mesh));
  auto expected = testing::elementsByType(mesh);
  expected.erase(ElementType::Point1);
  auto& triangles = expected.at(ElementType::Triangle3);
  triangles.pop_back();  // surface 6's, at x = 50, is in no group: not saved
  EXPECT_EQ(testing::elementsByType(back.mesh), expected);
  using G = std::tuple<int, int, std::string, std::vector<int>>;
  std::vector<G> groups;
  for (const auto& [id, g] : back.model.physicalGroups())
    groups.emplace_back(g.dim, g.tag, g.name, g.entities);
  EXPECT_EQ(groups, (std::vector<G>{G{1, 30, "", {4}}, G{2, 20, "wall", {3}},
                                    G{3, 10, "solid", {1}}, G{3, 11, "", {2}}}));
  EXPECT_EQ(back.mesh.find({3, 2})->elementCount(), 5u);
}

TEST(Unv, GroupsThatSplitAPropertyTableGetEntitiesOfTheirOwn) {
  const std::string text =
      "    -1\n  2411\n1 1 1 11\n0.0D+00 0.0D+00 0.0D+00\n2 1 1 11\n1.0D+00 0.0D+00 0.0D+00\n"
      "3 1 1 11\n0.0 1.0 0.0\n4 1 1 11\n1.0 1.0 0.0\n    -1\n"
      "    -1\n  2412\n1 41 1 0 7 3\n1 2 3\n2 91 1 0 7 3\n2 4 3\n3 11 1 0 7 2\n0 0 0\n1 2\n"
      "    -1\n    -1\n  2477\n5 0 0 0 0 0 0 2\nleft part\n8 1 0 0 7 3 0 0\n    -1\n"
      "    -1\n  164\nunits dataset, skipped\n    -1\n";
  const testing::ReadBack back = testing::readAs("unv", text);
  EXPECT_EQ(back.mesh.find({2, 1})->elementCount(), 1u);  // the triangle of the group
  EXPECT_EQ(back.mesh.find({2, 2})->elementCount(), 1u);  // the other one
  EXPECT_EQ(back.mesh.find({1, 1})->elementCount(), 1u);
  ASSERT_EQ(back.model.physicalGroups().size(), 1u);
  const PhysicalGroup& group = back.model.physicalGroups().begin()->second;
  EXPECT_EQ(group.name, "left part");
  EXPECT_EQ(group.entities, (std::vector<int>{1}));
}

TEST(Unv, MalformedFilesAreErrorsNamingTheFileAndLine) {
  const std::string nodes = "    -1\n  2411\n1 1 1 11\n0.0D+00 0.0D+00 0.0D+00\n    -1\n";
  EXPECT_EQ(
      testing::readErrorOf("unv", nodes + "    -1\n  2412\n1 161 1 0 7 1\n1\n    -1\n", "bad.unv"),
      "bad.unv:8: unsupported FE descriptor id 161");
  EXPECT_EQ(testing::readErrorOf("unv", nodes + "    -1\n  2412\n1 91 1 0 7 3\n1 2 1\n    -1\n",
                                 "bad.unv"),
            "bad.unv:9: node 2 is not defined");
  EXPECT_EQ(testing::readErrorOf("unv", nodes + "    -1\n  2412\n1 91 1 0 7 4\n1 1 1\n    -1\n",
                                 "bad.unv"),
            "bad.unv:8: FE descriptor 91 has 3 nodes, not 4");
  EXPECT_EQ(
      testing::readErrorOf("unv", "    -1\n  2411\n1 1 1 11\n0.0Q+00 0 0\n    -1\n", "bad.unv"),
      "bad.unv:4: expected a coordinate, found '0.0Q+00'");
  EXPECT_EQ(testing::readErrorOf("unv", "  2411\n", "bad.unv"),
            "bad.unv:1: expected -1, the start of a dataset");
  EXPECT_EQ(testing::readErrorOf("unv",
                                 nodes + "    -1\n  2477\n5 0 0 0 0 0 0 1\ng\n8 9 0 0\n"
                                         "    -1\n",
                                 "bad.unv"),
            "bad.unv:8: group 'g' names element 9, which is not defined");
}

}  // namespace
}  // namespace geomesh
