// Abaqus input files through the inp row of the format table: *NODE, *ELEMENT blocks and their
// types, node orders, *ELSET and *NSET as Mesh.SaveGroupsOf* select them, long data lines, and
// refused types.
#include <gtest/gtest.h>

#include <algorithm>
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

// A keyword line and the numbers of the data lines after it (continued lines joined).
struct InpBlock {
  std::string keyword;
  std::vector<std::vector<double>> rows;
};

std::vector<InpBlock> parseInp(const std::string& text) {
  std::vector<InpBlock> blocks;
  bool continued = false;
  for (const std::string& line : testing::linesOf(text)) {
    if (line.starts_with("*")) {
      blocks.push_back({line, {}});
      continue;
    }
    if (blocks.empty() || blocks.back().keyword == "*HEADING") continue;
    if (!continued) blocks.back().rows.emplace_back();
    std::istringstream in(line);
    for (std::string value; std::getline(in, value, ',');)
      if (value.find_first_not_of(' ') != std::string::npos)
        blocks.back().rows.back().push_back(std::stod(value));
    continued = !line.empty() && line.back() == ',';
  }
  return blocks;
}

const InpBlock& blockOf(const std::vector<InpBlock>& blocks, const std::string& keyword) {
  for (const InpBlock& b : blocks)
    if (b.keyword == keyword) return b;
  throw std::runtime_error("no " + keyword);
}

std::vector<Vec3> elementNodes(const std::vector<InpBlock>& blocks,
                               const std::vector<double>& row) {
  std::map<long long, Vec3> nodes;
  for (const auto& n : blockOf(blocks, "*NODE").rows)
    nodes[static_cast<long long>(n[0])] = {n[1], n[2], n[3]};
  std::vector<Vec3> out;
  for (std::size_t k = 1; k < row.size(); ++k)
    out.push_back(nodes.at(static_cast<long long>(row[k])));
  return out;
}

TEST(Inp, IsFoundByNameExtensionAndCodeAndIsWrittenOnly) {
  const MeshFormat* format = findFormatByName("inp");
  ASSERT_NE(format, nullptr);
  EXPECT_EQ(findFormatByExtension(".inp", 4.1), format);
  EXPECT_EQ(findFormatByCode(39, 4.1), format);
  EXPECT_EQ(findReaderByExtension(".inp"), nullptr);
}

TEST(Inp, WritesNodesAndOneElementBlockPerEntityAndType) {
  Model model;
  Mesh mesh;
  buildMixedMesh(model, mesh);
  const std::string text = writeText("inp", model, mesh);
  EXPECT_EQ(text.rfind("*HEADING\n", 0), 0u);
  const std::vector<InpBlock> blocks = parseInp(text);
  EXPECT_EQ(blockOf(blocks, "*NODE").rows.size(), 8u + 4 + 6 + 3 + 3 + 4 + 2 + 2 + 1);
  std::vector<std::pair<std::string, std::size_t>> elements;
  for (const InpBlock& b : blocks)
    if (b.keyword.starts_with("*ELEMENT")) elements.emplace_back(b.keyword, b.rows.size());
  using E = std::pair<std::string, std::size_t>;
  EXPECT_EQ(
      elements,
      (std::vector<E>{
          E{"*ELEMENT, TYPE=T3D2, ELSET=Line4", 2}, E{"*ELEMENT, TYPE=CPS3, ELSET=Surface3", 2},
          E{"*ELEMENT, TYPE=CPS4, ELSET=Surface3", 1}, E{"*ELEMENT, TYPE=C3D8, ELSET=Volume1", 1},
          E{"*ELEMENT, TYPE=C3D4, ELSET=Volume2", 1}, E{"*ELEMENT, TYPE=C3D6, ELSET=Volume2", 1}}));
  double number = 0;
  for (const InpBlock& b : blocks) {
    if (!b.keyword.starts_with("*ELEMENT")) continue;
    for (const auto& row : b.rows) EXPECT_EQ(row[0], ++number);
  }
}

TEST(Inp, VolumeElementsKeepPositiveCorners) {
  Model model;
  Mesh mesh;
  buildMixedMesh(model, mesh);
  const std::vector<InpBlock> blocks = parseInp(writeText("inp", model, mesh));
  const std::map<std::string, ElementFamily> volumes = {
      {"*ELEMENT, TYPE=C3D8, ELSET=Volume1", ElementFamily::Hex},
      {"*ELEMENT, TYPE=C3D4, ELSET=Volume2", ElementFamily::Tet},
      {"*ELEMENT, TYPE=C3D6, ELSET=Volume2", ElementFamily::Prism}};
  for (const auto& [keyword, family] : volumes)
    EXPECT_GT(
        testing::cornerVolume6(family, elementNodes(blocks, blockOf(blocks, keyword).rows[0])), 0)
        << keyword;
}

