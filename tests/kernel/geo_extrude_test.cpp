// Extrusions of the built-in kernel: result lists and tags as the built-in kernel of Gmsh
// gives them, and the geometry of the swept entities.
#include <gtest/gtest.h>

#include <cmath>

#include "kernel/geo/geo_factory.h"
#include "kernel/geometry_error.h"
#include "tests/kernel/kernel_test_helpers.h"

namespace geomesh {
namespace {

const double kPi = std::acos(-1.0);

std::vector<EntityId> ids(std::initializer_list<std::pair<int, int>> list) {
  std::vector<EntityId> out;
  for (auto [dim, tag] : list) out.push_back({dim, tag});
  return out;
}

const ExtrusionLayers kNoLayers{};

TEST(GeoExtrude, LineSweepsASurfaceWithGmshTags) {
  GeoFactory geo;
  geo.addPoint(1, {0, 0, 0}, 1);
  geo.addPoint(2, {1, 0, 0}, 1);
  geo.addLine(1, 1, 2);
  const auto out = geo.extrude({{1, 1}}, ExtrusionMotion::translate({0, 1, 0}), kNoLayers);
  EXPECT_EQ(out, ids({{1, 2}, {2, 5}, {1, 4}, {1, -3}}));
  EXPECT_EQ(geo.maxTag(0), 4);
  EXPECT_EQ(geo.curves().at(2).points, (std::vector<int>{3, 4}));
  EXPECT_EQ(geo.surfaces().at(5).loops.front(), (std::vector<int>{1, 4, -2, -3}));
}

TEST(GeoExtrude, ExistingSweptPointIsReused) {
  GeoFactory geo;
  geo.addPoint(1, {0, 0, 0}, 1);
  geo.addPoint(2, {1, 0, 0}, 1);
  geo.addLine(1, 1, 2);
  const auto motion = ExtrusionMotion::translate({0, 1, 0});
  EXPECT_EQ(geo.extrude({{0, 1}}, motion, kNoLayers), ids({{0, 3}, {1, 2}}));
  EXPECT_EQ(geo.extrude({{1, 1}}, motion, kNoLayers),
            ids({{1, 3}, {2, 6}, {1, 5}, {1, -2}}));
  EXPECT_EQ(geo.maxTag(0), 5);
}

TEST(GeoExtrude, SeveralShapesAreMergedOneAfterTheOther) {
  GeoFactory geo;
  for (int i = 0; i < 3; ++i) geo.addPoint(i + 1, {double(i), 0, 0}, 1);
  geo.addLine(1, 1, 2);
  geo.addLine(2, 2, 3);
  EXPECT_EQ(geo.extrude({{1, 1}, {1, 2}}, ExtrusionMotion::translate({0, 1, 0}), kNoLayers),
            ids({{1, 3}, {2, 6}, {1, 5}, {1, -4}, {1, 7}, {2, 10}, {1, 9}, {1, -5}}));
  EXPECT_EQ(geo.extrude({{0, 1}, {0, 2}}, ExtrusionMotion::translate({0, 0, 1}), kNoLayers),
            ids({{0, 8}, {1, 11}, {0, 9}, {1, 12}}));
}

TEST(GeoExtrude, SurfaceSweepsAVolumeWithGmshTags) {
  GeoFactory geo;
  addUnitSquareSurface(geo);
  const auto out = geo.extrude({{2, 1}}, ExtrusionMotion::translate({0, 0, 1}), kNoLayers);
  EXPECT_EQ(out, ids({{2, 26}, {3, 1}, {2, 13}, {2, 17}, {2, 21}, {2, 25}}));
  EXPECT_EQ(geo.maxTag(0), 14);
  EXPECT_EQ(geo.surfaces().at(26).loops.front(), (std::vector<int>{6, 7, 8, 9}));
  EXPECT_EQ(geo.curves().at(7).points, (std::vector<int>{6, 10}));
  EXPECT_EQ(geo.curves().at(20).points, (std::vector<int>{4, 14}));
  EXPECT_EQ(geo.volumes().at(1).shells.front(), (std::vector<int>{1, 26, 13, 17, 21, 25}));
  Model model;
  geo.synchronize(model);
  const auto& lateral = *model.surface(13)->geometry;
  const Vec3 p = lateral.point({0.5, 0.25});
  EXPECT_NEAR(p.x, 0.5, 1e-14);
  EXPECT_NEAR(p.z, 0.25, 1e-14);
}

TEST(GeoExtrude, ReversedBoundaryCurvesAreSweptAsTheLoopRuns) {
  GeoFactory geo;
  geo.addPoint(1, {0, 0, 0}, 1);
  geo.addPoint(2, {1, 0, 0}, 1);
  geo.addPoint(3, {1, 1, 0}, 1);
  geo.addPoint(4, {0, 1, 0}, 1);
  geo.addLine(1, 2, 1);
  geo.addLine(2, 2, 3);
  geo.addLine(3, 4, 3);
  geo.addLine(4, 4, 1);
  geo.addCurveLoop(1, {-1, 2, -3, 4});
  geo.addPlaneSurface(1, {1});
  const auto out = geo.extrude({{2, 1}}, ExtrusionMotion::translate({0, 0, 1}), kNoLayers);
  EXPECT_EQ(out, ids({{2, 26}, {3, 1}, {2, 13}, {2, 17}, {2, 21}, {2, 25}}));
  EXPECT_EQ(geo.curves().at(6).points, (std::vector<int>{5, 6}));
  EXPECT_EQ(geo.surfaces().at(13).loops.front(), (std::vector<int>{-1, 12, -6, -11}));
  EXPECT_EQ(geo.surfaces().at(21).loops.front(), (std::vector<int>{-3, 20, -8, -16}));
  EXPECT_EQ(geo.surfaces().at(26).loops.front(), (std::vector<int>{6, 7, 8, 9}));
  // The lateral surface of the reversed curve 1 runs it backwards: its loop, starting with
  // -1, goes counter-clockwise in the parameters (normal du x dv pointing out of the box).
  Model model;
  geo.synchronize(model);
  const SurfaceGeometry& side = *model.surface(13)->geometry;
  const Vec3 start = side.point({0, 0});
  EXPECT_NEAR(distance(start, {0, 0, 0}), 0, 1e-12);
  const SurfaceDerivatives d = side.firstDerivatives({0.5, 0.5});
  EXPECT_LT(cross(d.du, d.dv).y, 0);
}

TEST(GeoExtrude, PhysicalTagsCountInTheNumbering) {
  GeoFactory geo;
  addUnitSquareSurface(geo);
  const auto motion = ExtrusionMotion::translate({0, 0, 1});
  const auto first = geo.extrude({{2, 1}}, motion, kNoLayers);
  const auto second = geo.extrude({first[0]}, motion, kNoLayers);
  EXPECT_EQ(second, ids({{2, 48}, {3, 2}, {2, 35}, {2, 39}, {2, 43}, {2, 47}}));
  geo.addPhysicalGroup(3, 100, "", {1});
  EXPECT_EQ(geo.extrude({second[0]}, motion, kNoLayers),
            ids({{2, 122}, {3, 3}, {2, 109}, {2, 113}, {2, 117}, {2, 121}}));
}

TEST(GeoExtrude, RotationSweepsCircleArcsAroundNewCenters) {
  GeoFactory geo;
  geo.addPoint(1, {1, 0, 0}, 1);
  geo.addPoint(2, {2, 0, 0}, 1);
  geo.addLine(1, 1, 2);
  const auto motion = ExtrusionMotion::rotate({0, 0, 1}, {0, 0, 0}, kPi / 2);
  EXPECT_EQ(geo.extrude({{0, 2}}, motion, kNoLayers), ids({{0, 3}, {1, 2}}));
  EXPECT_EQ(geo.curves().at(2).points, (std::vector<int>{2, 4, 3}));
  EXPECT_EQ(geo.extrude({{1, 1}}, motion, kNoLayers), ids({{1, 3}, {2, 6}, {1, 2}, {1, -4}}));
  EXPECT_EQ(geo.maxTag(0), 5);
  Model model;
  geo.synchronize(model);
  // The swept surface is the quarter annulus.
  const auto& s = *model.surface(6)->geometry;
  const Vec3 p = s.point({0.5, 0.5});
  EXPECT_NEAR(std::hypot(p.x, p.y), 1.5, 1e-12);
  EXPECT_NEAR(std::atan2(p.y, p.x), kPi / 4, 1e-12);
  const Vec2 uv = s.project({1.2 * std::cos(0.3), 1.2 * std::sin(0.3), 0});
  EXPECT_NEAR(uv.u, 0.2, 1e-9);
  EXPECT_NEAR(uv.v, 0.3 / (kPi / 2), 1e-9);
  EXPECT_THROW(geo.extrude({{0, 1}}, ExtrusionMotion::rotate({0, 0, 1}, {}, kPi), kNoLayers),
               GeometryError);
}

TEST(GeoExtrude, TwistSweepsASplineThroughInnerPoints) {
  GeoFactory geo;
  geo.addPoint(1, {1, 0, 0}, 1);
  const auto motion = ExtrusionMotion::twist({0, 0, 1}, {0, 0, 1}, {0, 0, 0}, kPi / 2);
  EXPECT_EQ(geo.extrude({{0, 1}}, motion, kNoLayers), ids({{0, 6}, {1, 1}}));
  EXPECT_EQ(geo.curves().at(1).points, (std::vector<int>{1, 2, 3, 4, 5, 6}));
  const Vec3 second = geo.pointCoordinates(2);
  EXPECT_NEAR(second.x, std::cos(kPi / 10), 1e-12);
  EXPECT_NEAR(second.z, 0.2, 1e-12);
}

TEST(GeoExtrude, LayersAreRecordedOnSweptEntities) {
  GeoFactory geo;
  addUnitSquareSurface(geo);
  ExtrusionLayers layers{{4, 2}, {0.5, 1}, true};
  const auto out = geo.extrude({{2, 1}}, ExtrusionMotion::translate({0, 0, 2}), layers);
  Model model;
  geo.synchronize(model);
  const ModelVolume* volume = model.volume(out[1].tag);
  ASSERT_TRUE(volume && volume->extrusion);
  EXPECT_EQ(volume->extrusion->source, 1);
  EXPECT_EQ(volume->extrusion->layers, layers);
  EXPECT_EQ(volume->extrusion->top, out[0].tag);
  const ModelSurface* side = model.surface(out[2].tag);
  ASSERT_TRUE(side->extrusion);
  EXPECT_EQ(side->extrusion->source, 1);
  EXPECT_EQ(side->extrusion->top, 6);
  EXPECT_TRUE(side->extrusion->layers.recombine);
  EXPECT_EQ(model.curve(11)->extrusion->source, 1);
  EXPECT_EQ(model.curve(11)->extrusion->top, 5);
}

TEST(GeoExtrude, CircleArcsAreCopiedWithTheirCenters) {
  GeoFactory geo;
  geo.addPoint(1, {0, 0, 0}, 0.1);
  geo.addPoint(2, {1, 0, 0}, 0.1);
  geo.addPoint(3, {0, 1, 0}, 0.1);
  geo.addPoint(4, {-1, 0, 0}, 0.1);
  geo.addPoint(5, {0, -1, 0}, 0.1);
  for (int i = 0; i < 4; ++i) geo.addCircleArc(i + 1, i + 2, 1, (i + 1) % 4 + 2);
  geo.addCurveLoop(1, {1, 2, 3, 4});
  geo.addPlaneSurface(1, {1});
  const auto out = geo.extrude({{2, 1}}, ExtrusionMotion::translate({0, 0, 1}), kNoLayers);
  EXPECT_EQ(out, ids({{2, 26}, {3, 1}, {2, 13}, {2, 17}, {2, 21}, {2, 25}}));
  EXPECT_EQ(geo.maxTag(0), 18);
  EXPECT_EQ(geo.curves().at(6).points, (std::vector<int>{6, 7, 8}));
}

TEST(GeoExtrude, HolesAreSweptAgainstTheirGivenDirection) {
  GeoFactory geo;
  const Vec3 corners[] = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0},
                          {0.5, 0.5, 0}, {1.5, 0.5, 0}, {1, 1.5, 0}};
  for (int i = 0; i < 7; ++i) geo.addPoint(i + 1, corners[i], 0.1);
  for (int i = 1; i <= 4; ++i) geo.addLine(i, i, i % 4 + 1);
  geo.addLine(5, 5, 6);
  geo.addLine(6, 6, 7);
  geo.addLine(7, 7, 5);
  geo.addCurveLoop(1, {1, 2, 3, 4});
  geo.addCurveLoop(2, {5, 6, 7});
  geo.addPlaneSurface(1, {1, 2});
  const auto out = geo.extrude({{2, 1}}, ExtrusionMotion::translate({0, 0, 1}), kNoLayers);
  EXPECT_EQ(out, ids({{2, 44}, {3, 1}, {2, 19}, {2, 23}, {2, 27}, {2, 31}, {2, 35}, {2, 39},
                      {2, 43}}));
  EXPECT_EQ(geo.surfaces().at(35).loops.front(), (std::vector<int>{-7, 34, -13, -33}));
  const auto& top = geo.surfaces().at(44).loops;
  ASSERT_EQ(top.size(), 2u);
  EXPECT_EQ(top[1], (std::vector<int>{13, 14, 15}));
}

