// The OpenCASCADE factory's points, curves, loops, surfaces and volumes from boundaries.
#include <gtest/gtest.h>

#include <numbers>

#include "kernel/geometry_error.h"
#include "kernel/occ/occ_factory.h"
#include "tests/kernel/kernel_test_helpers.h"

namespace geomesh {
namespace {

constexpr double kPi = std::numbers::pi;

// A 2 x 2 square with a round hole of radius 0.5 made of two half circles.
OccFactory squareWithHole() {
  OccFactory occ;
  occ.addPoint(1, {0, 0, 0}, 0.1);
  occ.addPoint(2, {2, 0, 0}, 0);
  occ.addPoint(3, {2, 2, 0}, 0);
  occ.addPoint(4, {0, 2, 0}, 0);
  for (int i = 1; i <= 4; ++i) occ.addLine(i, i, i % 4 + 1);
  occ.addPoint(5, {1, 1, 0}, 0);
  occ.addPoint(6, {1.5, 1, 0}, 0);
  occ.addPoint(7, {0.5, 1, 0}, 0);
  occ.addCircleArc(5, 6, 5, 7);
  occ.addCircleArc(6, 7, 5, 6);
  occ.addCurveLoop(1, {1, 2, 3, 4});
  occ.addCurveLoop(2, {5, 6});
  occ.addPlaneSurface(1, {1, 2});
  return occ;
}

TEST(OccCurves, PlaneSurfaceWithHole) {
  OccFactory occ = squareWithHole();
  EXPECT_NEAR(occ.area(1), 4 - kPi / 4, 1e-9);
  EXPECT_NEAR(occ.length(5), kPi / 2, 1e-9);
  std::vector<int> edges;
  for (const EntityId& e : occ.boundary({{2, 1}}, false)) edges.push_back(e.tag);
  EXPECT_EQ(edges, (std::vector<int>{1, 2, 3, 4, 6, 5}));  // as the reference lists them
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
