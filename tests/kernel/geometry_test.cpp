// Tests of LineGeometry, fitPlane, PlaneGeometry and CircleArcGeometry.
#include <gtest/gtest.h>

#include "kernel/geo/circle_arc_geometry.h"
#include "kernel/geo/line_geometry.h"
#include "kernel/plane_geometry.h"
#include "tests/kernel/kernel_test_helpers.h"

namespace geomesh {
namespace {

TEST(LineGeometry, DerivativesMatchFiniteDifferences) {
  const LineGeometry line({1, 2, 3}, {4, -2, 3.5});
  EXPECT_EQ(line.range().min, 0);
  EXPECT_EQ(line.range().max, 1);
  expectNear(line.point(0), {1, 2, 3}, 0);
  expectNear(line.point(1), {4, -2, 3.5}, 1e-15);
  const double h = 1e-6;
  for (double t : {0.1, 0.5, 0.9}) {
    const Vec3 fd = (line.point(t + h) - line.point(t - h)) / (2 * h);
    expectNear(line.firstDerivative(t), fd, 1e-8);
    const Vec3 fd2 = (line.firstDerivative(t + h) - line.firstDerivative(t - h)) / (2 * h);
    expectNear(line.secondDerivative(t), fd2, 1e-8);
  }
}

TEST(LineGeometry, ProjectionIsExact) {
  const LineGeometry line({0, 0, 0}, {2, 0, 0});
  EXPECT_DOUBLE_EQ(line.project({1.5, 3, -1}), 0.75);
  EXPECT_DOUBLE_EQ(line.project(line.point(0.3)), 0.3);
}

TEST(PlaneFit, NewellNormalFollowsOrientation) {
  const std::vector<Vec3> ccw = {{0, 0, 5}, {2, 0, 5}, {2, 1, 5}, {0, 1, 5}};
  const PlaneFit fit = fitPlane(ccw);
  expectNear(fit.normal, {0, 0, 1}, 1e-15);
  expectNear(fit.origin, {1, 0.5, 5}, 1e-15);
  EXPECT_EQ(fit.maxDeviation, 0);
  const std::vector<Vec3> cw(ccw.rbegin(), ccw.rend());
  expectNear(fitPlane(cw).normal, {0, 0, -1}, 1e-15);
}

TEST(PlaneFit, CollinearPointsHaveNoNormal) {
  const std::vector<Vec3> line = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
  EXPECT_EQ(norm(fitPlane(line).normal), 0);
}

TEST(PlaneFit, ReportsDeviation) {
  const std::vector<Vec3> warped = {{0, 0, 0}, {1, 0, 0.1}, {1, 1, 0}, {0, 1, 0.1}};
  EXPECT_NEAR(fitPlane(warped).maxDeviation, 0.05, 1e-12);
}

TEST(PlaneGeometry, AxesAreOrthonormalAndRightHanded) {
  for (Vec3 n : {Vec3{0, 0, 1}, Vec3{0, 0, -1}, Vec3{1, 2, 3}, Vec3{-5, 0.1, 0}}) {
    const PlaneGeometry plane({1, 1, 1}, n);
    EXPECT_NEAR(norm(plane.uAxis()), 1, 1e-15);
    EXPECT_NEAR(norm(plane.vAxis()), 1, 1e-15);
    EXPECT_NEAR(dot(plane.uAxis(), plane.vAxis()), 0, 1e-15);
    expectNear(plane.normal(), normalized(n), 1e-15);
  }
  const PlaneGeometry xy({0, 0, 0}, {0, 0, 1});
  expectNear(xy.uAxis(), {1, 0, 0}, 0);
  expectNear(xy.vAxis(), {0, 1, 0}, 0);
}

TEST(PlaneGeometry, ProjectionInvertsPointAndDropsNormalOffset) {
  PlaneGeometry plane({1, 2, 3}, {1, 1, 0});
  const Vec2 uv{0.3, -1.7};
  const Vec3 p = plane.point(uv);
  const Vec2 back = plane.project(p + 4.0 * plane.normal());
  EXPECT_NEAR(back.u, uv.u, 1e-14);
  EXPECT_NEAR(back.v, uv.v, 1e-14);
  const double h = 1e-6;
  const SurfaceDerivatives d = plane.firstDerivatives(uv);
  expectNear(d.du, (plane.point({uv.u + h, uv.v}) - plane.point({uv.u - h, uv.v})) / (2 * h),
             1e-8);
  expectNear(d.dv, (plane.point({uv.u, uv.v + h}) - plane.point({uv.u, uv.v - h})) / (2 * h),
             1e-8);
  plane.include(p);
  plane.include(plane.point({1, 1}));
  EXPECT_NEAR(plane.bounds().u.min, 0.3, 1e-14);
  EXPECT_NEAR(plane.bounds().v.max, 1, 1e-14);
}

}  // namespace
}  // namespace geomesh

namespace geomesh {
namespace {

TEST(CircleArcGeometry, QuarterArcMatchesTheCircle) {
  const CircleArcGeometry arc({1, 1, 0}, {2, 1, 0}, {1, 2, 0}, {0, 0, 1});
  EXPECT_NEAR(arc.angle(), std::acos(-1.0) / 2, 1e-15);
  const Vec3 mid = arc.point(0.5);
  EXPECT_NEAR(mid.x, 1 + std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(mid.y, 1 + std::sqrt(0.5), 1e-15);
  const Vec3 end = arc.point(1);
  EXPECT_NEAR(end.x, 1, 1e-15);
  EXPECT_NEAR(end.y, 2, 1e-15);
}

TEST(CircleArcGeometry, DerivativesMatchFiniteDifferences) {
  // Ends at different radii: the radius varies along the arc.
  const CircleArcGeometry arc({0, 0, 1}, {1, 0, 1}, {0, 0, 2.05}, {0, -1, 0});
  const double h = 1e-6;
  for (double t : {0.0 + h, 0.3, 0.77, 1.0 - h}) {
    const Vec3 fd = (arc.point(t + h) - arc.point(t - h)) / (2 * h);
    const Vec3 d = arc.firstDerivative(t);
    EXPECT_NEAR(norm(d - fd), 0, 1e-7);
    const Vec3 fd2 = (arc.firstDerivative(t + h) - arc.firstDerivative(t - h)) / (2 * h);
    EXPECT_NEAR(norm(arc.secondDerivative(t) - fd2), 0, 1e-6);
  }
  EXPECT_NEAR(norm(arc.point(1) - Vec3{0, 0, 2.05}), 0, 1e-15);
}

}  // namespace
}  // namespace geomesh
