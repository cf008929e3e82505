// Tests of the 2D boundary layer: heights, fans, corners, shortening, the field's size.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "mesh/checks/mesh_check.h"
#include "mesh/pipeline/generate.h"
#include "mesh/sizes/boundary_layer_field.h"
#include "mesh/sizes/size_field.h"
#include "mesh_test_models.h"

namespace geomesh {
namespace {

using testing::PolygonModelBuilder;

class RecordingSink final : public MessageSink {
 public:
  std::vector<std::string> warnings;
  void info(std::string_view) override {}
  void warning(std::string_view m) override { warnings.emplace_back(m); }
};

// Field[1] = BoundaryLayer with the given options, and BoundaryLayer Field = 1.
void addLayer(Model& model, std::map<std::string, std::vector<double>> options) {
  model.meshConstraints().sizeFields[1] = {"BoundaryLayer", std::move(options)};
  model.meshConstraints().boundaryLayerFields = {1};
}

// The options of a layer of quadrangles on `curves`: first cell `size`, growing by `ratio`
// below `thickness`.
std::map<std::string, std::vector<double>> wallLayer(std::vector<double> curves, double size,
                                                     double ratio, double thickness) {
  return {{"CurvesList", std::move(curves)},
          {"Size", {size}},
          {"Ratio", {ratio}},
          {"Thickness", {thickness}},
          {"Quads", {1}}};
}

struct Meshed {
  Mesh mesh;
  RecordingSink log;
};

Meshed meshed(const Model& model) {
  Meshed m;
  generateMesh(model, {}, 2, m.mesh, m.log);
  return m;
}

double signedArea(const Mesh& mesh, std::span<const NodeIndex> n) {
  double area = 0;
  for (std::size_t k = 0; k < n.size(); ++k) {
    const Vec3 a = mesh.node(n[k]), b = mesh.node(n[(k + 1) % n.size()]);
    area += a.x * b.y - a.y * b.x;
  }
  return 0.5 * area;
}

struct SurfaceFigures {
  std::size_t triangles = 0, quadrangles = 0;
  double area = 0, smallestArea = 1e300;
};

// Counts and areas of a surface's elements (the plane's normal is +z: areas are signed).
SurfaceFigures figures(const Mesh& mesh, int surface) {
  SurfaceFigures f;
  const EntityMesh* em = mesh.find({2, surface});
  for (ElementType type : {ElementType::Triangle3, ElementType::Quad4}) {
    const ElementBlock* block = em ? em->findBlock(type) : nullptr;
    if (!block) continue;
    (type == ElementType::Triangle3 ? f.triangles : f.quadrangles) = block->size();
    for (std::size_t e = 0; e < block->size(); ++e) {
      const double a = signedArea(mesh, block->element(e));
      f.area += a;
      f.smallestArea = std::min(f.smallestArea, a);
    }
  }
  return f;
}

// The heights of the nodes above the node of the wall y = 0 nearest to abscissa x, below
// `below`, sorted.
std::vector<double> columnAt(const Mesh& mesh, double x, double below) {
  double wallX = 1e300;
  for (NodeIndex n = 0; n < mesh.nodeCount(); ++n) {
    const Vec3 p = mesh.node(n);
    if (p.y == 0 && std::abs(p.x - x) < std::abs(wallX - x)) wallX = p.x;
  }
  std::vector<double> ys;
  for (NodeIndex n = 0; n < mesh.nodeCount(); ++n) {
    const Vec3 p = mesh.node(n);
    if (p.x == wallX && p.y < below) ys.push_back(p.y);
  }
  std::sort(ys.begin(), ys.end());
  return ys;
}

// The elements of a surface holding the node at p: (triangles, quadrangles).
std::pair<int, int> elementsAround(const Mesh& mesh, int surface, Vec3 p) {
  NodeIndex node = static_cast<NodeIndex>(-1);
  for (NodeIndex n = 0; n < mesh.nodeCount(); ++n)
    if (distance(mesh.node(n), p) < 1e-12) node = n;
  std::pair<int, int> count{0, 0};
  const EntityMesh* em = mesh.find({2, surface});
  for (ElementType type : {ElementType::Triangle3, ElementType::Quad4}) {
    const ElementBlock* block = em->findBlock(type);
    if (!block) continue;
    for (std::size_t e = 0; e < block->size(); ++e) {
      const auto n = block->element(e);
      if (std::find(n.begin(), n.end(), node) == n.end()) continue;
      ++(type == ElementType::Triangle3 ? count.first : count.second);
    }
  }
  return count;
}

Model channel(double height, double h) {
  PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {1, 0}, {1, height}, {0, height}}, h)});
  return std::move(b.model);
}

