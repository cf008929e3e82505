// The OpenCASCADE factory's primitives: their sizes, entity counts and tags.
#include <gtest/gtest.h>

#include <numbers>

#include "kernel/geometry_error.h"
#include "kernel/occ/occ_factory.h"

namespace geomesh {
namespace {

constexpr double kPi = std::numbers::pi;

int count(const OccFactory& occ, int dim) { return static_cast<int>(occ.tags(dim).size()); }

TEST(OccPrimitives, VolumesAndAreas) {
  OccFactory occ;
  EXPECT_EQ(occ.addSphere(1, {0, 0, 0}, 2), 1);
  EXPECT_NEAR(occ.volume(1), 4 * kPi * 8 / 3, 1e-9);
  EXPECT_EQ(occ.addSphere(-1, {5, 0, 0}, 1, 0, kPi / 2, kPi), 2);  // a quarter ball
  EXPECT_NEAR(occ.volume(2), kPi / 3, 1e-9);
  occ.addCylinder(3, {10, 0, 0}, {0, 0, 2}, 0.5);
  EXPECT_NEAR(occ.volume(3), kPi * 0.25 * 2, 1e-9);
  occ.addCylinder(4, {10, 5, 0}, {0, 3, 4}, 1, kPi / 2);  // height 5, a quarter
  EXPECT_NEAR(occ.volume(4), kPi * 5 / 4, 1e-9);
  occ.addCone(5, {0, 10, 0}, {0, 0, 3}, 1, 0.5);
  EXPECT_NEAR(occ.volume(5), kPi * 3 * (1 + 0.5 + 0.25) / 3, 1e-9);
  occ.addCone(6, {0, 15, 0}, {0, 0, 3}, 1, 0);
  EXPECT_NEAR(occ.volume(6), kPi, 1e-9);
  occ.addTorus(7, {0, 20, 0}, 2, 0.5);
  EXPECT_NEAR(occ.volume(7), 2 * kPi * kPi * 2 * 0.25, 1e-9);
  occ.addWedge(8, {0, 30, 0}, {1, 2, 3});
  EXPECT_NEAR(occ.volume(8), 3, 1e-9);
  occ.addWedge(9, {0, 40, 0}, {2, 1, 1}, 1);  // top half as long as the base
  EXPECT_NEAR(occ.volume(9), 1.5, 1e-9);
  occ.addRectangle(101, {0, 50, 0}, 2, 1);
  EXPECT_NEAR(occ.area(101), 2, 1e-12);
  occ.addRectangle(102, {0, 60, 0}, 2, 1, 0.2);
  EXPECT_NEAR(occ.area(102), 2 - (4 - kPi) * 0.04, 1e-9);
  occ.addDisk(103, {0, 70, 0}, 1, 0.5);
  EXPECT_NEAR(occ.area(103), kPi * 0.5, 1e-9);
}

// Tags as the reference gives them to Box(1), Sphere(13), Cylinder(16), Cone(17), Torus(18),
// Wedge(19), Rectangle(100), Disk(101) and Rectangle(102) with rounded corners.
TEST(OccPrimitives, TagsFollowTheReference) {
  OccFactory occ;
  occ.addBox(1, {0, 0, 0}, {1, 2, 3});
  occ.addSphere(13, {5, 0, 0}, 1);
  EXPECT_EQ(count(occ, 0), 10);
  EXPECT_EQ(count(occ, 1), 15);
  EXPECT_EQ(count(occ, 2), 7);
  occ.addCylinder(16, {10, 0, 0}, {0, 0, 2}, 0.5);
  occ.addCone(17, {0, 10, 0}, {0, 0, 1}, 1, 0.5);
  occ.addTorus(18, {0, 20, 0}, 2, 0.5);
  occ.addWedge(19, {0, 30, 0}, {1, 1, 1});
  EXPECT_EQ(occ.addRectangle(100, {0, 40, 0}, 2, 1), 100);
  EXPECT_EQ(occ.addDisk(101, {0, 50, 0}, 1, 0.5), 101);
  EXPECT_EQ(occ.addRectangle(102, {0, 60, 0}, 2, 1, 0.2), 102);
  EXPECT_EQ(count(occ, 0), 34);
  EXPECT_EQ(count(occ, 1), 45);
  EXPECT_EQ(count(occ, 2), 22);
  EXPECT_EQ(occ.maxTag(0), 34);
  EXPECT_EQ(occ.maxTag(1), 45);
  EXPECT_EQ(occ.maxTag(2), 102);
  EXPECT_EQ(occ.maxTag(3), 19);
  // The rounded rectangle: 8 curves, from 38 on; the sphere's seam and poles: curves 13..15.
  std::vector<int> curves;
  for (const EntityId& e : occ.boundary({{2, 102}}, false)) curves.push_back(e.tag);
  EXPECT_EQ(curves, (std::vector<int>{38, 39, 40, 41, 42, 43, 44, 45}));
  std::vector<EntityId> sphere = occ.boundary({{2, 7}}, false);
  ASSERT_EQ(sphere.size(), 4u);
  EXPECT_EQ(sphere[0].tag, 13);
  EXPECT_EQ(sphere[1].tag, 14);
  EXPECT_EQ(sphere[3].tag, 14);  // the seam, twice
}

TEST(OccPrimitives, BoundingBoxHoldsTheToleranceAsTheReferenceDoes) {
  OccFactory occ;
  occ.addBox(1, {0, 0, 0}, {1, 2, 3});
  const BoundingBox box = occ.boundingBox({3, 1});
  EXPECT_NEAR(box.min.x, -1e-7, 1e-12);
  EXPECT_NEAR(box.max.z, 3 + 1e-7, 1e-12);
  occ.addBox(2, {5, 0, 0}, {1, 1, 1});
  EXPECT_EQ(occ.entitiesInBox(3, {{-1, -1, -1}, {2, 3, 4}}), (std::vector<int>{1}));
  EXPECT_EQ(occ.entitiesInBox(2, {{4.5, -1, -1}, {5.5, 3, 4}}), (std::vector<int>{7}));
}

TEST(OccPrimitives, BadInputIsAGeometryError) {
  OccFactory occ;
  EXPECT_THROW(occ.addSphere(1, {0, 0, 0}, 0), GeometryError);
  EXPECT_THROW(occ.addCylinder(1, {0, 0, 0}, {0, 0, 0}, 1), GeometryError);
  EXPECT_THROW(occ.addCone(1, {0, 0, 0}, {0, 0, 1}, 0, 0), GeometryError);
  EXPECT_THROW(occ.addTorus(1, {0, 0, 0}, 1, -1), GeometryError);
  EXPECT_THROW(occ.addWedge(1, {0, 0, 0}, {1, 0, 1}), GeometryError);
  EXPECT_THROW(occ.addDisk(1, {0, 0, 0}, 0.5, 1), GeometryError);
  EXPECT_THROW(occ.addRectangle(1, {0, 0, 0}, 1, 1, 0.6), GeometryError);
  EXPECT_THROW(occ.addSphere(1, {0, 0, 0}, 1, 0, kPi / 2, 7), GeometryError);
  occ.addSphere(1, {0, 0, 0}, 1);
  try {
    occ.addBox(1, {0, 0, 0}, {1, 1, 1});
    FAIL() << "a reused tag was accepted";
  } catch (const GeometryError& e) {
    EXPECT_NE(std::string(e.what()).find("Volume 1 already exists"), std::string::npos);
  }
}

// A transformed shape keeps its tag; its sub-shapes are numbered anew, after the largest tags
// still in use (the reference's numbering).
TEST(OccPrimitives, TransformsNumberSubShapesAnew) {
  OccFactory occ;
  occ.addBox(1, {0, 0, 0}, {1, 1, 1});
  occ.addSphere(2, {3, 0, 0}, 0.5);
  EXPECT_EQ(occ.duplicate({{3, 1}}), (std::vector<EntityId>{{3, 3}}));  // points 11..18
  occ.transform({{3, 2}}, AffineMap::dilation({0, 0, 0}, {2, 2, 2}));
  EXPECT_FALSE(occ.contains({0, 9}));
  EXPECT_EQ(occ.maxTag(0), 20);
  EXPECT_EQ(occ.boundary({{3, 2}}, false), (std::vector<EntityId>{{2, 14}}));
  EXPECT_NEAR(occ.volume(2), 4 * std::numbers::pi / 3, 1e-9);
}

TEST(OccPrimitives, TransformAndDuplicateKeepTags) {
  OccFactory occ;
  occ.addBox(1, {0, 0, 0}, {1, 1, 1});
  occ.transform({{3, 1}}, AffineMap::translation({2, 0, 0}));
  EXPECT_NEAR(occ.boundingBox({3, 1}).min.x, 2 - 1e-7, 1e-9);
  EXPECT_EQ(occ.maxTag(0), 8);
  EXPECT_NEAR(occ.pointCoordinates(2).x, 2, 1e-12);
  occ.transform({{3, 1}}, AffineMap::dilation({0, 0, 0}, {1, 2, 3}));  // not a similarity
  EXPECT_NEAR(occ.volume(1), 6, 1e-9);
  const std::vector<EntityId> copy = occ.duplicate({{3, 1}});
  ASSERT_EQ(copy.size(), 1u);
  EXPECT_EQ(copy[0].tag, 2);
  EXPECT_EQ(occ.maxTag(0), 16);
  occ.remove({{3, 2}}, true);
  EXPECT_EQ(occ.maxTag(0), 8);
  EXPECT_EQ(occ.maxTag(3), 1);
  occ.remove({{2, 1}}, false);  // a face of volume 1: kept
  EXPECT_TRUE(occ.contains({2, 1}));
}

}  // namespace
}  // namespace geomesh
