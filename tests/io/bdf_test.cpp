// Nastran bulk data through the bdf row of the format table: GRID* and element cards, fixed
// field layout and continuations, property ids, node orders, refused types, and the reader:
// free, small and large fields, continuations, round trips, errors.
#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "io/mesh_scanner.h"
#include "tests/io/format_test_meshes.h"
#include "tests/io/solver_format_meshes.h"
#include "tests/scratch.h"

namespace geomesh {
namespace {

using testing::buildMixedMesh;
using testing::writeText;

std::string trimmed(const std::string& s) {
  const std::size_t a = s.find_first_not_of(' ');
  return a == std::string::npos ? "" : s.substr(a, s.find_last_not_of(' ') - a + 1);
}

// A card of the writer's output: its name and its fields (continuation marks checked and left
// out), read by columns.
struct Card {
  std::string name;
  std::vector<std::string> fields;
};

std::vector<Card> parseBdf(const std::string& text) {
  std::vector<Card> cards;
  std::string pendingMark;
  for (const std::string& line : testing::linesOf(text)) {
    if (line.starts_with("$") || line == "BEGIN BULK" || line == "ENDDATA") continue;
    const bool large = line.starts_with("GRID*") || line.starts_with("*");
    const std::size_t width = large ? 16 : 8;
    if (line.starts_with("+") || line.starts_with("*")) {
      EXPECT_EQ(trimmed(line.substr(0, 8)), pendingMark) << line;
    } else {
      EXPECT_EQ(pendingMark, "") << line;
      cards.push_back({trimmed(line.substr(0, 8)), {}});
    }
    EXPECT_LE(line.size(), 80u) << line;
    for (std::size_t at = 8; at < std::min<std::size_t>(line.size(), 72); at += width)
      cards.back().fields.push_back(trimmed(line.substr(at, width)));
    pendingMark = line.size() > 72 ? trimmed(line.substr(72)) : "";
  }
  return cards;
}

std::map<long long, Vec3> gridsOf(const std::vector<Card>& cards) {
  std::map<long long, Vec3> grids;
  for (const Card& c : cards)
    if (c.name == "GRID*")
      grids[std::stoll(c.fields[0])] = {std::stod(c.fields[2]), std::stod(c.fields[3]),
                                        std::stod(c.fields[4])};
  return grids;
}

std::vector<Vec3> nodesOf(const std::vector<Card>& cards, const Card& card) {
  const auto grids = gridsOf(cards);
  std::vector<Vec3> out;
  for (std::size_t k = 2; k < card.fields.size(); ++k)
    out.push_back(grids.at(std::stoll(card.fields[k])));
  return out;
}

const Card& cardWith(const std::vector<Card>& cards, const std::string& name, std::size_t nodes) {
  for (const Card& c : cards)
    if (c.name == name && c.fields.size() == nodes + 2) return c;
  throw std::runtime_error("no " + name + " with " + std::to_string(nodes) + " grid points");
}

TEST(Bdf, IsFoundByNameExtensionsAndCode) {
  const MeshFormat* format = findFormatByName("bdf");
  ASSERT_NE(format, nullptr);
  EXPECT_EQ(findFormatByExtension(".bdf", 4.1), format);
  EXPECT_EQ(findFormatByExtension(".nas", 4.1), format);
  EXPECT_EQ(findFormatByCode(31, 4.1), format);
  EXPECT_EQ(findReaderByExtension(".bdf"), format);
}

TEST(Bdf, WritesGridPointsAndOneCardPerElementWithItsPropertyId) {
  Model model;
  Mesh mesh;
  buildMixedMesh(model, mesh);
  testing::addPyramid(model, mesh);
  const std::string text = writeText("bdf", model, mesh);
  EXPECT_EQ(text.rfind("$ geomesh mesh\nBEGIN BULK\n", 0), 0u);
  EXPECT_TRUE(text.ends_with("ENDDATA\n"));
  const std::vector<Card> cards = parseBdf(text);
  std::map<std::string, std::vector<std::string>> properties;
  for (const Card& c : cards)
    if (c.name != "GRID*") properties[c.name].push_back(c.fields[1]);
  using P = std::vector<std::string>;
  EXPECT_EQ(properties, (std::map<std::string, P>{{"CROD", {"30", "30"}},
                                                  {"CTRIA3", {"20", "20"}},
                                                  {"CQUAD4", {"20"}},
                                                  {"CHEXA", {"10"}},
                                                  {"CTETRA", {"11"}},
                                                  {"CPENTA", {"11"}},
                                                  {"CPYRAM", {"11"}}}));
  EXPECT_EQ(gridsOf(cards).size(), 8u + 4 + 6 + 3 + 3 + 4 + 2 + 2 + 1 + 5);
  MeshWriteOptions all;
  all.saveAll = true;
  EXPECT_EQ(cardWith(parseBdf(writeText("bdf", model, mesh, all)), "CTRIA3", 3).fields[1], "20");
  bool entityTag = false;
  for (const Card& c : parseBdf(writeText("bdf", model, mesh, all)))
    entityTag = entityTag || (c.name == "CTRIA3" && c.fields[1] == "6");
  EXPECT_TRUE(entityTag);  // surface 6 has no group
}

TEST(Bdf, CoordinatesKeepTenSignificantDigits) {
  Model model;
  Mesh mesh;
  const NodeIndex a = mesh.addNode({1.0 / 3, -2.0 / 3e-7, 12345678.9});
  mesh.entity({0, 1}).nodes.push_back(a);
  mesh.entity({0, 1}).block(ElementType::Point1).nodes.push_back(a);
  const std::vector<Card> cards = parseBdf(writeText("bdf", model, mesh));
  const Vec3 p = gridsOf(cards).at(1);
  EXPECT_NEAR(p.x, 1.0 / 3, 1e-10);
  EXPECT_NEAR(p.y, -2.0 / 3e-7, 1e-9 * 2.0 / 3e-7);
  EXPECT_NEAR(p.z, 12345678.9, 1e-9 * 12345678.9);
}

TEST(Bdf, VolumeElementsKeepPositiveCorners) {
  Model model;
  Mesh mesh;
  buildMixedMesh(model, mesh);
  testing::addPyramid(model, mesh);
  const std::vector<Card> cards = parseBdf(writeText("bdf", model, mesh));
  const std::vector<std::tuple<std::string, std::size_t, ElementFamily>> volumes = {
      {"CHEXA", 8, ElementFamily::Hex},
      {"CTETRA", 4, ElementFamily::Tet},
      {"CPENTA", 6, ElementFamily::Prism},
      {"CPYRAM", 5, ElementFamily::Pyramid}};
  for (const auto& [name, nodes, family] : volumes)
    EXPECT_GT(testing::cornerVolume6(family, nodesOf(cards, cardWith(cards, name, nodes))), 0)
        << name;
}

TEST(Bdf, SecondOrderGridPointsFollowNastranNumbering) {
  Model model;
  Mesh mesh;
  using T = ElementType;
  for (T type : {T::Triangle6, T::Quad8, T::Tet10, T::Prism15, T::Pyramid13, T::Hex20})
    testing::addReferenceElement(mesh, {dimension(type), 1}, type,
                                 {5.0 * static_cast<int>(type), 0, 0});
  const std::vector<Card> cards = parseBdf(writeText("bdf", model, mesh));
  using testing::cornersAnd;
  // Mid-edge grid points: the bottom face's edges, the vertical ones, the top face's.
  const std::vector<std::tuple<std::string, std::size_t, std::vector<std::vector<int>>>> layouts = {
      {"CTRIA6", 6, cornersAnd(3, {{0, 1}, {1, 2}, {2, 0}})},
      {"CQUAD8", 8, cornersAnd(4, {{0, 1}, {1, 2}, {2, 3}, {3, 0}})},
      {"CTETRA", 10, cornersAnd(4, {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}})},
      {"CPENTA", 15,
       cornersAnd(6, {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 4}, {2, 5}, {3, 4}, {4, 5}, {5, 3}})},
      {"CPYRAM", 13,
       cornersAnd(5, {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 4}, {2, 4}, {3, 4}})},
      {"CHEXA", 20,
       cornersAnd(8, {{0, 1},
                      {1, 2},
                      {2, 3},
                      {3, 0},
                      {0, 4},
                      {1, 5},
                      {2, 6},
                      {3, 7},
                      {4, 5},
                      {5, 6},
                      {6, 7},
                      {7, 4}})}};
  for (const auto& [name, nodes, places] : layouts)
    testing::expectLayout(nodesOf(cards, cardWith(cards, name, nodes)), places, name);
}

