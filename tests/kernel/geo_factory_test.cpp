// Tests of GeoFactory: adjacencies, loop chaining and orientation, planarity, holes, errors.
#include "kernel/geo/geo_factory.h"

#include <gtest/gtest.h>

#include <cmath>

#include "kernel/geometry_error.h"
#include "kernel/plane_geometry.h"

namespace geomesh {
namespace {

// The unit square: points 1..4 counter-clockwise seen from +z, lines 1..4 around it.
void addUnitSquare(GeoFactory& geo) {
  geo.addPoint(1, {0, 0, 0}, 0.1);
  geo.addPoint(2, {1, 0, 0}, 0.1);
  geo.addPoint(3, {1, 1, 0}, 0.1);
  geo.addPoint(4, {0, 1, 0}, 0.1);
  geo.addLine(1, 1, 2);
  geo.addLine(2, 2, 3);
  geo.addLine(3, 3, 4);
  geo.addLine(4, 4, 1);
}

// The unit cube: the square at z = 0 and z = 1, vertical lines 9..12, six plane surfaces.
void addUnitCube(GeoFactory& geo) {
  const Vec3 corners[] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                          {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (int i = 0; i < 8; ++i) geo.addPoint(i + 1, corners[i], 1);
  for (int i = 0; i < 4; ++i) {
    geo.addLine(i + 1, i + 1, (i + 1) % 4 + 1);
    geo.addLine(i + 5, i + 5, (i + 1) % 4 + 5);
    geo.addLine(i + 9, i + 1, i + 5);
  }
  geo.addCurveLoop(1, {-4, -3, -2, -1});
  geo.addCurveLoop(2, {5, 6, 7, 8});
  geo.addCurveLoop(3, {1, 10, -5, -9});
  geo.addCurveLoop(4, {2, 11, -6, -10});
  geo.addCurveLoop(5, {3, 12, -7, -11});
  geo.addCurveLoop(6, {4, 9, -8, -12});
  for (int i = 1; i <= 6; ++i) geo.addPlaneSurface(i, {i});
  geo.addSurfaceLoop(1, {1, 2, 3, 4, 5, 6});
  geo.addVolume(1, {1});
}

std::string errorOf(auto&& action) {
  try {
    action();
  } catch (const GeometryError& e) {
    return e.what();
  }
  return "";
}

TEST(GeoFactory, SynchronizeBuildsAdjacencies) {
  GeoFactory geo;
  addUnitCube(geo);
  geo.addPhysicalGroup(2, 7, "bottom", {1});
  geo.addPhysicalGroup(3, 3, "", {1});
  geo.addPhysicalGroup(1, 4, "edges", {-9, 2});  // a member given reversed is a member
  Model model;
  geo.synchronize(model);
  EXPECT_EQ(model.points().size(), 8u);
  EXPECT_EQ(model.curves().size(), 12u);
  EXPECT_EQ(model.surfaces().size(), 6u);
  EXPECT_EQ(model.volumes().size(), 1u);
  EXPECT_EQ(model.boundary({1, 9}), (std::vector<int>{1, 5}));
  EXPECT_EQ(model.boundary({2, 3}), (std::vector<int>{1, 10, -5, -9}));
  EXPECT_EQ(model.boundary({3, 1}), (std::vector<int>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(model.upward({0, 1}), (std::vector<int>{1, 4, 9}));
  EXPECT_EQ(model.upward({1, 1}), (std::vector<int>{1, 3}));
  EXPECT_EQ(model.upward({2, 6}), (std::vector<int>{1}));
  EXPECT_EQ(model.physicalTagsOf({2, 1}), (std::vector<int>{7}));
  EXPECT_EQ(model.physicalTagsOf({1, 9}), (std::vector<int>{4}));
  EXPECT_EQ(model.physicalTagsOf({1, 2}), (std::vector<int>{4}));
  EXPECT_EQ(model.physicalGroups().at({2, 7}).name, "bottom");
  EXPECT_EQ(model.point(7)->xyz, (Vec3{1, 1, 1}));
  EXPECT_EQ(model.point(7)->meshSize, 1);
  const BoundingBox box = model.boundingBox({2, 4});
  EXPECT_EQ(box.min, (Vec3{1, 0, 0}));
  EXPECT_EQ(box.max, (Vec3{1, 1, 1}));
}

TEST(GeoFactory, SurfaceNormalFollowsOuterLoop) {
  GeoFactory geo;
  addUnitCube(geo);
  Model model;
  geo.synchronize(model);
  auto normalOf = [&](int s) {
    auto d = model.surface(s)->geometry->firstDerivatives({0, 0});
    return cross(d.du, d.dv);
  };
  // Loop 1 runs clockwise seen from +z: its normal points down (out of the cube).
  EXPECT_NEAR(dot(normalOf(1), {0, 0, -1}), 1, 1e-15);
  EXPECT_NEAR(dot(normalOf(2), {0, 0, 1}), 1, 1e-15);
  EXPECT_NEAR(dot(normalOf(3), {0, -1, 0}), 1, 1e-15);
  EXPECT_NEAR(dot(normalOf(4), {1, 0, 0}), 1, 1e-15);
  EXPECT_TRUE(model.surface(1)->geometry->isPlane());
}

TEST(GeoFactory, LoopGivenOutOfOrderIsChained) {
  GeoFactory geo;
  addUnitSquare(geo);
  geo.addCurveLoop(1, {1, 3, 2, 4});
  geo.addCurveLoop(2, {3, 4, 1, 2});
  geo.addPlaneSurface(1, {1});
  geo.addPlaneSurface(2, {2});
  Model model;
  geo.synchronize(model);
  EXPECT_EQ(model.surface(1)->loops.front(), (std::vector<int>{1, 2, 3, 4}));
  EXPECT_EQ(model.surface(2)->loops.front(), (std::vector<int>{3, 4, 1, 2}));
}

TEST(GeoFactory, NegativeLoopTagReversesTheLoop) {
  GeoFactory geo;
  addUnitSquare(geo);
  geo.addCurveLoop(1, {1, 2, 3, 4});
  geo.addPlaneSurface(1, {-1});
  Model model;
  geo.synchronize(model);
  EXPECT_EQ(model.surface(1)->loops.front(), (std::vector<int>{-4, -3, -2, -1}));
}

TEST(GeoFactory, ErrorsNameTheTags) {
  GeoFactory geo;
  addUnitSquare(geo);
  EXPECT_EQ(errorOf([&] { geo.addLine(7, 1, 9); }), "Line 7: point 9 is not defined");
  // A line from a point to itself makes no curve, as in the reference, but uses up its tag.
  EXPECT_EQ(errorOf([&] { geo.addLine(8, 2, 2); }), "");
  EXPECT_FALSE(geo.contains({1, 8}));
  EXPECT_EQ(geo.maxTag(1), 8);
  geo.addPoint(5, {1, 1, 1e-12}, 1);
  EXPECT_EQ(errorOf([&] { geo.addLine(7, 3, 5); }), "Line 7: points 3 and 5 coincide");
  EXPECT_EQ(errorOf([&] { geo.addPoint(1, {5, 5, 5}, 1); }), "Point 1 already exists");
  EXPECT_EQ(errorOf([&] { geo.addLine(1, 1, 3); }), "Curve 1 already exists");
  EXPECT_EQ(errorOf([&] { geo.addCurveLoop(1, {1, 2, 8}); }),
            "Curve loop 1: curve 8 is not defined");
  EXPECT_EQ(errorOf([&] { geo.addCurveLoop(1, {1, 2, 3}); }),
            "Curve loop 1 does not close: gap between point 4 (end of curve 3) and point 1 "
            "(start of curve 1)");
  EXPECT_EQ(errorOf([&] { geo.addCurveLoop(1, {1, -3, 2, 4}); }),
            "Curve loop 1 is not a chain: curve 2 ends at point 3 and no other curve of the "
            "loop starts there");
  EXPECT_EQ(errorOf([&] { geo.addPlaneSurface(1, {4}); }),
            "Plane surface 1: curve loop 4 is not defined");
  EXPECT_EQ(errorOf([&] { geo.addVolume(1, {4}); }), "Volume 1: surface loop 4 is not defined");
  EXPECT_EQ(errorOf([&] { geo.pointCoordinates(42); }), "Point 42 is not defined");
  EXPECT_EQ(errorOf([&] { geo.addPoint(8, {0, std::nan(""), 0}, 1); }),
            "Point 8: its coordinates are not finite numbers");
}

TEST(GeoFactory, NonPlanarLoopIsRejected) {
  GeoFactory geo;
  addUnitSquare(geo);
  geo.addPoint(5, {0.5, 1.5, 0.25}, 1);
  geo.addLine(5, 3, 5);
  geo.addLine(6, 5, 4);
  geo.addCurveLoop(1, {1, 2, 5, 6, 4});
  const std::string error = errorOf([&] { geo.addPlaneSurface(1, {1}); });
  EXPECT_NE(error.find("Plane surface 1 is not plane"), std::string::npos) << error;
}

TEST(GeoFactory, TinyDeviationWithinToleranceIsPlane) {
  GeoFactory geo;
  addUnitSquare(geo);
  geo.addPoint(5, {0.5, 1.5, 1e-12}, 1);
  geo.addLine(5, 3, 5);
  geo.addLine(6, 5, 4);
  geo.addCurveLoop(1, {1, 2, 5, 6, 4});
  EXPECT_NO_THROW(geo.addPlaneSurface(1, {1}));
}

TEST(GeoFactory, OpenSurfaceLoopIsRejectedByItsVolume) {
  GeoFactory geo;
  addUnitCube(geo);
  geo.addSurfaceLoop(2, {1, 2, 3, 4, 5});  // the reference takes it too
  EXPECT_EQ(errorOf([&] { geo.addVolume(2, {2}); }),
            "Surface loop 2 is not closed: curve 4 bounds 1 of its surfaces (surface 1)");
  geo.addSurfaceLoop(3, {6});  // together, loops 2 and 3 close
  EXPECT_EQ(errorOf([&] { geo.addVolume(2, {2, 3}); }), "");
  geo.addSurfaceLoop(4, {1, 2});
  EXPECT_EQ(errorOf([&] { geo.addVolume(3, {4, 3}); }),
            "Volume 3: its surface loops are not closed: curve 1 bounds 1 of its surfaces "
            "(surface 1)");
}

// Points 5 to 7 and lines 5 to 7: a triangle inside the unit square, counter-clockwise.
void addTriangleHole(GeoFactory& geo) {
  geo.addPoint(5, {0.25, 0.25, 0}, 1);
  geo.addPoint(6, {0.75, 0.25, 0}, 1);
  geo.addPoint(7, {0.5, 0.75, 0}, 1);
  geo.addLine(5, 5, 6);
  geo.addLine(6, 6, 7);
  geo.addLine(7, 7, 5);
}

TEST(GeoFactory, SurfaceWithHoleKeepsBothLoops) {
  GeoFactory geo;
  addUnitSquare(geo);
  addTriangleHole(geo);
  geo.addCurveLoop(1, {1, 2, 3, 4});
  geo.addCurveLoop(2, {5, 6, 7});
  geo.addPlaneSurface(1, {1, 2});
  Model model;
  geo.synchronize(model);
  EXPECT_EQ(model.surface(1)->loops.size(), 2u);
  // Holes are listed reversed, as Gmsh lists them.
  EXPECT_EQ(model.boundary({2, 1}), (std::vector<int>{1, 2, 3, 4, -7, -6, -5}));
  const ParamBox b = model.surface(1)->geometry->bounds();
  EXPECT_NEAR(b.u.max - b.u.min, 1, 1e-15);
  EXPECT_NEAR(b.v.max - b.v.min, 1, 1e-15);
}

TEST(GeoFactory, OneLoopMayHoldTheBoundaryAndItsHoles) {
  // As in Gmsh: the curves of a hole may follow the outer ones in the same curve loop.
  GeoFactory geo;
  addUnitSquare(geo);
  addTriangleHole(geo);
  geo.addCurveLoop(1, {2, 3, -6, 4, -5, 1, -7});
  geo.addPlaneSurface(1, {1});
  Model model;
  geo.synchronize(model);
  ASSERT_EQ(model.surface(1)->loops.size(), 2u);
  EXPECT_EQ(model.surface(1)->loops[0], (std::vector<int>{2, 3, 4, 1}));
  EXPECT_EQ(model.surface(1)->loops[1], (std::vector<int>{-6, -5, -7}));
  // A chain that stops before closing is still an error.
  EXPECT_EQ(errorOf([&] { geo.addCurveLoop(2, {1, 2, 3, 4, 5, 6}); }),
            "Curve loop 2 does not close: gap between point 7 (end of curve 6) and point 5 "
            "(start of curve 5)");
}

TEST(GeoFactory, MaxTagAndPhysicalGroups) {
  GeoFactory geo;
  addUnitCube(geo);
  EXPECT_EQ(geo.maxTag(0), 8);
  EXPECT_EQ(geo.maxTag(1), 12);
  EXPECT_EQ(geo.maxTag(2), 6);
  EXPECT_EQ(geo.maxTag(3), 1);
  EXPECT_EQ(geo.maxTag(GeoFactory::kCurveLoop), 6);
  EXPECT_EQ(geo.maxTag(GeoFactory::kSurfaceLoop), 1);
  geo.addPhysicalGroup(1, 5, "edges", {1, 2});
  geo.addPhysicalGroup(1, 5, "", {2, 3, 99});
  Model model;
  geo.synchronize(model);
  const PhysicalGroup& g = model.physicalGroups().at({1, 5});
  EXPECT_EQ(g.name, "edges");
  EXPECT_EQ(g.entities, (std::vector<int>{1, 2, 3}));  // 99 does not exist: dropped
  geo.clear();
  EXPECT_EQ(geo.maxTag(0), 0);
  EXPECT_FALSE(geo.hasPoint(1));
}

}  // namespace
}  // namespace geomesh

namespace geomesh {
namespace {

// A disk from four quarter arcs, and a half disk closed by its diameter.
TEST(GeoFactory, CircleArcsBoundPlaneSurfaces) {
  GeoFactory geo;
  geo.addPoint(1, {0, 0, 0}, 0.1);
  geo.addPoint(2, {1, 0, 0}, 0.1);
  geo.addPoint(3, {0, 1, 0}, 0.1);
  geo.addPoint(4, {-1, 0, 0}, 0.1);
  geo.addPoint(5, {0, -1, 0}, 0.1);
  geo.addCircleArc(1, 2, 1, 3);
  geo.addCircleArc(2, 3, 1, 4);
  geo.addCircleArc(3, 4, 1, 5);
  geo.addCircleArc(4, 5, 1, 2);
  geo.addCircleArc(5, 2, 1, 4);  // a half circle: turns about +z, through (0, 1, 0)
  geo.addLine(6, 4, 2);
  geo.addCurveLoop(1, {1, 2, 3, 4});
  geo.addPlaneSurface(1, {1});
  geo.addCurveLoop(2, {5, 6});
  geo.addPlaneSurface(2, {2});
  Model model;
  geo.synchronize(model);
  const Vec3 top = model.curve(5)->geometry->point(0.5);
  EXPECT_NEAR(top.x, 0, 1e-15);
  EXPECT_NEAR(top.y, 1, 1e-15);
  EXPECT_EQ(model.curve(1)->geometry->range().max, 1);
  const ParamBox b = model.surface(1)->geometry->bounds();
  EXPECT_NEAR(b.u.max - b.u.min, 2, 1e-12);
  EXPECT_NEAR(b.v.max - b.v.min, 2, 1e-12);
  const auto d = model.surface(2)->geometry->firstDerivatives({0, 0});
  EXPECT_NEAR(cross(d.du, d.dv).z, 1, 1e-15);  // the loop runs counter-clockwise about +z
  const BoundingBox box = model.boundingBox({1, 1});
  EXPECT_NEAR(box.max.x, 1, 1e-15);
  EXPECT_NEAR(box.max.y, 1, 1e-15);
}

TEST(GeoFactory, CircleArcErrors) {
  GeoFactory geo;
  geo.addPoint(1, {0, 0, 0}, 0.1);
  geo.addPoint(2, {1, 0, 0}, 0.1);
  geo.addPoint(3, {0, 2, 0}, 0.1);
  EXPECT_EQ(errorOf([&] { geo.addCircleArc(1, 2, 1, 9); }), "Circle 1: point 9 is not defined");
  EXPECT_EQ(errorOf([&] { geo.addCircleArc(1, 2, 1, 3); }),
            "Circle 1: points 2 and 3 are not on one circle around point 1 (radii 1 and 2)");
  EXPECT_EQ(errorOf([&] { geo.addCircleArc(1, 2, 2, 3); }),
            "Circle 1: its center, point 2, is one of its ends");
}

}  // namespace
}  // namespace geomesh