TEST(GeoExtrude, PointsOnTheAxisStayAndTheirSweepsVanish) {
  GeoFactory geo;
  addUnitSquareSurface(geo);
  const auto out =
      geo.extrude({{2, 1}}, ExtrusionMotion::rotate({0, 1, 0}, {0, 0, 0}, kPi / 2), kNoLayers);
  EXPECT_EQ(out, ids({{2, 21}, {3, 1}, {2, 12}, {2, 16}, {2, 19}}));
  EXPECT_EQ(geo.maxTag(0), 10);
  EXPECT_EQ(geo.surfaces().at(12).loops.front(), (std::vector<int>{1, 11, -6}));
  EXPECT_EQ(geo.surfaces().at(19).loops.front(), (std::vector<int>{-8, -15, 3}));
  EXPECT_EQ(geo.surfaces().at(21).loops.front(), (std::vector<int>{6, 7, 8, 4}));
  EXPECT_EQ(geo.curves().at(11).points, (std::vector<int>{2, 1, 6}));
  Model model;
  geo.synchronize(model);
  const Vec3 p = model.surface(12)->geometry->point({0.5, 1});
  EXPECT_NEAR(p.z, -0.5, 1e-12);
}

TEST(GeoExtrude, DuplicatedVolumesTakeTheSharedNumbering) {
  GeoFactory geo;
  addUnitSquareSurface(geo);
  const auto out = geo.extrude({{2, 1}}, ExtrusionMotion::translate({0, 0, 1}), kNoLayers);
  const auto copies = geo.duplicate({out[1]});
  EXPECT_EQ(copies.front(), (EntityId{3, 27}));
  geo.transform(copies, AffineMap::translation({0, 0, 0}));
  // Coherence merges the copied surfaces back, but keeps both volumes.
  EXPECT_EQ(geo.volumes().size(), 2u);
  EXPECT_EQ(geo.volumes().at(27).shells.front(), (std::vector<int>{1, 26, 13, 17, 21, 25}));
}

