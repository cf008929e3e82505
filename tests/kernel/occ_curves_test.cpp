// The OpenCASCADE factory's points, curves, loops, surfaces and volumes from boundaries.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "kernel/geometry_error.h"
#include "kernel/occ/occ_factory.h"
#include "tests/kernel/kernel_test_helpers.h"

namespace geomesh {
namespace {

constexpr double kPi = std::numbers::pi;

// A 2 x 2 square with a round hole of radius 0.5 made of four quarter circles, counter-clockwise.
OccFactory squareWithHole() {
  OccFactory occ;
  occ.addPoint(1, {0, 0, 0}, 0.1);
  occ.addPoint(2, {2, 0, 0}, 0);
  occ.addPoint(3, {2, 2, 0}, 0);
  occ.addPoint(4, {0, 2, 0}, 0);
  for (int i = 1; i <= 4; ++i) occ.addLine(i, i, i % 4 + 1);
  occ.addPoint(5, {1, 1, 0}, 0);
  occ.addPoint(6, {1.5, 1, 0}, 0);
  occ.addPoint(7, {1, 1.5, 0}, 0);
  occ.addPoint(8, {0.5, 1, 0}, 0);
  occ.addPoint(9, {1, 0.5, 0}, 0);
  for (int i = 0; i < 4; ++i) occ.addCircleArc(5 + i, 6 + i, 5, 6 + (i + 1) % 4);
  occ.addCurveLoop(1, {1, 2, 3, 4});
  occ.addCurveLoop(2, {5, 6, 7, 8});
  occ.addPlaneSurface(1, {1, 2});
  return occ;
}

TEST(OccCurves, PlaneSurfaceWithHole) {
  OccFactory occ = squareWithHole();
  EXPECT_NEAR(occ.area(1), 4 - kPi / 4, 1e-9);
  EXPECT_NEAR(occ.length(5), kPi / 4, 1e-9);
  std::vector<int> edges;
  for (const EntityId& e : occ.boundary({{2, 1}}, false)) edges.push_back(e.tag);
  EXPECT_EQ(edges, (std::vector<int>{1, 2, 3, 4, 8, 7, 6, 5}));  // as the reference lists them
  EXPECT_EQ(occ.maxTag(OccFactory::kCurveLoop), 2);
  Model model;
  occ.synchronize(model);
  EXPECT_EQ(model.point(1)->meshSize, 0.1);
  EXPECT_EQ(model.surface(1)->loops.size(), 2u);
}

TEST(OccCurves, ArcsSplinesAndBeziers) {
  OccFactory occ;
  occ.addPoint(10, {5, 0, 0}, 0);
  occ.addPoint(11, {6, 0, 0}, 0);
  occ.addPoint(12, {5, 1, 0}, 0);
  occ.addPoint(13, {7, 1, 0}, 0);
  occ.addPoint(14, {5, 0.5, 0}, 0);
  occ.addEllipseArc(20, 11, 10, 11, 14);  // a quarter of ellipse, radii 1 and 0.5
  occ.addSpline(21, {10, 11, 13, 12});
  occ.addBSpline(22, {10, 11, 13, 12});
  occ.addBezier(23, {10, 11, 13, 12});
  EXPECT_NEAR(occ.length(20), 1.2110560275684594, 1e-9);
  for (int c : {21, 22, 23}) {
    const std::vector<EntityId> ends = occ.boundary({{1, c}}, false);
    EXPECT_EQ(ends, (std::vector<EntityId>{{0, 10}, {0, 12}}));
  }
  EXPECT_GT(occ.length(21), occ.length(22));  // through the points vs. guided by them
  EXPECT_EQ(occ.boundary({{1, -21}}, false), (std::vector<EntityId>{{0, 12}, {0, 10}}));
}

// The curve's point halfway through its parameter range.
Vec3 midpoint(const Model& model, int curve) {
  const CurveGeometry& geometry = *model.curve(curve)->geometry;
  return geometry.point((geometry.range().min + geometry.range().max) / 2);
}

// The figures are the reference's for the same curves.
TEST(OccCurves, ClosedBSplineIsPeriodicWithAVertexOfItsOwn) {
  OccFactory occ;
  occ.addPoint(1, {1, 0, 0}, 0.1);
  occ.addPoint(2, {0, 1, 0}, 0.5);
  occ.addPoint(3, {-1, 0, 0}, 0.5);
  occ.addPoint(4, {0, -1, 0}, 0.5);
  occ.addBSpline(1, {1, 2, 3, 4, 1});
  occ.addCurveLoop(1, {1});
  occ.addPlaneSurface(1, {1});
  EXPECT_NEAR(occ.length(1), 4.1303146248640425, 1e-9);
  EXPECT_NEAR(occ.area(1), 1.3555830934527089, 1e-9);
  Model model;
  occ.synchronize(model);
  const ModelCurve& curve = *model.curve(1);
  EXPECT_EQ(curve.startPoint, 5);
  EXPECT_EQ(curve.endPoint, 5);
  expectNear(model.point(5)->xyz, {0, 2.0 / 3, 0});
  EXPECT_EQ(model.point(5)->meshSize, 0.1);  // point 1's
  EXPECT_NE(model.point(1), nullptr);        // left apart
  EXPECT_EQ(curve.geometry->range().min, 0);
  EXPECT_EQ(curve.geometry->range().max, 4);  // one knot span per distinct point
  expectNear(curve.geometry->point(0.5), {-11.0 / 24, 11.0 / 24, 0});  // cubic
}

// The degree is 3, or the number of distinct points when smaller: the curve's vertex, at
// parameter 0, tells which.
TEST(OccCurves, ClosedBSplineDegree) {
  OccFactory occ;
  occ.addPoint(6, {3, 0, 0}, 0);
  occ.addPoint(7, {4, 1, 0}, 0);
  occ.addPoint(8, {5, -0.5, 0}, 0);
  occ.addBSpline(2, {6, 7, 8, 6});
  occ.addPoint(10, {3, 3, 0}, 0);
  occ.addPoint(11, {4, 4, 1}, 0);
  occ.addBSpline(3, {10, 11, 10});
  Model model;
  occ.synchronize(model);
  EXPECT_EQ(model.curve(2)->startPoint, 9);
  expectNear(model.point(9)->xyz, {4, 3.5 / 6, 0});  // (P6 + 4 P7 + P8) / 6
  EXPECT_EQ(model.point(9)->meshSize, 0);            // point 6 has none
  EXPECT_EQ(model.curve(3)->startPoint, 12);
  expectNear(model.point(12)->xyz, {3.5, 3.5, 0.5});  // (P10 + P11) / 2
}

TEST(OccCurves, ClosedSplineAndBezier) {
  OccFactory occ;
  occ.addPoint(1, {1, 0, 0}, 0);
  occ.addPoint(2, {0, 1, 0}, 0);
  occ.addPoint(3, {-1, 0.2, 0}, 0);
  occ.addPoint(4, {0, -1, 0.3}, 0);
  occ.addSpline(1, {1, 2, 3, 4, 1});  // through its points: closed at point 1
  EXPECT_EQ(occ.boundary({{1, 1}}, false), (std::vector<EntityId>{{0, 1}, {0, 1}}));
  EXPECT_NEAR(occ.length(1), 6.471729228146969, 1e-9);
  EXPECT_THROW(occ.addBezier(2, {1, 2, 3, 4, 1}), GeometryError);
  EXPECT_THROW(occ.addBezier(2, {1, 2, 1}), GeometryError);
}

// Ends exactly opposite: the plane z = constant of the center, turning clockwise seen from +z.
TEST(OccCurves, HalfCircleTurnsClockwiseAboutZ) {
  OccFactory occ;
  occ.addPoint(1, {0, 0, 0}, 0);
  occ.addPoint(2, {0, -1, 0}, 0);
  occ.addPoint(3, {0, 1, 0}, 0);
  occ.addCircleArc(1, 2, 1, 3);
  occ.addCircleArc(2, 3, 1, 2);
  occ.addPoint(10, {10, 20, 3}, 0);
  occ.addPoint(11, {11, 21, 3}, 0);
  occ.addPoint(12, {9, 19, 3}, 0);
  occ.addCircleArc(3, 11, 10, 12);
  // Within the vertex tolerance of the plane.
  occ.addPoint(13, {1, 0, 1e-9}, 0);
  occ.addPoint(14, {-1, 0, -1e-9}, 0);
  occ.addCircleArc(4, 13, 1, 14);
  // Sin(Pi) is not 0: these ends are not exactly opposite, so the points' plane and sense hold.
  occ.addPoint(15, {1, 0, 5}, 0);
  occ.addPoint(16, {0, 0, 5}, 0);
  occ.addPoint(17, {std::cos(kPi), std::sin(kPi), 5}, 0);
  occ.addCircleArc(5, 15, 16, 17);
  Model model;
  occ.synchronize(model);
  expectNear(midpoint(model, 1), {-1, 0, 0});
  expectNear(midpoint(model, 2), {1, 0, 0});
  expectNear(midpoint(model, 3), {11, 19, 3}, 1e-9);
  expectNear(midpoint(model, 4), {0, -1, 0}, 1e-9);
  expectNear(midpoint(model, 5), {0, 1, 5});
  for (int c = 1; c <= 5; ++c) EXPECT_NEAR(occ.length(c), c == 3 ? kPi * std::sqrt(2) : kPi, 1e-9);
}

// The reference makes no half circle whose ends leave the plane z = constant of its center.
TEST(OccCurves, HalfCircleOutOfItsPlaneIsRefused) {
  OccFactory occ;
  occ.addPoint(1, {0, 0, 0}, 0);
  occ.addPoint(2, {0, 0, 1}, 0);
  occ.addPoint(3, {0, 0, -1}, 0);
  occ.addPoint(4, {1, 0, 1}, 0);
  occ.addPoint(5, {-1, 0, -1}, 0);
  EXPECT_THROW(occ.addCircleArc(1, 2, 1, 3), GeometryError);
  EXPECT_THROW(occ.addCircleArc(1, 4, 1, 5), GeometryError);
  occ.addPoint(6, {-1, 0, 1}, 0);
  occ.addCircleArc(1, 4, 1, 6);  // a quarter turn in the plane y = 0 is well defined
  EXPECT_NEAR(occ.length(1), kPi / std::sqrt(2), 1e-9);
}

// Arcs are parametrized as in the reference (whose parameter ranges these are): about their
// normal, from the angle of their start, the angles counted from the x axis opposite to the one
// OpenCASCADE picks for that normal. Fillings sample their loops at parameters.
TEST(OccCurves, ArcsParametrizedAsInTheReference) {
  OccFactory occ;
  occ.addPoint(1, {0, 0, 0}, 0);
  occ.addPoint(2, {1, 0, 0}, 0);
  occ.addPoint(3, {0, 1, 0}, 0);
  occ.addPoint(4, {-1, 0, 0}, 0);
  occ.addPoint(5, {0, -1, 0}, 0);
  occ.addPoint(6, {0.6, 0.8, 0}, 0);
  occ.addPoint(7, {0, 0, 1}, 0);
  occ.addPoint(8, {0.6, 0, 0.8}, 0);
  occ.addCircleArc(1, 2, 1, 3);
  occ.addCircleArc(2, 6, 1, 4);
  occ.addCircleArc(3, 2, 1, 4);  // half circles turn clockwise about z
  occ.addCircleArc(4, 4, 1, 2);
  occ.addCircleArc(5, 3, 1, 5);
  occ.addCircleArc(6, 2, 1, 7);
  occ.addCircleArc(7, 8, 1, 7);
  Model model;
  occ.synchronize(model);
  const double start2 = kPi + std::atan2(0.8, 0.6);  // 4.06888787 in the reference
  const double start7 = 2 * kPi - std::asin(0.6);    // 5.6396842
  const double expected[7][2] = {{kPi, 1.5 * kPi}, {start2, 2 * kPi},      {0, kPi},
                                 {kPi, 2 * kPi},   {1.5 * kPi, 2.5 * kPi}, {1.5 * kPi, 2 * kPi},
                                 {start7, 2 * kPi}};
  for (int c = 1; c <= 7; ++c) {
    const Interval range = model.curve(c)->geometry->range();
    EXPECT_NEAR(range.min, expected[c - 1][0], 1e-8) << "curve " << c;
    EXPECT_NEAR(range.max, expected[c - 1][1], 1e-8) << "curve " << c;
  }
  expectNear(model.curve(2)->geometry->point(start2), {0.6, 0.8, 0}, 1e-12);
  expectNear(midpoint(model, 3), {0, -1, 0}, 1e-12);
}

TEST(OccCurves, CubeFromItsFaces) {
  OccFactory occ;
  occ.addBox(1, {0, 0, 0}, {1, 1, 1});
  std::vector<int> faces = occ.tags(2);
  occ.addSurfaceLoop(1, faces);
  occ.addVolume(2, {1});
  EXPECT_NEAR(occ.volume(2), 1, 1e-9);
  EXPECT_EQ(occ.maxTag(2), 6);  // the faces are shared, not copied
}

TEST(OccCurves, BadInput) {
  OccFactory occ;
  occ.addPoint(1, {0, 0, 0}, 0);
  occ.addPoint(2, {1, 0, 0}, 0);
  occ.addPoint(3, {1, 1, 0}, 0);
  EXPECT_THROW(occ.addLine(1, 1, 1), GeometryError);
  EXPECT_THROW(occ.addLine(1, 1, 9), GeometryError);
  occ.addLine(1, 1, 2);
  occ.addLine(2, 2, 3);
  EXPECT_THROW(occ.addCurveLoop(1, {1, 2}), GeometryError);  // open
  EXPECT_THROW(occ.addPlaneSurface(1, {1}), GeometryError);  // no such loop
  EXPECT_THROW(occ.addPoint(1, {0, 0, 0}, 0), GeometryError);
  occ.addLine(3, 3, 1);
  occ.addCurveLoop(1, {1, 2, 3});
  occ.addPlaneSurface(1, {1});
  EXPECT_THROW(occ.addSurfaceLoop(1, {1}), GeometryError);  // not closed
  EXPECT_NEAR(occ.area(1), 0.5, 1e-12);
}

}  // namespace
}  // namespace geomesh
