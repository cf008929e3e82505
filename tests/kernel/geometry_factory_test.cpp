// The factory interface: unsupported operations, the fallback factory, the selection, and
// what curves and surfaces say they are.
#include "kernel/geometry_factory.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "kernel/factory_selection.h"
#include "kernel/fallback_factory.h"
#include "kernel/occ/occ_factory.h"
#include "tests/kernel/kernel_test_helpers.h"

namespace geomesh {
namespace {

TEST(UnsupportedOperation, NamesTheOperationAndTheFactory) {
  OccFactory occ;
  GeometryFactory& factory = occ;
  try {
    factory.setPeriodicByCurves(2, {5}, 1, {1});
    FAIL() << "no exception";
  } catch (const UnsupportedOperation& e) {
    EXPECT_EQ(e.operation(), "Periodic");
    EXPECT_EQ(e.factory(), "OpenCASCADE");
    EXPECT_STREQ(e.what(), "'Periodic' is not supported by the OpenCASCADE factory");
  }
  GeoFactory geo;
  GeometryFactory& builtIn = geo;
  EXPECT_THROW(builtIn.addBox(1, {0, 0, 0}, {1, 1, 1}), UnsupportedOperation);
  EXPECT_THROW(builtIn.addBox(1, {0, 0, 0}, {1, 1, 1}), GeometryError);  // its base
}

TEST(OccFactory, AnswersQueriesAboutItsShapes) {
  OccFactory occ;
  occ.addBox(2, {1, 2, 3}, {1, 1, 2});
  EXPECT_TRUE(occ.contains({3, 2}));
  EXPECT_FALSE(occ.contains({3, 1}));
  EXPECT_TRUE(occ.hasPoint(8));
  EXPECT_FALSE(occ.hasPoint(9));
  EXPECT_EQ(occ.tags(2), (std::vector<int>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(occ.maxTag(GeometryFactory::kCurveLoop), 0);
  // As the reference gives it: OpenCASCADE's box, with the shape's tolerance around it.
  const BoundingBox box = occ.boundingBox({3, 2});
  expectNear(box.min, {1 - 1e-7, 2 - 1e-7, 3 - 1e-7}, 1e-12);
  expectNear(box.max, {2 + 1e-7, 3 + 1e-7, 5 + 1e-7}, 1e-12);
  const Vec3 p = occ.pointCoordinates(1);
  EXPECT_TRUE(p.x == 1 || p.x == 2);
  EXPECT_THROW(occ.pointCoordinates(9), GeometryError);
}

TEST(OccFactory, PointsOfAndMeshSizes) {
  OccFactory occ;
  occ.addBox(1, {0, 0, 0}, {1, 1, 1});
  std::vector<int> points = occ.pointsOf({{3, 1}});
  std::sort(points.begin(), points.end());
  EXPECT_EQ(points, (std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8}));
  EXPECT_EQ(occ.pointsOf({{1, -1}}).size(), 2u);
  EXPECT_THROW(occ.pointsOf({{3, 2}}), GeometryError);
  occ.setMeshSize({2, 5}, 0.25);
  EXPECT_THROW(occ.setMeshSize({9}, 0.25), GeometryError);
  Model model;
  occ.synchronize(model);
  EXPECT_EQ(model.point(2)->meshSize, 0.25);
  EXPECT_EQ(model.point(5)->meshSize, 0.25);
  EXPECT_EQ(model.point(1)->meshSize, 0);
}

TEST(OccFactory, BoundaryOfTheBoxsShapes) {
  OccFactory occ;
  occ.addBox(1, {0, 0, 0}, {1, 1, 1});
  const std::vector<EntityId> faces = occ.boundary({{3, 1}}, false);
  ASSERT_EQ(faces.size(), 6u);
  for (EntityId f : faces) EXPECT_EQ(f.dim, 2);
  EXPECT_EQ(occ.boundary({{2, 1}}, false).size(), 4u);
  const std::vector<EntityId> ends = occ.boundary({{1, 1}}, false);
  ASSERT_EQ(ends.size(), 2u);
  const std::vector<EntityId> reversed = occ.boundary({{1, -1}}, false);
  EXPECT_EQ(reversed[0], ends[1]);
  EXPECT_EQ(reversed[1], ends[0]);
  Model model;
  occ.synchronize(model);
  EXPECT_EQ(model.curve(1)->startPoint, ends[0].tag);
  // Two faces of the box share one edge: 4 + 4 - 2.
  std::vector<EntityId> shared;
  for (int face = 2; face <= 6 && shared.empty(); ++face)
    if (cancelShared(occ.boundary({{2, 1}, {2, face}}, false)).size() == 6)
      shared = occ.boundary({{2, 1}, {2, face}}, true);
  EXPECT_EQ(shared.size(), 6u);
  EXPECT_TRUE(std::is_sorted(shared.begin(), shared.end()));
  EXPECT_TRUE(occ.boundary({{3, 1}}, true).size() == 6u);
  EXPECT_THROW(occ.boundary({{3, 2}}, false), GeometryError);
}

// Records the operations handed over.
struct Handovers {
  std::vector<std::string> operations;
  FallbackFactory::Handover callback() {
    return [this](const UnsupportedOperation& e) { operations.push_back(e.operation()); };
  }
};

TEST(FallbackFactory, HandsOverWhatThePrimaryCannotDo) {
  OccFactory occ;
  GeoFactory geo;
  FallbackFactory factory(occ, geo);
  Handovers handovers;
  factory.onHandover(handovers.callback());
  EXPECT_EQ(factory.name(), "OpenCASCADE");
  EXPECT_EQ(factory.addBox(-1, {0, 0, 0}, {1, 1, 1}), 1);
  geo.addPoint(20, {5, 0, 0}, 0.5);  // built-in entities beside the box
  geo.addPoint(21, {6, 0, 0}, 0.5);
  geo.addLine(30, 20, 21);
  // Curves of the built-in kernel are not the OpenCASCADE factory's to match: the built-in
  // one tries (and finds no surface 2).
  EXPECT_THROW(factory.setPeriodicByCurves(2, {30}, 1, {30}), GeometryError);
  EXPECT_EQ(handovers.operations, (std::vector<std::string>{"Periodic"}));
  EXPECT_TRUE(occ.contains({3, 1}));
  EXPECT_TRUE(geo.contains({1, 30}));
  EXPECT_FALSE(occ.contains({0, 20}));
  // Queries see both.
  EXPECT_EQ(factory.maxTag(0), 21);
  EXPECT_EQ(factory.maxTag(1), 30);
  EXPECT_TRUE(factory.contains({3, 1}) && factory.contains({0, 21}));
  expectNear(factory.pointCoordinates(21), {6, 0, 0});
  EXPECT_EQ(factory.tags(1).size(), 13u);
  // Physical groups live in the fallback, without a handover.
  factory.addPhysicalGroup(3, 1, "box", {1});
  EXPECT_EQ(geo.physicalGroups().size(), 1u);
  EXPECT_EQ(handovers.operations.size(), 1u);
  Model model;
  factory.synchronize(model);
  EXPECT_EQ(model.points().size(), 10u);
  EXPECT_EQ(model.volumes().size(), 1u);
  ASSERT_TRUE(model.physicalGroups().contains({3, 1}));
  EXPECT_EQ(model.physicalGroups().at({3, 1}).entities, std::vector<int>{1});
}

TEST(FallbackFactory, SizesAndPointsOfGoToTheFactoryHoldingThem) {
  OccFactory occ;
  GeoFactory geo;
  FallbackFactory factory(occ, geo);
  Handovers handovers;
  factory.onHandover(handovers.callback());
  factory.addBox(1, {0, 0, 0}, {1, 1, 1});
  geo.addPoint(20, {5, 0, 0}, 0);
  factory.setMeshSize({1, 20}, 0.5);
  EXPECT_EQ(geo.points().at(20).meshSize, 0.5);
  std::vector<int> points = factory.pointsOf({{0, 20}, {3, 1}});
  EXPECT_EQ(points.size(), 9u);
  EXPECT_EQ(points.front(), 20);
  EXPECT_TRUE(handovers.operations.empty());
  EXPECT_THROW(factory.setMeshSize({99}, 1), GeometryError);
  Model model;
  factory.synchronize(model);
  EXPECT_EQ(model.point(1)->meshSize, 0.5);
}

TEST(FallbackFactory, ErrorsOfTheFallbackPassThrough) {
  OccFactory occ;
  GeoFactory geo;
  FallbackFactory factory(occ, geo);
  EXPECT_THROW(factory.addLine(1, 1, 2), GeometryError);  // no such points
  EXPECT_THROW(factory.addBox(1, {0, 0, 0}, {0, 1, 1}), GeometryError);
}

TEST(FactorySelection, SelectsByTheScriptsNames) {
  FactorySelection factories;
  EXPECT_EQ(factories.current().name(), "Built-in");
  EXPECT_TRUE(factories.select("OpenCASCADE"));
  EXPECT_EQ(factories.current().name(), "OpenCASCADE");
  EXPECT_FALSE(factories.select("Parasolid"));
  EXPECT_EQ(factories.current().name(), "OpenCASCADE");
  EXPECT_TRUE(factories.select("Geo"));
  EXPECT_EQ(factories.current().name(), "Built-in");
  EXPECT_TRUE(factories.select("built-in"));
  EXPECT_FALSE(factories.hasEntities());
}

TEST(FactorySelection, SynchronizesEveryFactoryIntoOneModel) {
  FactorySelection factories;
  factories.select("OpenCASCADE");
  factories.current().addBox(1, {0, 0, 0}, {1, 1, 1});
  factories.select("Built-in");
  factories.current().addPoint(100, {3, 0, 0}, 0);
  EXPECT_TRUE(factories.hasEntities());
  Model model;
  model.addPoint(ModelPoint{500, {9, 9, 9}, 0});  // stale: synchronize starts afresh
  factories.synchronize(model);
  EXPECT_EQ(model.points().size(), 9u);
  EXPECT_EQ(model.volumes().size(), 1u);
  EXPECT_FALSE(model.contains({0, 500}));
  factories.clear();
  EXPECT_FALSE(factories.hasEntities());
}

TEST(CurveKind, BuiltInCurvesSayWhatTheyAre) {
  GeoFactory geo;
  geo.addPoint(1, {1, 0, 0}, 0);
  geo.addPoint(2, {0, 0, 0}, 0);
  geo.addPoint(3, {0, 1, 0}, 0);
  geo.addPoint(4, {0, 2, 0}, 0);
  geo.addLine(1, 1, 2);
  geo.addCircleArc(2, 1, 2, 3);
  geo.addEllipseArc(3, 1, 2, 1, 4);
  geo.addSpline(4, {1, 3, 4});
  geo.addBSpline(5, {1, 3, 4});
  geo.addBezier(6, {1, 3, 4});
  Model model;
  geo.synchronize(model);
  const CurveKind expected[] = {CurveKind::Line,   CurveKind::CircleArc, CurveKind::EllipseArc,
                                CurveKind::Spline, CurveKind::BSpline,   CurveKind::Bezier};
  for (int tag = 1; tag <= 6; ++tag)
    EXPECT_EQ(model.curve(tag)->geometry->kind(), expected[tag - 1]) << "curve " << tag;
  EXPECT_NEAR(model.curve(2)->geometry->arcAngle(), std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(model.curve(3)->geometry->arcAngle(), std::numbers::pi / 2, 1e-12);
}

TEST(CurveKind, ClosedBSplineMovesItsEndPointOntoTheCurve) {
  GeoFactory geo;
  const Vec3 control[] = {{0, 0, 0}, {1, 0.2, 0}, {2, 0, 0}, {1.6, 1, 0}, {1, 1.6, 0}, {0.2, 0.8, 0}};
  for (int i = 0; i < 6; ++i) geo.addPoint(i + 1, control[i], 0);
  geo.addBSpline(1, {1, 2, 3, 4, 5, 6, 1});
  Model model;
  geo.synchronize(model);
  // A uniform cubic periodic B-spline starts at (last + 4 first + second) / 6.
  const Vec3 start = model.point(1)->xyz;
  EXPECT_NEAR(start.x, 0.2, 1e-12);
  EXPECT_NEAR(start.y, 1.0 / 6.0, 1e-12);
  const auto& curve = *model.curve(1)->geometry;
  const Vec3 a = curve.point(curve.range().min), b = curve.point(curve.range().max);
  EXPECT_LT(norm(a - start), 1e-12);
  EXPECT_LT(norm(b - start), 1e-12);
  EXPECT_EQ(model.point(2)->xyz.x, 1.0);  // the other control points stay
}

TEST(SurfaceKind, PlanesAndBoxFacesArePlanes) {
  GeoFactory geo;
  addUnitSquareSurface(geo);
  OccFactory occ;
  occ.addBox(1, {0, 0, 5}, {1, 1, 1});
  Model model;
  occ.synchronize(model);
  for (const auto& [tag, curve] : model.curves())
    EXPECT_EQ(curve.geometry->kind(), CurveKind::Line) << "curve " << tag;
  for (const auto& [tag, surface] : model.surfaces()) {
    EXPECT_EQ(surface.geometry->kind(), SurfaceKind::Plane) << "surface " << tag;
    EXPECT_TRUE(surface.geometry->isPlane());
  }
  Model squareModel;
  geo.synchronize(squareModel);
  EXPECT_EQ(squareModel.surface(1)->geometry->kind(), SurfaceKind::Plane);
}

}  // namespace
}  // namespace geomesh