TEST(BoundaryLayer2D, FlatWallHeightsFollowTheGeometricLaw) {
  Model model = channel(0.4, 0.1);
  addLayer(model, wallLayer({1}, 0.01, 1.2, 0.05));
  auto [mesh, log] = meshed(model);
  EXPECT_TRUE(log.warnings.empty());
  for (double x : {0.1, 0.5, 0.9}) {
    const std::vector<double> ys = columnAt(mesh, x, 0.1);
    ASSERT_EQ(ys.size(), 4u) << x;  // the wall and 3 layers: 0.0364 + 0.01728 > 0.05
    EXPECT_EQ(ys[0], 0.0);
    EXPECT_EQ(ys[1], 0.01);  // the first cell is Size exactly
    for (std::size_t k = 2; k < ys.size(); ++k)
      EXPECT_NEAR((ys[k] - ys[k - 1]) / (ys[k - 1] - ys[k - 2]), 1.2, 1e-9);
  }
  const SurfaceFigures f = figures(mesh, 1);
  EXPECT_EQ(f.quadrangles, 24u);  // 9 columns (not at the wall's ends), 3 layers
  EXPECT_GT(f.triangles, 50u);
  EXPECT_LT(f.triangles, 200u);
  EXPECT_GT(f.smallestArea, 0);
  EXPECT_NEAR(f.area, 0.4, 1e-9);
  EXPECT_TRUE(checkMesh(model, mesh).ok());
}

TEST(BoundaryLayer2D, WithoutQuadsEachCellIsTwoTriangles) {
  Model model = channel(0.4, 0.1);
  addLayer(model,
           {{"EdgesList", {1}}, {"hwall_n", {0.01}}, {"Ratio", {1.2}}, {"Thickness", {0.05}}});
  auto [mesh, log] = meshed(model);
  const SurfaceFigures f = figures(mesh, 1);
  EXPECT_EQ(f.quadrangles, 0u);
  EXPECT_EQ(columnAt(mesh, 0.5, 0.1).size(), 4u);
  EXPECT_GT(f.triangles, 48u);
  EXPECT_GT(f.smallestArea, 0);
  EXPECT_NEAR(f.area, 0.4, 1e-9);
}

TEST(BoundaryLayer2D, RecombineSurfaceKeepsTheLayerAndRecombinesTheRest) {
  Model model = channel(0.4, 0.05);
  addLayer(model, wallLayer({1}, 0.01, 1.2, 0.05));
  model.meshConstraints().recombinedSurfaces[1] = 45;
  auto [mesh, log] = meshed(model);
  // The layer's columns are as without recombination: the recombination moves no layer node.
  for (double x : {0.1, 0.5, 0.9}) {
    const std::vector<double> ys = columnAt(mesh, x, 0.05);
    ASSERT_EQ(ys.size(), 4u) << x;
    EXPECT_EQ(ys[1], 0.01);
    for (std::size_t k = 2; k < ys.size(); ++k)
      EXPECT_NEAR((ys[k] - ys[k - 1]) / (ys[k - 1] - ys[k - 2]), 1.2, 1e-9);
  }
  const SurfaceFigures f = figures(mesh, 1);
  // 19 columns of 3 layer quadrangles, and the rest (0.4 x 1 at size 0.05, about 160 cells)
  // recombined: quadrangles with few triangles left over.
  EXPECT_GT(f.quadrangles, 57u + 120u);
  EXPECT_LT(f.triangles, f.quadrangles / 10);
  EXPECT_GT(f.smallestArea, 0);
  EXPECT_NEAR(f.area, 0.4, 1e-9);
  EXPECT_TRUE(checkMesh(model, mesh).ok());
}

