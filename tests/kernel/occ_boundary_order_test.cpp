// The order in which the OpenCASCADE factory lists the curves of a plane surface with holes,
// as the reference (Gmsh 4.15.2) lists them: the outer loop the way the script's loop runs
// (the way its first curve goes), from its first curve; each hole as its loop reversed as a
// whole, from its last curve. Whatever the listing, the face bounds the same region: the
// outer loop counter-clockwise, the holes clockwise.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

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

// The postcondition whatever the listing: the outer loop counter-clockwise, the holes
// clockwise, seen from the face's normal (+z here).
void expectHolesTurnAgainstOuterLoop(OccFactory& occ, int surface) {
  Model model;
  occ.synchronize(model);
  const auto& loops = model.surface(surface)->loops;
  ASSERT_GE(loops.size(), 2u);
  EXPECT_GT(signedArea(model, loops[0]), 0);
  for (std::size_t i = 1; i < loops.size(); ++i) EXPECT_LT(signedArea(model, loops[i]), 0);
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

}  // namespace
}  // namespace geomesh
