// The OpenCASCADE factory's Booleans: the shapes they make and the tags they give, checked
// against what the reference gives the same operations.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
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

Vec3 center(const OccFactory& occ, EntityId e) {
  const BoundingBox box = occ.boundingBox(e);
  return {(box.min.x + box.max.x) / 2, (box.min.y + box.max.y) / 2, (box.min.z + box.max.z) / 2};
}

std::vector<int> sortedTags(std::vector<EntityId> shapes) {
  std::vector<int> tags;
  for (const EntityId& e : shapes) tags.push_back(std::abs(e.tag));
  std::sort(tags.begin(), tags.end());
  return tags;
}

// The multi-material pattern: two touching boxes fragmented, both deleted. As in the reference,
// the first box gets its faces 1..6, curves 1..12 and points 1..8 again; the second's faces
// follow in its own order (its far face 7, then its sides), the face they share being the
// first box's face 2.
TEST(OccBooleans, TouchingBoxesFragmentedKeepTheFirstBoxsNumbers) {
  OccFactory occ;
  occ.addBox(1, {0, 0, 0}, {1, 1, 1});
  occ.addBox(2, {1, 0, 0}, {1, 1, 1});
  EXPECT_EQ(occ.boolean(Op::Fragments, {{3, 1}}, {{3, 2}}, true, true),
            (std::vector<EntityId>{{3, 1}, {3, 2}}));
  EXPECT_EQ(counts(occ), (std::vector<int>{12, 20, 11, 2}));
  EXPECT_EQ(tagsOf(occ.boundary({{3, 1}}, false)), (std::vector<int>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(sortedTags(occ.boundary({{3, 2}}, false)), (std::vector<int>{2, 7, 8, 9, 10, 11}));
  EXPECT_NEAR(center(occ, {2, 1}).x, 0, 1e-6);
  EXPECT_NEAR(center(occ, {2, 2}).x, 1, 1e-6);
  EXPECT_NEAR(center(occ, {2, 7}).x, 2, 1e-6);
  EXPECT_NEAR(center(occ, {2, 8}).y, 0, 1e-6);
  EXPECT_EQ(sortedTags(occ.boundary({{2, 2}}, false)), (std::vector<int>{5, 6, 7, 8}));
  EXPECT_EQ(sortedTags(occ.boundary({{2, 7}}, false)), (std::vector<int>{13, 14, 15, 16}));
  EXPECT_NEAR(occ.pointCoordinates(8).x, 1, 1e-12);
  EXPECT_NEAR(occ.pointCoordinates(9).x, 2, 1e-12);

  // Given the other way round, the second box's numbers come first.
  OccFactory reversed;
  reversed.addBox(1, {0, 0, 0}, {1, 1, 1});
  reversed.addBox(2, {1, 0, 0}, {1, 1, 1});
  reversed.boolean(Op::Fragments, {{3, 2}}, {{3, 1}}, true, true);
  EXPECT_EQ(tagsOf(reversed.boundary({{3, 2}}, false)), (std::vector<int>{1, 2, 3, 4, 5, 6}));
  EXPECT_NEAR(center(reversed, {2, 1}).x, 1, 1e-6);
  EXPECT_NEAR(center(reversed, {2, 7}).x, 0, 1e-6);
}

// A piece that took the tag of the input it replaces numbers its faces after the new pieces:
// of a box beside two overlapping ones, the three new pieces' faces are 1..16 (the face the
// box shares with them among them), the box's own 17..21.
TEST(OccBooleans, NewPiecesAreNumberedBeforeAPieceThatKeptItsTag) {
  OccFactory occ;
  occ.addBox(1, {0, 0, 0}, {1, 1, 1});
  occ.addBox(2, {1, 0, 0}, {1, 1, 1});
  occ.addBox(3, {1.5, 0, 0}, {1, 1, 1});
  EXPECT_EQ(tagsOf(occ.boolean(Op::Fragments, {{3, 1}}, {{3, 2}, {3, 3}}, true, true)),
            (std::vector<int>{1, 2, 3, 4}));
  EXPECT_EQ(counts(occ), (std::vector<int>{20, 36, 21, 4}));
  EXPECT_EQ(sortedTags(occ.boundary({{3, 1}}, false)), (std::vector<int>{1, 17, 18, 19, 20, 21}));
  EXPECT_NEAR(center(occ, {2, 1}).x, 1, 1e-6);
  EXPECT_NEAR(center(occ, {2, 17}).x, 0, 1e-6);
  EXPECT_NEAR(occ.pointCoordinates(17).x, 0, 1e-12);
}

// A cut keeps the tags of its deleted tool's faces that the result holds as they were, with
// their curves and points (the pole curves of a sphere too); the object's faces are numbered
// after them. A tool's curve left whole while its faces were cut is numbered anew.
TEST(OccBooleans, ACutKeepsTheToolsFacesItHoldsWhole) {
  OccFactory pocket;
  pocket.addBox(1, {0, 0, 0}, {3, 3, 3});
  pocket.addBox(2, {1, 1, 2}, {1, 1, 2});
  pocket.boolean(Op::Difference, {{3, 1}}, {{3, 2}}, true, true);
  EXPECT_EQ(pocket.tags(2).front(), 11);  // the tool's bottom face
  EXPECT_NEAR(center(pocket, {2, 11}).z, 2, 1e-6);
  EXPECT_EQ(sortedTags(pocket.boundary({{2, 11}}, false)), (std::vector<int>{16, 20, 21, 23}));
  std::vector<int> corners = pocket.pointsOf({{2, 11}});
  std::sort(corners.begin(), corners.end());
  EXPECT_EQ(corners, (std::vector<int>{10, 12, 14, 16}));
  EXPECT_EQ(pocket.maxTag(2), 21);
  EXPECT_EQ(pocket.maxTag(1), 43);

  OccFactory notch;
  notch.addBox(1, {0, 0, 0}, {3, 3, 3});
  notch.addBox(2, {2.5, 2.5, 1}, {1, 1, 1});
  notch.boolean(Op::Difference, {{3, 1}}, {{3, 2}}, true, true);
  EXPECT_EQ(counts(notch), (std::vector<int>{16, 24, 10, 1}));
  EXPECT_EQ(notch.maxTag(1), 24);  // the tool's edge at x = y = 2.5 too

  OccFactory cavity;
  cavity.addBox(1, {0, 0, 0}, {2, 2, 2});
  cavity.addSphere(2, {1, 1, 1}, 0.5);
  cavity.boolean(Op::Difference, {{3, 1}}, {{3, 2}}, true, true);
  EXPECT_EQ(cavity.tags(2), (std::vector<int>{7, 8, 9, 10, 11, 12, 13}));
  EXPECT_NEAR(cavity.area(7), std::numbers::pi, 1e-6);
  // The seam bounds the sphere's face twice.
  EXPECT_EQ(sortedTags(cavity.boundary({{2, 7}}, false)), (std::vector<int>{13, 14, 14, 15}));
}

// A union keeps the tags of a deleted tool's curves left whole when the tool merged into the
// objects; a tool that left a piece of its own (the union not unified) is numbered anew, as
// are a fragment's tools always.
TEST(OccBooleans, AJoinedToolKeepsItsWholeCurves) {
  OccFactory joined;
  joined.addRectangle(1, {0, 0, 0}, 1, 1);
  joined.addRectangle(2, {0.5, 0.5, 0}, 1, 1);
  EXPECT_EQ(tagsOf(joined.boolean(Op::Union, {{2, 1}}, {{2, 2}}, true, true)),
            (std::vector<int>{1}));
  EXPECT_EQ(joined.tags(1), (std::vector<int>{6, 7, 8, 9, 10, 11, 12, 13}));
  EXPECT_NEAR(center(joined, {1, 6}).x, 1.5, 1e-6);
  EXPECT_NEAR(center(joined, {1, 7}).y, 1.5, 1e-6);

  OccFactory pieces;
  pieces.setBooleanOptions({0, false, true});
  pieces.addRectangle(1, {0, 0, 0}, 1, 1);
  pieces.addRectangle(2, {0.5, 0.5, 0}, 1, 1);
  EXPECT_EQ(tagsOf(pieces.boolean(Op::Union, {{2, 1}}, {{2, 2}}, true, true)),
            (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(pieces.maxTag(1), 12);
  EXPECT_NEAR(center(pieces, {1, 11}).x, 1.5, 1e-6);
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

// With a tag for the result, the reference numbers the result anew: the deleted inputs go
// (their tags are free again), then the result's sub-shapes take the next free tags in the
// result's order. A box hollowed out by a sphere gets its faces 1..6 back, the cavity 7.
TEST(OccBooleans, GivenTagNumbersTheResultAnew) {
  OccFactory occ;
  occ.addBox(1, {0, 0, 0}, {2, 2, 2});
  occ.addSphere(2, {1, 1, 1}, 0.5);
  EXPECT_EQ(occ.boolean(Op::Difference, {{3, 1}}, {{3, 2}}, true, true, 3),
            (std::vector<EntityId>{{3, 3}}));
  EXPECT_EQ(tagsOf(occ.boundary({{3, 3}}, false)), (std::vector<int>{1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(counts(occ), (std::vector<int>{10, 15, 7, 1}));
  EXPECT_EQ(occ.maxTag(1), 15);

  // In 2D: the ellipse is curve 1 again, the hole curve 2.
  OccFactory plate;
  plate.addDisk(1, {0, 0, 0}, 3, 1.5);
  plate.addDisk(2, {0.8, 0, 0}, 0.4, 0.4);
  plate.boolean(Op::Difference, {{2, 1}}, {{2, 2}}, true, true, 3);
  EXPECT_EQ(tagsOf(plate.boundary({{2, 3}}, false)), (std::vector<int>{1, 2}));
  EXPECT_NEAR(plate.length(2), 2 * std::numbers::pi * 0.4, 1e-9);

  // A hollow sphere: the outer sphere's face is 1, the inner one's 2 (not the tool's 2 kept).
  OccFactory shell;
  shell.addSphere(1, {0, 0, 0}, 1);
  shell.addSphere(2, {0, 0, 0}, 0.7);
  shell.boolean(Op::Difference, {{3, 1}}, {{3, 2}}, true, true, 3);
  EXPECT_NEAR(shell.area(1), 4 * std::numbers::pi, 1e-6);
  EXPECT_NEAR(shell.area(2), 4 * std::numbers::pi * 0.49, 1e-6);
}

// Renumbered, a deleted input the operation kept as it was goes too: a point inside a face is
// numbered anew after the face's corners; a square apart from a box is dropped, as only the
// shape of the highest dimension takes the tag. Inputs kept (no Delete) keep their tags.
TEST(OccBooleans, GivenTagRenumbersWhatTheResultHolds) {
  OccFactory plate;
  plate.addRectangle(1, {0, 0, 0}, 2, 1);
  plate.addPoint(20, {0.5, 0.5, 0}, 0);
  EXPECT_EQ(plate.boolean(Op::Fragments, {{2, 1}}, {{0, 20}}, true, true, 4),
            (std::vector<EntityId>{{2, 4}}));
  EXPECT_EQ(plate.tags(0), (std::vector<int>{1, 2, 3, 4, 5}));
  EXPECT_NEAR(plate.pointCoordinates(5).x, 0.5, 1e-12);

  OccFactory apart;
  apart.addBox(1, {0, 0, 0}, {1, 1, 1});
  apart.addRectangle(10, {3, 0, 0}, 1, 1);
  EXPECT_EQ(apart.boolean(Op::Fragments, {{3, 1}}, {{2, 10}}, true, true, 5),
            (std::vector<EntityId>{{3, 5}}));
  EXPECT_EQ(counts(apart), (std::vector<int>{8, 12, 6, 1}));

  OccFactory kept;
  kept.addBox(1, {0, 0, 0}, {2, 2, 2});
  kept.addSphere(2, {1, 1, 1}, 0.5);
  kept.boolean(Op::Difference, {{3, 1}}, {{3, 2}}, true, false, 3);
  EXPECT_EQ(kept.tags(3), (std::vector<int>{2, 3}));
  EXPECT_EQ(tagsOf(kept.boundary({{3, 3}}, false)), (std::vector<int>{8, 9, 10, 11, 12, 13, 7}));
}

// The reference refuses a tag in use in the first object's dimension before it operates (the
// object's own tag too); a tag in use in another dimension, or by a deleted tool of a lower
// dimension, is free.
TEST(OccBooleans, GivenTagInUse) {
  OccFactory occ = overlappingCubes();
  EXPECT_THROW(occ.boolean(Op::Difference, {{3, 1}}, {{3, 2}}, true, true, 1), GeometryError);
  EXPECT_THROW(occ.boolean(Op::Difference, {{3, 1}}, {{3, 2}}, true, true, 2), GeometryError);
  EXPECT_EQ(counts(occ), (std::vector<int>{16, 24, 12, 2}));  // nothing changed
  EXPECT_EQ(occ.tags(3), (std::vector<int>{1, 2}));
  occ.boolean(Op::Difference, {{3, 1}}, {{3, 2}}, true, true, 12);  // surface 12 exists
  EXPECT_EQ(occ.tags(3), (std::vector<int>{12}));

  OccFactory crack;
  crack.addBox(1, {0, 0, 0}, {1, 1, 1});
  crack.addRectangle(10, {0.2, 0.2, 0.5}, 0.5, 0.5);
  EXPECT_THROW(crack.boolean(Op::Fragments, {{2, 10}}, {{3, 1}}, true, true, 10), GeometryError);
  EXPECT_EQ(crack.boolean(Op::Fragments, {{3, 1}}, {{2, 10}}, true, true, 10),
            (std::vector<EntityId>{{3, 10}}));
  EXPECT_EQ(crack.tags(2), (std::vector<int>{1, 2, 3, 4, 5, 6, 7}));  // the crack is 7
}

// Geometry.OCCBooleanPreserveNumbering off: numbered anew as with a tag, and the result lists
// the shapes new to the model (a point inside a face among them), not those kept.
TEST(OccBooleans, PreserveNumberingOff) {
  OccFactory occ;
  occ.setBooleanOptions({0, true, false});
  occ.addRectangle(1, {0, 0, 0}, 2, 1);
  occ.addPoint(20, {0.5, 0.5, 0}, 0);
  occ.addPoint(21, {3, 3, 0}, 0);
  EXPECT_EQ(occ.boolean(Op::Fragments, {{2, 1}}, {{0, 20}, {0, 21}}, true, true),
            (std::vector<EntityId>{{2, 1}, {0, 5}, {0, 6}}));
  EXPECT_NEAR(occ.pointCoordinates(6).x, 3, 1e-12);

  OccFactory keep;
  keep.setBooleanOptions({0, true, false});
  keep.addRectangle(1, {0, 0, 0}, 2, 1);
  keep.addPoint(20, {0.5, 0.5, 0}, 0);
  keep.addPoint(21, {3, 3, 0}, 0);
  EXPECT_EQ(keep.boolean(Op::Fragments, {{2, 1}}, {{0, 20}, {0, 21}}, true, false),
            (std::vector<EntityId>{{2, 1}}));
  EXPECT_TRUE(keep.contains({0, 20}));
  EXPECT_TRUE(keep.contains({0, 21}));
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