TEST(BoundaryLayer2D, BothChannelWallsAndAConcaveCorner) {
  Model model = channel(0.4, 0.1);
  // Layers on the bottom (1) and left (4) walls: they meet at the concave corner (0, 0).
  addLayer(model, wallLayer({1, 4}, 0.01, 1.2, 0.05));
  auto [mesh, log] = meshed(model);
  // The corner's column runs along the bisector, its points where the two layers meet.
  for (double h : {0.01, 0.022, 0.0364}) {
    bool found = false;
    for (NodeIndex n = 0; n < mesh.nodeCount(); ++n)
      found = found || distance(mesh.node(n), {h, h, 0}) < 1e-9;
    EXPECT_TRUE(found) << h;
  }
  const SurfaceFigures f = figures(mesh, 1);
  EXPECT_EQ(f.quadrangles, (9u + 3) * 3);  // 9 covered segments below, 3 on the left
  EXPECT_GT(f.smallestArea, 0);
  EXPECT_NEAR(f.area, 0.4, 1e-9);
  EXPECT_TRUE(checkMesh(model, mesh).ok());
}

// The cells of the layer of a surface: its first em.layer quadrangles, all positive.
std::size_t layerQuadrangles(const Mesh& mesh, int surface) {
  const EntityMesh* em = mesh.find({2, surface});
  return em && em->layer ? em->layer->quadrangles : 0;
}

TEST(BoundaryLayer2D, LayersMeetingAtAConcaveCornerAcrossSeveralCellsDoNotOverlap) {
  // A fin on a channel's floor, its wall nodes 0.02 apart under a layer 0.03 thick: near the
  // fin's feet the floor's columns run up the fin's layer and the fin's columns along the
  // floor's. They are cut where the cells overlap, and the layer stays.
  PolygonModelBuilder b;
  const std::vector<int> c = b.polygon(
      {{0, 0}, {0.5, 0}, {0.5, 0.2}, {0.58, 0.2}, {0.58, 0}, {1.6, 0}, {1.6, 0.5}, {0, 0.5}},
      0.02);
  b.surface({c});
  Model model = std::move(b.model);
  addLayer(model, wallLayer({1, 2, 3, 4, 5}, 0.002, 1.2, 0.03));
  auto [mesh, log] = meshed(model);
  for (const std::string& w : log.warnings)
    EXPECT_EQ(w.find("could not be joined"), std::string::npos) << w;
  // 141 wall segments of 7 cells each, less the corners' cut columns.
  EXPECT_GT(layerQuadrangles(mesh, 1), 600u);
  const SurfaceFigures f = figures(mesh, 1);
  EXPECT_GT(f.smallestArea, 0);
  EXPECT_NEAR(f.area, 1.6 * 0.5 - 0.08 * 0.2, 1e-9);
  EXPECT_TRUE(checkMesh(model, mesh).ok());
}

TEST(BoundaryLayer2D, AWallTipBetweenTwoColumnsCutsTheCellsItReaches) {
  // A needle hangs from the ceiling down to 0.06 above the floor, between the floor's
  // columns at x = 0.5 and 0.55, whose rays miss it: the layer, 0.1 thick, is cut below
  // the tip there instead of wrapping round it.
  PolygonModelBuilder b;
  const std::vector<int> c = b.polygon({{0, 0}, {1, 0}, {1, 0.4}, {0.53, 0.4}, {0.525, 0.06},
                                        {0.52, 0.4}, {0, 0.4}},
                                       0.05);
  b.surface({c});
  Model model = std::move(b.model);
  addLayer(model, wallLayer({1}, 0.01, 1.2, 0.1));
  Mesh mesh;
  RecordingSink log;
  ASSERT_NO_THROW(generateMesh(model, {}, 2, mesh, log));
  // Far from the needle the columns keep their 6 cells (0.01 ... 0.0744 below 0.1).
  EXPECT_EQ(columnAt(mesh, 0.2, 0.2).size(), 7u);
  // Under the needle they stop below its tip.
  for (double x : {0.5, 0.55}) {
    const std::vector<double> ys = columnAt(mesh, x, 0.2);
    ASSERT_FALSE(ys.empty());
    EXPECT_LT(ys.back(), 0.06) << x;
  }
  EXPECT_GT(layerQuadrangles(mesh, 1), 80u);
  const SurfaceFigures f = figures(mesh, 1);
  EXPECT_GT(f.smallestArea, 0);
  EXPECT_NEAR(f.area, 0.4 - 0.5 * 0.01 * 0.34, 1e-9);
  EXPECT_TRUE(checkMesh(model, mesh).ok());
}

