// Pictures of meshes through their rows of the format table: SVG (well-formed, one polygon
// per face drawn) and PNG (decodes, its size, entity colours, where a planar mesh lands), the
// camera, volume meshes drawn by their boundary faces, lines, the refusal of empty meshes; the
// PNG encoding (indexed or RGB, lossless) and the reduction of colours to a palette.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "io/picture.h"
#include "io/picture_raster.h"
#include "io/rgb_image.h"
#include "tests/io/format_test_meshes.h"
#include "tests/scratch.h"

namespace geomesh {
namespace {

using namespace testing;

// The unit square at z = 0 in four quadrangles, quadrant q on surface q + 1: 1 lower left,
// 2 lower right, 3 upper left, 4 upper right.
void buildQuadrants(Model& model, Mesh& mesh, double z = 0) {
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) mesh.addNode({0.5 * i, 0.5 * j, z});
  for (int q = 0; q < 4; ++q) {
    const NodeIndex first = static_cast<NodeIndex>((q / 2) * 3 + q % 2);
    mesh.entity({2, q + 1}).block(ElementType::Quad4).nodes = {first, first + 1, first + 4,
                                                               first + 3};
  }
  addDiscreteEntities(model, mesh);
}

// Two tetrahedra sharing the face (0, 1, 2), on volume 1, and no surface element.
void buildTwoTets(Model& model, Mesh& mesh) {
  for (Vec3 p : {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}, Vec3{0, 0, -1}})
    mesh.addNode(p);
  mesh.entity({3, 1}).block(ElementType::Tet4).nodes = {0, 1, 2, 3, 0, 2, 1, 4};
  addDiscreteEntities(model, mesh);
}

MeshWriteOptions sized(int width, int height) {
  MeshWriteOptions options;
  options.pictureWidth = width;
  options.pictureHeight = height;
  return options;
}

std::string write(const char* format, const Model& model, const Mesh& mesh,
                  const MeshWriteOptions& options = {}) {
  std::ostringstream out;
  findFormatByName(format)->write(out, model, mesh, options);
  return out.str();
}

std::size_t countOf(const std::string& text, const std::string& word) {
  std::size_t n = 0;
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1))
    ++n;
  return n;
}

// Whether the text is one XML element with properly nested tags and quoted attributes.
bool wellFormedXml(const std::string& text, std::string& why) {
  const auto fail = [&](const std::string& reason) {
    why = reason;
    return false;
  };
  std::vector<std::string> open;
  int roots = 0;
  const std::regex tag(R"re(<(/?)([A-Za-z][\w:-]*)((?:\s+[\w:-]+="[^"<]*")*)\s*(/?)>)re");
  std::size_t at = text.find("?>");
  if (!text.starts_with("<?xml") || at == std::string::npos) return fail("no XML declaration");
  at += 2;
  while ((at = text.find('<', at)) != std::string::npos) {
    const std::size_t end = text.find('>', at);
    if (end == std::string::npos) return fail("unterminated tag");
    const std::string rest = text.substr(at, end + 1 - at);
    std::smatch m;
    if (!std::regex_match(rest, m, tag)) return fail("malformed tag " + rest);
    if (m[1] == "/") {
      if (open.empty() || open.back() != m[2]) return fail("unbalanced " + rest);
      open.pop_back();
    } else {
      if (open.empty()) ++roots;
      if (m[4] != "/") open.push_back(m[2]);
    }
    at = end + 1;
  }
  if (!open.empty()) return fail("unclosed <" + open.back() + ">");
  if (roots != 1) return fail(std::to_string(roots) + " root elements");
  return true;
}

std::vector<std::string> fills(const std::string& svg) {
  std::vector<std::string> result;
  const std::regex fill(R"re(<polygon points="[^"]*" fill="(#[0-9a-f]{6})"/>)re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), fill); it != std::sregex_iterator();
       ++it)
    result.push_back((*it)[1]);
  return result;
}

std::string hex(Rgb c) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", c.r, c.g, c.b);
  return text;
}

int brightness(Rgb c) { return c.r + c.g + c.b; }

std::size_t pixelsOf(const RgbImage& image, Rgb color) {
  std::size_t n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) n += image.at(x, y) == color;
  return n;
}

