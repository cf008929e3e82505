// Tests of the built-in kernel's curves: splines, B-splines, Bezier curves, ellipse arcs.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include "kernel/geo/ellipse_arc_geometry.h"
#include "kernel/geo/geo_factory.h"
#include "kernel/geo/spline_geometry.h"
#include "kernel/geometry_error.h"
#include "tests/kernel/kernel_test_helpers.h"

namespace geomesh {
namespace {

const double kPi = std::acos(-1.0);

// First and second derivatives agree with central differences of the point (resp. first
// derivative), away from the joints of piecewise curves.
void expectConsistentDerivatives(const CurveGeometry& curve) {
  const double h = 1e-6;
  for (double t : {0.05, 0.21, 0.38, 0.62, 0.79, 0.93}) {
    const Vec3 d1 = (curve.point(t + h) - curve.point(t - h)) / (2 * h);
    expectNear(curve.firstDerivative(t), d1, 1e-5 * (1 + norm(d1)));
    const Vec3 d2 = (curve.firstDerivative(t + h) - curve.firstDerivative(t - h)) / (2 * h);
    expectNear(curve.secondDerivative(t), d2, 1e-4 * (1 + norm(d2)));
  }
}

double length(const CurveGeometry& curve) {
  constexpr int kSteps = 2000;  // Simpson's rule
  double sum = 0;
  for (int i = 0; i <= kSteps; ++i) {
    const double w = (i == 0 || i == kSteps) ? 1 : (i % 2 ? 4 : 2);
    sum += w * norm(curve.firstDerivative(static_cast<double>(i) / kSteps));
  }
  return sum / (3.0 * kSteps);
}

const std::vector<Vec3> kPolygon = {{0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {3, 0, 1}, {4, 2, 0}};

TEST(SplineGeometry, InterpolatesItsPointsWithMirroredEnds) {
  CatmullRomGeometry spline(kPolygon);
  for (int i = 0; i < 5; ++i) expectNear(spline.point(i / 4.0), kPolygon[i], 1e-14);
  expectNear(spline.point(0.1), {0.4, -0.048, 0}, 1e-12);
  expectNear(spline.point(0.77), {3.08, 0.058432, 0.987712}, 1e-12);
  expectConsistentDerivatives(spline);
}

TEST(SplineGeometry, ClosedSplineWrapsAround) {
  CatmullRomGeometry spline({{0, 0, 1}, {1, 0, 0}, {2, 1, 0}, {3, 0, 2}, {0, 0, 1}});
  expectNear(spline.point(0.1), {0.112, -0.048, 0.552}, 1e-12);
  expectNear(spline.point(0.77), {2.883648, -0.033856, 2.021568}, 1e-12);
  // The tangent is continuous across the closing joint.
  expectNear(spline.firstDerivative(0), spline.firstDerivative(1), 1e-12);
}

TEST(BSplineGeometry, ClampedCubicStartsAndEndsAtItsEndPoints) {
  BSplineGeometry curve = BSplineGeometry::uniform(kPolygon, false);
  expectNear(curve.point(0), kPolygon.front(), 1e-14);
  expectNear(curve.point(1), kPolygon.back(), 1e-14);
  expectNear(curve.point(0.5), {2, 0.5, 0.25}, 1e-12);
  expectNear(curve.point(0.1), {0.544, 0.052, 0.002}, 1e-12);
  expectConsistentDerivatives(curve);
}

TEST(BSplineGeometry, FewPointsLowerTheDegree) {
  BSplineGeometry curve = BSplineGeometry::uniform({{0, 0, 1}, {1, 0, 0}, {2, 1, 0}}, false);
  expectNear(curve.point(0.1), {0.2, 0.01, 0.81}, 1e-12);
  expectConsistentDerivatives(curve);
}

TEST(BSplineGeometry, ClosedPolygonGivesAPeriodicCurve) {
  BSplineGeometry curve =
      BSplineGeometry::uniform({{0, 0, 1}, {1, 0, 0}, {2, 1, 0}, {3, 0, 2}, {0, 0, 1}}, true);
  expectNear(curve.point(0), {2.0 / 3, 0, 1}, 1e-12);
  expectNear(curve.point(1), curve.point(0), 1e-12);
  expectNear(curve.point(0.5), {2, 2.0 / 3, 1.0 / 3}, 1e-12);
  expectNear(curve.firstDerivative(0), curve.firstDerivative(1), 1e-12);
  expectConsistentDerivatives(curve);
}

TEST(BezierGeometry, MatchesBernsteinForm) {
  BSplineGeometry curve = BSplineGeometry::bezier(kPolygon);
  expectNear(curve.point(0.5), {2, 0.5, 0.25}, 1e-12);
  expectNear(curve.point(0.1), {0.4, 0.0488, 0.0036}, 1e-12);
  expectConsistentDerivatives(curve);
  // A Bezier curve with collinear evenly spaced points is the segment, run at constant speed.
  BSplineGeometry segment = BSplineGeometry::bezier({{0, 0, 0}, {1, 1, 0}, {2, 2, 0}, {3, 3, 0}});
  EXPECT_NEAR(length(segment), 3 * std::sqrt(2.0), 1e-10);
}

TEST(EllipseArcGeometry, FitsBothEndsWithTheGivenMajorAxis) {
  const Vec3 start{std::sqrt(2.0), std::sqrt(2.0) / 2, 0}, end{-1, std::sqrt(3.0) / 2, 0};
  EllipseArcGeometry arc = makeEllipseArc(start, {0, 0, 0}, {7, 0, 0}, end, "Ellipse 1");
  expectNear(arc.point(0), start, 1e-12);
  expectNear(arc.point(1), end, 1e-12);
  expectNear(arc.point(0.5), {0.261052, 0.991445, 0}, 1e-6);
  expectConsistentDerivatives(arc);
}

TEST(EllipseArcGeometry, QuarterOfACircleHasTheRightLength) {
  EllipseArcGeometry arc = makeEllipseArc({2, 0, 0}, {0, 0, 0}, {2, 0, 0}, {0, 2, 0}, "E");
  EXPECT_NEAR(length(arc), kPi, 1e-9);
  EllipseArcGeometry flat = makeEllipseArc({2, 0, 0}, {0, 0, 0}, {2, 0, 0}, {0, 1, 0}, "E");
  expectNear(flat.point(0.1), {1.975377, 0.156434, 0}, 1e-6);
}

TEST(EllipseArcGeometry, MajorAxisPointAtTheCenterTakesTheStartsDirection) {
  // {start, center, center, end}: the axis through the start, a quarter of the ellipse 2 x 1.
  EllipseArcGeometry arc = makeEllipseArc({2, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 1, 0}, "E");
  EXPECT_NEAR(length(arc), 2.4221120551, 1e-8);
  expectNear(arc.point(0.1), {1.975377, 0.156434, 0}, 1e-6);
  EXPECT_THROW(makeEllipseArc({0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 1, 0}, "E"), GeometryError);
}

TEST(EllipseArcGeometry, RejectsImpossibleEnds) {
  EXPECT_THROW(makeEllipseArc({1, 0, 0}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}, "Ellipse 3"),
               GeometryError);
}

TEST(GeoFactoryCurves, BuildsEveryCurveKind) {
  GeoFactory geo;
  for (int i = 0; i < 5; ++i) geo.addPoint(i + 1, kPolygon[i], 0);
  geo.addPoint(10, {0, 1, 0}, 0);
  geo.addSpline(1, {1, 2, 3, 4, 5});
  geo.addBSpline(2, {1, 2, 3, 4, 5});
  geo.addBezier(3, {1, 2, 3});
  geo.addEllipseArc(4, 2, 1, 2, 10);
  EXPECT_THROW(geo.addSpline(5, {1, 99}), GeometryError);
  EXPECT_THROW(geo.addBezier(1, {1, 2}), GeometryError);
  Model model;
  geo.synchronize(model);
  ASSERT_EQ(model.curves().size(), 4u);
  EXPECT_EQ(model.curve(1)->endPoint, 5);
  EXPECT_EQ(model.curve(4)->startPoint, 2);
  expectNear(model.curve(4)->geometry->point(1), {0, 1, 0}, 1e-12);
  expectNear(model.curve(2)->geometry->point(0.5), {2, 0.5, 0.25}, 1e-12);
}

}  // namespace
}  // namespace geomesh