TEST(Bdf, LongCardsContinueOnMarkedLines) {
  Model model;
  Mesh mesh;
  testing::addReferenceElement(mesh, {3, 1}, ElementType::Hex20, {0, 0, 0});
  const std::vector<std::string> lines = testing::linesOf(writeText("bdf", model, mesh));
  std::size_t at = 0;
  while (!lines[at].starts_with("CHEXA")) ++at;
  ASSERT_LT(at + 2, lines.size());
  // 2 ids and 6 grid points, then 8, then 6: each line but the last ends with a mark (field
  // 10) that the next one starts with (field 1).
  auto field1 = [](const std::string& mark) { return mark + std::string(8 - mark.size(), ' '); };
  const std::string first = lines[at].substr(72), second = lines[at + 1].substr(72);
  EXPECT_TRUE(first.starts_with("+") && second.starts_with("+") && first != second);
  EXPECT_EQ(lines[at + 1].substr(0, 8), field1(first));
  EXPECT_EQ(lines[at + 2].substr(0, 8), field1(second));
  EXPECT_EQ(lines[at + 2].size(), 8u + 6 * 8);
  EXPECT_EQ(lines[at + 3], "ENDDATA");
}

TEST(Bdf, TypesWithoutACardAreRefusedBeforeAnythingIsWritten) {
  for (ElementType type : {ElementType::Line3, ElementType::Quad9, ElementType::Hex27,
                           ElementType::Pyramid14, ElementType::Tet20}) {
    Model model;
    Mesh mesh;
    buildMixedMesh(model, mesh);
    testing::addReferenceElement(mesh, {3, 1}, type, {60, 0, 0});  // in group 10
    std::ostringstream out;
    EXPECT_THROW(findFormatByName("bdf")->write(out, model, mesh, {}), std::invalid_argument);
    EXPECT_EQ(out.str(), "");
    testing::expectRefusedWithoutFile("bdf", model, mesh, scratch::path("refused.bdf"),
                                      std::string("Nastran output of ") + elementName(type));
  }
}