TEST(Svg, IsWellFormedWithOnePolygonPerFace) {
  Model model;
  Mesh mesh;
  buildQuadrants(model, mesh);
  const std::string svg = write("svg", model, mesh, sized(400, 300));
  std::string why;
  EXPECT_TRUE(wellFormedXml(svg, why)) << why << "\n" << svg;
  EXPECT_NE(svg.find("width=\"400\" height=\"300\" viewBox=\"0 0 400 300\""), std::string::npos);
  EXPECT_EQ(countOf(svg, "<polygon "), 4u);
  // Seen from +z, each quadrant is its surface's colour, unshaded.
  const std::vector<std::string> colors = fills(svg);
  ASSERT_EQ(colors.size(), 4u);
  for (int tag = 1; tag <= 4; ++tag)
    EXPECT_EQ(std::count(colors.begin(), colors.end(), hex(entityColor(tag))), 1) << tag;
}

TEST(Svg, HighOrderElementsAreDrawnByTheirCorners) {
  Model model;
  Mesh mesh;
  for (Vec3 p : {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0.5, 0, 0}, Vec3{0.5, 0.5, 0},
                 Vec3{0, 0.5, 0}})
    mesh.addNode(p);
  mesh.entity({2, 1}).block(ElementType::Triangle6).nodes = {0, 1, 2, 3, 4, 5};
  addDiscreteEntities(model, mesh);
  const std::string svg = write("svg", model, mesh);
  ASSERT_EQ(countOf(svg, "<polygon "), 1u);
  const std::regex points(R"re(<polygon points="([^"]*)")re");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(svg, m, points));
  EXPECT_EQ(countOf(m[1], ","), 3u) << m[1];
}

TEST(Svg, VolumeMeshWithoutSurfaceElementsShowsItsBoundaryFaces) {
  Model model;
  Mesh mesh;
  buildTwoTets(model, mesh);
  const std::string svg = write("svg", model, mesh);
  EXPECT_EQ(countOf(svg, "<polygon "), 6u);  // 8 faces, the shared one left out

  Model hexModel;
  Mesh hexMesh;
  buildHexCube(hexModel, hexMesh);
  const std::string cube = write("svg", hexModel, hexMesh);
  EXPECT_EQ(countOf(cube, "<polygon "), 6u);
  // Seen obliquely, the cube's three pairs of opposite faces are shaded three ways.
  const std::vector<std::string> colors = fills(cube);
  EXPECT_EQ(std::set<std::string>(colors.begin(), colors.end()).size(), 3u) << cube;
}

TEST(Svg, SurfaceElementsOfAVolumeBoundaryAreDrawnInsteadOfItsElementFaces) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh);
  mesh.entity({3, 1}).block(ElementType::Hex8).nodes = {0, 1, 3, 2, 4, 5, 7, 6};
  model.addVolume({1, {{1, 2, 3, 4, 5, 6}}});
  EXPECT_EQ(countOf(write("svg", model, mesh), "<polygon "), 6u);
}

TEST(Svg, LinesAreDrawnWhenThereIsNoFace) {
  Model model;
  Mesh mesh;
  for (int i = 0; i < 4; ++i) mesh.addNode({double(i), double(i % 2), 0});
  mesh.entity({1, 1}).block(ElementType::Line2).nodes = {0, 1, 1, 2, 2, 3};
  addDiscreteEntities(model, mesh);
  const std::string svg = write("svg", model, mesh);
  EXPECT_EQ(countOf(svg, "<polygon "), 0u);
  EXPECT_EQ(countOf(svg, "<path "), 1u);
  EXPECT_EQ(countOf(svg, " L"), 3u);
}

TEST(Png, DecodesWithTheRequestedSize) {
  Model model;
  Mesh mesh;
  buildQuadrants(model, mesh);
  const RgbImage image = decodePng(write("png", model, mesh, sized(321, 203)));
  EXPECT_EQ(image.width, 321);
  EXPECT_EQ(image.height, 203);
  const RgbImage defaults = decodePng(write("png", model, mesh));
  EXPECT_EQ(defaults.width, 800);
  EXPECT_EQ(defaults.height, 600);
}