// NACA 0012 (closed trailing edge) as a polygon, from the trailing edge over the upper side.
std::vector<Vec2> naca0012(int n) {
  auto thickness = [](double x) {
    return 0.6 * (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x -
                  0.1036 * x * x * x * x);
  };
  std::vector<Vec2> points;
  const double pi = std::acos(-1.0);
  for (int i = n; i >= 0; --i) {
    const double x = 0.5 * (1 - std::cos(pi * i / n));
    points.push_back({x, i == n ? 0 : thickness(x)});
  }
  for (int i = 1; i < n; ++i) {
    const double x = 0.5 * (1 - std::cos(pi * i / n));
    points.push_back({x, -thickness(x)});
  }
  return points;
}

TEST(BoundaryLayer2D, AirfoilTrailingEdgeGetsTheRequestedFan) {
  PolygonModelBuilder b;
  const std::vector<int> box = b.polygon({{-1, -1}, {2.5, -1}, {2.5, 1}, {-1, 1}}, 0.25);
  const std::vector<Vec2> profile = naca0012(40);
  // The airfoil's hole runs clockwise; its first point is the trailing edge.
  std::vector<Vec2> clockwise(profile.rbegin(), profile.rend());
  std::rotate(clockwise.begin(), clockwise.end() - 1, clockwise.end());
  const std::vector<int> airfoil = b.polygon(clockwise, 0.03);
  b.surface({box, airfoil});
  const int trailingEdge = 5;  // the first point after the box's four
  std::vector<double> walls(airfoil.begin(), airfoil.end());
  for (int fan : {7, 3}) {
    addLayer(b.model, {{"CurvesList", walls},
                       {"Size", {0.001}},
                       {"Ratio", {1.2}},
                       {"Thickness", {0.01}},
                       {"Quads", {1}},
                       {"FanPointsList", {double(trailingEdge)}},
                       {"FanPointsSizesList", {double(fan)}}});
    Mesh mesh;
    RecordingSink log;
    generateMesh(b.model, {}, 2, mesh, log);
    const auto [triangles, quadrangles] = elementsAround(mesh, 1, {1, 0, 0});
    EXPECT_EQ(triangles, fan);
    EXPECT_EQ(quadrangles, 2);
    double airfoilArea = 0;
    for (std::size_t k = 0; k < profile.size(); ++k) {
      const Vec2 p = profile[k], q = profile[(k + 1) % profile.size()];
      airfoilArea += 0.5 * (p.u * q.v - p.v * q.u);
    }
    const SurfaceFigures f = figures(mesh, 1);
    EXPECT_GT(f.smallestArea, 0);
    EXPECT_NEAR(f.area, 3.5 * 2 - std::abs(airfoilArea), 1e-9);
    // 6 layers (0.001 growing by 1.2 up to 0.01) on every wall segment, and 5 above the fan.
    std::size_t segments = 0;
    for (int c : airfoil) segments += mesh.find({1, c})->findBlock(ElementType::Line2)->size();
    EXPECT_EQ(f.quadrangles, segments * 6 + 5 * fan);
    EXPECT_TRUE(log.warnings.empty());
    EXPECT_TRUE(checkMesh(b.model, mesh).ok());
  }
}

TEST(BoundaryLayer2D, DefaultFanAtAConvexCornerOfAnObstacle) {
  PolygonModelBuilder b;
  const std::vector<int> box = b.polygon({{0, 0}, {2, 0}, {2, 1.5}, {0, 1.5}}, 0.2);
  const std::vector<int> square =
      b.polygon({{0.7, 0.5}, {0.7, 1.0}, {1.2, 1.0}, {1.2, 0.5}}, 0.05);  // clockwise
  b.surface({box, square});
  std::vector<double> walls(square.begin(), square.end());
  addLayer(b.model, {{"CurvesList", walls},
                     {"Size", {0.004}},
                     {"Ratio", {1.25}},
                     {"Thickness", {0.03}},
                     {"Quads", {1}},
                     {"FanPointsList", {6}}});
  Mesh mesh;
  RecordingSink log;
  generateMesh(b.model, {}, 2, mesh, log);
  EXPECT_EQ(elementsAround(mesh, 1, {0.7, 1.0, 0}).first, 5);  // Mesh.BoundaryLayerFanElements
  EXPECT_EQ(elementsAround(mesh, 1, {1.2, 1.0, 0}).first, 0);  // no fan: one bisector column
  const SurfaceFigures f = figures(mesh, 1);
  EXPECT_GT(f.smallestArea, 0);
  EXPECT_NEAR(f.area, 3 - 0.25, 1e-9);
  EXPECT_TRUE(checkMesh(b.model, mesh).ok());
}

