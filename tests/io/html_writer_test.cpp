// The HTML page of a mesh: the data block holds the shown elements' counts, the groups, the
// node coordinates and the volume-face neighbours (decoded back here), the viewer script is
// embedded whole, and a mesh with nothing to show is refused without leaving a file.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "io/base64.h"
#include "io/discrete_mesh.h"
#include "io/formats.h"
#include "io/viewer_script.h"
#include "mesh/core/quality.h"
#include "tests/scratch.h"

namespace geomesh {
namespace {

// Two tetrahedra sharing the face (1, 2, 3) on volume 1, a triangle on surface 1 and a line
// on curve 1; groups "solid" (volume 1) and an unnamed one (surface 1).
void buildTwoTets(Model& model, Mesh& mesh) {
  for (Vec3 p : {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}, Vec3{1, 1, 1}})
    mesh.addNode(p + Vec3{100, 200, 300});
  mesh.entity({1, 1}).block(ElementType::Line2).nodes = {0, 1};
  mesh.entity({2, 1}).block(ElementType::Triangle3).nodes = {0, 1, 2};
  mesh.entity({3, 1}).block(ElementType::Tet4).nodes = {0, 1, 2, 3, 1, 2, 3, 4};
  addDiscreteEntities(model, mesh, {{3, 7, "solid", {1}}, {2, 5, "", {1}}});
}

std::string pageOf(const Model& model, const Mesh& mesh, bool saveAll = false) {
  std::ostringstream out;
  MeshWriteOptions options;
  options.saveAll = saveAll;
  findFormatByName("html")->write(out, model, mesh, options);
  return out.str();
}

// The JSON block of a page.
std::string dataOf(const std::string& page) {
  const std::string open = "<script type=\"application/json\" id=\"geomesh-mesh\">";
  const std::size_t start = page.find(open);
  EXPECT_NE(start, std::string::npos);
  const std::size_t end = page.find("</script>", start);
  return page.substr(start + open.size(), end - start - open.size());
}

// The text of `"key":` up to the end of its value, when that value is a string, an array or
// a number: the first occurrence after `from`.
std::string valueOf(const std::string& json, const std::string& key, std::size_t from = 0) {
  const std::size_t at = json.find("\"" + key + "\":", from);
  if (at == std::string::npos) return "";
  std::size_t i = at + key.size() + 3;
  if (json[i] == '"') return json.substr(i + 1, json.find('"', i + 1) - i - 1);
  int depth = 0;
  std::size_t j = i;
  for (; j < json.size(); ++j) {
    if (json[j] == '[' || json[j] == '{') ++depth;
    if (json[j] == ']' || json[j] == '}') --depth;
    if (depth < 0 || (depth == 0 && json[j] == ',')) break;
    if (depth == 0 && (json[j] == ']' || json[j] == '}')) {
      ++j;
      break;
    }
  }
  return json.substr(i, j - i);
}

template <class T>
std::vector<T> decoded(const std::string& base64) {
  const auto bytes = decodeBase64(base64);
  EXPECT_TRUE(bytes.has_value()) << base64;
  std::vector<T> values(bytes ? bytes->size() / sizeof(T) : 0);
  if (bytes) std::memcpy(values.data(), bytes->data(), values.size() * sizeof(T));
  return values;
}

std::vector<double> numbers(const std::string& array) {
  std::vector<double> out;
  std::istringstream in(array.substr(1));
  double v = 0;
  char separator = 0;
  while (in >> v) {
    out.push_back(v);
    in >> separator;
  }
  return out;
}

TEST(Base64, RoundTripsEveryLength) {
  EXPECT_EQ(encodeBase64(std::vector<std::uint8_t>{'M', 'a', 'n'}), "TWFu");
  EXPECT_EQ(encodeBase64(std::vector<std::uint8_t>{'M', 'a'}), "TWE=");
  EXPECT_EQ(encodeBase64(std::vector<std::uint8_t>{'M'}), "TQ==");
  for (std::size_t n = 0; n < 10; ++n) {
    std::vector<std::uint8_t> bytes;
    for (std::size_t i = 0; i < n; ++i) bytes.push_back(static_cast<std::uint8_t>(37 * i + 200));
    EXPECT_EQ(decodeBase64(encodeBase64(bytes)), bytes);
  }
  EXPECT_FALSE(decodeBase64("TWF").has_value());
  EXPECT_FALSE(decodeBase64("T*Fu").has_value());
}

TEST(HtmlWriter, IsAFormatOfTheTable) {
  const MeshFormat* html = findFormatByExtension(".html", 4.1);
  ASSERT_NE(html, nullptr);
  EXPECT_EQ(html->name(), "html");
  EXPECT_EQ(findFormatByName("html"), html);
  EXPECT_EQ(findReaderByExtension(".html"), nullptr);
}

TEST(HtmlWriter, EmbedsTheViewerScriptWhole) {
  Model model;
  Mesh mesh;
  buildTwoTets(model, mesh);
  const std::string page = pageOf(model, mesh);
  EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
  ASSERT_GT(viewerScript().size(), 10000u);
  EXPECT_NE(page.find("<script>" + viewerScript() + "</script>"), std::string::npos);
  EXPECT_EQ(viewerScript().find("</script"), std::string::npos);
  // Nothing is loaded from elsewhere: no script, style sheet or image by address.
  EXPECT_EQ(page.find("<script src"), std::string::npos);
  EXPECT_EQ(page.find("<link"), std::string::npos);
  EXPECT_EQ(page.find("<img"), std::string::npos);
}

TEST(HtmlWriter, HoldsThePhysicalGroupsAndTheirCounts) {
  Model model;
  Mesh mesh;
  buildTwoTets(model, mesh);
  const std::string data = dataOf(pageOf(model, mesh));
  EXPECT_EQ(valueOf(data, "groups"), R"([{"name":"solid","dim":3,"tag":7,"physical":true},)"
                                     R"({"name":"","dim":2,"tag":5,"physical":true}])");
  // The line is in no group: left out, as a mesh file would leave it.
  EXPECT_EQ(valueOf(data, "counts"), R"([["triangle",1],["tetrahedron",2]])");
}

TEST(HtmlWriter, WithSaveAllListsUngroupedEntities) {
  Model model;
  Mesh mesh;
  buildTwoTets(model, mesh);
  const std::string data = dataOf(pageOf(model, mesh, true));
  EXPECT_NE(valueOf(data, "groups").find(R"({"name":"","dim":1,"tag":1,"physical":false})"),
            std::string::npos);
  EXPECT_EQ(valueOf(data, "counts"), R"([["line",1],["triangle",1],["tetrahedron",2]])");
  // Ids follow the mesh file: the line first.
  EXPECT_EQ(valueOf(data, "firstId", data.find("\"type\":\"tetrahedron\"")), "3");
}

TEST(HtmlWriter, HoldsTheNodesAroundAnOrigin) {
  Model model;
  Mesh mesh;
  buildTwoTets(model, mesh);
  const std::string data = dataOf(pageOf(model, mesh));
  const std::vector<double> origin = numbers(valueOf(data, "origin"));
  ASSERT_EQ(origin.size(), 3u);
  EXPECT_EQ(origin[0], 100.5);
  EXPECT_EQ(origin[2], 300.5);
  const std::vector<float> xyz = decoded<float>(valueOf(data, "nodes"));
  ASSERT_EQ(xyz.size(), 3 * mesh.nodeCount());
  for (NodeIndex n = 0; n < mesh.nodeCount(); ++n) {
    const Vec3 p = mesh.node(n);
    EXPECT_FLOAT_EQ(xyz[3 * n] + origin[0], p.x);
    EXPECT_FLOAT_EQ(xyz[3 * n + 1] + origin[1], p.y);
    EXPECT_FLOAT_EQ(xyz[3 * n + 2] + origin[2], p.z);
  }
}

TEST(HtmlWriter, HoldsCornersQualityAndNeighbours) {
  Model model;
  Mesh mesh;
  buildTwoTets(model, mesh);
  const std::string data = dataOf(pageOf(model, mesh));
  const std::size_t tets = data.find("\"type\":\"tetrahedron\"");
  ASSERT_NE(tets, std::string::npos);
  EXPECT_EQ(valueOf(data, "firstId", tets), "2");  // after the triangle
  EXPECT_EQ(decoded<std::uint32_t>(valueOf(data, "nodes", tets)),
            (std::vector<std::uint32_t>{0, 1, 2, 3, 1, 2, 3, 4}));
  // Faces (0 2 1), (0 1 3), (0 3 2), (1 2 3): tetrahedron 2 meets 3 across its last face,
  // and 3 meets 2 across its first.
  EXPECT_EQ(decoded<std::uint32_t>(valueOf(data, "neighbours", tets)),
            (std::vector<std::uint32_t>{0, 0, 0, 3, 2, 0, 0, 0}));
  const std::vector<float> gamma = decoded<float>(valueOf(data, "gamma", tets));
  ASSERT_EQ(gamma.size(), 2u);
  EXPECT_FLOAT_EQ(gamma[1], static_cast<float>(
                                tetGamma(mesh.node(1), mesh.node(2), mesh.node(3), mesh.node(4))));
  const std::vector<float> sicn = decoded<float>(valueOf(data, "sicn", tets));
  EXPECT_FLOAT_EQ(
      sicn[0], static_cast<float>(tetSicn(mesh.node(0), mesh.node(1), mesh.node(2), mesh.node(3))));
}

TEST(HtmlWriter, NamesCannotCloseTheDataBlock) {
  Model model;
  Mesh mesh;
  buildTwoTets(model, mesh);
  model.addPhysicalGroup({2, 9, "</script><b>", {1}});
  const std::string page = pageOf(model, mesh);
  EXPECT_EQ(page.find("<b>"), std::string::npos);
  EXPECT_NE(dataOf(page).find(R"(\u003c/script\u003e\u003cb\u003e)"), std::string::npos);
}

TEST(HtmlWriter, RefusesAMeshWithNothingToShowAndLeavesNoFile) {
  Model tets;
  Mesh mesh;
  buildTwoTets(tets, mesh);
  for (int dim = 1; dim <= 3; ++dim) mesh.eraseEntity({dim, 1});
  mesh.entity({0, 1}).block(ElementType::Point1).nodes = {0};
  Model model;
  addDiscreteEntities(model, mesh);
  const std::filesystem::path path = scratch::path("points.html");
  try {
    writeMeshFile(path.string(), *findFormatByName("html"), model, mesh, {});
    FAIL() << "written";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("nothing to show"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(path.string() + ".partial"));
}

}  // namespace
}  // namespace geomesh