TEST(Png, PlanarMeshSeenFromPlusZCoversTheFittedSquare) {
  Model model;
  Mesh mesh;
  buildQuadrants(model, mesh, 2.5);
  const RgbImage image = decodePng(write("png", model, mesh, sized(400, 400)));
  ASSERT_EQ(image.width, 400);
  // The margin is 4% of 400 pixels: the square spans pixels 16 to 384 both ways.
  std::size_t outside = 0, blankInside = 0;
  for (int y = 0; y < 400; ++y)
    for (int x = 0; x < 400; ++x) {
      const bool in = x >= 17 && x < 383 && y >= 17 && y < 383;
      const bool out = x < 15 || x >= 385 || y < 15 || y >= 385;
      const bool white = image.at(x, y) == kPictureBackground;
      outside += out && !white;
      blankInside += in && white;
    }
  EXPECT_EQ(outside, 0u);
  EXPECT_EQ(blankInside, 0u);
  // x to the right, y up: surface 1 lower left, 2 lower right, 3 upper left, 4 upper right.
  EXPECT_EQ(image.at(100, 300), entityColor(1));
  EXPECT_EQ(image.at(300, 300), entityColor(2));
  EXPECT_EQ(image.at(100, 100), entityColor(3));
  EXPECT_EQ(image.at(300, 100), entityColor(4));
  // Element edges are dark: the lines between the quadrants, at x = 200 and y = 200.
  EXPECT_LT(brightness(image.at(200, 100)), 0.75 * brightness(entityColor(3)));
  EXPECT_LT(brightness(image.at(200, 100)), 0.75 * brightness(entityColor(4)));
  EXPECT_LT(brightness(image.at(100, 200)), 0.75 * brightness(entityColor(1)));
  EXPECT_LT(brightness(image.at(100, 200)), 0.75 * brightness(entityColor(3)));
  EXPECT_EQ(image.at(205, 100), entityColor(4));
}

TEST(Png, RotationTurnsTheView) {
  Model model;
  Mesh mesh;
  buildQuadrants(model, mesh);
  MeshWriteOptions options = sized(400, 400);
  options.viewRotation = std::array<double, 3>{0, 0, 90};  // a quarter turn about z
  const RgbImage image = decodePng(write("png", model, mesh, options));
  EXPECT_EQ(image.at(300, 300), entityColor(1));
  EXPECT_EQ(image.at(300, 100), entityColor(2));
  EXPECT_EQ(image.at(100, 300), entityColor(3));
}

TEST(Png, IsNotBlankAndShowsEachSurfaceColour) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh, true);
  const RgbImage image = decodePng(write("png", model, mesh, sized(300, 300)));
  std::size_t background = pixelsOf(image, kPictureBackground);
  EXPECT_LT(background, 300u * 300u * 3 / 4);
  // Three faces are seen, each shaded but of its surface's hue: some pixel's channels are
  // the entity colour's scaled by one factor.
  std::set<int> seen;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const Rgb c = image.at(x, y);
      for (int tag = 1; tag <= 6; ++tag) {
        const Rgb e = entityColor(tag);
        const double k = double(c.r) / e.r;
        if (k > 0.3 && std::abs(c.g - k * e.g) < 1.5 && std::abs(c.b - k * e.b) < 1.5)
          seen.insert(tag);
      }
    }
  EXPECT_GE(seen.size(), 3u);
}

TEST(Png, VolumeOnlyMeshDrawsItsBoundary) {
  Model model;
  Mesh mesh;
  buildHexCube(model, mesh);
  const RgbImage image = decodePng(write("png", model, mesh, sized(200, 200)));
  EXPECT_LT(pixelsOf(image, kPictureBackground), 200u * 200u * 3 / 4);
  EXPECT_EQ(image.at(100, 100) == kPictureBackground, false);
}

TEST(Png, LinesOnlyMeshIsStroked) {
  Model model;
  Mesh mesh;
  mesh.addNode({0, 0, 0});
  mesh.addNode({1, 1, 0});
  mesh.entity({1, 1}).block(ElementType::Line2).nodes = {0, 1};
  addDiscreteEntities(model, mesh);
  const RgbImage image = decodePng(write("png", model, mesh, sized(100, 100)));
  // The diagonal from pixel (4, 96) to (96, 4), margin included, is dark; the rest white.
  EXPECT_LT(brightness(image.at(49, 50)), brightness(kPictureBackground) / 3);
  EXPECT_LT(brightness(image.at(79, 20)), brightness(kPictureBackground) / 3);
  EXPECT_EQ(image.at(80, 80), kPictureBackground);
  EXPECT_EQ(image.at(20, 20), kPictureBackground);
}

