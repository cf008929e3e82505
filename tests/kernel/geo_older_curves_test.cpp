// Tests of the built-in kernel's curves of older scripts: Line through several points, Nurbs,
// half circles turning about a given normal, Split Curve, and nearly plane surfaces.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "kernel/geo/geo_factory.h"
#include "kernel/geometry_error.h"
#include "tests/kernel/kernel_test_helpers.h"

namespace geomesh {
namespace {

std::string errorOf(auto action) {
  try {
    action();
  } catch (const GeometryError& e) {
    return e.what();
  }
  return "no error";
}

std::shared_ptr<const CurveGeometry> curveOf(const GeoFactory& geo, int tag) {
  Model model;
  geo.synchronize(model);
  return model.curve(tag)->geometry;
}

void addPoints(GeoFactory& geo, std::initializer_list<Vec3> points) {
  int tag = 1;
  for (Vec3 p : points) geo.addPoint(tag++, p, 1);
}

TEST(GeoOlderCurves, PolylineRunsThroughItsPointsByLength) {
  GeoFactory geo;
  addPoints(geo, {{0, 0, 0}, {1, 0, 0}, {1, 3, 0}});
  geo.addPolyline(1, {1, 2, 3});
  const auto curve = curveOf(geo, 1);
  expectNear(curve->point(0), {0, 0, 0});
  expectNear(curve->point(0.25), {1, 0, 0});  // 1 of the 4 units of length
  expectNear(curve->point(0.5), {1, 1, 0});
  expectNear(curve->point(1), {1, 3, 0});
  expectNear(curve->firstDerivative(0.75), {0, 4, 0});
  EXPECT_EQ(geo.curves().at(1).points, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(errorOf([&] { geo.addPolyline(2, {1, 2, 2}); }), "Line 2: points 2 and 2 coincide");
}

TEST(GeoOlderCurves, NurbsWithClampedKnotsIsTheBezierCurve) {
  GeoFactory geo;
  addPoints(geo, {{0, 0, 0}, {1, 1, 0}, {2, 1, 0}, {3, 0, 0}});
  geo.addNurbs(1, {1, 2, 3, 4}, {0, 0, 0, 0, 1, 1, 1, 1}, 3);
  geo.addBezier(2, {1, 2, 3, 4});
  const auto nurbs = curveOf(geo, 1), bezier = curveOf(geo, 2);
  for (double t : {0.0, 0.2, 0.5, 0.9, 1.0}) expectNear(nurbs->point(t), bezier->point(t));
  expectNear(nurbs->point(0.5), {1.5, 0.75, 0});
}

TEST(GeoOlderCurves, NurbsKnotsAreChecked) {
  GeoFactory geo;
  addPoints(geo, {{0, 0, 0}, {1, 1, 0}, {2, 1, 0}});
  EXPECT_EQ(errorOf([&] { geo.addNurbs(1, {1, 2, 3}, {0, 0, 1, 1}, 2); }),
            "Nurbs 1: 3 points of order 2 need 6 knots, not 4");
  EXPECT_EQ(errorOf([&] { geo.addNurbs(1, {1, 2, 3}, {0, 0, 1, 0.5, 1, 1}, 2); }),
            "Nurbs 1: its knots decrease");
  EXPECT_EQ(errorOf([&] { geo.addNurbs(1, {1, 2, 3}, {0, 0, 0, 1}, 0); }),
            "Nurbs 1: its order must be at least 1, not 0");
  geo.addNurbs(1, {1, 2, 3}, {0, 0, 0, 2, 2, 2}, 2);  // knots need not span [0, 1]
  expectNear(curveOf(geo, 1)->point(1), {2, 1, 0});
}

TEST(GeoOlderCurves, HalfCircleTurnsAboutTheGivenNormal) {
  GeoFactory geo;
  addPoints(geo, {{0, 0, 0}, {1, 0, 0}, {-1, 0, 0}});
  geo.addCircleArcAbout(1, 2, 1, 3, {0, 0, 1});
  geo.addCircleArcAbout(2, 2, 1, 3, {0, 0, -1});
  geo.addCircleArcAbout(3, 2, 1, 3, {0, 2, 0});
  geo.addCircleArc(4, 2, 1, 3);
  expectNear(curveOf(geo, 1)->point(0.5), {0, 1, 0}, 1e-12);
  expectNear(curveOf(geo, 2)->point(0.5), {0, -1, 0}, 1e-12);
  expectNear(curveOf(geo, 3)->point(0.5), {0, 0, -1}, 1e-12);
  expectNear(curveOf(geo, 4)->point(0.5), curveOf(geo, 1)->point(0.5));
  EXPECT_EQ(errorOf([&] { geo.addCircleArcAbout(5, 2, 1, 3, {0, 0, 0}); }),
            "Circle 5: its plane's normal is zero");
}

TEST(GeoOlderCurves, SplitCurveMakesPiecesAndUpdatesLoops) {
  GeoFactory geo;
  addPoints(geo, {{0, 0, 0}, {1, 0.5, 0}, {2, -0.5, 0}, {3, 0.3, 0}, {4, 0, 0}});
  geo.addSpline(7, {1, 2, 3, 4, 5});
  geo.addLine(8, 5, 1);
  geo.addCurveLoop(1, {7, 8});
  EXPECT_EQ(geo.splitCurve(7, {2, 4}), (std::vector<int>{9, 10, 11}));
  EXPECT_FALSE(geo.contains({1, 7}));
  EXPECT_EQ(geo.curves().at(10).points, (std::vector<int>{2, 3, 4}));
  EXPECT_EQ(geo.curves().at(10).kind, CurveKind::Spline);
  EXPECT_EQ(geo.curveLoops().at(1), (std::vector<int>{9, 10, 11, 8}));
  EXPECT_EQ(geo.splitCurve(8, {3}), (std::vector<int>{8}));  // not one of its points
  EXPECT_EQ(errorOf([&] { geo.splitCurve(7, {2}); }), "Split Curve: curve 7 is not defined");
}

TEST(GeoOlderCurves, SplitReversedCurveInALoop) {
  GeoFactory geo;
  addPoints(geo, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {1, 1, 0}});
  geo.addPolyline(1, {1, 2, 3});
  geo.addLine(2, 3, 4);
  geo.addLine(3, 4, 1);
  geo.addCurveLoop(1, {-3, -2, -1});
  geo.splitCurve(1, {2});
  EXPECT_EQ(geo.curveLoops().at(1), (std::vector<int>{-3, -2, -5, -4}));
}

TEST(GeoOlderCurves, NearlyPlaneSurfaceLiesOnItsMeanPlane) {
  GeoFactory geo;
  addPoints(geo, {{0, 0, 0}, {1, 0, 0.01}, {1, 1, 0}, {0, 1, 0.01}});
  for (int i = 1; i <= 4; ++i) geo.addLine(i, i, i % 4 + 1);
  geo.addCurveLoop(1, {1, 2, 3, 4});
  geo.addPlaneSurface(1, {1});
  EXPECT_NEAR(geo.planeDeviation(1), 0.005, 1e-12);
  Model model;
  geo.synchronize(model);
  // The least-squares plane z = 0.005 (its normal is +z by symmetry).
  const auto d = model.surface(1)->geometry->firstDerivatives({0, 0});
  EXPECT_NEAR(std::abs(cross(d.du, d.dv).z) / norm(cross(d.du, d.dv)), 1.0, 1e-12);
  EXPECT_NEAR(model.surface(1)->geometry->point({0.3, 0.2}).z, 0.005, 1e-12);
  geo.addLine(5, 1, 3);
  geo.addCurveLoop(2, {1, 2, -5});
  geo.addPlaneSurface(2, {2});
  EXPECT_EQ(geo.planeDeviation(2), 0);  // three points are always plane
}

TEST(GeoOlderCurves, FarFromPlaneLoopIsStillAnError) {
  GeoFactory geo;
  addPoints(geo, {{0, 0, 0}, {1, 0, 0}, {1, 1, 1}, {0, 1, 0}});
  for (int i = 1; i <= 4; ++i) geo.addLine(i, i, i % 4 + 1);
  geo.addCurveLoop(1, {1, 2, 3, 4});
  const std::string error = errorOf([&] { geo.addPlaneSurface(1, {1}); });
  EXPECT_NE(error.find("Plane surface 1 is not plane"), std::string::npos) << error;
}

}  // namespace
}  // namespace geomesh
