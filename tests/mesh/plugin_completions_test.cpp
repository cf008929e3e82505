// Plugins' ExtractVolume (CutPlane, CutSphere, Isosurface), Skin of the mesh and the IGE measure.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "kernel/messages.h"
#include "mesh/core/mesh.h"
#include "mesh/views/plugins.h"
#include "plugin_fixtures.h"

namespace geomesh::post {
namespace {

using testing::addTetCube;
using testing::surfaceArea;

using testing::linearField;
using testing::nodeOf;

double signedTetVolume(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  return dot(b - a, cross(c - a, d - a)) / 6;
}

// Signed volume of the tetrahedra and hexahedra (the latter as 6 tetrahedra) of a view.
double volume(const View& view) {
  static constexpr int kHexTets[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                                         {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
  double sum = 0;
  for (const ElementList& list : view.lists)
    for (std::size_t e = 0; e < list.size(); ++e) {
      const auto p = [&](int i) { return nodeOf(list, e, i); };
      if (list.shape == ElementShape::Tetrahedron) sum += signedTetVolume(p(0), p(1), p(2), p(3));
      if (list.shape == ElementShape::Hexahedron)
        for (const auto& t : kHexTets) sum += signedTetVolume(p(t[0]), p(t[1]), p(t[2]), p(t[3]));
    }
  return sum;
}

double lineLength(const View& view) {
  double sum = 0;
  for (const ElementList& list : view.lists)
    if (list.shape == ElementShape::Line)
      for (std::size_t e = 0; e < list.size(); ++e)
        sum += distance(nodeOf(list, e, 0), nodeOf(list, e, 1));
  return sum;
}

struct CompletionsTest : ::testing::Test {
  ViewStore views;
  Mesh mesh;
  SilentSink log;
  PluginContext context{views, mesh, log, testing::compileWithMathExpression};

  View& field(int n, double (*f)(Vec3)) {
    View& view = views.add("field");
    addTetCube(view, n, f);
    return view;
  }
  void run(const std::string& name, PluginOptions options) {
    ASSERT_EQ(runPlugin(name, options, context), PluginOutcome::Ran);
  }
  // Every node's value is f at the node, and lies on the kept side of `level`.
  void expectValuesAndSide(const View& view, double (*f)(Vec3), double (*level)(Vec3)) {
    std::size_t nodes = 0;
    for (const ElementList& list : view.lists)
      for (std::size_t e = 0; e < list.size(); ++e)
        for (int i = 0; i < list.nodesPerElement; ++i, ++nodes) {
          const Vec3 p = nodeOf(list, e, i);
          EXPECT_NEAR(list.value(e, 0, i, 0), f(p), 1e-12);
          EXPECT_GE(level(p), -1e-12);
        }
    EXPECT_GT(nodes, 0u);
  }
};

// --- ExtractVolume

TEST_F(CompletionsTest, CutPlaneExtractVolumeKeepsThePositiveOrNegativeSide) {
  field(2, linearField);
  run("CutPlane", {{{"View", 0}, {"A", 1}, {"D", -0.3}, {"ExtractVolume", 1}}, {}});
  run("CutPlane", {{{"View", 0}, {"A", 1}, {"D", -0.3}, {"ExtractVolume", -1}}, {}});
  ASSERT_EQ(views.size(), 3u);
  EXPECT_EQ(views.at(1).name, "field_Levelset");
  // x > 0.3 (as Gmsh 4.15: same side and values), then x < 0.3; every piece positive.
  EXPECT_NEAR(volume(views.at(1)), 0.7, 1e-12);
  EXPECT_NEAR(volume(views.at(2)), 0.3, 1e-12);
  expectValuesAndSide(views.at(1), linearField, [](Vec3 p) { return p.x - 0.3; });
  expectValuesAndSide(views.at(2), linearField, [](Vec3 p) { return 0.3 - p.x; });
  for (std::size_t v = 1; v < 3; ++v)
    for (const ElementList& list : views.at(v).lists) {
      ASSERT_EQ(list.shape, ElementShape::Tetrahedron);
      for (std::size_t e = 0; e < list.size(); ++e)
        EXPECT_GT(signedTetVolume(nodeOf(list, e, 0), nodeOf(list, e, 1), nodeOf(list, e, 2),
                                  nodeOf(list, e, 3)),
                  0);
    }
}

TEST_F(CompletionsTest, CutPlaneThroughNodesSplitsTheCubeInHalves) {
  field(2, linearField);
  run("CutPlane", {{{"View", 0}, {"A", 1}, {"D", -0.5}, {"ExtractVolume", 1}}, {}});
  run("CutPlane", {{{"View", 0}, {"A", 1}, {"D", -0.5}, {"ExtractVolume", -1}}, {}});
  EXPECT_NEAR(volume(views.at(1)), 0.5, 1e-12);
  EXPECT_NEAR(volume(views.at(2)), 0.5, 1e-12);
}

TEST_F(CompletionsTest, CutSphereExtractVolumeInsideIsTheCornerOfTheTetrahedron) {
  for (int side : {-1, 1}) {
    View& view = views.add("one");
    ElementList& tet = view.list(ElementShape::Tetrahedron, FieldKind::Scalar);
    tet.coordinates = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    tet.values = {0, 1, 2, 3};
    run("CutSphere", {{{"R", 0.5}, {"ExtractVolume", side}}, {}});
  }
  // The level |p|^2 - R^2 is -0.25 at the origin and 0.75 elsewhere: the cut is a quarter
  // of the way along the edges from the origin; inside (-1) is the tetrahedron scaled by 1/4.
  const View& inside = views.at(1);
  const View& outside = views.at(3);
  EXPECT_NEAR(volume(inside), 1.0 / 6 / 64, 1e-15);
  EXPECT_NEAR(volume(outside), 1.0 / 6 - 1.0 / 6 / 64, 1e-15);
  const ElementList& corner = inside.lists.at(0);
  ASSERT_EQ(corner.size(), 1u);
  for (int i = 1; i < 4; ++i) {
    const Vec3 p = nodeOf(corner, 0, i);
    EXPECT_NEAR(p.x + p.y + p.z, 0.25, 1e-15);
    EXPECT_NEAR(corner.value(0, 0, i, 0), linearField(p), 1e-15);  // the tet's values: linear
  }
  EXPECT_EQ(outside.lists.at(0).size(), 3u);  // the prism left: 3 tetrahedra
}

TEST_F(CompletionsTest, IsosurfaceExtractVolumeKeepsValuesAboveOrBelow) {
  const auto f = [](Vec3 p) { return p.x + p.y; };
  field(3, f);
  run("Isosurface", {{{"View", 0}, {"Value", 0.8}, {"ExtractVolume", 1}}, {}});
  run("Isosurface", {{{"View", 0}, {"Value", 0.8}, {"ExtractVolume", -1}}, {}});
  EXPECT_EQ(views.at(1).name, "field_Levelset_0");
  EXPECT_NEAR(volume(views.at(1)), 1 - 0.32, 1e-12);  // x + y > 0.8 in the unit cube
  EXPECT_NEAR(volume(views.at(2)), 0.32, 1e-12);
  expectValuesAndSide(views.at(1), f, [](Vec3 p) { return p.x + p.y - 0.8; });
  expectValuesAndSide(views.at(2), f, [](Vec3 p) { return 0.8 - p.x - p.y; });
}

TEST_F(CompletionsTest, ExtractVolumeOfTrianglesGivesTriangles) {
  View& view = views.add("square");
  ElementList& tri = view.list(ElementShape::Triangle, FieldKind::Scalar);
  tri.coordinates = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0};
  tri.values = {0, 1, 1, 0, 1, 0};  // x
  run("Isosurface", {{{"View", 0}, {"Value", 0.25}, {"ExtractVolume", 1}}, {}});
  run("Isosurface", {{{"View", 0}, {"Value", 0.25}, {"ExtractVolume", -1}}, {}});
  for (std::size_t v = 1; v < 3; ++v) {
    ASSERT_EQ(views.at(v).lists.size(), 1u);
    EXPECT_EQ(views.at(v).lists[0].shape, ElementShape::Triangle);
  }
  EXPECT_NEAR(surfaceArea(views.at(1)), 0.75, 1e-15);
  EXPECT_NEAR(surfaceArea(views.at(2)), 0.25, 1e-15);
  const ElementList& kept = views.at(1).lists[0];
  for (std::size_t e = 0; e < kept.size(); ++e) {
    const Vec3 a = nodeOf(kept, e, 0), b = nodeOf(kept, e, 1), c = nodeOf(kept, e, 2);
    EXPECT_GT(cross(b - a, c - a).z, 0);  // turned as the square's triangles
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(kept.value(e, 0, i, 0), nodeOf(kept, e, i).x, 1e-15);
  }
}

TEST_F(CompletionsTest, ExtractVolumeOfALineKeepsItsPart) {
  View& view = views.add("segment");
  ElementList& line = view.list(ElementShape::Line, FieldKind::Scalar);
  line.coordinates = {0, 0, 0, 1, 0, 0};
  line.values = {0, 4};
  run("CutPlane", {{{"A", 1}, {"D", -0.25}, {"ExtractVolume", 1}}, {}});
  const ElementList& part = views.at(1).lists.at(0);
  ASSERT_EQ(part.shape, ElementShape::Line);
  EXPECT_NEAR(lineLength(views.at(1)), 0.75, 1e-15);
  EXPECT_EQ(nodeOf(part, 0, 0), (Vec3{0.25, 0, 0}));  // running as the line runs
  EXPECT_EQ(nodeOf(part, 0, 1), (Vec3{1, 0, 0}));
  EXPECT_NEAR(part.value(0, 0, 0, 0), 1.0, 1e-15);
  EXPECT_NEAR(part.value(0, 0, 1, 0), 4.0, 1e-15);
}

TEST_F(CompletionsTest, ExtractVolumeKeepsWholeHexahedraAndSplitsTheCutOnes) {
  View& view = views.add("bricks");
  ElementList& hex = view.list(ElementShape::Hexahedron, FieldKind::Scalar);
  static constexpr int kCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                        {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (int brick = 0; brick < 2; ++brick)
    for (const auto& c : kCorner) {
      const Vec3 p{double(c[0] + brick), double(c[1]), double(c[2])};
      hex.coordinates.insert(hex.coordinates.end(), {p.x, p.y, p.z});
      hex.values.push_back(linearField(p));
    }
  run("CutPlane", {{{"A", 1}, {"D", -1.5}, {"ExtractVolume", -1}}, {}});
  View& kept = views.at(1);
  EXPECT_NEAR(volume(kept), 1.5, 1e-12);
  const ElementList& whole = kept.list(ElementShape::Hexahedron, FieldKind::Scalar);
  ASSERT_EQ(whole.size(), 1u);
  EXPECT_EQ(nodeOf(whole, 0, 6), (Vec3{1, 1, 1}));
  expectValuesAndSide(kept, linearField, [](Vec3 p) { return 1.5 - p.x; });
}

TEST_F(CompletionsTest, ExtractVolumeKeepsEveryTimeStep) {
  View& view = views.add("steps");
  ElementList& tet = view.list(ElementShape::Tetrahedron, FieldKind::Scalar);
  tet.steps = 2;
  tet.coordinates = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  tet.values = {0, 1, 0, 0, 10, 20, 10, 10};                             // x, then 10 + 10 x
  run("CutPlane", {{{"A", -1}, {"D", 0.5}, {"ExtractVolume", 1}}, {}});  // x < 0.5
  const ElementList& part = views.at(1).lists.at(0);
  EXPECT_EQ(part.steps, 2);
  for (std::size_t e = 0; e < part.size(); ++e)
    for (int i = 0; i < 4; ++i) {
      const double x = nodeOf(part, e, i).x;
      EXPECT_NEAR(part.value(e, 0, i, 0), x, 1e-15);
      EXPECT_NEAR(part.value(e, 1, i, 0), 10 + 10 * x, 1e-14);
    }
  EXPECT_NEAR(volume(views.at(1)), 1.0 / 6 - 1.0 / 48, 1e-15);
}

// --- Skin of the mesh (FromMesh = 1)

// The unit cube meshed as n^3 cubes, each a hexahedron or 6 tetrahedra, on shared nodes.
void meshCube(Mesh& mesh, int n, bool hexahedra) {
  static constexpr int kCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                        {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  static constexpr int kTets[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                                      {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
  const auto id = [n](int i, int j, int k) { return NodeIndex((k * (n + 1) + j) * (n + 1) + i); };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) mesh.addNode({double(i) / n, double(j) / n, double(k) / n});
  ElementBlock& block =
      mesh.entity({3, 1}).block(hexahedra ? ElementType::Hex8 : ElementType::Tet4);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        std::array<NodeIndex, 8> c;
        for (int m = 0; m < 8; ++m)
          c[std::size_t(m)] = id(i + kCorner[m][0], j + kCorner[m][1], k + kCorner[m][2]);
        if (hexahedra)
          block.nodes.insert(block.nodes.end(), c.begin(), c.end());
        else
          for (const auto& tet : kTets)
            for (int m : tet) block.nodes.push_back(c[std::size_t(m)]);
      }
}

// Every facet of the skin turns outwards: its normal points away from the cube's centre.
void expectOutwards(const ElementList& list) {
  for (std::size_t e = 0; e < list.size(); ++e) {
    const Vec3 a = nodeOf(list, e, 0), b = nodeOf(list, e, 1), c = nodeOf(list, e, 2);
    EXPECT_GT(dot(cross(b - a, c - a), a - Vec3{0.5, 0.5, 0.5}), 0) << "facet " << e;
  }
}

TEST_F(CompletionsTest, SkinOfATetrahedralCubeMeshIsTwoTrianglesPerSquareOfItsFaces) {
  meshCube(mesh, 3, false);
  mesh.entity({2, 1}).block(ElementType::Triangle3).nodes = {0, 1, 5};  // ignored: volumes exist
  run("Skin", {{{"FromMesh", 1}}, {}});
  ASSERT_EQ(views.size(), 1u);
  const View& skin = views.at(0);
  EXPECT_EQ(skin.name, "Skin");
  ASSERT_EQ(skin.lists.size(), 1u);
  ASSERT_EQ(skin.lists[0].shape, ElementShape::Triangle);
  EXPECT_EQ(skin.lists[0].size(), 6u * 9u * 2u);
  EXPECT_NEAR(surfaceArea(skin), 6.0, 1e-12);
  EXPECT_EQ(skin.maximum(), 0.0);
  EXPECT_EQ(skin.minimum(), 0.0);
  expectOutwards(skin.lists[0]);
}

TEST_F(CompletionsTest, SkinOfAHexahedralCubeMeshIsItsQuadrangles) {
  meshCube(mesh, 2, true);
  run("Skin", {{{"FromMesh", 1}}, {}});
  const View& skin = views.at(0);
  ASSERT_EQ(skin.lists.size(), 1u);
  ASSERT_EQ(skin.lists[0].shape, ElementShape::Quadrangle);
  EXPECT_EQ(skin.lists[0].size(), 6u * 4u);
  EXPECT_NEAR(surfaceArea(skin), 6.0, 1e-12);
  expectOutwards(skin.lists[0]);
}

TEST_F(CompletionsTest, SkinOfASurfaceMeshIsItsBoundaryEdges) {
  // The square [0, 2]^2 as 2 x 2 quadrangles on shared nodes.
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 2; ++i) mesh.addNode({double(i), double(j), 0});
  ElementBlock& quads = mesh.entity({2, 1}).block(ElementType::Quad4);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const NodeIndex a = NodeIndex(3 * j + i);
      quads.nodes.insert(quads.nodes.end(), {a, a + 1, a + 4, a + 3});
    }
  run("Skin", {{{"FromMesh", 1}}, {}});
  const View& skin = views.at(0);
  ASSERT_EQ(skin.lists.size(), 1u);
  ASSERT_EQ(skin.lists[0].shape, ElementShape::Line);
  EXPECT_EQ(skin.lists[0].size(), 8u);
  EXPECT_NEAR(lineLength(skin), 8.0, 1e-15);
}

TEST_F(CompletionsTest, SkinOfAnEmptyMeshIsAnError) {
  EXPECT_THROW(runPlugin("Skin", {{{"FromMesh", 1}}, {}}, context), PluginError);
}

// --- IGE measure (values of Gmsh 4.15's AnalyseMeshQuality on the same elements)

struct IgeCase {
  std::vector<Vec3> corners;
  double expected;
};

// The IGE the plugin gives one element of a type.
double igeOf(ElementType type, const std::vector<Vec3>& corners) {
  ViewStore views;
  Mesh mesh;
  SilentSink log;
  PluginContext context{views, mesh, log};
  ElementBlock& block = mesh.entity({dimension(type), 1}).block(type);
  for (const Vec3& p : corners) block.nodes.push_back(mesh.addNode(p));
  const PluginOptions options{{{"IGEMeasure", 1}, {"CreateView", 1}}, {}};
  EXPECT_EQ(runPlugin("AnalyseMeshQuality", options, context), PluginOutcome::Ran);
  EXPECT_EQ(views.size(), 1u);
  EXPECT_EQ(views.at(0).name, "IGE " + std::to_string(dimension(type)) + "D");
  return views.at(0).lists.at(0).value(0, 0, 0, 0);
}

TEST(IgeMeasure, TrianglesSumTheSinesOfTheirAngles) {
  const double s3 = std::sqrt(3.0);
  const std::vector<IgeCase> cases = {
      {{{0, 0, 0}, {1, 0, 0}, {0.5, s3 / 2, 0}}, 1.0},
      {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, (2 + 2 * std::sqrt(2.0)) / (3 * s3)},  // 0.929231233
      {{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}}, 0.929231233411568},  // turned the other way
      {{{0, 0, 0}, {2, 0, 0}, {0, 1, 0}}, 0.9012979589540726},
      {{{0, 0, 0}, {1, 0, 0}, {0.5, 0.1, 0}}, 0.299008801780722},
      {{{0, 0, 0}, {1, 0, 0}, {3, 1, 0}}, 0.3482818224499928},
      {{{0, 0, 0}, {1, 0, 1}, {0, 1, 0.3}}, 0.9639797430620762},
  };
  for (const IgeCase& c : cases)
    EXPECT_NEAR(igeOf(ElementType::Triangle3, c.corners), c.expected, 1e-13);
}

TEST(IgeMeasure, TetrahedraSumOverThePathsThroughTheirCorners) {
  const double s3 = std::sqrt(3.0);
  const std::vector<IgeCase> cases = {
      {{{0, 0, 0}, {1, 0, 0}, {0.5, s3 / 2, 0}, {0.5, s3 / 6, std::sqrt(2.0 / 3)}}, 1.0},
      {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, (2 + std::sqrt(2.0)) / 4},  // 0.8535533906
      {{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}}, 0.853553390593274},         // inverted
      {{{0, 0, 0}, {2, 0, 0}, {0, 1, 0}, {0, 0, 1}}, 0.8007821345916899},
      {{{0, 0, 0}, {0.5, 0, 0}, {0, 1, 0}, {0, 0, 1}}, 0.8007821345916901},
      {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.3, 0.3, 0.05}}, 0.12780312101916724},
      {{{0, 0, 0}, {10, 0, 0}, {10, 1, 0}, {10, 1, 1}}, 0.6294042711256604},
      {{{0, 0, 0}, {1, 0, 0}, {0.5, s3 / 2, 0}, {0.5, s3 / 6, 0.1}}, 0.2828708557444596},
  };
  for (const IgeCase& c : cases)
    EXPECT_NEAR(igeOf(ElementType::Tet4, c.corners), c.expected, 1e-13);
}