TEST(Png, ImagesEncodeLosslesslyIndexedOrNot) {
  RgbImage few(16, 8, kPictureBackground);
  few.pixels[3 * 5] = 10;
  few.pixels[3 * 70 + 2] = 200;
  const std::string indexed = encodePng(few);
  EXPECT_EQ(indexed[25], 3) << "colour type: indexed";
  EXPECT_EQ(decodePng(indexed).pixels, few.pixels);
  RgbImage many(40, 30, kPictureBackground);
  for (std::size_t p = 0; p < many.pixels.size() / 3; ++p) {  // 1200 colours
    many.pixels[3 * p] = std::uint8_t(p);
    many.pixels[3 * p + 1] = std::uint8_t(p >> 8);
  }
  const std::string rgb = encodePng(many);
  EXPECT_EQ(rgb[25], 2) << "colour type: RGB";
  const RgbImage back = decodePng(rgb);
  EXPECT_EQ(back.width, 40);
  EXPECT_EQ(back.pixels, many.pixels);
  EXPECT_THROW(decodePng("not a png"), std::runtime_error);
}

TEST(Png, LimitColorsKeepsTheMostFrequentAndMapsTheRestToTheNearest) {
  RgbImage image(20, 20, Rgb{200, 0, 0});  // 400 pixels of red
  for (int i = 0; i < 100; ++i) {           // then 100 distinct blues, 2 pixels each
    const std::size_t at = 3 * std::size_t(2 * i);
    for (std::size_t k : {at, at + 3}) {
      image.pixels[k] = 0;
      image.pixels[k + 1] = 0;
      image.pixels[k + 2] = std::uint8_t(100 + i);
    }
  }
  image.pixels[3 * 399 + 2] = 150;  // one more pixel of blue 150, now the most frequent blue
  image.pixels[3 * 399] = 0;
  limitColors(image, 2);
  std::set<std::uint32_t> colors;
  for (std::size_t i = 0; i < image.pixels.size(); i += 3)
    colors.insert(image.pixels[i] << 16 | image.pixels[i + 1] << 8 | image.pixels[i + 2]);
  EXPECT_EQ(colors, (std::set<std::uint32_t>{150, 200u << 16}));
  EXPECT_EQ(image.at(0, 0), (Rgb{0, 0, 150}));
}

TEST(Png, SameMeshGivesTheSameBytes) {
  Model model;
  Mesh mesh;
  buildCubeSurface(model, mesh, true);
  EXPECT_EQ(write("png", model, mesh), write("png", model, mesh));
  EXPECT_EQ(write("svg", model, mesh), write("svg", model, mesh));
}

TEST(Picture, EmptyMeshIsRefusedAndLeavesNoFile) {
  for (const char* format : {"png", "svg"}) {
    Model model;
    Mesh mesh;
    const std::filesystem::path path = scratch::path(std::string("empty.") + format);
    try {
      writeMeshFile(path.string(), *findFormatByExtension(std::string(".") + format, 4.1), model,
                    mesh, {});
      ADD_FAILURE() << format << " written";
    } catch (const std::runtime_error& e) {
      const std::string expected = std::string(format) + " pictures show line, surface and "
                                   "volume elements: the mesh to save has none";
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
    EXPECT_FALSE(std::filesystem::exists(path));
    EXPECT_FALSE(std::filesystem::exists(path.string() + ".partial"));
  }
}

TEST(Picture, FormatsAreFoundByNameAndExtension) {
  EXPECT_EQ(findFormatByName("png"), findFormatByExtension(".png", 4.1));
  EXPECT_EQ(findFormatByName("svg"), findFormatByExtension(".svg", 4.1));
  ASSERT_NE(findFormatByName("png"), nullptr);
  EXPECT_TRUE(findFormatByName("png")->showsAllElements);
  EXPECT_EQ(findReaderByExtension(".png"), nullptr);
}

// A plate of about 20000 triangles: composed, rasterized and encoded well within a tenth of
// a second at 800x600 (the bound here leaves room for slow and instrumented builds).
TEST(Png, LargeMeshIsFast) {
  Model model;
  Mesh mesh;
  constexpr int n = 100;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) mesh.addNode({double(i), double(j), 0.1 * std::sin(0.2 * i)});
  ElementBlock& block = mesh.entity({2, 1}).block(ElementType::Triangle3);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const NodeIndex a = static_cast<NodeIndex>(j * (n + 1) + i), b = a + 1,
                      c = a + n + 1, d = c + 1;
      block.nodes.insert(block.nodes.end(), {a, b, d, a, d, c});
    }
  addDiscreteEntities(model, mesh);
  const auto start = std::chrono::steady_clock::now();
  const std::string png = write("png", model, mesh);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RecordProperty("seconds", std::to_string(seconds));
  EXPECT_EQ(decodePng(png).width, 800);
  EXPECT_LT(seconds, 1.0);
}

}  // namespace
}  // namespace geomesh