TEST(Inp, SecondOrderNodeOrdersAreAbaqusOnes) {
  Model model;
  Mesh mesh;
  using T = ElementType;
  for (T type : {T::Line3, T::Triangle6, T::Quad8, T::Tet10, T::Prism15, T::Hex20})
    testing::addReferenceElement(mesh, {dimension(type), 1}, type,
                                 {5.0 * static_cast<int>(type), 0, 0});
  const std::vector<InpBlock> blocks = parseInp(writeText("inp", model, mesh));
  using testing::cornersAnd;
  struct Layout {
    std::string keyword;
    std::vector<std::vector<int>> places;
  };
  const std::vector<Layout> layouts = {
      {"TYPE=T3D3, ELSET=Line1", cornersAnd(2, {{0, 1}})},
      {"TYPE=CPS6, ELSET=Surface1", cornersAnd(3, {{0, 1}, {1, 2}, {2, 0}})},
      {"TYPE=CPS8, ELSET=Surface1", cornersAnd(4, {{0, 1}, {1, 2}, {2, 3}, {3, 0}})},
      {"TYPE=C3D10, ELSET=Volume1",
       cornersAnd(4, {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}})},
      {"TYPE=C3D15, ELSET=Volume1",
       cornersAnd(6, {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}, {0, 3}, {1, 4}, {2, 5}})},
      {"TYPE=C3D20, ELSET=Volume1", cornersAnd(8, {{0, 1},
                                                   {1, 2},
                                                   {2, 3},
                                                   {3, 0},
                                                   {4, 5},
                                                   {5, 6},
                                                   {6, 7},
                                                   {7, 4},
                                                   {0, 4},
                                                   {1, 5},
                                                   {2, 6},
                                                   {3, 7}})}};
  for (const Layout& layout : layouts) {
    const InpBlock& block = blockOf(blocks, "*ELEMENT, " + layout.keyword);
    testing::expectLayout(elementNodes(blocks, block.rows.at(0)), layout.places, layout.keyword);
  }
  const auto tet =
      elementNodes(blocks, blockOf(blocks, "*ELEMENT, TYPE=C3D10, ELSET=Volume1").rows[0]);
  EXPECT_GT(testing::cornerVolume6(ElementFamily::Tet, tet), 0);
}

TEST(Inp, DataLinesHoldAtMostSixteenValues) {
  Model model;
  Mesh mesh;
  testing::addReferenceElement(mesh, {3, 1}, ElementType::Hex20, {0, 0, 0});
  const std::vector<std::string> lines = testing::linesOf(writeText("inp", model, mesh));
  std::size_t at = 0;
  while (!lines[at].starts_with("*ELEMENT")) ++at;
  EXPECT_EQ(std::count(lines[at + 1].begin(), lines[at + 1].end(), ','), 16);  // ends with one
  EXPECT_EQ(lines[at + 1].back(), ',');
  EXPECT_EQ(std::count(lines[at + 2].begin(), lines[at + 2].end(), ','), 4);
}

TEST(Inp, SetsFollowTheSaveGroupsOptions) {
  Model model;
  Mesh mesh;
  buildMixedMesh(model, mesh);
  std::vector<InpBlock> blocks = parseInp(writeText("inp", model, mesh));
  std::vector<std::pair<std::string, std::vector<double>>> sets;
  for (const InpBlock& b : blocks)
    if (b.keyword.starts_with("*ELSET") || b.keyword.starts_with("*NSET"))
      sets.emplace_back(b.keyword, b.rows.at(0));
  using S = std::pair<std::string, std::vector<double>>;
  EXPECT_EQ(sets, (std::vector<S>{S{"*ELSET, ELSET=PhysicalLine30", {1, 2}},
                                  S{"*ELSET, ELSET=wall", {3, 4, 5}}, S{"*ELSET, ELSET=solid", {6}},
                                  S{"*ELSET, ELSET=PhysicalVolume11", {7, 8}}}));
  MeshWriteOptions options;
  options.saveGroupsOfElements = -100;  // surfaces only
  options.saveGroupsOfNodes = -11;      // points and curves
  blocks = parseInp(writeText("inp", model, mesh, options));
  sets.clear();
  for (const InpBlock& b : blocks)
    if (b.keyword.starts_with("*ELSET") || b.keyword.starts_with("*NSET"))
      sets.emplace_back(b.keyword, b.rows.at(0));
  ASSERT_EQ(sets.size(), 3u);
  EXPECT_EQ(sets[0], (S{"*NSET, NSET=tip", {1}}));
  EXPECT_EQ(sets[1].first, "*NSET, NSET=PhysicalLine30");
  EXPECT_EQ(sets[1].second.size(), 4u);
  EXPECT_EQ(sets[2].first, "*ELSET, ELSET=wall");
}

TEST(Inp, SetNamesThatAreNotWordsAreQuoted) {
  Model model;
  Mesh mesh;
  buildMixedMesh(model, mesh);
  model.addPhysicalGroup({2, 20, "left wall", {3}});
  EXPECT_NE(writeText("inp", model, mesh).find("*ELSET, ELSET=\"left wall\"\n"), std::string::npos);
}

TEST(Inp, PyramidsAndTypesWithoutAnAbaqusElementAreRefused) {
  for (ElementType type :
       {ElementType::Pyramid5, ElementType::Quad9, ElementType::Hex27, ElementType::Tet20}) {
    Model model;
    Mesh mesh;
    buildMixedMesh(model, mesh);
    testing::addReferenceElement(mesh, {3, 1}, type, {60, 0, 0});  // in group 10
    std::ostringstream out;
    EXPECT_THROW(findFormatByName("inp")->write(out, model, mesh, {}), std::invalid_argument);
    EXPECT_EQ(out.str(), "");
    testing::expectRefusedWithoutFile("inp", model, mesh, scratch::path("refused.inp"),
                                      std::string("Abaqus output of ") + elementName(type));
  }
}

}  // namespace
}  // namespace geomesh
