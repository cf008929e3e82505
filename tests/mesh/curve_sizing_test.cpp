// Sizes from curvature (Mesh.MeshSizeFromCurvature) and the minimum node counts per curve kind
// (Mesh.MinimumCircleNodes, Mesh.MinimumCurveNodes). Expected counts are those of the
// reference implementation on the same shapes.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "kernel/geo/ellipse_arc_geometry.h"
#include "kernel/geo/line_geometry.h"
#include "kernel/geo/spline_geometry.h"
#include "mesh/curves/curve_mesher.h"
#include "mesh/pipeline/generate.h"
#include "mesh/sizes/size_rules.h"
#include "mesh_test_models.h"

namespace geomesh {
namespace {

using testing::PolygonModelBuilder;
constexpr double kPi = testing::CircleGeometry::kPi;

Mesh meshCurves(const Model& model, const MeshOptions& options) {
  Mesh mesh;
  SilentSink log;
  generateMesh(model, options, 1, mesh, log);
  return mesh;
}

std::size_t segments(const Mesh& mesh, int curve) {
  return mesh.find({1, curve})->elementCount();
}

MeshOptions curvature(double elementsPerTwoPi) {
  MeshOptions options;
  options.sizeFromCurvature = elementsPerTwoPi;
  return options;
}

int addCurve(Model& model, int tag, int start, int end,
             std::shared_ptr<const CurveGeometry> geometry) {
  model.addCurve({tag, start, end, std::move(geometry)});
  return tag;
}

// The longest segment of a curve's mesh.
double longestSegment(const Model& model, const Mesh& mesh, int curve) {
  const std::vector<NodeIndex> chain = curveNodeChain(model, mesh, curve);
  double longest = 0;
  for (std::size_t k = 0; k + 1 < chain.size(); ++k)
    longest = std::max(longest, distance(mesh.node(chain[k]), mesh.node(chain[k + 1])));
  return longest;
}

TEST(CurveSizing, UnitCircleGetsTheRequestedElementsPerTurn) {
  PolygonModelBuilder b;
  b.circle({0, 0}, 1, 1);
  EXPECT_EQ(segments(meshCurves(b.model, {}), 1), 7u);  // 2*pi / 1, rounded up
  EXPECT_EQ(segments(meshCurves(b.model, curvature(20)), 1), 20u);
  EXPECT_EQ(segments(meshCurves(b.model, curvature(40)), 1), 40u);
}

TEST(CurveSizing, CurvatureSizeIsClampedAndScaledLikeOtherSizes) {
  PolygonModelBuilder b;
  b.circle({0, 0}, 1, 1);
  MeshOptions options = curvature(20);
  options.sizeMin = 0.5;  // 2*pi / 0.5 = 12.6
  EXPECT_EQ(segments(meshCurves(b.model, options), 1), 13u);
  options = curvature(20);
  options.sizeMax = 0.1;
  EXPECT_EQ(segments(meshCurves(b.model, options), 1), 63u);
  options = curvature(20);
  options.sizeFactor = 0.5;
  EXPECT_EQ(segments(meshCurves(b.model, options), 1), 40u);
  options = curvature(20);
  options.sizeFromPoints = false;
  EXPECT_EQ(segments(meshCurves(b.model, options), 1), 20u);
}

TEST(CurveSizing, CurvatureBoundsTheSizeOfPointNodes) {
  // A quarter circle and a straight segment leaving its start point, size 1 everywhere: the
  // arc gets 5 segments; the shared point's node asks for 2*pi/20, the segment's far end for 1.
  PolygonModelBuilder b;
  const int arc = b.arc({0, 0}, 1, 0, kPi / 2, 1);
  const int far = b.point(3, 0, 1);
  b.line(1, far);
  const MeshOptions options = curvature(20);
  EXPECT_EQ(segments(meshCurves(b.model, options), arc), 5u);
  const SizeRules rules = SizeRules::from(b.model, options);
  EXPECT_NEAR(rules.pointSize(*b.model.point(1)), 2 * kPi / 20, 1e-9);
  EXPECT_NEAR(rules.pointSize(*b.model.point(far)), 1, 1e-15);
}

TEST(CurveSizing, StraightCurvesAreUnaffected) {
  PolygonModelBuilder b;
  b.line(b.point(0, 0, 0.3), b.point(2, 0, 0.3));
  EXPECT_EQ(segments(meshCurves(b.model, curvature(20)), 1), 7u);
  EXPECT_EQ(segments(meshCurves(b.model, {}), 1), 7u);
}

TEST(CurveSizing, EllipseIsRefinedWhereItBendsMost) {
  // x^2/4 + y^2 = 1: curvature 2 at (+-2, 0), 1/4 at (0, +-1).
  Model model;
  model.addPoint({1, {2, 0, 0}, 1});
  addCurve(model, 1, 1, 1,
           std::make_shared<EllipseArcGeometry>(Vec3{}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, 2, 1, 0,
                                                2 * kPi));
  const Mesh mesh = meshCurves(model, curvature(20));
  const std::vector<NodeIndex> chain = curveNodeChain(model, mesh, 1);
  // The integral of N * curvature / (2 pi) is N = 20 over the whole turn; the flat parts, where
  // the point size 1 is smaller than the curvature bound, add a little.
  EXPECT_GE(chain.size() - 1, 20u);
  EXPECT_LE(chain.size() - 1, 22u);
  for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
    const Vec3 a = mesh.node(chain[k]), c = mesh.node(chain[k + 1]);
    const double length = distance(a, c);
    // Near the sharp ends the segments are bounded by 2*pi / (20 * 2) = 0.157 (plus the
    // chord's slack), at the flat sides by the point size 1.
    if (std::abs(a.x) > 1.9 && std::abs(c.x) > 1.9) {
      EXPECT_LT(length, 0.2) << k;
    }
    EXPECT_LT(length, 1.0) << k;
  }
}

TEST(CurveSizing, SizeOf1e22IsNoSizeAtAll) {
  // Scripts saved by the reference's interface write 1e22 for "no size": such points take the
  // default size as points without a size do (here, along the x axis only, a tenth of the
  // diagonal of a 10 x 20 box: the reference's 5 segments).
  PolygonModelBuilder unset, none;
  unset.line(unset.point(0, 0, 1e22), unset.point(10, 0, 1e22));
  none.line(none.point(0, 0, 0), none.point(10, 0, 0));
  const std::size_t expected = segments(meshCurves(none.model, {}), 1);
  EXPECT_EQ(expected, 5u);
  EXPECT_EQ(segments(meshCurves(unset.model, {}), 1), expected);
  const SizeRules rules = SizeRules::from(unset.model, {});
  EXPECT_NEAR(rules.pointSize(*unset.model.point(1)), std::sqrt(5.0), 1e-12);
}

TEST(CurveSizing, DefaultSizeFollowsTheReferencesBox) {
  // Measured on the reference: a tenth of the diagonal; an x or y extent of zero counts as
  // twice the diagonal (a line along x of length 1 gets 5 segments, along z 4, a model in the
  // x-z plane 1 x 0.5 a size of 0.25); a zero z extent does not count.
  auto box = [](Vec3 a, Vec3 b) {
    BoundingBox box;
    box.include(a);
    box.include(b);
    return box;
  };
  EXPECT_NEAR(defaultSizeOf(box({0, 0, 0}, {10, 3, 0})), std::sqrt(109.0) / 10, 1e-12);
  EXPECT_NEAR(defaultSizeOf(box({0, 0, 0}, {1, 1, 1})), std::sqrt(3.0) / 10, 1e-12);
  EXPECT_NEAR(defaultSizeOf(box({0, 0, 0}, {1, 0, 0})), std::sqrt(5.0) / 10, 1e-12);
  EXPECT_NEAR(defaultSizeOf(box({0, 0, 0}, {0, 0, 1})), 0.3, 1e-12);
  EXPECT_NEAR(defaultSizeOf(box({0, 0, 0}, {1, 0, 0.5})), 0.25, 1e-12);
  EXPECT_EQ(defaultSizeOf(box({1, 1, 1}, {1, 1, 1})), 1.0);
  EXPECT_EQ(defaultSizeOf(BoundingBox{}), 1.0);
}

TEST(CurveSizing, OffMeansNoCurvatureBound) {
  SizeRules rules;
  EXPECT_GT(rules.curvatureSize(1), 1e20);
  rules.elementsPerTwoPi = 10;
  EXPECT_NEAR(rules.curvatureSize(2), kPi / 10, 1e-15);
  EXPECT_GT(rules.curvatureSize(0), 1e20);
}

TEST(MinimumSegments, FullCircleGetsMinimumCircleNodes) {
  PolygonModelBuilder b;
  b.circle({0, 0}, 1, 100);
  EXPECT_EQ(segments(meshCurves(b.model, {}), 1), 7u);
  MeshOptions options;
  options.minCircleNodes = 12;
  EXPECT_EQ(segments(meshCurves(b.model, options), 1), 12u);
}

TEST(MinimumSegments, ArcsGetTheirShareOfMinimumCircleNodes) {
  PolygonModelBuilder b;
  b.arc({0, 0}, 1, 0, kPi / 2, 100);
  MeshOptions options;
  EXPECT_EQ(segments(meshCurves(b.model, options), 1), 2u);  // 7/4, rounded up
  options.minCircleNodes = 20;
  EXPECT_EQ(segments(meshCurves(b.model, options), 1), 5u);
  options.minCircleNodes = 2;
  EXPECT_EQ(segments(meshCurves(b.model, options), 1), 1u);
}

TEST(MinimumSegments, EllipseArcsCountAsArcs) {
  Model model;
  model.addPoint({1, {2, 0, 0}, 100});
  model.addPoint({2, {0, 1, 0}, 100});
  addCurve(model, 1, 1, 2,
           std::make_shared<EllipseArcGeometry>(Vec3{}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, 2, 1, 0,
                                                kPi / 2));
  MeshOptions options;
  options.minCircleNodes = 30;
  EXPECT_EQ(segments(meshCurves(model, options), 1), 8u);
  options.minCurveNodes = 20;  // not a "curve"
  options.minCircleNodes = 7;
  EXPECT_EQ(segments(meshCurves(model, options), 1), 2u);
}

TEST(MinimumSegments, SplinesGetMinimumCurveNodesEvenWhenStraight) {
  Model model;
  model.addPoint({1, {0, 0, 0}, 100});
  model.addPoint({2, {2, 0, 0}, 100});
  model.addPoint({3, {0, 5, 0}, 100});
  model.addPoint({4, {3, 6, 0}, 100});
  addCurve(model, 1, 1, 2,
           std::make_shared<CatmullRomGeometry>(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}));
  addCurve(model, 2, 3, 4,
           std::make_shared<CatmullRomGeometry>(
               std::vector<Vec3>{{0, 5, 0}, {1, 6, 0}, {2, 5, 0}, {3, 6, 0}}));
  MeshOptions options;
  Mesh mesh = meshCurves(model, options);
  EXPECT_EQ(segments(mesh, 1), 2u);
  EXPECT_EQ(segments(mesh, 2), 2u);
  options.minCurveNodes = 10;
  mesh = meshCurves(model, options);
  EXPECT_EQ(segments(mesh, 1), 9u);
  EXPECT_EQ(segments(mesh, 2), 9u);
}

