// The seams and poles of OpenCASCADE faces as the model sees them: a seam's two occurrences in
// a loop lie on the two sides of the parameter box, a pole's degenerate curve along a side.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "kernel/occ/occ_factory.h"
#include "tests/occ_fixtures.h"

namespace geomesh {
namespace {

using namespace occ_fixtures;

TEST(OccSeams, CylinderSeamIsOneCurveUsedTwice) {
  OccFactory occ;
  occ.importShapes(writeBrep(cylinder()));
  Model model;
  occ.synchronize(model);
  EXPECT_EQ(model.curves().size(), 3u);  // two circles and the seam
  int seamFaces = 0;
  for (const auto& [tag, s] : model.surfaces()) {
    if (s.loops[0].size() != 4) continue;
    ++seamFaces;
    int seam = 0;
    for (int c : s.loops[0])
      for (int d : s.loops[0])
        if (c == -d) seam = std::abs(c);
    ASSERT_NE(seam, 0);
    const Interval r = model.curve(seam)->geometry->range();
    const auto forward = s.geometry->curveParameters(seam, r.min);
    const auto backward = s.geometry->curveParameters(-seam, r.min);
    ASSERT_TRUE(forward && backward);
    EXPECT_NEAR(std::abs(forward->u - backward->u), 2 * std::numbers::pi, 1e-9);
    EXPECT_NEAR(forward->v, backward->v, 1e-9);
  }
  EXPECT_EQ(seamFaces, 1);
}

// The seam's two occurrences lie on the two sides of the parameter box; a pole's curve runs
// along a side at the pole's latitude.
TEST(OccSeams, SphereSeamAndPoles) {
  OccFactory occ;
  occ.importShapes(writeBrep(sphere()));
  Model model;
  occ.synchronize(model);
  const ModelSurface& s = model.surfaces().begin()->second;
  ASSERT_EQ(s.loops.size(), 1u);
  ASSERT_EQ(s.loops[0].size(), 4u);
  int seams = 0, poles = 0;
  const double pi = std::numbers::pi;
  for (int c : s.loops[0]) {
    const ModelCurve& curve = *model.curve(std::abs(c));
    const Interval r = curve.geometry->range();
    const auto a = s.geometry->curveParameters(c, r.min);
    const auto b = s.geometry->curveParameters(c, r.max);
    ASSERT_TRUE(a && b);
    if (curve.geometry->isDegenerate()) {
      ++poles;
      EXPECT_NEAR(std::abs(a->v), pi / 2, 1e-9);
      EXPECT_NEAR(std::abs(a->u - b->u), 2 * pi, 1e-9);
    } else {
      ++seams;
      EXPECT_NEAR(std::abs(b->v - a->v), pi, 1e-9);
    }
  }
  EXPECT_EQ(poles, 2);
  EXPECT_EQ(seams, 2);
  // The seam, used in both directions, lies at u = 0 one way and u = 2 pi the other.
  int seam = 0;
  for (int c : s.loops[0])
    if (!model.curve(std::abs(c))->geometry->isDegenerate()) seam = std::abs(c);
  const double t = model.curve(seam)->geometry->range().min;
  const auto forward = s.geometry->curveParameters(seam, t);
  const auto backward = s.geometry->curveParameters(-seam, t);
  ASSERT_TRUE(forward && backward);
  EXPECT_NEAR(std::abs(forward->u - backward->u), 2 * pi, 1e-9);
}

}  // namespace
}  // namespace geomesh
