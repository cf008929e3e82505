// VTU (VTK XML UnstructuredGrid) through its row of the format table: the XML structure, the
// cells of the legacy VTK writer, ASCII and base64 binary data arrays holding the same values.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "io/base64.h"
#include "tests/io/format_test_meshes.h"

namespace geomesh {
namespace {

using namespace testing;

// The bytes of a binary DataArray's content: base64, with the line breaks and spaces around it.
std::string decodedContent(const std::string& text) {
  std::string digits;
  for (char c : text)
    if (c != '\n' && c != ' ') digits += c;
  const std::optional<std::vector<std::uint8_t>> bytes = decodeBase64(digits);
  EXPECT_TRUE(bytes.has_value()) << text;
  return bytes ? std::string(bytes->begin(), bytes->end()) : std::string();
}

// The DataArray whose opening tag holds `marker`: that tag, and the text up to its closing tag.
struct DataArray {
  std::string tag;
  std::string content;
};

DataArray dataArray(const std::string& xml, const std::string& marker) {
  const std::size_t at = xml.find(marker);
  EXPECT_NE(at, std::string::npos) << marker;
  const std::size_t start = xml.rfind("<DataArray", at);
  const std::size_t tagEnd = xml.find('>', start);
  const std::size_t end = xml.find("</DataArray>", tagEnd);
  return {xml.substr(start, tagEnd + 1 - start), xml.substr(tagEnd + 1, end - tagEnd - 1)};
}

template <class T>
std::vector<T> asciiValues(const DataArray& array) {
  std::istringstream in(array.content);
  std::vector<T> values;
  for (double v; in >> v;) values.push_back(static_cast<T>(v));
  return values;
}

// The values of a binary array: a UInt64 byte count, then little-endian values.
template <class T>
std::vector<T> binaryValues(const DataArray& array) {
  const std::string bytes = decodedContent(array.content);
  std::uint64_t size = 0;
  std::memcpy(&size, bytes.data(), 8);
  EXPECT_EQ(size + 8, bytes.size());
  std::vector<T> values(size / sizeof(T));
  std::memcpy(values.data(), bytes.data() + 8, size);
  return values;
}

TEST(Vtu, IsFoundByNameAndExtensionWithoutACode) {
  const MeshFormat* vtu = findFormatByName("vtu");
  ASSERT_NE(vtu, nullptr);
  EXPECT_EQ(findFormatByExtension(".vtu", 4.1), vtu);
  EXPECT_EQ(vtu->code, 0);
  EXPECT_EQ(vtu->maxOrder, 2);
  EXPECT_EQ(findFormatByCode(0, 4.1), nullptr);
}

TEST(Vtu, WritesTheUnstructuredGridStructure) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh, true);
  const std::string xml = writeAs("vtu", model, mesh);
  EXPECT_EQ(xml.rfind("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\"", 0), 0u);
  EXPECT_NE(xml.find("<Piece NumberOfPoints=\"8\" NumberOfCells=\"9\">"), std::string::npos);
  for (const char* tag : {"<UnstructuredGrid>", "<Points>", "</Points>", "<Cells>", "</Cells>",
                          "<CellData Scalars=\"CellEntityIds\">", "</CellData>", "</Piece>",
                          "</UnstructuredGrid>", "</VTKFile>"})
    EXPECT_NE(xml.find(tag), std::string::npos) << tag;
  EXPECT_EQ(asciiValues<double>(dataArray(xml, "NumberOfComponents=\"3\"")).size(), 24u);
  // Faces 1 to 3 are two triangles each, 4 to 6 a quadrangle: VTK types 5 and 9.
  EXPECT_EQ(asciiValues<int>(dataArray(xml, "Name=\"types\"")),
            (std::vector<int>{5, 5, 5, 5, 5, 5, 9, 9, 9}));
  EXPECT_EQ(asciiValues<int>(dataArray(xml, "Name=\"offsets\"")),
            (std::vector<int>{3, 6, 9, 12, 15, 18, 22, 26, 30}));
  EXPECT_EQ(asciiValues<int>(dataArray(xml, "Name=\"CellEntityIds\"")),
            (std::vector<int>{1, 1, 2, 2, 3, 3, 4, 5, 6}));
  EXPECT_EQ(asciiValues<int>(dataArray(xml, "Name=\"connectivity\"")).size(), 30u);
}