TEST(IgeMeasure, QuadranglesAndHexahedraTakeTheirSmallestScaledJacobian) {
  EXPECT_NEAR(igeOf(ElementType::Quad4, {{0, 0, 0}, {2, 0, 0}, {1.5, 1, 0}, {0.5, 1, 0}}),
              2 / std::sqrt(5.0), 1e-13);
  EXPECT_NEAR(igeOf(ElementType::Quad4, {{0, 0, 0}, {1, 0, 0}, {0.6, 0.6, 0}, {0, 1, 0}}),
              0.38461538461538447, 1e-13);
  EXPECT_NEAR(igeOf(ElementType::Quad4, {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}), 1.0, 1e-15);
  EXPECT_EQ(igeOf(ElementType::Quad4, {{0, 0, 0}, {1, 0, 0}, {0.3, 0.3, 0}, {0, 1, 0}}), 0.0);
  const std::vector<Vec3> sheared = {{0, 0, 0},   {1, 0, 0},   {1, 1, 0},   {0, 1, 0},
                                     {0.5, 0, 1}, {1.5, 0, 1}, {1.5, 1, 1}, {0.5, 1, 1}};
  EXPECT_NEAR(igeOf(ElementType::Hex8, sheared), 2 / std::sqrt(5.0), 1e-13);
  const std::vector<Vec3> tapered = {{0, 0, 0},     {2, 0, 0},     {2, 1, 0},       {0, 1, 0},
                                     {0.5, 0.2, 1}, {1.5, 0.2, 1}, {1.4, 0.9, 1.2}, {0.5, 0.8, 1}};
  EXPECT_NEAR(igeOf(ElementType::Hex8, tapered), 0.7595317031885825, 1e-13);
  std::vector<Vec3> folded = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                              {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  EXPECT_NEAR(igeOf(ElementType::Hex8, folded), 1.0, 1e-15);
  folded[6] = {0.2, 0.2, 0.2};  // a corner pushed through: the Jacobian changes sign
  EXPECT_EQ(igeOf(ElementType::Hex8, folded), 0.0);
}

}  // namespace
}  // namespace geomesh::post