TEST(Bdf, ReadsBackTypesNodeOrdersEntitiesAndGroups) {
  Model model;
  Mesh mesh;
  buildMixedMesh(model, mesh);
  testing::addPyramid(model, mesh);
  using T = ElementType;
  for (T type : {T::Triangle6, T::Quad8, T::Tet10, T::Prism15, T::Pyramid13, T::Hex20})
    testing::addReferenceElement(mesh, {dimension(type), dimension(type) == 2 ? 3 : 2}, type,
                                 {5.0 * static_cast<int>(type), 9, 0});
  MeshWriteOptions all;
  all.saveAll = true;
  const testing::ReadBack back = testing::readAs("bdf", writeText("bdf", model, mesh, all));
  auto expected = testing::elementsByType(mesh);
  expected.erase(ElementType::Point1);
  const auto actual = testing::elementsByType(back.mesh);
  ASSERT_EQ(actual.size(), expected.size());
  for (const auto& [type, elements] : expected) {
    ASSERT_EQ(actual.at(type).size(), elements.size()) << elementName(type);
    for (std::size_t i = 0; i < elements.size(); ++i)
      for (std::size_t k = 0; k < elements[i].size(); ++k)
        EXPECT_NEAR(actual.at(type)[i][k], elements[i][k], 1e-9) << elementName(type);
  }
  std::vector<std::pair<int, int>> groups;
  for (const auto& [id, g] : back.model.physicalGroups()) groups.emplace_back(g.dim, g.tag);
  EXPECT_EQ(groups, (std::vector<std::pair<int, int>>{{1, 30}, {2, 6}, {2, 20}, {3, 10}, {3, 11}}));
  EXPECT_EQ(back.mesh.find({3, 11})->elementCount(), 3u + 4);
}