TEST(Vtu, HasTheCellsOfTheLegacyFile) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh, true);
  mesh.entity({3, 1}).block(ElementType::Hex8).nodes = {0, 1, 3, 2, 4, 5, 7, 6};
  model.addVolume({1, {}});
  const std::string xml = writeAs("vtu", model, mesh);
  const std::string text = writeAs("vtk", model, mesh);
  // The legacy CELLS list without its counts is the VTU connectivity.
  std::istringstream cells(text.substr(text.find("CELLS")));
  std::string keyword;
  std::size_t n = 0, size = 0;
  cells >> keyword >> n >> size;
  std::vector<int> connectivity;
  for (std::size_t i = 0; i < n; ++i) {
    int count = 0;
    cells >> count;
    for (int k = 0; k < count; ++k) {
      int node = 0;
      cells >> node;
      connectivity.push_back(node);
    }
  }
  EXPECT_EQ(asciiValues<int>(dataArray(xml, "Name=\"connectivity\"")), connectivity);
  EXPECT_EQ(asciiValues<int>(dataArray(xml, "Name=\"types\"")).back(), 12);
}

TEST(Vtu, BinaryArraysHoldTheAsciiValues) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh, true);
  mesh.setNode(3, {0.1, 1.0 / 3, -2e-9});
  const std::string ascii = writeAs("vtu", model, mesh);
  const std::string binary = writeAs("vtu", model, mesh, true);
  EXPECT_NE(binary.find("header_type=\"UInt64\""), std::string::npos);
  EXPECT_NE(binary.find("byte_order=\"LittleEndian\""), std::string::npos);
  const DataArray points = dataArray(binary, "NumberOfComponents=\"3\"");
  EXPECT_NE(points.tag.find("format=\"binary\""), std::string::npos) << points.tag;
  EXPECT_EQ(binaryValues<double>(points),
            asciiValues<double>(dataArray(ascii, "NumberOfComponents=\"3\"")));
  EXPECT_EQ(binaryValues<std::int64_t>(dataArray(binary, "Name=\"connectivity\"")),
            asciiValues<std::int64_t>(dataArray(ascii, "Name=\"connectivity\"")));
  EXPECT_EQ(binaryValues<std::int64_t>(dataArray(binary, "Name=\"offsets\"")),
            asciiValues<std::int64_t>(dataArray(ascii, "Name=\"offsets\"")));
  EXPECT_EQ(binaryValues<std::uint8_t>(dataArray(binary, "Name=\"types\"")),
            asciiValues<std::uint8_t>(dataArray(ascii, "Name=\"types\"")));
  EXPECT_EQ(binaryValues<std::int32_t>(dataArray(binary, "Name=\"CellEntityIds\"")),
            asciiValues<std::int32_t>(dataArray(ascii, "Name=\"CellEntityIds\"")));
}

TEST(Vtu, ElementsAboveOrderTwoAreRefusedBeforeAnythingIsWritten) {
  Model model;
  Mesh mesh;
  for (int i = 0; i < 4; ++i) mesh.addNode({double(i), 0, 0});
  mesh.entity({1, 1}).block(ElementType::Line4).nodes = {0, 1, 2, 3};
  addDiscreteEntities(model, mesh);
  std::ostringstream out;
  try {
    findFormatByName("vtu")->write(out, model, mesh, {});
    FAIL() << "written";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("line4"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("up to order 2"), std::string::npos) << e.what();
  }
  EXPECT_EQ(out.str(), "");
}

}  // namespace
}  // namespace geomesh
