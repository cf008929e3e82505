// The OpenCASCADE factory's extrusions and revolutions: shapes, records and tags.
#include <gtest/gtest.h>

#include <numbers>

#include "kernel/geometry_error.h"
#include "kernel/occ/occ_factory.h"

namespace geomesh {
namespace {

std::vector<int> tagList(const std::vector<EntityId>& shapes) {
  std::vector<int> tags;
  for (const EntityId& e : shapes) tags.push_back(e.tag);
  return tags;
}

// Extrusions list, for each shape, its top, the swept entity and the lateral ones, with the
// tags the reference gives.
TEST(OccExtrude, PrismsOfSurfaces) {
  OccFactory occ;
  occ.addRectangle(1, {0, 0, 0}, 2, 1);
  occ.addDisk(2, {5, 0, 0}, 1, 1);
  const std::vector<EntityId> r =
      occ.extrude({{2, 1}, {2, 2}}, ExtrusionMotion::translate({0, 0, 1}), {});
  EXPECT_EQ(tagList(r), (std::vector<int>{7, 1, 3, 4, 5, 6, 9, 2, 8}));
  EXPECT_EQ(r[1], (EntityId{3, 1}));
  EXPECT_NEAR(occ.volume(1), 2, 1e-9);
  EXPECT_NEAR(occ.volume(2), std::numbers::pi, 1e-9);
  EXPECT_EQ(occ.maxTag(1), 15);
}

TEST(OccExtrude, CurveThenSurfaceThenRevolution) {
  OccFactory occ;
  occ.addPoint(1, {0, 0, 0}, 0);
  occ.addPoint(2, {1, 0, 0}, 0);
  occ.addLine(1, 1, 2);
  ExtrusionLayers layers;
  layers.elements = {4};
  layers.heights = {1};
  std::vector<EntityId> r = occ.extrude({{1, 1}}, ExtrusionMotion::translate({0, 1, 0}), layers);
  EXPECT_EQ(tagList(r), (std::vector<int>{4, 1, 2, 3}));
  r = occ.extrude({{2, 1}}, ExtrusionMotion::translate({0, 0, 1}), {});
  EXPECT_EQ(tagList(r), (std::vector<int>{6, 1, 2, 3, 4, 5}));
  const auto quarterTurn = ExtrusionMotion::rotate({0, 0, 1}, {0, 0, 0}, std::numbers::pi / 2);
  r = occ.extrude({{0, 2}}, quarterTurn, {});
  EXPECT_EQ(r, (std::vector<EntityId>{{0, 9}, {1, 13}}));
  EXPECT_NEAR(occ.length(13), std::numbers::pi / 2, 1e-9);
  Model model;
  occ.synchronize(model);
  ASSERT_TRUE(model.surface(1)->extrusion.has_value());
  EXPECT_EQ(model.surface(1)->extrusion->source, 1);
  EXPECT_EQ(model.surface(1)->extrusion->top, 4);
  EXPECT_EQ(model.surface(1)->extrusion->layers.elements, (std::vector<int>{4}));
  EXPECT_FALSE(model.volume(1)->extrusion->layers.elements.size());
}

TEST(OccExtrude, RevolvedSurfaces) {
  OccFactory occ;
  occ.addRectangle(1, {1, 0, 0}, 1, 1);
  const auto quarter = ExtrusionMotion::rotate({0, 1, 0}, {0, 0, 0}, std::numbers::pi / 2);
  const std::vector<EntityId> r = occ.extrude({{2, 1}}, quarter, {});
  EXPECT_EQ(r.size(), 6u);
  EXPECT_NEAR(occ.volume(r[1].tag), std::numbers::pi / 2 * (4 - 1) / 2, 1e-9);
  EXPECT_THROW(occ.extrude({{2, 1}}, ExtrusionMotion::twist({0, 0, 1}, {0, 0, 1}, {}, 1), {}),
               GeometryError);
  EXPECT_THROW(occ.extrude({{3, 1}}, ExtrusionMotion::translate({0, 0, 1}), {}), GeometryError);
}

// A whole turn: OpenCASCADE keeps no history for it, yet the list is the reference's: the
// profile (its own far face), the volume, then one face per curve off the axis.
TEST(OccExtrude, WholeTurns) {
  OccFactory occ;
  occ.addRectangle(1, {1, 0, 0}, 1, 1);  // in the xy plane, off the y axis
  const auto turn = ExtrusionMotion::rotate({0, 1, 0}, {0, 0, 0}, 2 * std::numbers::pi);
  std::vector<EntityId> r = occ.extrude({{2, 1}}, turn, {});
  EXPECT_EQ(r, (std::vector<EntityId>{{2, 1}, {3, 1}, {2, 2}, {2, 3}, {2, 4}, {2, 5}}));
  EXPECT_NEAR(occ.volume(1), std::numbers::pi * (4 - 1), 1e-9);
  // A profile with a side on the axis: that side sweeps nothing.
  occ.addRectangle(10, {0, 5, 0}, 1, 1);
  r = occ.extrude({{2, 10}}, turn, {});
  ASSERT_EQ(r.size(), 5u);
  EXPECT_EQ(r[0], (EntityId{2, 10}));
  EXPECT_EQ(r[1].dim, 3);
  EXPECT_NEAR(occ.volume(r[1].tag), std::numbers::pi, 1e-9);
}

// Extrude Using Wire: a disk swept along a straight wire is a cylinder; the result is the
// volume alone, as the reference returns it.
TEST(OccExtrude, AlongAWire) {
  OccFactory occ;
  occ.addPoint(1, {0, 0, 0}, 0);
  occ.addPoint(2, {0, 0, 2}, 0);
  occ.addLine(1, 1, 2);
  occ.addWire(1, {1});
  occ.addDisk(1, {0, 0, 0}, 0.5, 0.5);
  const std::vector<EntityId> r = occ.extrudeAlongWire({{2, 1}}, 1);
  EXPECT_EQ(r, (std::vector<EntityId>{{3, 1}}));
  EXPECT_NEAR(occ.volume(1), std::numbers::pi * 0.25 * 2, 1e-6);
  EXPECT_THROW(occ.extrudeAlongWire({{2, 1}}, 7), GeometryError);
}

// The mesh size the model gives the point at `at` (-1 if there is none there).
double sizeAt(const Model& model, Vec3 at) {
  for (const auto& [tag, p] : model.points())
    if (distance(p.xyz, at) < 1e-9) return p.meshSize;
  return -1;
}

// As in the reference, the points an extrusion makes have the mesh sizes of the points they
// were swept from, as these were when swept; a point swept from one with no size has none.
TEST(OccExtrude, NewPointsTakeTheMeshSizesOfTheirSources) {
  OccFactory occ;
  occ.addPoint(1, {0, 0, 0}, 0.1);
  occ.addPoint(2, {1, 0, 0}, 0.2);
  occ.addPoint(3, {1, 1, 0}, 0.3);
  occ.addPoint(4, {0, 1, 0}, 0);
  for (int i = 1; i <= 4; ++i) occ.addLine(i, i, i % 4 + 1);
  occ.addCurveLoop(1, {1, 2, 3, 4});
  occ.addPlaneSurface(1, {1});
  occ.extrude({{2, 1}}, ExtrusionMotion::translate({0, 0, 1}), {});
  occ.addPoint(20, {5, 0, 0}, 0.05);
  occ.extrude({{0, 20}}, ExtrusionMotion::rotate({0, 1, 0}, {4, 0, 0}, std::numbers::pi), {});
  occ.setMeshSize({20}, 0.5);  // after the sweep: the swept point keeps 0.05
  Model model;
  occ.synchronize(model);
  EXPECT_DOUBLE_EQ(sizeAt(model, {0, 0, 1}), 0.1);
  EXPECT_DOUBLE_EQ(sizeAt(model, {1, 0, 1}), 0.2);
  EXPECT_DOUBLE_EQ(sizeAt(model, {1, 1, 1}), 0.3);
  EXPECT_DOUBLE_EQ(sizeAt(model, {0, 1, 1}), 0);
  EXPECT_DOUBLE_EQ(sizeAt(model, {3, 0, 0}), 0.05);
  EXPECT_DOUBLE_EQ(sizeAt(model, {5, 0, 0}), 0.5);
}

// A point swept from one with no size has none, even under the tag of a removed point that
// had one.
TEST(OccExtrude, NewPointsDoNotTakeTheSizeOfARemovedPoint) {
  OccFactory occ;
  occ.addPoint(1, {0, 0, 0}, 0);
  occ.addPoint(2, {1, 0, 0}, 0.5);
  occ.remove({{0, 2}}, false);
  const std::vector<EntityId> r = occ.extrude({{0, 1}}, ExtrusionMotion::translate({0, 0, 1}), {});
  ASSERT_EQ(r[0], (EntityId{0, 2}));
  Model model;
  occ.synchronize(model);
  EXPECT_DOUBLE_EQ(sizeAt(model, {0, 0, 1}), 0);
}

// Extrude Using Wire: the reference gives a point the size of a point at the same place, so
// the copies of the profile's points at the start of the pipe have their sizes; the points
// at its far end have none.
TEST(OccExtrude, PipeStartPointsTakeTheSizesOfTheProfilePoints) {
  OccFactory occ;
  occ.addPoint(1, {0, 0, 5}, 0.3);
  occ.addPoint(2, {0, 0, 6}, 0.4);
  occ.addLine(1, 1, 2);
  occ.addWire(1, {1});
  occ.addPoint(10, {0.2, 0, 5}, 0.01);
  occ.addPoint(11, {0.4, 0, 5}, 0.02);
  occ.addLine(10, 10, 11);
  occ.extrudeAlongWire({{1, 10}}, 1);
  Model model;
  occ.synchronize(model);
  int atStart = 0;
  for (const auto& [tag, p] : model.points()) {
    if (tag <= 11) continue;
    if (p.xyz.z == 5) {
      ++atStart;
      EXPECT_DOUBLE_EQ(p.meshSize, p.xyz.x < 0.3 ? 0.01 : 0.02) << "point " << tag;
    } else {
      EXPECT_EQ(p.meshSize, 0) << "point " << tag;
    }
  }
  EXPECT_EQ(atStart, 2);
}

}  // namespace
}  // namespace geomesh
