// Tests of the curve mesher: segment counts, graded sizes, clamping, circle nodes, chaining.
#include "mesh/curves/curve_mesher.h"

#include <gtest/gtest.h>

#include "mesh/pipeline/generate.h"
#include "mesh_test_models.h"

namespace geomesh {
namespace {

using testing::PolygonModelBuilder;

// The nodes of curve 1 of the mesh of `model`, from start to end.
std::vector<Vec3> curveNodes(const Model& model, const MeshOptions& options = {}) {
  Mesh mesh;
  SilentSink log;
  generateMesh(model, options, 1, mesh, log);
  std::vector<Vec3> nodes;
  for (NodeIndex n : curveNodeChain(model, mesh, 1)) nodes.push_back(mesh.node(n));
  return nodes;
}

int segmentsOfUnitLine(double startSize, double endSize, const MeshOptions& options = {}) {
  PolygonModelBuilder b;
  const int start = b.point(0, 0, startSize);
  b.line(start, b.point(1, 0, endSize));
  return static_cast<int>(curveNodes(b.model, options).size()) - 1;
}

TEST(CurveMesher, UniformSizeGivesEqualSegments) {
  PolygonModelBuilder b;
  const int start = b.point(0, 0, 0.1);
  b.line(start, b.point(0, 2, 0.1));
  const std::vector<Vec3> nodes = curveNodes(b.model);
  ASSERT_EQ(nodes.size(), 21u);
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    EXPECT_NEAR(nodes[k].x, 0, 1e-15);
    EXPECT_NEAR(nodes[k].y, 0.1 * static_cast<double>(k), 1e-9);
  }
}

TEST(CurveMesher, SegmentCountRoundsUpWithOnePercentSlack) {
  EXPECT_EQ(segmentsOfUnitLine(0.1, 0.1), 10);
  EXPECT_EQ(segmentsOfUnitLine(0.3, 0.3), 4);      // 3.33
  EXPECT_EQ(segmentsOfUnitLine(0.4, 0.4), 3);      // 2.5
  EXPECT_EQ(segmentsOfUnitLine(0.6, 0.6), 2);      // 1.67
  EXPECT_EQ(segmentsOfUnitLine(0.99, 0.99), 2);    // 1.0101
  EXPECT_EQ(segmentsOfUnitLine(0.995, 0.995), 1);  // 1.005
  EXPECT_EQ(segmentsOfUnitLine(5, 5), 1);
}

TEST(CurveMesher, GradedSizeIntegratesOneOverSize) {
  // Integral of 1 / (0.01 + 0.09 x) over [0, 1] = ln(10) / 0.09 = 25.58.
  EXPECT_EQ(segmentsOfUnitLine(0.01, 0.1), 26);
  PolygonModelBuilder b;
  const int start = b.point(0, 0, 0.01);
  b.line(start, b.point(1, 0, 0.1));
  const std::vector<Vec3> nodes = curveNodes(b.model);
  // Equal increments of the integral: x_k = 0.01 (10^(k/n) - 1) / 0.09.
  const double n = static_cast<double>(nodes.size() - 1);
  for (std::size_t k = 0; k < nodes.size(); ++k)
    EXPECT_NEAR(nodes[k].x, 0.01 * (std::pow(10.0, static_cast<double>(k) / n) - 1) / 0.09, 1e-6);
  for (std::size_t k = 2; k < nodes.size(); ++k)
    EXPECT_GT(nodes[k].x - nodes[k - 1].x, nodes[k - 1].x - nodes[k - 2].x);
}

TEST(CurveMesher, SizesAreClampedThenScaled) {
  MeshOptions atLeast;
  atLeast.sizeMin = 0.2;
  EXPECT_EQ(segmentsOfUnitLine(0.1, 0.1, atLeast), 5);
  MeshOptions atMost;
  atMost.sizeMax = 0.05;
  EXPECT_EQ(segmentsOfUnitLine(0.1, 0.1, atMost), 20);
  MeshOptions scaled;
  scaled.sizeFactor = 2;
  EXPECT_EQ(segmentsOfUnitLine(0.1, 0.1, scaled), 5);
  MeshOptions both;
  both.sizeMin = 0.2;
  both.sizeFactor = 2;
  EXPECT_EQ(segmentsOfUnitLine(0.1, 0.1, both), 3);  // 0.2 * 2 = 0.4
  MeshOptions clampedGrading;
  clampedGrading.sizeMin = 0.05;
  // 1 / size with size = max(0.01 + 0.09 x, 0.05): 0.444 / 0.05 + ln(0.1 / 0.05) / 0.09.
  EXPECT_EQ(segmentsOfUnitLine(0.01, 0.1, clampedGrading), 17);
}

TEST(CurveMesher, AbsurdlySmallSizeIsAnErrorNotAnOverflow) {
  try {
    segmentsOfUnitLine(1e-12, 1e-12);
    FAIL() << "expected MeshError";
  } catch (const MeshError& e) {
    EXPECT_EQ(e.entity, (EntityId{1, 1}));
  }
}

TEST(CurveMesher, IgnoringPointSizesLeavesOnlySizeMax) {
  MeshOptions ignore;
  ignore.sizeFromPoints = false;
  EXPECT_EQ(segmentsOfUnitLine(0.1, 0.1, ignore), 1);
  ignore.sizeMax = 0.25;
  EXPECT_EQ(segmentsOfUnitLine(0.1, 0.1, ignore), 4);
}

TEST(CurveMesher, PointsWithoutSizeUseATenthOfTheModelDiagonal) {
  PolygonModelBuilder b;
  b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0);  // diagonal sqrt(2): size 0.1414
  Mesh mesh;
  SilentSink log;
  generateMesh(b.model, {}, 1, mesh, log);
  for (int c = 1; c <= 4; ++c) EXPECT_EQ(mesh.find({1, c})->elementCount(), 8u);
  b.model.addPoint({10, {0, 3, 0}, 0});  // diagonal sqrt(10): size 0.316
  generateMesh(b.model, {}, 1, mesh, log);
  EXPECT_EQ(mesh.find({1, 1})->elementCount(), 4u);
}