TEST(MinimumSegments, StraightLinesKeepOneSegment) {
  Model model;
  model.addPoint({1, {0, 0, 0}, 100});
  model.addPoint({2, {1, 0, 0}, 100});
  addCurve(model, 1, 1, 2, std::make_shared<LineGeometry>(Vec3{0, 0, 0}, Vec3{1, 0, 0}));
  PolygonModelBuilder b;  // a straight curve of unknown kind
  b.line(b.point(0, 0, 100), b.point(1, 0, 100));
  MeshOptions options;
  options.minCurveNodes = 10;
  options.minCircleNodes = 50;
  EXPECT_EQ(segments(meshCurves(model, options), 1), 1u);
  EXPECT_EQ(segments(meshCurves(b.model, options), 1), 1u);
}

TEST(MinimumSegments, ClosedCurvesGetAtLeastThree) {
  Model model;
  model.addPoint({1, {0, 0, 0}, 100});
  addCurve(model, 1, 1, 1,
           std::make_shared<CatmullRomGeometry>(
               std::vector<Vec3>{{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {1, -1, 0}, {0, 0, 0}}));
  const Mesh mesh = meshCurves(model, {});
  EXPECT_EQ(segments(mesh, 1), 3u);
  EXPECT_GT(longestSegment(model, mesh, 1), 0);
}

// The bend bound: left alone while an element spans at most a quarter turn (a fillet of radius
// 0.08 under size 0.12), applied beyond (a rod of radius 0.02 under size 0.1), six elements per
// turn then, never below a tenth of the largest size.
TEST(BendSize, AppliesOnlyWhereElementsWouldWrapRoundTheBend) {
  EXPECT_FALSE(sizesOutgrowBend(1 / 0.08, 0.12));
  EXPECT_TRUE(sizesOutgrowBend(1 / 0.02, 0.1));
  EXPECT_FALSE(sizesOutgrowBend(0, 1e22));
  EXPECT_NEAR(bendSize(1 / 0.02, 0.1), 2 * std::numbers::pi * 0.02 / 6, 1e-12);
  EXPECT_NEAR(bendSize(1e6, 0.1), 0.01, 1e-12);
  EXPECT_GT(bendSize(0, 0.1), 1e20);
}

}  // namespace
}  // namespace geomesh
