// The order in which the OpenCASCADE factory lists the curves of a plane surface with holes,
// as the reference (Gmsh 4.15.2) lists them: the outer loop the way the script's loop runs
// (the way its first curve goes), from its first curve; each hole as its loop reversed as a
// whole, from its last curve; a loop from a negative first curve as if reversed as a whole.
// Whatever the listing, the face bounds the same region: the outer loop counter-clockwise, the
// holes clockwise, seen from the side the face faces. Fillings are listed by other rules.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <utility>

#include "kernel/model.h"
#include "kernel/occ/occ_factory.h"

namespace geomesh {
namespace {

constexpr double kPi = std::numbers::pi;

// A 4 x 4 square, lines 100..103 counter-clockwise from (10, 0), and a unit square hole,
// points 104..107 counter-clockwise from (11, 1), lines 104..107 between them (104 from 104
// to 105, ..., 107 from 107 to 104).
void addSquares(OccFactory& occ) {
  const double outer[4][2] = {{10, 0}, {14, 0}, {14, 4}, {10, 4}};
  const double hole[4][2] = {{11, 1}, {12, 1}, {12, 2}, {11, 2}};
  for (int i = 0; i < 4; ++i) {
    occ.addPoint(100 + i, {outer[i][0], outer[i][1], 0}, 0);
    occ.addPoint(104 + i, {hole[i][0], hole[i][1], 0}, 0);
  }
  for (int i = 0; i < 4; ++i) {
    occ.addLine(100 + i, 100 + i, 100 + (i + 1) % 4);
    occ.addLine(104 + i, 104 + i, 104 + (i + 1) % 4);
  }
}

std::vector<int> boundaryOf(const OccFactory& occ, int surface) {
  std::vector<int> curves;
  for (const EntityId& e : occ.boundary({{2, surface}}, false)) curves.push_back(e.tag);
  return curves;
}

// The area a loop of the model encloses, positive counter-clockwise seen from +z.
double signedArea(const Model& model, const std::vector<int>& loop) {
  double twice = 0;
  for (int signedTag : loop) {
    const CurveGeometry& curve = *model.curve(std::abs(signedTag))->geometry;
    const Interval r = curve.range();
    constexpr int kSteps = 64;
    for (int i = 0; i < kSteps; ++i) {
      double s0 = r.min + (r.max - r.min) * i / kSteps;
      double s1 = r.min + (r.max - r.min) * (i + 1) / kSteps;
      if (signedTag < 0) {
        s0 = r.max - (s0 - r.min);
        s1 = r.max - (s1 - r.min);
      }
      const Vec3 a = curve.point(s0), b = curve.point(s1);
      twice += a.x * b.y - b.x * a.y;
    }
  }
  return twice / 2;
}

// The z of the surface's normal (its u and v derivatives crossed) in the middle of its
// parameters: the side its mesh faces.
double normalZ(const Model& model, int surface) {
  const SurfaceGeometry& geometry = *model.surface(surface)->geometry;
  const ParamBox box = geometry.bounds();
  const SurfaceDerivatives d =
      geometry.firstDerivatives({(box.u.min + box.u.max) / 2, (box.v.min + box.v.max) / 2});
  return cross(d.du, d.dv).z;
}

// The postcondition whatever the listing: the outer loop counter-clockwise, the holes
// clockwise, seen from the side the face's normal points to (+z unless `facesDown`).
void expectHolesTurnAgainstOuterLoop(OccFactory& occ, int surface, bool facesDown = false) {
  Model model;
  occ.synchronize(model);
  const auto& loops = model.surface(surface)->loops;
  ASSERT_GE(loops.size(), 2u);
  const double up = facesDown ? -1 : 1;
  EXPECT_GT(up * normalZ(model, surface), 0);
  EXPECT_GT(up * signedArea(model, loops[0]), 0);
  for (std::size_t i = 1; i < loops.size(); ++i) EXPECT_LT(up * signedArea(model, loops[i]), 0);
}

TEST(OccBoundaryOrder, HoleCounterClockwiseIsListedFromItsLastCurve) {
  OccFactory occ;
  addSquares(occ);
  occ.addCurveLoop(100, {100, 101, 102, 103});
  occ.addCurveLoop(101, {105, 106, 107, 104});
  occ.addPlaneSurface(1, {100, 101});
  EXPECT_EQ(boundaryOf(occ, 1), (std::vector<int>{100, 101, 102, 103, 104, 107, 106, 105}));
  EXPECT_NEAR(occ.area(1), 15, 1e-9);
  expectHolesTurnAgainstOuterLoop(occ, 1);
}

// Curves given in the order opposite to their own direction: the loop runs the way its first
// curve goes, counter-clockwise here, so the hole is listed clockwise from its last curve.
TEST(OccBoundaryOrder, LoopRunsTheWayItsFirstCurveGoes) {
  OccFactory occ;
  addSquares(occ);
  occ.addCurveLoop(100, {103, 102, 101, 100});
  occ.addCurveLoop(101, {107, 106, 105, 104});
  occ.addPlaneSurface(1, {100, 101});
  EXPECT_EQ(boundaryOf(occ, 1), (std::vector<int>{103, 100, 101, 102, 104, 107, 106, 105}));
  expectHolesTurnAgainstOuterLoop(occ, 1);
}

// A hole whose first curve runs clockwise: reversed as a whole, it is listed counter-clockwise,
// against the way it bounds the face.
TEST(OccBoundaryOrder, HoleRunningClockwiseIsListedCounterClockwise) {
  OccFactory occ;
  addSquares(occ);
  occ.addLine(110, 104, 107);
  occ.addLine(111, 107, 106);
  occ.addLine(112, 106, 105);
  occ.addLine(113, 105, 104);
  occ.addCurveLoop(100, {100, 101, 102, 103});
  occ.addCurveLoop(101, {110, 111, 112, 113});
  occ.addPlaneSurface(1, {100, 101});
  EXPECT_EQ(boundaryOf(occ, 1), (std::vector<int>{100, 101, 102, 103, 113, 112, 111, 110}));
  EXPECT_NEAR(occ.area(1), 15, 1e-9);
  expectHolesTurnAgainstOuterLoop(occ, 1);
}

// Several holes, listed in the order given: two half circles (which turn clockwise), a
// triangle whose curves are given in the order opposite to the way it runs, a whole circle.
TEST(OccBoundaryOrder, SeveralHolesOfArcsAndLines) {
  OccFactory occ;
  addSquares(occ);
  occ.addPoint(1, {13, 3, 0}, 0);
  occ.addPoint(2, {13.5, 3, 0}, 0);
  occ.addPoint(3, {12.5, 3, 0}, 0);
  occ.addCircleArc(1, 2, 1, 3);
  occ.addCircleArc(2, 3, 1, 2);
  occ.addLine(3, 104, 105);
  occ.addLine(4, 105, 106);
  occ.addLine(5, 104, 106);
  occ.addCircle(6, {11, 3, 0}, 0.5, {});
  occ.addCurveLoop(100, {100, 101, 102, 103});
  occ.addCurveLoop(101, {1, 2});
  occ.addCurveLoop(102, {4, 3, 5});
  occ.addCurveLoop(103, {6});
  occ.addPlaneSurface(1, {100, 101, 102, 103});
  EXPECT_EQ(boundaryOf(occ, 1), (std::vector<int>{100, 101, 102, 103, 2, 1, 5, 4, 3, 6}));
  EXPECT_NEAR(occ.area(1), 16 - 2 * kPi * 0.25 - 0.5, 1e-9);
  expectHolesTurnAgainstOuterLoop(occ, 1);
}

// A negative first curve turns the loop round (the signs of the other curves do not matter):
// the face faces -z, and the loops are listed as if each were reversed as a whole.
TEST(OccBoundaryOrder, NegativeFirstCurveTurnsTheLoopAndTheFace) {
  OccFactory occ;
  addSquares(occ);
  occ.addCurveLoop(100, {-101, 102, 103, 100});
  occ.addCurveLoop(101, {-107, 106, 105, 104});
  occ.addPlaneSurface(1, {100, 101});
  EXPECT_EQ(boundaryOf(occ, 1), (std::vector<int>{100, 103, 102, 101, 107, 104, 105, 106}));
  EXPECT_NEAR(occ.area(1), 15, 1e-9);
  expectHolesTurnAgainstOuterLoop(occ, 1, true);
}

TEST(OccBoundaryOrder, NegativeCurvesGivenAgainstTheirOrder) {
  OccFactory occ;
  addSquares(occ);
  occ.addCurveLoop(100, {-103, -102, 101, 100});
  occ.addCurveLoop(101, {104, 105, 106, 107});
  occ.addPlaneSurface(1, {100, 101});
  EXPECT_EQ(boundaryOf(occ, 1), (std::vector<int>{100, 103, 102, 101, 107, 106, 105, 104}));
  expectHolesTurnAgainstOuterLoop(occ, 1, true);
}

// Two half circles (which turn clockwise) from a negative first curve: a hole running
// counter-clockwise, listed from its first curve.
TEST(OccBoundaryOrder, HoleOfHalfCirclesFromANegativeCurve) {
  OccFactory occ;
  addSquares(occ);
  occ.addPoint(1, {12, 2.5, 0}, 0);
  occ.addPoint(2, {12.5, 2.5, 0}, 0);
  occ.addPoint(3, {11.5, 2.5, 0}, 0);
  occ.addCircleArc(1, 2, 1, 3);
  occ.addCircleArc(2, 3, 1, 2);
  occ.addCurveLoop(100, {100, 101, 102, 103});
  occ.addCurveLoop(101, {-1, 2});
  occ.addPlaneSurface(1, {100, 101});
  EXPECT_EQ(boundaryOf(occ, 1), (std::vector<int>{100, 101, 102, 103, 1, 2}));
  EXPECT_NEAR(occ.area(1), 16 - kPi * 0.25, 1e-9);
  expectHolesTurnAgainstOuterLoop(occ, 1);
}

// Fillings (Surface) face the side about which their loop turns counter-clockwise, but are
// listed the way the parameters of OpenCASCADE's plate run round the loop: from the loop's first
// stored curve when the plate faces the same side, else the other way round, ending at it.
// The cases below are listed as the reference lists them.
class OccFillingOrder : public ::testing::Test {
 protected:
  // The filling of the loop of `curves` as surface `s`, its normal's z sign, its listing.
  std::pair<int, std::vector<int>> fill(int s, const std::vector<int>& curves) {
    occ_.addCurveLoop(s, curves);
    occ_.addFillingSurface(s, {s}, {});
    Model model;
    occ_.synchronize(model);
    return {normalZ(model, s) > 0 ? 1 : -1, boundaryOf(occ_, s)};
  }
  OccFactory occ_;
};

TEST_F(OccFillingOrder, PlaneSquareCounterClockwise) {
  addSquares(occ_);
  EXPECT_EQ(fill(1, {100, 101, 102, 103}), std::make_pair(1, std::vector<int>{100, 101, 102, 103}));
  EXPECT_EQ(fill(2, {-103, -102, -101, -100}),
            std::make_pair(-1, std::vector<int>{101, 102, 103, 100}));
}

// This triangle's plate faces -z whichever way the loop runs.
TEST_F(OccFillingOrder, TriangleWhosePlateFacesDown) {
  occ_.addPoint(140, {20, 0, 0}, 0);
  occ_.addPoint(141, {30, 0, 0}, 0);
  occ_.addPoint(142, {20, 10, 0}, 0);
  occ_.addLine(140, 140, 141);
  occ_.addLine(141, 141, 142);
  occ_.addLine(142, 142, 140);
  EXPECT_EQ(fill(1, {140, -142, -141}), std::make_pair(1, std::vector<int>{142, 141, 140}));
  EXPECT_EQ(fill(2, {-140, -142, -141}), std::make_pair(-1, std::vector<int>{142, 140, 141}));
}

// A disk of two half circles, clockwise: its plate faces +z given one way, -z the other, and
// both are listed alike.
TEST_F(OccFillingOrder, DiskOfHalfCircles) {
  occ_.addPoint(10, {0, 0, 0}, 0);
  occ_.addPoint(11, {20, 0, 0}, 0);
  occ_.addPoint(12, {-20, 0, 0}, 0);
  occ_.addCircleArc(9, 11, 10, 12);
  occ_.addCircleArc(10, 12, 10, 11);
  EXPECT_EQ(fill(3, {9, 10}), std::make_pair(-1, std::vector<int>{10, 9}));
  EXPECT_EQ(fill(4, {10, 9}), std::make_pair(-1, std::vector<int>{10, 9}));
  EXPECT_EQ(fill(5, {-9, -10}), std::make_pair(1, std::vector<int>{9, 10}));
  // Filling a plane loop leaves its curves' tolerances as they were.
  const BoundingBox box = occ_.boundingBox({1, 9});
  EXPECT_NEAR(box.min.x, -20, 1e-6);
  EXPECT_NEAR(box.max.y, 0, 1e-6);
}

// One corner lifted: the plate is no plane, and it faces +z; a loop running clockwise has its
// surface's parameters turned round, so that its mesh faces -z.
TEST_F(OccFillingOrder, LiftedSquare) {
  const double corners[4][3] = {{8, 0, 0}, {9, 0, 0.3}, {9, 1, 0}, {8, 1, 0}};
  for (int i = 0; i < 4; ++i)
    occ_.addPoint(1 + i, {corners[i][0], corners[i][1], corners[i][2]}, 0);
  for (int i = 0; i < 4; ++i) occ_.addLine(1 + i, 1 + i, 1 + (i + 1) % 4);
  EXPECT_EQ(fill(1, {1, 2, 3, 4}), std::make_pair(1, std::vector<int>{1, 2, 3, 4}));
  EXPECT_EQ(fill(2, {-4, -3, -2, -1}), std::make_pair(-1, std::vector<int>{2, 3, 4, 1}));
  EXPECT_EQ(fill(3, {-2, 3, 4, 1}), std::make_pair(-1, std::vector<int>{2, 3, 4, 1}));
}

}  // namespace
}  // namespace geomesh
