// Tests of transfinite curves (Progression, Bump, Beta) and transfinite surfaces.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "mesh/pipeline/generate.h"
#include "mesh/checks/mesh_check.h"
#include "mesh/curves/transfinite_curve.h"
#include "mesh_test_models.h"

namespace geomesh {
namespace {

using testing::PolygonModelBuilder;

class SilentSink final : public MessageSink {
 public:
  void info(std::string_view) override {}
  void warning(std::string_view) override {}
};

TransfiniteCurve law(int nodes, TransfiniteCurve::Law kind, double coefficient,
                     bool reversed = false) {
  TransfiniteCurve t;
  t.nodes = nodes;
  t.law = kind;
  t.coefficient = coefficient;
  t.reversed = reversed;
  return t;
}

void expectFractions(const std::vector<double>& actual, const std::vector<double>& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t k = 0; k < actual.size(); ++k)
    EXPECT_NEAR(actual[k], expected[k], 1e-5) << "node " << k;
}

TEST(TransfiniteCurve, ProgressionIsGeometric) {
  expectFractions(transfiniteFractions(law(6, TransfiniteCurve::Law::Progression, 2)),
                  {0, 1 / 31.0, 3 / 31.0, 7 / 31.0, 15 / 31.0, 1});
}

TEST(TransfiniteCurve, ReversedProgressionIsMirrored) {
  expectFractions(transfiniteFractions(law(6, TransfiniteCurve::Law::Progression, 2, true)),
                  {0, 16 / 31.0, 24 / 31.0, 28 / 31.0, 30 / 31.0, 1});
}

TEST(TransfiniteCurve, UnitProgressionIsEven) {
  expectFractions(transfiniteFractions(law(5, TransfiniteCurve::Law::Progression, 1)),
                  {0, 0.25, 0.5, 0.75, 1});
}

TEST(TransfiniteCurve, BumpRefinesBothEnds) {
  // Sizes 1 : 2 : 3 : 3 : 2 : 1 for 7 nodes and a coefficient of 0.2.
  expectFractions(transfiniteFractions(law(7, TransfiniteCurve::Law::Bump, 0.2)),
                  {0, 1 / 12.0, 3 / 12.0, 0.5, 9 / 12.0, 11 / 12.0, 1});
  const std::vector<double> coarseEnds =
      transfiniteFractions(law(11, TransfiniteCurve::Law::Bump, 2));
  EXPECT_NEAR(coarseEnds[1], 0.136729, 2e-4);
  EXPECT_NEAR(coarseEnds[5], 0.5, 1e-12);
}

TEST(TransfiniteCurve, BetaFollowsRobertsStretching) {
  expectFractions(transfiniteFractions(law(6, TransfiniteCurve::Law::Beta, 1.5)),
                  {0, 0.148803, 0.327238, 0.533181, 0.760647, 1});
}

TEST(TransfiniteCurve, MesherPlacesNodesAlongTheCurve) {
  PolygonModelBuilder b;
  const int p = b.point(0, 0), q = b.point(1, 0);
  const int line = b.line(p, q);
  b.model.meshConstraints().transfiniteCurves[line] =
      law(6, TransfiniteCurve::Law::Progression, 2, true);
  Mesh mesh;
  SilentSink log;
  generateMesh(b.model, {}, 1, mesh, log);
  const EntityMesh* em = mesh.find({1, line});
  ASSERT_NE(em, nullptr);
  ASSERT_EQ(em->nodes.size(), 4u);
  EXPECT_NEAR(mesh.node(em->nodes[0]).x, 16 / 31.0, 1e-9);
  EXPECT_NEAR(mesh.node(em->nodes[3]).x, 30 / 31.0, 1e-9);
  EXPECT_EQ(mesh.elementCount(1), 5u);
}

// A 2 x 1 rectangle with n nodes on its horizontal sides and m on its vertical ones.
Model rectangle(int n, int m) {
  PolygonModelBuilder b;
  const std::vector<int> loop = b.polygon({{0, 0}, {2, 0}, {2, 1}, {0, 1}}, 0.1);
  b.surface({loop});
  auto& c = b.model.meshConstraints();
  c.transfiniteCurves[loop[0]] = law(n, TransfiniteCurve::Law::Progression, 1);
  c.transfiniteCurves[loop[2]] = law(n, TransfiniteCurve::Law::Progression, 1.2);
  c.transfiniteCurves[loop[1]] = law(m, TransfiniteCurve::Law::Progression, 1);
  c.transfiniteCurves[loop[3]] = law(m, TransfiniteCurve::Law::Bump, 0.5);
  c.transfiniteSurfaces[1] = {};
  return std::move(b.model);
}

double faceArea(const Mesh& mesh, int surface) {
  double area = 0;
  for (const ElementBlock& block : mesh.find({2, surface})->blocks)
    for (std::size_t e = 0; e < block.size(); ++e) {
      const auto n = block.element(e);
      for (std::size_t k = 1; k + 1 < n.size(); ++k)
        area += 0.5 * norm(cross(mesh.node(n[k]) - mesh.node(n[0]),
                                 mesh.node(n[k + 1]) - mesh.node(n[0])));
    }
  return area;
}

TEST(TransfiniteSurface, RectangleGetsTwoTrianglesPerCell) {
  for (auto arrangement :
       {TransfiniteSurface::Arrangement::Left, TransfiniteSurface::Arrangement::Right,
        TransfiniteSurface::Arrangement::AlternateLeft}) {
    Model model = rectangle(7, 5);
    model.meshConstraints().transfiniteSurfaces[1].arrangement = arrangement;
    Mesh mesh;
    SilentSink log;
    generateMesh(model, {}, 2, mesh, log);
    EXPECT_EQ(mesh.elementCount(2), 2u * 6 * 4);
    EXPECT_EQ(mesh.nodeCount(), 7u * 5);
    EXPECT_NEAR(faceArea(mesh, 1), 2.0, 1e-12);
    const MeshCheckReport report = checkMesh(model, mesh);
    EXPECT_TRUE(report.ok()) << report.summary();
  }
}

TEST(TransfiniteSurface, RecombinedRectangleGetsQuadrangles) {
  Model model = rectangle(9, 4);
  model.meshConstraints().recombinedSurfaces[1] = 45;
  Mesh mesh;
  SilentSink log;
  generateMesh(model, {}, 2, mesh, log);
  const EntityMesh* em = mesh.find({2, 1});
  ASSERT_NE(em->findBlock(ElementType::Quad4), nullptr);
  EXPECT_EQ(em->findBlock(ElementType::Quad4)->size(), 8u * 3);
  EXPECT_EQ(em->findBlock(ElementType::Triangle3), nullptr);
  EXPECT_NEAR(faceArea(mesh, 1), 2.0, 1e-12);
  const MeshCheckReport report = checkMesh(model, mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
}

TEST(TransfiniteSurface, FlippedPlaneKeepsPositiveOrientation) {
  PolygonModelBuilder b;
  const std::vector<int> loop = b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.1);
  b.surface({loop}, /*flipped=*/true);
  for (int c : loop)
    b.model.meshConstraints().transfiniteCurves[c] = law(4, TransfiniteCurve::Law::Progression, 1);
  b.model.meshConstraints().transfiniteSurfaces[1] = {};
  Mesh mesh;
  SilentSink log;
  generateMesh(b.model, {}, 2, mesh, log);
  EXPECT_EQ(mesh.elementCount(2), 18u);
  const MeshCheckReport report = checkMesh(b.model, mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
}

TEST(TransfiniteSurface, TriangleCollapsesTheFirstCorner) {
  PolygonModelBuilder b;
  const std::vector<int> loop = b.polygon({{0, 0}, {2, 0}, {0, 1}}, 0.1);
  b.surface({loop});
  auto& c = b.model.meshConstraints();
  c.transfiniteCurves[loop[0]] = law(4, TransfiniteCurve::Law::Progression, 1);
  c.transfiniteCurves[loop[1]] = law(3, TransfiniteCurve::Law::Progression, 1);
  c.transfiniteCurves[loop[2]] = law(4, TransfiniteCurve::Law::Progression, 1);
  c.transfiniteSurfaces[1] = {};
  Mesh mesh;
  SilentSink log;
  generateMesh(b.model, {}, 2, mesh, log);
  EXPECT_EQ(mesh.nodeCount(), 10u);
  EXPECT_EQ(mesh.elementCount(2), 10u);
  EXPECT_NEAR(faceArea(mesh, 1), 1.0, 1e-12);
  const MeshCheckReport report = checkMesh(b.model, mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
}

TEST(TransfiniteSurface, UnequalOppositeSidesFallBackToTheUnstructuredMesher) {
  // As the reference: a warning naming the sides, then the surface meshed as if it were not
  // transfinite (its curves keep their transfinite nodes).
  class WarningSink final : public MessageSink {
   public:
    void info(std::string_view) override {}
    void warning(std::string_view m) override { warnings.emplace_back(m); }
    std::vector<std::string> warnings;
  };
  Model model = rectangle(7, 5);
  model.meshConstraints().transfiniteCurves[3].nodes = 6;
  Mesh mesh;
  WarningSink log;
  generateMesh(model, {}, 2, mesh, log);
  ASSERT_EQ(log.warnings.size(), 1u);
  EXPECT_EQ(log.warnings[0],
            "surface 1 is meshed as if not transfinite: transfinite surface: sides 1 and 3 have "
            "7 and 6 nodes; they must have as many");
  EXPECT_NEAR(faceArea(mesh, 1), 2.0, 1e-12);
  EXPECT_EQ(mesh.find({1, 3})->nodes.size(), 4u);  // 6 nodes with both ends
  const MeshCheckReport report = checkMesh(model, mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
}

TEST(TransfiniteSurface, ExplicitCornersSplitALongerLoop) {
  PolygonModelBuilder b;
  // Five points: the bottom side is two curves.
  const std::vector<int> loop = b.polygon({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {0, 1}}, 0.1);
  b.surface({loop});
  auto& c = b.model.meshConstraints();
  c.transfiniteCurves[loop[0]] = law(3, TransfiniteCurve::Law::Progression, 1);
  c.transfiniteCurves[loop[1]] = law(3, TransfiniteCurve::Law::Progression, 1);
  c.transfiniteCurves[loop[2]] = law(4, TransfiniteCurve::Law::Progression, 1);
  c.transfiniteCurves[loop[3]] = law(5, TransfiniteCurve::Law::Progression, 1);
  c.transfiniteCurves[loop[4]] = law(4, TransfiniteCurve::Law::Progression, 1);
  c.transfiniteSurfaces[1].corners = {1, 3, 4, 5};
  Mesh mesh;
  SilentSink log;
  generateMesh(b.model, {}, 2, mesh, log);
  EXPECT_EQ(mesh.elementCount(2), 2u * 4 * 3);
  const MeshCheckReport report = checkMesh(b.model, mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
}

}  // namespace
}  // namespace geomesh

namespace geomesh {
namespace {

// A patch of the unit sphere from the equator to latitude 1.2, a quarter turn wide.
Model spherePatch() {
  Model model;
  const auto sphere = std::make_shared<testing::SphereGeometry>();
  const double kPi = testing::SphereGeometry::kPi;
  const std::vector<Vec2> corners{{0, 0}, {kPi / 2, 0}, {kPi / 2, 1.2}, {0, 1.2}};
  ModelSurface patch{1, {{}}, sphere, {}, {}};
  for (int k = 0; k < 4; ++k) model.addPoint({k + 1, sphere->point(corners[k]), 0.1});
  for (int k = 0; k < 4; ++k) {
    model.addCurve({k + 1, k + 1, (k + 1) % 4 + 1,
                    std::make_shared<testing::IsoCurve>(sphere, corners[k], corners[(k + 1) % 4])});
    patch.loops[0].push_back(k + 1);
    model.meshConstraints().transfiniteCurves[k + 1] =
        law(k % 2 == 0 ? 11 : 7, TransfiniteCurve::Law::Progression, 1);
  }
  model.addSurface(patch);
  model.meshConstraints().transfiniteSurfaces[1] = {};
  return model;
}

TEST(TransfiniteSurface, CurvedSurfaceGridLiesOnTheSurface) {
  for (bool recombine : {false, true}) {
    Model model = spherePatch();
    if (recombine) model.meshConstraints().recombinedSurfaces[1] = 45;
    Mesh mesh;
    SilentSink log;
    generateMesh(model, {}, 2, mesh, log);
    EXPECT_EQ(mesh.elementCount(2), (recombine ? 1u : 2u) * 10 * 6);
    const double exactArea = testing::SphereGeometry::kPi / 2 * std::sin(1.2);
    EXPECT_NEAR(faceArea(mesh, 1), exactArea, 0.02 * exactArea);
    const MeshCheckReport report = checkMesh(model, mesh);  // orientation: outward normals
    EXPECT_TRUE(report.ok()) << report.summary();
  }
}

TEST(Recombine, CurvedSurfaceKeepsQuadranglesOnIt) {
  Model model = spherePatch();
  model.meshConstraints().transfiniteSurfaces.clear();
  model.meshConstraints().transfiniteCurves.clear();
  model.meshConstraints().recombinedSurfaces[1] = 45;
  Mesh mesh;
  SilentSink log;
  generateMesh(model, {}, 2, mesh, log);
  EXPECT_GT(mesh.find({2, 1})->findBlock(ElementType::Quad4)->size(), 50u);
  const MeshCheckReport report = checkMesh(model, mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
}

}  // namespace
}  // namespace geomesh

namespace geomesh {
namespace {

// Whether a triangle of surface 1 has an edge between the nodes at a and b.
bool hasEdge(const Mesh& mesh, Vec3 a, Vec3 b) {
  const ElementBlock* t = mesh.find({2, 1})->findBlock(ElementType::Triangle3);
  for (std::size_t e = 0; e < t->size(); ++e) {
    const auto n = t->element(e);
    int found = 0;
    for (int k = 0; k < 3; ++k)
      found += distance(mesh.node(n[k]), a) < 1e-9 || distance(mesh.node(n[k]), b) < 1e-9;
    if (found == 2) return true;
  }
  return false;
}

TEST(TransfiniteSurface, DiagonalsFollowTheArrangement) {
  using A = TransfiniteSurface::Arrangement;
  // Cells of the 2 x 1 rectangle with 4 x 3 nodes are 2/3 wide and 1/2 high. First cell
  // (0, 0) and the one above it (0, 1): true for a "left" diagonal (bottom right to top left).
  const struct {
    A arrangement;
    bool firstLeft, aboveLeft;
  } cases[] = {{A::Left, true, true},
               {A::Right, false, false},
               {A::AlternateLeft, false, true},
               {A::AlternateRight, true, false}};
  for (const auto& c : cases) {
    Model model = rectangle(4, 3);
    model.meshConstraints().transfiniteSurfaces[1].arrangement = c.arrangement;
    model.meshConstraints().transfiniteCurves[3].coefficient = 1;
    model.meshConstraints().transfiniteCurves[4] = law(3, TransfiniteCurve::Law::Progression, 1);
    Mesh mesh;
    SilentSink log;
    generateMesh(model, {}, 2, mesh, log);
    const double w = 2.0 / 3;
    EXPECT_EQ(hasEdge(mesh, {w, 0, 0}, {0, 0.5, 0}), c.firstLeft);
    EXPECT_EQ(hasEdge(mesh, {0, 0, 0}, {w, 0.5, 0}), !c.firstLeft);
    EXPECT_EQ(hasEdge(mesh, {w, 0.5, 0}, {0, 1, 0}), c.aboveLeft);
    EXPECT_EQ(hasEdge(mesh, {0, 0.5, 0}, {w, 1, 0}), !c.aboveLeft);
  }
}

}  // namespace
}  // namespace geomesh
