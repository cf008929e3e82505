// HealShapes and the healing of imported files: loose faces sewn and made a solid, degenerated
// edges removed, solids kept, tags renumbered; scaling and units on import.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "kernel/geometry_error.h"
#include "kernel/occ/occ_factory.h"
#include "tests/scratch.h"

namespace geomesh {
namespace {

using Options = SolidModeling::HealingOptions;

// The six faces of the unit cube, each with its own points and curves.
void addLooseCube(OccFactory& occ) {
  const std::array<std::array<Vec3, 4>, 6> faces{{
      {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}},
      {{{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}},
      {{{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}},
      {{{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}}},
      {{{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}}},
      {{{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}},
  }};
  for (const auto& corners : faces) {
    const int p = occ.maxTag(0) + 1, c = occ.maxTag(1) + 1, s = occ.maxTag(2) + 1;
    for (int k = 0; k < 4; ++k) occ.addPoint(p + k, corners[static_cast<std::size_t>(k)], 0);
    for (int k = 0; k < 4; ++k) occ.addLine(c + k, p + k, p + (k + 1) % 4);
    occ.addCurveLoop(s, {c, c + 1, c + 2, c + 3});
    occ.addPlaneSurface(s, {s});
  }
}

TEST(OccHealing, SewsLooseFacesIntoASolidAndRenumbersFromOne) {
  OccFactory occ;
  addLooseCube(occ);
  ASSERT_EQ(occ.tags(0).size(), 24u);
  Options options;
  options.sewFaces = options.makeSolids = true;
  const std::vector<EntityId> healed = occ.healShapes({}, options);
  EXPECT_EQ(healed, (std::vector<EntityId>{{3, 1}}));
  EXPECT_EQ(occ.tags(2), (std::vector<int>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(occ.tags(1).size(), 12u);
  EXPECT_EQ(occ.tags(0).size(), 8u);
  EXPECT_NEAR(occ.volume(1), 1, 1e-12);
}

TEST(OccHealing, SewingKeepsTheSolidsBesideTheFaces) {
  // The reference loses the sphere here; geomesh keeps it.
  OccFactory occ;
  occ.addSphere(7, {3, 0, 0}, 0.5);
  addLooseCube(occ);
  Options options;
  options.sewFaces = options.makeSolids = true;
  occ.healShapes({}, options);
  EXPECT_EQ(occ.tags(3), (std::vector<int>{1, 2}));
  EXPECT_NEAR(occ.volume(1) + occ.volume(2), 1 + 4 * std::numbers::pi * 0.125 / 3, 1e-6);
}

TEST(OccHealing, SmallEdgesGoWithTheSpheresDegeneratedEdges) {
  OccFactory occ;
  occ.addSphere(1, {0, 0, 0}, 1);
  ASSERT_EQ(occ.tags(1).size(), 3u);  // the seam and the two poles
  Options options;
  options.fixSmallEdges = true;
  occ.healShapes({}, options);
  EXPECT_EQ(occ.tags(1), (std::vector<int>{1}));
  EXPECT_NEAR(occ.volume(1), 4 * std::numbers::pi / 3, 1e-6);
}

TEST(OccHealing, HealingSomeShapesLeavesTheOthersAlone) {
  OccFactory occ;
  occ.addBox(3, {5, 0, 0}, {1, 1, 1});
  addLooseCube(occ);
  Options options;
  options.sewFaces = options.makeSolids = true;
  std::vector<EntityId> faces;
  for (int s = 7; s <= 12; ++s) faces.push_back({2, s});
  const std::vector<EntityId> healed = occ.healShapes(faces, options);
  EXPECT_EQ(healed, (std::vector<EntityId>{{3, 4}}));
  EXPECT_EQ(occ.tags(3), (std::vector<int>{3, 4}));
  EXPECT_EQ(occ.tags(2).size(), 12u);
  EXPECT_NEAR(occ.volume(3), 1, 1e-12);
}

TEST(OccHealing, ImportSewsAndScales) {
  OccFactory maker;
  addLooseCube(maker);
  const std::string path = scratch::path("occ-loose-cube.brep");
  maker.exportShapes(path);
  OccFactory occ;
  Options healing;
  healing.sewFaces = healing.makeSolids = true;
  occ.setImportOptions({2, "", healing});
  EXPECT_EQ(occ.importShapes(path), (std::vector<EntityId>{{3, 1}}));
  EXPECT_NEAR(occ.volume(1), 8, 1e-9);
  std::remove(path.c_str());
}

TEST(OccHealing, ImportConvertsStepUnits) {
  OccFactory maker;
  maker.addBox(1, {0, 0, 0}, {10, 20, 30});
  const std::string path = scratch::path("occ-box-mm.step");
  maker.exportShapes(path);
  OccFactory occ;
  occ.setImportOptions({1, "M", {}});
  occ.importShapes(path);
  EXPECT_NEAR(occ.volume(1), 0.01 * 0.02 * 0.03, 1e-12);
  occ.setImportOptions({1, "", {}});  // millimetres again: the unit does not stick
  occ.importShapes(path);
  EXPECT_NEAR(occ.volume(2), 6000, 1e-6);
  occ.setImportOptions({1, "PARSEC", {}});
  EXPECT_THROW(occ.importShapes(path), GeometryError);
  occ.setImportOptions({-1, "", {}});
  EXPECT_THROW(occ.importShapes(path), GeometryError);
  std::remove(path.c_str());
}

}  // namespace
}  // namespace geomesh