TEST(Bdf, ReadsFreeSmallAndLargeFieldsAndContinuations) {
  auto field = [](const std::string& text, std::size_t width) {
    return text + std::string(width - text.size(), ' ');
  };
  const std::string largeGrid = field("GRID*", 8) + field("3", 16) + field("", 16) +
                                field("0.0", 16) + field("1.0", 16) + "*G3\n" + field("*G3", 8) +
                                field("0.", 16) + "\n";
  const std::string text =
      "SOL 101\nCEND\nBEGIN BULK\n"
      "$ free, small and large fields; a real without its E (1.+0)\n"
      "GRID,1,,0.0,0.0,0.0\n"
      "GRID    2               1.0     0.      0.\n" +
      largeGrid +
      "GRID,4,0,0.,0.,1.+0\n"
      "PSOLID,7,1\n"
      "CTETRA  1       7       1       2       3       4\n"
      "CTRIA3,2,8,1,2,3,0.5\n"
      "CBAR    3       9       1       4       1.0     0.0     0.0\n"
      "CTETRA,4,7,1,2,3,4,,,+C\n"
      "+C,,,,\n"
      "ENDDATA\nGRID,99,,a,b,c\n";
  const testing::ReadBack back = testing::readAs("bdf", text);
  EXPECT_EQ(back.mesh.nodeCount(), 4u);
  EXPECT_EQ(back.mesh.find({3, 7})->elementCount(), 2u);
  EXPECT_EQ(back.mesh.find({2, 8})->elementCount(), 1u);
  EXPECT_EQ(back.mesh.find({1, 9})->elementCount(), 1u);
  EXPECT_EQ(back.mesh.node(back.mesh.find({3, 7})->blocks[0].nodes[3]).z, 1);
  EXPECT_EQ(back.mesh.node(back.mesh.find({3, 7})->blocks[0].nodes[2]).y, 1);
}

TEST(Bdf, MalformedFilesAreErrorsNamingTheFileAndLine) {
  EXPECT_EQ(testing::readErrorOf("bdf", "BEGIN BULK\nGRID,1,,0.,0.,x\nENDDATA\n", "bad.bdf"),
            "bad.bdf:2: expected a real, found 'x'");
  EXPECT_EQ(testing::readErrorOf("bdf", "GRID,1,,0.,0.,0.\nCTRIA3,1,1,1,2,3\n", "bad.bdf"),
            "bad.bdf:2: grid point 2 is not defined");
  EXPECT_EQ(testing::readErrorOf("bdf", "GRID,1,,0.,0.,0.\nCHEXA,1,1,1,1,1\n", "bad.bdf"),
            "bad.bdf:2: CHEXA with 3 grid points is not supported");
  EXPECT_EQ(testing::readErrorOf("bdf", "GRID,1,2,0.,0.,0.\n", "bad.bdf"),
            "bad.bdf:1: grid point 1 is given in coordinate system 2: coordinate systems are "
            "not supported");
  EXPECT_EQ(testing::readErrorOf("bdf", "GRID,1,,0.,0.,0.\nGRID,1,,0.,0.,0.\n", "bad.bdf"),
            "bad.bdf:2: grid point 1 is defined twice");
  EXPECT_EQ(testing::readErrorOf("bdf", "$ nothing\n", "bad.bdf"), "bad.bdf:1: no bulk data cards");
}

}  // namespace
}  // namespace geomesh