TEST(GeoExtrude, OptionsDropLateralsAndCoherence) {
  GeoFactory geo;
  addUnitSquareSurface(geo);
  geo.setExtrudeReturnsLateralEntities(false);
  geo.setAutoCoherence(false);
  const auto out = geo.extrude({{1, 1}}, ExtrusionMotion::translate({0, 0, 1}), kNoLayers);
  EXPECT_EQ(out, ids({{1, 5}, {2, 8}}));
  EXPECT_EQ(geo.maxTag(0), 10);  // the copies' points stay apart from the swept points
}

TEST(GeoExtrude, RejectsMotionsThatMoveNothing) {
  GeoFactory geo;
  geo.addPoint(1, {1, 0, 0}, 1);
  EXPECT_THROW(geo.extrude({{0, 1}}, ExtrusionMotion::translate({0, 0, 0}), kNoLayers),
               GeometryError);
  EXPECT_THROW(geo.extrude({{0, 1}}, ExtrusionMotion::rotate({0, 0, 1}, {}, 0), kNoLayers),
               GeometryError);
  EXPECT_THROW(geo.extrude({{0, 1}}, ExtrusionMotion::translate({0, 0, NAN}), kNoLayers),
               GeometryError);
  EXPECT_THROW(geo.transform({{0, 1}}, AffineMap::translation({INFINITY, 0, 0})), GeometryError);
  EXPECT_EQ(geo.maxTag(0), 1);
}

TEST(GeoExtrude, UndefinedShapeIsNamed) {
  GeoFactory geo;
  try {
    geo.extrude({{2, 7}}, ExtrusionMotion::translate({0, 0, 1}), kNoLayers);
    FAIL();
  } catch (const GeometryError& e) {
    EXPECT_STREQ(e.what(), "Extrude: Surface 7 is not defined");
  }
}

}  // namespace
}  // namespace geomesh