TEST(CurveMesher, CurveWithOneSizedEndStaysCoarse) {
  // The unsized end asks for an unbounded size: the size grows at once from the sized end.
  EXPECT_EQ(segmentsOfUnitLine(0.1, 0), 1);
  EXPECT_EQ(segmentsOfUnitLine(0, 0.01), 1);
  MeshOptions bounded;
  bounded.sizeMax = 0.2;
  EXPECT_EQ(segmentsOfUnitLine(0.1, 0, bounded), 5);
  // A square with one sized corner: its two sides are coarse, the others use the default.
  PolygonModelBuilder b;
  const std::vector<int> corners{b.point(0, 0, 0.05), b.point(1, 0), b.point(1, 1), b.point(0, 1)};
  for (int k = 0; k < 4; ++k) b.line(corners[k], corners[(k + 1) % 4]);
  Mesh mesh;
  SilentSink log;
  generateMesh(b.model, {}, 1, mesh, log);
  const std::size_t expected[4] = {1, 8, 8, 1};
  for (int c = 1; c <= 4; ++c) EXPECT_EQ(mesh.find({1, c})->elementCount(), expected[c - 1]);
}

TEST(CurveMesher, ClosedCircleGetsMinimumCircleNodesSegments) {
  PolygonModelBuilder b;
  b.circle({0, 0}, 1, 100);
  Mesh mesh;
  SilentSink log;
  generateMesh(b.model, {}, 1, mesh, log);
  const EntityMesh* em = mesh.find({1, 1});
  EXPECT_EQ(em->elementCount(), 7u);  // Mesh.MinimumCircleNodes
  const ElementBlock* lines = em->findBlock(ElementType::Line2);
  EXPECT_EQ(lines->nodes.front(), lines->nodes.back());
}

TEST(CurveMesher, ArcsGetMinimumCircleNodesPerFullTurnAtLeast) {
  // Arcs of 20, 40, ..., 160 degrees with a huge size: ceil(7 angle / 360), with 1% slack.
  PolygonModelBuilder b;
  const double degree = testing::CircleGeometry::kPi / 180;
  for (int k = 1; k <= 8; ++k) b.arc({0, 0}, 1, 0, 20 * k * degree, 100);
  Mesh mesh;
  SilentSink log;
  generateMesh(b.model, {}, 1, mesh, log);
  const std::size_t expected[8] = {1, 1, 2, 2, 2, 3, 3, 4};
  for (int k = 1; k <= 8; ++k) EXPECT_EQ(mesh.find({1, k})->elementCount(), expected[k - 1]) << k;
  // A straight segment keeps one.
  EXPECT_EQ(segmentsOfUnitLine(100, 100), 1);
}

TEST(CurveMesher, CircleNodesLieOnTheCurveAtEqualArcLength) {
  PolygonModelBuilder b;
  b.circle({0, 0}, 1, 0.1);  // circumference 6.283: 63 segments
  Mesh mesh;
  SilentSink log;
  generateMesh(b.model, {}, 1, mesh, log);
  const EntityMesh* em = mesh.find({1, 1});
  ASSERT_EQ(em->elementCount(), 63u);
  ASSERT_EQ(em->parametric.size(), em->nodes.size());
  for (std::size_t k = 0; k < em->nodes.size(); ++k) {
    EXPECT_NEAR(norm(mesh.node(em->nodes[k])), 1, 1e-12);
    EXPECT_NEAR(em->parametric[k], 2 * testing::CircleGeometry::kPi * (k + 1) / 63.0, 1e-6);
  }
}

TEST(CurveMesher, ElementsChainFromStartToEndWithIncreasingParameters) {
  PolygonModelBuilder b;
  const int start = b.point(1, 1, 0.05);
  b.line(start, b.point(0, 0, 0.2));
  Mesh mesh;
  SilentSink log;
  generateMesh(b.model, {}, 1, mesh, log);
  const EntityMesh* em = mesh.find({1, 1});
  const ElementBlock* lines = em->findBlock(ElementType::Line2);
  EXPECT_EQ(lines->nodes.front(), mesh.find({0, 1})->nodes[0]);
  EXPECT_EQ(lines->nodes.back(), mesh.find({0, 2})->nodes[0]);
  for (std::size_t e = 1; e < lines->size(); ++e)
    EXPECT_EQ(lines->element(e)[0], lines->element(e - 1)[1]);
  for (std::size_t k = 1; k < em->parametric.size(); ++k)
    EXPECT_GT(em->parametric[k], em->parametric[k - 1]);
}

}  // namespace
}  // namespace geomesh
