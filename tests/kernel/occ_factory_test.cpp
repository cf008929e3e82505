// Tests of OccFactory: box volume, closed B-rep, loop orientation, evaluators.
#include "kernel/occ/occ_factory.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <map>

#include "kernel/geometry_error.h"
#include "tests/kernel/kernel_test_helpers.h"

namespace geomesh {
namespace {

TEST(OccFactory, BoxVolume) {
  OccFactory occ;
  EXPECT_EQ(occ.addBox(1, {0, 0, 0}, {1, 2, 3}), 1);
  EXPECT_NEAR(occ.volume(1), 6, 1e-12);
  EXPECT_EQ(occ.addBox(-1, {5, 0, 0}, {-0.5, 0.25, 2}), 2);  // negative extents are allowed
  EXPECT_NEAR(occ.volume(2), 0.25, 1e-12);
  EXPECT_THROW(occ.addBox(1, {0, 0, 0}, {1, 1, 1}), GeometryError);
  EXPECT_THROW(occ.addBox(3, {0, 0, 0}, {1, 0, 1}), GeometryError);
  EXPECT_THROW(occ.volume(7), GeometryError);
  EXPECT_EQ(occ.maxTag(0), 16);
  EXPECT_EQ(occ.maxTag(1), 24);
  EXPECT_EQ(occ.maxTag(2), 12);
  EXPECT_EQ(occ.maxTag(3), 2);
}

TEST(OccFactory, SynchronizedBoxIsAClosedBrep) {
  OccFactory occ;
  occ.addBox(1, {0, 0, 0}, {1, 2, 3});
  Model model;
  occ.synchronize(model);
  ASSERT_EQ(model.points().size(), 8u);
  ASSERT_EQ(model.curves().size(), 12u);
  ASSERT_EQ(model.surfaces().size(), 6u);
  ASSERT_EQ(model.volumes().size(), 1u);
  // Each curve joins two distinct points, at its parameter ends.
  for (const auto& [tag, c] : model.curves()) {
    EXPECT_NE(c.startPoint, c.endPoint);
    const Interval r = c.geometry->range();
    expectNear(c.geometry->point(r.min), model.point(c.startPoint)->xyz, 1e-12);
    expectNear(c.geometry->point(r.max), model.point(c.endPoint)->xyz, 1e-12);
    EXPECT_EQ(model.upward({1, tag}).size(), 2u);  // each edge bounds two faces
  }
  for (const auto& [tag, p] : model.points()) EXPECT_EQ(model.upward({0, tag}).size(), 3u);
  for (const auto& [tag, s] : model.surfaces()) {
    ASSERT_EQ(s.loops.size(), 1u);
    ASSERT_EQ(s.loops[0].size(), 4u);
    // The loop is a chain: each signed curve ends where the next one starts.
    auto ends = [&](int c) {
      const ModelCurve* curve = model.curve(std::abs(c));
      return c > 0 ? std::pair{curve->startPoint, curve->endPoint}
                   : std::pair{curve->endPoint, curve->startPoint};
    };
    for (std::size_t i = 0; i < 4; ++i)
      EXPECT_EQ(ends(s.loops[0][i]).second, ends(s.loops[0][(i + 1) % 4]).first);
    EXPECT_TRUE(s.geometry->isPlane());
    EXPECT_EQ(model.upward({2, tag}), (std::vector<int>{1}));
  }
  EXPECT_EQ(model.boundary({3, 1}).size(), 6u);
  const BoundingBox box = model.boundingBox({3, 1});
  expectNear(box.min, {0, 0, 0}, 1e-12);
  expectNear(box.max, {1, 2, 3}, 1e-12);
}

// The outer loop runs counter-clockwise in the surface's parameters: its signed area there is
// positive.
TEST(OccFactory, OuterLoopsAreCounterClockwiseInParameters) {
  OccFactory occ;
  occ.addBox(1, {0, 0, 0}, {1, 2, 3});
  Model model;
  occ.synchronize(model);
  for (const auto& [tag, s] : model.surfaces()) {
    double area = 0;
    for (int c : s.loops[0]) {
      const ModelCurve* curve = model.curve(std::abs(c));
      const Interval r = curve->geometry->range();
      for (int i = 0; i < 8; ++i) {
        double t0 = r.min + (r.max - r.min) * i / 8, t1 = r.min + (r.max - r.min) * (i + 1) / 8;
        if (c < 0) std::swap(t0, t1);
        const Vec2 a = s.geometry->project(curve->geometry->point(t0));
        const Vec2 b = s.geometry->project(curve->geometry->point(t1));
        area += a.u * b.v - b.u * a.v;
      }
    }
    EXPECT_GT(area, 0) << "surface " << tag;
  }
}

TEST(OccFactory, EvaluatorsMatchFiniteDifferences) {
  OccFactory occ;
  occ.addBox(1, {0.5, -1, 2}, {1, 2, 3});
  Model model;
  occ.synchronize(model);
  const double h = 1e-6;
  for (const auto& [tag, c] : model.curves()) {
    const Interval r = c.geometry->range();
    const double t = r.min + 0.3 * (r.max - r.min);
    expectNear(c.geometry->firstDerivative(t),
               (c.geometry->point(t + h) - c.geometry->point(t - h)) / (2 * h), 1e-7);
    expectNear(c.geometry->secondDerivative(t),
               (c.geometry->firstDerivative(t + h) - c.geometry->firstDerivative(t - h)) / (2 * h),
               1e-7);
  }
  for (const auto& entry : model.surfaces()) {
    const ModelSurface& s = entry.second;
    const ParamBox b = s.geometry->bounds();
    const Vec2 uv{b.u.min + 0.3 * (b.u.max - b.u.min), b.v.min + 0.6 * (b.v.max - b.v.min)};
    const SurfaceDerivatives d = s.geometry->firstDerivatives(uv);
    auto at = [&](double du, double dv) { return s.geometry->point({uv.u + du, uv.v + dv}); };
    expectNear(d.du, (at(h, 0) - at(-h, 0)) / (2 * h), 1e-7);
    expectNear(d.dv, (at(0, h) - at(0, -h)) / (2 * h), 1e-7);
    const Vec2 back = s.geometry->project(s.geometry->point(uv));
    EXPECT_NEAR(back.u, uv.u, 1e-9);
    EXPECT_NEAR(back.v, uv.v, 1e-9);
  }
}

TEST(OccFactory, SynchronizeKeepsOtherEntities) {
  Model model;
  model.addPoint({100, {9, 9, 9}, 0});
  OccFactory occ;
  occ.addBox(1, {0, 0, 0}, {1, 1, 1});
  occ.synchronize(model);
  EXPECT_EQ(model.points().size(), 9u);
  occ.clear();
  EXPECT_EQ(occ.maxTag(3), 0);
}

}  // namespace
}  // namespace geomesh
