// The OpenCASCADE factory's whole circles and ellipses, lofts, fillets and chamfers.
#include <gtest/gtest.h>

#include <string>

#include <numbers>

#include "kernel/geometry_error.h"
#include "kernel/occ/occ_factory.h"

namespace geomesh {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(OccLofts, CirclesEllipsesAndThruSections) {
  OccFactory occ;
  EXPECT_EQ(occ.addCircle(1, {0, 0, 0}, 0.5, {}), 1);
  EXPECT_NEAR(occ.length(1), kPi, 1e-9);
  occ.addCurveLoop(1, {1});
  occ.addCircle(2, {0, 0, 1}, 0.5, {});
  occ.addCurveLoop(2, {2});
  EXPECT_EQ(occ.addThruSections(1, {1, 2}, false), (std::vector<EntityId>{{3, 1}}));
  EXPECT_NEAR(occ.volume(1), kPi / 4, 1e-6);  // a cylinder
  // The reference's numbering: the smooth loft makes curves of its own, the ruled one does not.
  occ.addCircle(11, {2, 0, 0}, 0.5, {});
  occ.addCurveLoop(11, {11});
  occ.addCircle(12, {2, 0, 1}, 0.25, {});
  occ.addCurveLoop(12, {12});
  EXPECT_EQ(occ.addThruSections(11, {11, 12}, true), (std::vector<EntityId>{{3, 11}}));
  EXPECT_NEAR(occ.volume(11), kPi / 3 * (0.25 + 0.125 + 0.0625), 1e-6);  // a cone frustum
  occ.addCircle(20, {5, 0, 0}, 1, {0, kPi / 2});
  EXPECT_NEAR(occ.length(20), kPi / 2, 1e-9);
  occ.addEllipse(21, {8, 0, 0}, 2, 1, {0, kPi});
  EXPECT_NEAR(occ.pointCoordinates(occ.boundary({{1, 21}}, false)[1].tag).x, 6, 1e-12);
  EXPECT_THROW(occ.addEllipse(22, {0, 0, 0}, 1, 2, {}), GeometryError);
  EXPECT_THROW(occ.addThruSections(30, {1}, false), GeometryError);
}

TEST(OccLofts, CoincidentConsecutiveSectionsAreAnErrorNotACrash) {
  // OpenCASCADE's smooth loft dereferences a null pointer between two equal sections.
  OccFactory occ;
  occ.addCircle(1, {0, 0, 0}, 0.5, {});
  occ.addCurveLoop(1, {1});
  occ.addCircle(2, {0, 0, 1}, 0.1, {});
  occ.addCurveLoop(2, {2});
  occ.addCircle(3, {0, 0, 1}, 0.1, {});
  occ.addCurveLoop(3, {3});
  try {
    occ.addThruSections(1, {1, 2, 3}, false);
    FAIL() << "a loft through coincident sections was built";
  } catch (const GeometryError& e) {
    EXPECT_NE(std::string(e.what()).find("sections 2 and 3 coincide"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(occ.addThruSections(1, {1, 2}, false), (std::vector<EntityId>{{3, 1}}));
}

TEST(OccLofts, FilletAndChamferReplaceTheVolume) {
  OccFactory occ;
  occ.addBox(1, {0, 0, 0}, {1, 1, 1});
  occ.addBox(2, {3, 0, 0}, {1, 1, 1});
  EXPECT_EQ(occ.fillet({1}, {1, 2}, {0.1}), (std::vector<EntityId>{{3, 3}}));
  EXPECT_FALSE(occ.contains({3, 1}));
  // Two rounded edges, meeting at a corner: less than two quarter-round strips removed.
  const double strip = 0.01 - kPi * 0.01 / 4;
  EXPECT_GT(occ.volume(3), 1 - 2 * strip);
  EXPECT_LT(occ.volume(3), 1 - strip);
  EXPECT_EQ(occ.maxTag(0), 27);  // as the reference numbers the rounded box
  EXPECT_EQ(occ.chamfer({2}, {13}, {7}, {0.1}), (std::vector<EntityId>{{3, 4}}));
  EXPECT_NEAR(occ.volume(4), 1 - 0.005, 1e-9);
  EXPECT_THROW(occ.fillet({4}, {1000}, {0.1}), GeometryError);
  try {
    occ.fillet({4}, {occ.maxTag(1)}, {5});
    FAIL() << "a radius larger than the volume was accepted";
  } catch (const GeometryError& e) {
    EXPECT_NE(std::string(e.what()).find("Fillet"), std::string::npos);
  }
  EXPECT_TRUE(occ.contains({3, 4}));  // a failed fillet leaves the volume
}

}  // namespace
}  // namespace geomesh
