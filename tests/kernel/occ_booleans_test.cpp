// The OpenCASCADE factory's Booleans: the shapes they make and the tags they give, checked
// against what the reference gives the same operations.
#include <gtest/gtest.h>

#include <numbers>

#include "kernel/geometry_error.h"
#include "kernel/occ/occ_factory.h"

namespace geomesh {
namespace {

using Op = OccFactory::BooleanOperation;

std::vector<int> tagsOf(const std::vector<EntityId>& shapes) {
  std::vector<int> tags;
  for (const EntityId& e : shapes) tags.push_back(e.tag);
  return tags;
}

std::vector<int> counts(const OccFactory& occ) {
  std::vector<int> n;
  for (int dim = 0; dim <= 3; ++dim) n.push_back(static_cast<int>(occ.tags(dim).size()));
  return n;
}

// Two unit cubes overlapping on a cube of side 0.5.
OccFactory overlappingCubes() {
  OccFactory occ;
  occ.addBox(1, {0, 0, 0}, {1, 1, 1});
  occ.addBox(2, {0.5, 0.5, 0.5}, {1, 1, 1});
  return occ;
}

TEST(OccBooleans, UnionIntersectionDifferenceWithDelete) {
  OccFactory occ = overlappingCubes();
  EXPECT_EQ(occ.boolean(Op::Union, {{3, 1}}, {{3, 2}}, true, true),
            (std::vector<EntityId>{{3, 1}}));
  EXPECT_NEAR(occ.volume(1), 2 - 0.125, 1e-9);
  EXPECT_EQ(counts(occ), (std::vector<int>{20, 30, 12, 1}));

  occ = overlappingCubes();
  EXPECT_EQ(tagsOf(occ.boolean(Op::Difference, {{3, 1}}, {{3, 2}}, true, true)),
            (std::vector<int>{1}));
  EXPECT_NEAR(occ.volume(1), 0.875, 1e-9);
  EXPECT_EQ(counts(occ), (std::vector<int>{14, 21, 9, 1}));

  occ = overlappingCubes();
  EXPECT_EQ(tagsOf(occ.boolean(Op::Intersection, {{3, 1}}, {{3, 2}}, true, true)),
            (std::vector<int>{1}));
  EXPECT_NEAR(occ.volume(1), 0.125, 1e-9);
  EXPECT_EQ(counts(occ), (std::vector<int>{8, 12, 6, 1}));
  EXPECT_EQ(occ.maxTag(0), 8);  // everything renumbered from 1
}

TEST(OccBooleans, KeptInputsStayAndTheResultIsNew) {
  OccFactory occ = overlappingCubes();
  EXPECT_EQ(tagsOf(occ.boolean(Op::Difference, {{3, 1}}, {{3, 2}}, false, false)),
            (std::vector<int>{3}));
  EXPECT_NEAR(occ.volume(1), 1, 1e-9);
  EXPECT_NEAR(occ.volume(3), 0.875, 1e-9);
  EXPECT_EQ(counts(occ), (std::vector<int>{22, 36, 18, 3}));
  // The result's faces that are the first cube's keep the cube's tags.
  EXPECT_EQ(tagsOf(occ.boundary({{3, 3}}, false)),
            (std::vector<int>{1, 3, 13, 14, 5, 15, 16, 17, 18}));
}

// A deleted object that becomes one volume passes its tag on; the sub-shapes of the result are
// numbered after the largest tags still in use.
TEST(OccBooleans, SingleImageKeepsTheTag) {
  OccFactory occ;
  occ.addBox(1, {0, 0, 0}, {1, 1, 1});
  occ.addBox(2, {5, 0, 0}, {1, 1, 1});
  occ.addBox(3, {5.5, 0.5, 0.5}, {1, 1, 1});
  occ.addBox(4, {10, 0, 0}, {1, 1, 1});
  EXPECT_EQ(tagsOf(occ.boolean(Op::Difference, {{3, 2}}, {{3, 3}}, true, true)),
            (std::vector<int>{2}));
  EXPECT_EQ(occ.tags(3), (std::vector<int>{1, 2, 4}));
  EXPECT_EQ(occ.maxTag(0), 46);
  EXPECT_EQ(occ.maxTag(1), 69);
  EXPECT_EQ(occ.maxTag(2), 33);
  EXPECT_EQ(tagsOf(occ.boundary({{3, 2}}, false)).front(), 25);
}

TEST(OccBooleans, FragmentsOfSeveralVolumes) {
  OccFactory occ;
  occ.addBox(1, {0, 0, 0}, {1, 1, 1});
  occ.addBox(2, {0.5, 0, 0}, {1, 1, 1});
  occ.addBox(3, {3, 0, 0}, {1, 1, 1});
  occ.addSphere(4, {1.2, 0.5, 1}, 0.3);
  const std::vector<EntityId> r =
      occ.boolean(Op::Fragments, {{3, 1}, {3, 2}}, {{3, 3}, {3, 4}}, true, true);
  EXPECT_EQ(tagsOf(r), (std::vector<int>{4, 5, 6, 7, 8, 3, 9}));
  double total = 0;
  for (const EntityId& e : r) total += occ.volume(e.tag);
  EXPECT_NEAR(total, 1.5 + 1 + 4 * std::numbers::pi * 0.027 / 6, 1e-6);
  EXPECT_EQ(counts(occ), (std::vector<int>{29, 51, 29, 7}));
  EXPECT_EQ(occ.maxTag(0), 45);  // box 3, untouched, keeps points 17..24
  EXPECT_EQ(occ.pointsOf({{3, 3}}).front(), 17);
}

TEST(OccBooleans, FragmentsInTwoDimensions) {
  OccFactory occ;
  occ.addRectangle(1, {0, 0, 0}, 2, 1);
  occ.addRectangle(2, {1, 0.5, 0}, 2, 1);
  occ.addDisk(3, {0.5, 0.5, 0}, 0.3, 0.3);
  const std::vector<EntityId> r =
      occ.boolean(Op::Fragments, {{2, 1}}, {{2, 2}, {2, 3}}, true, true);
  EXPECT_EQ(tagsOf(r), (std::vector<int>{4, 5, 3, 6}));
  double total = 0;
  for (const EntityId& e : r) total += occ.area(e.tag);
  EXPECT_NEAR(total, 3.5, 1e-9);
  EXPECT_EQ(counts(occ), (std::vector<int>{11, 13, 4, 0}));
  EXPECT_NEAR(occ.pointCoordinates(7).x, 0.8, 1e-12);  // the disk's point, renumbered
}

TEST(OccBooleans, MixedDimensions) {
  OccFactory occ;
  occ.addBox(1, {0, 0, 0}, {1, 1, 1});
  occ.addRectangle(10, {-0.5, -0.5, 0.5}, 2, 2);
  EXPECT_EQ(occ.boolean(Op::Fragments, {{3, 1}}, {{2, 10}}, true, true),
            (std::vector<EntityId>{{3, 1}, {3, 2}, {2, 12}}));
  EXPECT_EQ(counts(occ), (std::vector<int>{16, 24, 12, 2}));

  OccFactory plate;
  plate.addRectangle(1, {0, 0, 0}, 1, 1);
  plate.addPoint(20, {0.5, 0.5, 0}, 0);
  plate.addPoint(21, {-0.5, 0.25, 0}, 0);
  plate.addPoint(22, {1.5, 0.75, 0}, 0);
  plate.addLine(30, 21, 22);
  const std::vector<EntityId> r =
      plate.boolean(Op::Fragments, {{2, 1}}, {{0, 20}, {1, 30}}, true, true);
  // As the reference lists it: the pieces, then point 20 at each of its places in the result
  // (the end of four curves, two faces' boundaries and itself).
  std::vector<EntityId> expected{{2, 1}, {2, 2}, {1, 9}, {1, 10}};
  expected.insert(expected.end(), 7, EntityId{0, 20});
  EXPECT_EQ(r, expected);
  EXPECT_EQ(counts(plate), (std::vector<int>{9, 10, 2, 0}));
  EXPECT_TRUE(plate.contains({0, 20}));  // the point, on the cut, keeps its tag
}

TEST(OccBooleans, UnionMergesCoplanarFaces) {
  OccFactory occ;
  occ.addBox(1, {0, 0, 0}, {1, 1, 1});
  occ.addBox(2, {1, 0, 0}, {1, 1, 1});
  occ.addBox(3, {0.5, 0.5, 0.5}, {1, 1, 1});
  EXPECT_EQ(tagsOf(occ.boolean(Op::Union, {{3, 1}}, {{3, 2}, {3, 3}}, true, true)),
            (std::vector<int>{1}));
  EXPECT_EQ(counts(occ), (std::vector<int>{20, 30, 12, 1}));
  EXPECT_NEAR(occ.volume(1), 3 - 0.25, 1e-9);
}

// BooleanDifference(3) = ..: the result takes the tag given; a result of several volumes
// cannot, and the model stays as it was.
TEST(OccBooleans, GivenTag) {
  OccFactory occ = overlappingCubes();
  occ.addBox(5, {5, 0, 0}, {1, 1, 1});
  EXPECT_EQ(tagsOf(occ.boolean(Op::Difference, {{3, 1}}, {{3, 2}}, true, true, 3)),
            (std::vector<int>{3}));
  EXPECT_EQ(occ.tags(3), (std::vector<int>{3, 5}));
  EXPECT_EQ(occ.maxTag(0), 38);  // numbered after box 5, as the reference numbers them
  occ.addBox(6, {10, 0, 0}, {1, 1, 1});
  occ.addBox(7, {10.5, 0, 0}, {1, 1, 1});
  EXPECT_THROW(occ.boolean(Op::Fragments, {{3, 6}}, {{3, 7}}, true, true, 20), GeometryError);
  EXPECT_EQ(occ.tags(3), (std::vector<int>{3, 5, 6, 7}));
}

TEST(OccBooleans, BadInput) {
  OccFactory occ = overlappingCubes();
  try {
    occ.boolean(Op::Union, {{3, 1}}, {{3, 7}}, true, true);
    FAIL() << "an undefined tool was accepted";
  } catch (const GeometryError& e) {
    EXPECT_NE(std::string(e.what()).find("Volume 7 is not defined"), std::string::npos);
  }
  EXPECT_THROW(occ.boolean(Op::Difference, {{3, 1}}, {}, true, true), GeometryError);
  EXPECT_EQ(counts(occ), (std::vector<int>{16, 24, 12, 2}));  // nothing changed
}

}  // namespace
}  // namespace geomesh
