// Transformations, copies, deletion and queries of the built-in kernel.
#include <gtest/gtest.h>

#include <cmath>

#include "kernel/geo/geo_factory.h"
#include "kernel/geometry_error.h"
#include "tests/kernel/kernel_test_helpers.h"

namespace geomesh {
namespace {

const double kPi = std::acos(-1.0);

TEST(AffineMap, BuildsTheUsualTransformations) {
  expectNear(AffineMap::rotation({0, 0, 1}, {1, 0, 0}, kPi / 2).apply({2, 0, 0}), {1, 1, 0});
  expectNear(AffineMap::symmetry(1, 0, 0, -1).apply({3, 2, 1}), {-1, 2, 1});
  expectNear(AffineMap::dilation({1, 1, 1}, {2, 3, 4}).apply({2, 2, 2}), {3, 4, 5});
  expectNear(AffineMap::translation({1, 2, 3}).apply({1, 1, 1}), {2, 3, 4});
}

TEST(GeoTransform, TranslatedDuplicateGetsGmshTags) {
  GeoFactory geo;
  addUnitSquareSurface(geo);
  const auto copies = geo.duplicate({{2, 1}});
  ASSERT_EQ(copies.size(), 1u);
  EXPECT_EQ(copies[0].tag, 5);
  EXPECT_EQ(geo.maxTag(0), 20);  // four point tags per copied line
  geo.transform(copies, AffineMap::translation({2, 0, 0}));
  EXPECT_EQ(geo.maxTag(0), 14);
  EXPECT_EQ(geo.maxTag(1), 9);
  EXPECT_EQ(geo.surfaces().at(5).loops.front(), (std::vector<int>{6, 7, 8, 9}));
  EXPECT_EQ(geo.curves().at(8).points, (std::vector<int>{10, 14}));
  expectNear(geo.pointCoordinates(10), {3, 1, 0});
  Model model;
  geo.synchronize(model);
  EXPECT_EQ(model.boundary({2, 5}), (std::vector<int>{6, 7, 8, 9}));
  EXPECT_EQ(model.points().size(), 8u);
}

TEST(GeoTransform, DuplicatesOfCurvesAndPoints) {
  GeoFactory geo;
  addUnitSquareSurface(geo);
  const auto copies = geo.duplicate({{1, 1}, {1, 2}, {0, 1}});
  EXPECT_EQ(copies[0].tag, 5);
  EXPECT_EQ(copies[1].tag, 6);
  EXPECT_EQ(copies[2].tag, 13);
}

TEST(GeoTransform, CoherenceMergesAnUnmovedDuplicateBack) {
  GeoFactory geo;
  addUnitSquareSurface(geo);
  geo.duplicate({{2, 1}});
  geo.coherence();
  EXPECT_EQ(geo.maxTag(0), 4);
  EXPECT_EQ(geo.maxTag(1), 4);
  EXPECT_EQ(geo.surfaces().size(), 1u);
}

TEST(GeoTransform, RotationMovesControlPointsOfCurves) {
  GeoFactory geo;
  geo.addPoint(1, {1, 0, 0}, 1);
  geo.addPoint(2, {0, 0, 0}, 1);
  geo.addPoint(3, {0, 1, 0}, 1);
  geo.addCircleArc(1, 1, 2, 3);
  geo.transform({{1, 1}}, AffineMap::rotation({1, 0, 0}, {0, 0, 0}, kPi / 2));
  expectNear(geo.pointCoordinates(3), {0, 0, 1});
  Model model;
  geo.synchronize(model);
  const Vec3 mid = model.curve(1)->geometry->point(0.5);
  expectNear(mid, {std::sqrt(0.5), 0, std::sqrt(0.5)});
}

TEST(GeoTransform, DilationThatBreaksACircleIsRefused) {
  GeoFactory geo;
  geo.addPoint(1, {0, 0, 0}, 1);
  geo.addPoint(2, {1, 0, 0}, 1);
  geo.addPoint(3, {0, 1, 0}, 1);
  geo.addCircleArc(1, 2, 1, 3);
  EXPECT_THROW(geo.transform({{1, 1}}, AffineMap::dilation({0, 0, 0}, {2, 1, 1})),
               GeometryError);
  expectNear(geo.pointCoordinates(2), {1, 0, 0});  // nothing moved
  geo.transform({{1, 1}}, AffineMap::dilation({0, 0, 0}, {2, 2, 2}));
  expectNear(geo.pointCoordinates(2), {2, 0, 0});
}

TEST(GeoTransform, BoundariesAreOriented) {
  GeoFactory geo;
  addUnitSquareSurface(geo);
  auto tags = [](const std::vector<EntityId>& v) {
    std::vector<int> out;
    for (EntityId e : v) out.push_back(e.tag);
    return out;
  };
  EXPECT_EQ(tags(geo.boundary({{2, 1}}, false)), (std::vector<int>{1, 2, 3, 4}));
  EXPECT_EQ(tags(geo.boundary({{2, -1}}, false)), (std::vector<int>{1, 2, 3, 4}));
  EXPECT_EQ(tags(geo.boundary({{1, -1}, {1, 2}}, false)), (std::vector<int>{2, 1, 2, 3}));
  EXPECT_EQ(tags(geo.boundary({{1, 2}, {1, 1}}, true)), (std::vector<int>{1, 3}));
  EXPECT_EQ(tags(geo.boundary({{1, -3}, {1, -2}, {1, -1}}, true)), (std::vector<int>{1, 4}));
  EXPECT_EQ(geo.pointsOf({{2, 1}}), (std::vector<int>{1, 2, 3, 4}));
}

TEST(GeoTransform, BoundingBoxesAndBoxQueries) {
  GeoFactory geo;
  addUnitSquareSurface(geo);
  const BoundingBox box = geo.boundingBox({2, 1});
  expectNear(box.min, {0, 0, 0});
  expectNear(box.max, {1, 1, 0});
  BoundingBox query;
  query.include(Vec3{-1, -1, -1});
  query.include(Vec3{1.5, 0.5, 1});
  EXPECT_EQ(geo.entitiesInBox(0, query), (std::vector<int>{1, 2}));
  EXPECT_EQ(geo.entitiesInBox(1, query), (std::vector<int>{1}));
  EXPECT_TRUE(geo.entitiesInBox(2, query).empty());
}

TEST(GeoTransform, DeleteKeepsWhatIsUsed) {
  GeoFactory geo;
  addUnitSquareSurface(geo);
  geo.addPoint(50, {5, 5, 5}, 1);
  geo.remove({{0, 1}}, false);
  EXPECT_TRUE(geo.hasPoint(1));
  geo.remove({{0, 50}}, false);
  EXPECT_FALSE(geo.hasPoint(50));
  EXPECT_EQ(geo.maxTag(0), 49);
  geo.remove({{2, 1}}, true);
  EXPECT_TRUE(geo.surfaces().empty());
  EXPECT_TRUE(geo.curves().empty());
  EXPECT_TRUE(geo.points().empty());
}

TEST(GeoTransform, LoopsOfDeletedCurvesAreReported) {
  GeoFactory geo;
  addUnitSquareSurface(geo);
  geo.remove({{2, 1}}, false);
  geo.remove({{1, 3}}, false);
  try {
    geo.addPlaneSurface(2, {1});
    FAIL();
  } catch (const GeometryError& e) {
    EXPECT_STREQ(e.what(), "Plane surface 2: curve 3 of curve loop 1 has been deleted");
  }
}

TEST(GeoTransform, UndefinedShapeIsNamed) {
  GeoFactory geo;
  try {
    geo.transform({{1, 3}}, AffineMap::translation({1, 0, 0}));
    FAIL();
  } catch (const GeometryError& e) {
    EXPECT_STREQ(e.what(), "Transformation: Curve 3 is not defined");
  }
}

// The surface's first derivatives at uv against central differences.
void expectDerivativesMatch(const SurfaceGeometry& s, Vec2 uv, double tolerance) {
  const double h = 1e-6;
  const SurfaceDerivatives d = s.firstDerivatives(uv);
  const Vec3 du = (s.point({uv.u + h, uv.v}) - s.point({uv.u - h, uv.v})) / (2 * h);
  const Vec3 dv = (s.point({uv.u, uv.v + h}) - s.point({uv.u, uv.v - h})) / (2 * h);
  EXPECT_NEAR(distance(d.du, du), 0, tolerance);
  EXPECT_NEAR(distance(d.dv, dv), 0, tolerance);
}

TEST(GeoSurfaces, FillingSurfaceInterpolatesItsBoundary) {
  GeoFactory geo;
  geo.addPoint(1, {0, 0, 0}, 1);
  geo.addPoint(2, {1, 0, 0}, 1);
  geo.addPoint(3, {1, 1, 0.5}, 1);
  geo.addPoint(4, {0, 1, 0}, 1);
  for (int i = 1; i <= 4; ++i) geo.addLine(i, i, i % 4 + 1);
  geo.addCurveLoop(1, {1, 2, 3, 4});
  EXPECT_THROW(geo.addPlaneSurface(1, {1}), GeometryError);
  geo.addFillingSurface(1, {1}, {});
  Model model;
  geo.synchronize(model);
  const SurfaceGeometry& s = *model.surface(1)->geometry;
  expectNear(s.point({1, 1}), {1, 1, 0.5});
  expectNear(s.point({0.5, 0}), {0.5, 0, 0});
  const Vec3 p = s.point({0.3, 0.6});
  const Vec2 uv = s.project(p);
  EXPECT_NEAR(uv.u, 0.3, 1e-9);
  EXPECT_NEAR(uv.v, 0.6, 1e-9);
  expectDerivativesMatch(s, {0.3, 0.6}, 1e-8);
}

// Gmsh's parametrization: the triangle 0 <= v <= u <= 1, an affine map for straight sides.
TEST(GeoSurfaces, TriangularFillingSurface) {
  GeoFactory geo;
  geo.addPoint(1, {3, 0, 0}, 1);
  geo.addPoint(2, {4, 0, 0}, 1);
  geo.addPoint(3, {3, 1, 1}, 1);
  geo.addPoint(4, {3.5, -0.2, 0}, 1);
  geo.addSpline(1, {1, 4, 2});
  geo.addLine(2, 2, 3);
  geo.addLine(3, 3, 1);
  geo.addCurveLoop(1, {1, 2, 3});
  geo.addFillingSurface(1, {1}, {});
  Model model;
  geo.synchronize(model);
  const SurfaceGeometry& s = *model.surface(1)->geometry;
  const auto side = model.curve(1)->geometry;
  expectNear(s.point({0.4, 0}), side->point(0.4));
  expectNear(s.point({1, 0.5}), {3.5, 0.5, 0.5});
  expectNear(s.point({0.5, 0.5}), {3, 0.5, 0.5});
  expectNear(s.point({1, 1}), {3, 1, 1});
  const Vec2 uv = s.project(s.point({0.7, 0.3}));
  EXPECT_NEAR(uv.u, 0.7, 1e-9);
  EXPECT_NEAR(uv.v, 0.3, 1e-9);
  expectDerivativesMatch(s, {0.6, 0.2}, 1e-7);
}

// Three curved sides: the surface is continuous at its corners, whatever the direction it
// approaches them from (a side's deviation fades out towards the opposite corner).
TEST(GeoSurfaces, TriangularFillingSurfaceIsContinuousAtItsCorners) {
  GeoFactory geo;
  geo.addPoint(1, {0, 0, 0}, 1);
  geo.addPoint(2, {2, 0, 0}, 1);
  geo.addPoint(3, {0, 1, 0}, 1);
  geo.addPoint(4, {0, 0, 0.5}, 1);
  geo.addEllipseArc(1, 2, 1, 2, 3);
  geo.addEllipseArc(2, 3, 1, 3, 4);
  geo.addEllipseArc(3, 4, 1, 2, 2);
  geo.addCurveLoop(1, {1, 2, 3});
  geo.addFillingSurface(1, {1}, {});
  Model model;
  geo.synchronize(model);
  const SurfaceGeometry& s = *model.surface(1)->geometry;
  const Vec2 corners[3] = {{0, 0}, {1, 0}, {1, 1}};
  for (int k = 0; k < 3; ++k) {
    const Vec2 c = corners[k];
    const Vec3 at = s.point(c);
    // Towards the triangle's inside from corner k, along rays between its two sides.
    const Vec2 a = corners[(k + 1) % 3], b = corners[(k + 2) % 3];
    for (double t : {0.1, 0.5, 0.9}) {
      const Vec2 dir{(1 - t) * (a.u - c.u) + t * (b.u - c.u),
                     (1 - t) * (a.v - c.v) + t * (b.v - c.v)};
      const double e = 1e-7;
      EXPECT_LT(distance(s.point({c.u + e * dir.u, c.v + e * dir.v}), at), 1e-5) << k << " " << t;
    }
  }
  expectDerivativesMatch(s, {0.6, 0.2}, 1e-6);
}

// An octant of the unit sphere bounded by three quarter circles about the origin: the filling
// surface lies on the sphere, as in Gmsh, rather than bulging out of it.
TEST(GeoSurfaces, FillingSurfaceOfArcsOfOneSphereLiesOnIt) {
  GeoFactory geo;
  geo.addPoint(1, {0, 0, 0}, 1);
  geo.addPoint(2, {1, 0, 0}, 1);
  geo.addPoint(3, {0, 1, 0}, 1);
  geo.addPoint(4, {0, 0, 1}, 1);
  geo.addCircleArc(1, 2, 1, 3);
  geo.addCircleArc(2, 3, 1, 4);
  geo.addCircleArc(3, 4, 1, 2);
  geo.addCurveLoop(1, {1, 2, 3});
  geo.addFillingSurface(1, {1}, {});
  Model model;
  geo.synchronize(model);
  const SurfaceGeometry& s = *model.surface(1)->geometry;
  // Surface area over the triangle 0 <= v <= u <= 1, with v = u t: the midpoint rule in (u, t).
  constexpr int kCells = 200;
  double area = 0;
  for (int i = 0; i < kCells; ++i)
    for (int j = 0; j < kCells; ++j) {
      const double u = (i + 0.5) / kCells, t = (j + 0.5) / kCells;
      EXPECT_NEAR(norm(s.point({u, u * t})), 1, 1e-12);
      const SurfaceDerivatives d = s.firstDerivatives({u, u * t});
      area += norm(cross(d.du, d.dv)) * u / (kCells * kCells);
    }
  EXPECT_NEAR(area, std::acos(-1.0) / 2, 1e-3);
  expectDerivativesMatch(s, {0.6, 0.2}, 1e-7);
  const Vec2 uv = s.project(s.point({0.7, 0.3}));
  EXPECT_NEAR(uv.u, 0.7, 1e-9);
  EXPECT_NEAR(uv.v, 0.3, 1e-9);
}

TEST(GeoEmbedding, RecordsEmbeddedEntitiesAndPeriodicity) {
  GeoFactory geo;
  addUnitSquareSurface(geo);
  geo.addPoint(5, {0.5, 0.5, 0}, 1);
  geo.embed(0, {5}, 2, 1);
  geo.setPeriodic(1, {3}, {1}, AffineMap::translation({0, 1, 0}));
  geo.addPhysicalGroup(1, 7, "walls", {1, 2, 3});
  geo.removeFromPhysicalGroup(1, 7, {2});
  Model model;
  geo.synchronize(model);
  EXPECT_EQ(model.surface(1)->embeddedPoints, (std::vector<int>{5}));
  ASSERT_TRUE(model.curve(3)->periodic);
  EXPECT_EQ(model.curve(3)->periodic->master, 1);
  EXPECT_EQ(model.curve(3)->periodic->affine[7], 1);
  EXPECT_EQ(model.physicalGroups().at({1, 7}).entities, (std::vector<int>{1, 3}));
  EXPECT_THROW(geo.embed(2, {1}, 1, 1), GeometryError);
}

// Two unit squares: surface 1 in the plane y = 0 from x = 1 to 2, surface 2 its image by a
// quarter turn about the z axis (in the plane x = 0 from y = 1 to 2).
void addSquarePair(GeoFactory& geo) {
  const Vec3 corners[4] = {{1, 0, 0}, {2, 0, 0}, {2, 0, 1}, {1, 0, 1}};
  for (int k = 0; k < 4; ++k) {
    geo.addPoint(k + 1, corners[k], 1);
    geo.addPoint(k + 5, {-corners[k].y, corners[k].x, corners[k].z}, 1);
  }
  for (int k = 0; k < 4; ++k) {
    geo.addLine(k + 1, k + 1, (k + 1) % 4 + 1);
    geo.addLine(k + 5, k + 5, (k + 1) % 4 + 5);
  }
  geo.addCurveLoop(1, {1, 2, 3, 4});
  geo.addCurveLoop(2, {5, 6, 7, 8});
  geo.addPlaneSurface(1, {1});
  geo.addPlaneSurface(2, {2});
}

TEST(GeoEmbedding, PeriodicSurfaceFromCurvesFindsTheRigidMotion) {
  GeoFactory geo;
  addSquarePair(geo);
  geo.setPeriodicByCurves(2, {5, 6, 7, 8}, 1, {1, 2, 3, 4});
  Model model;
  geo.synchronize(model);
  ASSERT_TRUE(model.surface(2)->periodic);
  EXPECT_EQ(model.surface(2)->periodic->master, 1);
  const std::vector<double> quarterTurn{0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  for (std::size_t k = 0; k < 16; ++k)
    EXPECT_NEAR(model.surface(2)->periodic->affine[k], quarterTurn[k], 1e-12) << k;
}

TEST(GeoEmbedding, PeriodicSurfaceFromCurvesNeedsARigidMotion) {
  GeoFactory geo;
  addSquarePair(geo);
  // A quadrangle that is not a unit square is no image of surface 1.
  geo.addPoint(9, {0, 3, 1}, 1);
  geo.addLine(9, 6, 9);
  geo.addLine(10, 9, 8);
  geo.addCurveLoop(3, {5, 9, 10, 8});
  geo.addPlaneSurface(3, {3});
  EXPECT_THROW(geo.setPeriodicByCurves(3, {5, 9, 10, 8}, 1, {1, 2, 3, 4}), GeometryError);
  EXPECT_THROW(geo.setPeriodicByCurves(2, {5, 6, 7}, 1, {1, 2, 3, 4}), GeometryError);
  // A master point cannot have two images.
  EXPECT_THROW(geo.setPeriodicByCurves(2, {5, 5, 7, 8}, 1, {1, 2, 3, 4}), GeometryError);
}

}  // namespace
}  // namespace geomesh