TEST(BoundaryLayer2D, FacingLayersInAThinChannelAreShortenedWithAWarning) {
  Model model = channel(0.05, 0.02);
  addLayer(model, wallLayer({1, 3}, 0.004, 1.2, 0.05));
  auto [mesh, log] = meshed(model);
  ASSERT_FALSE(log.warnings.empty());
  EXPECT_NE(log.warnings.front().find("surface 1 shortened"), std::string::npos);
  const std::vector<double> ys = columnAt(mesh, 0.5, 0.026);
  ASSERT_GE(ys.size(), 2u);
  EXPECT_LT(ys.back(), 0.45 * 0.05 + 1e-12);
  const SurfaceFigures f = figures(mesh, 1);
  EXPECT_GT(f.smallestArea, 0);
  EXPECT_NEAR(f.area, 0.05, 1e-9);
  EXPECT_TRUE(checkMesh(model, mesh).ok());
}

TEST(BoundaryLayer2D, ACurvedSurfaceIsMeshedWithoutLayerAndAWarning) {
  Model model = testing::spherePatchModel(0.2);
  addLayer(model, {{"CurvesList", {1}}, {"Size", {0.01}}, {"Thickness", {0.05}}});
  auto [mesh, log] = meshed(model);
  EXPECT_TRUE(std::any_of(log.warnings.begin(), log.warnings.end(), [](const std::string& w) {
    return w.find("surface 1 is not plane") != std::string::npos;
  }));
  EXPECT_GT(mesh.elementCount(2), 0u);
}

TEST(BoundaryLayerField, HeightsOfTheBetaLawAndTheLayerCount) {
  BoundaryLayerParameters p;
  p.ratio = 1.0;
  p.thickness = 0.05;
  EXPECT_EQ(p.heights(0.01).size(), 5u);  // a top at Thickness is kept
  p.betaLaw = true;
  p.layers = 4;
  p.beta = 1.2;
  const std::vector<double> beta = p.heights(0.01);  // the reference's heights
  const std::vector<double> expected{0.01, 0.02526472, 0.04618136, 0.07097031};
  ASSERT_EQ(beta.size(), expected.size());
  EXPECT_DOUBLE_EQ(beta[0], 0.01);
  for (std::size_t k = 1; k < beta.size(); ++k) EXPECT_NEAR(beta[k], expected[k], 1e-7);
}

TEST(BoundaryLayerField, AsASizeFieldItGivesTheCellHeightAtTheDistance) {
  Model model = channel(0.4, 0.1);
  model.meshConstraints().sizeFields[1] = {
      "BoundaryLayer", {{"CurvesList", {1}}, {"Size", {0.01}}, {"Ratio", {1.5}}, {"hfar", {0.08}}}};
  model.meshConstraints().backgroundField = 1;
  RecordingSink log;
  const SizeFields fields(model, log);
  EXPECT_TRUE(log.warnings.empty());
  EXPECT_NEAR(fields.at({0.5, 0, 0}, {2, 1}), 0.01, 1e-12);
  EXPECT_NEAR(fields.at({0.5, 0.1, 0}, {2, 1}), 0.01 + 0.1 * 0.5, 1e-12);
  EXPECT_NEAR(fields.at({0.5, 0.3, 0}, {2, 1}), 0.08, 1e-12);  // SizeFar
}

TEST(BoundaryLayerField, ANameThatIsNotALayerFieldIsReported) {
  Model model = channel(0.4, 0.1);
  model.meshConstraints().sizeFields[1] = {"Box", {}};
  model.meshConstraints().boundaryLayerFields = {1, 2};
  RecordingSink log;
  const SizeFields fields(model, log);
  EXPECT_TRUE(fields.boundaryLayers().empty());
  ASSERT_EQ(log.warnings.size(), 2u);
  EXPECT_NE(log.warnings[0].find("not a BoundaryLayer field"), std::string::npos);
  EXPECT_NE(log.warnings[1].find("not defined"), std::string::npos);
}

}  // namespace
}  // namespace geomesh
