// Tests of the Delaunay triangulation, segment recovery, spatial sort and exact predicates.
#include "mesh/surfaces/delaunay2d.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "mesh/surfaces/constrained_delaunay.h"
#include "mesh/core/predicates.h"
#include "mesh/core/spatial_sort.h"

namespace geomesh {
namespace {

std::vector<Vec2> randomPoints(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  std::vector<Vec2> points(n);
  for (Vec2& p : points) p = {coordinate(rng), coordinate(rng)};
  return points;
}

void expectValidTriangulation(const Triangulation2D& tri) {
  for (std::uint32_t t = 0; t < tri.triangleCount(); ++t) {
    const Vec2 a = tri.point(tri.vertex(3 * t)), b = tri.point(tri.vertex(3 * t + 1)),
               c = tri.point(tri.vertex(3 * t + 2));
    ASSERT_GT(orient2d(a, b, c), 0) << "triangle " << t;
    for (std::uint32_t corner = 3 * t; corner < 3 * t + 3; ++corner) {
      const std::uint32_t across = tri.neighbour(corner);
      if (across == kNone) continue;
      ASSERT_EQ(tri.neighbour(across), corner);
      // The shared edge has the same end points, in opposite order.
      ASSERT_EQ(tri.vertex(across - across % 3 + (across + 1) % 3),
                tri.vertex(corner - corner % 3 + (corner + 2) % 3));
    }
  }
}

// No inserted point strictly inside any triangle's circumcircle (brute force).
void expectEmptyCircumcircles(const Triangulation2D& tri) {
  for (std::uint32_t t = 0; t < tri.triangleCount(); ++t) {
    const Vec2 a = tri.point(tri.vertex(3 * t)), b = tri.point(tri.vertex(3 * t + 1)),
               c = tri.point(tri.vertex(3 * t + 2));
    for (std::uint32_t v = Triangulation2D::kFirstVertex; v < tri.pointCount(); ++v)
      ASSERT_LE(incircle(a, b, c, tri.point(v)), 0) << "triangle " << t << ", point " << v;
  }
}

TEST(Delaunay2D, RandomPointsGiveADelaunayTriangulation) {
  const std::vector<Vec2> points = randomPoints(600, 7);
  const Triangulation2D tri = delaunayTriangulation(points);
  // n points inside the enclosing triangle: 2n + 1 triangles.
  EXPECT_EQ(tri.triangleCount(), 2 * points.size() + 1);
  expectValidTriangulation(tri);
  expectEmptyCircumcircles(tri);
  for (std::uint32_t k = 0; k < points.size(); ++k) {
    EXPECT_NE(tri.triangleOf(k + Triangulation2D::kFirstVertex), kNone);
    EXPECT_EQ(tri.point(k + Triangulation2D::kFirstVertex), points[k]);
  }
}

TEST(Delaunay2D, CocircularGridPointsStayValid) {
  std::vector<Vec2> points;
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 30; ++j) points.push_back({i * 0.1, j * 0.1});
  const Triangulation2D tri = delaunayTriangulation(points);
  EXPECT_EQ(tri.triangleCount(), 2 * points.size() + 1);
  expectValidTriangulation(tri);
  expectEmptyCircumcircles(tri);
}

TEST(Delaunay2D, DuplicatePointsAreLeftOut) {
  std::vector<Vec2> points = randomPoints(50, 3);
  points.push_back(points[10]);
  points.push_back(points[20]);
  const Triangulation2D tri = delaunayTriangulation(points);
  EXPECT_EQ(tri.triangleCount(), 2 * 50 + 1u);
  // Of each pair of equal points, exactly one is in the triangulation.
  constexpr std::uint32_t f = Triangulation2D::kFirstVertex;
  EXPECT_NE(tri.triangleOf(f + 10) == kNone, tri.triangleOf(f + 50) == kNone);
  EXPECT_NE(tri.triangleOf(f + 20) == kNone, tri.triangleOf(f + 51) == kNone);
  expectValidTriangulation(tri);
}

TEST(Delaunay2D, LargeRandomSetIsLocallyDelaunayEverywhere) {
  const std::vector<Vec2> points = randomPoints(100000, 11);
  Triangulation2D tri = delaunayTriangulation(points);
  EXPECT_EQ(tri.triangleCount(), 2 * points.size() + 1);
  expectValidTriangulation(tri);
  for (std::uint32_t c = 0; c < 3 * tri.triangleCount(); ++c) ASSERT_FALSE(tri.shouldFlip(c));
}

TEST(ConstrainedDelaunay, RecoversSegmentsCrossingManyTriangles) {
  // A square (boundary) with random points inside and a zigzag of embedded segments.
  std::vector<Vec2> points{{-1.5, -1.5}, {1.5, -1.5}, {1.5, 1.5}, {-1.5, 1.5},
                           {-1.2, 0.0},  {1.2, 0.05}, {0.0, 1.2}, {0.05, -1.2}};
  const std::vector<Vec2> inner = randomPoints(400, 5);
  points.insert(points.end(), inner.begin(), inner.end());
  Triangulation2D tri = delaunayTriangulation(points);
  constexpr std::uint32_t f = Triangulation2D::kFirstVertex;
  const std::vector<ConstrainedSegment> segments{
      {f + 0, f + 1, EdgeKind::Boundary}, {f + 1, f + 2, EdgeKind::Boundary},
      {f + 2, f + 3, EdgeKind::Boundary}, {f + 3, f + 0, EdgeKind::Boundary},
      {f + 4, f + 5, EdgeKind::Embedded}, {f + 6, f + 7, EdgeKind::Embedded}};
  // The two embedded segments cross: the second cannot be recovered.
  EXPECT_EQ(recoverSegments(tri, segments), 5);

  Triangulation2D tri2 = delaunayTriangulation(points);
  const std::vector<ConstrainedSegment> valid(segments.begin(), segments.end() - 1);
  ASSERT_EQ(recoverSegments(tri2, valid), -1);
  expectValidTriangulation(tri2);
  for (const ConstrainedSegment& s : valid) {
    const std::uint32_t c = tri2.findEdge(s.a, s.b);
    ASSERT_NE(c, kNone);
    EXPECT_EQ(tri2.kind(c), s.kind);
  }
  // Free edges are constrained Delaunay again.
  for (std::uint32_t c = 0; c < 3 * tri2.triangleCount(); ++c) ASSERT_FALSE(tri2.shouldFlip(c));
  // Inside: the square's triangles, on both sides of the embedded segment.
  const std::vector<std::uint8_t> inside = classifyInside(tri2);
  double area = 0;
  for (std::uint32_t t = 0; t < tri2.triangleCount(); ++t) {
    if (!inside[t]) continue;
    const Vec2 a = tri2.point(tri2.vertex(3 * t)), b = tri2.point(tri2.vertex(3 * t + 1)),
               c = tri2.point(tri2.vertex(3 * t + 2));
    area += 0.5 * ((b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u));
    EXPECT_FALSE(tri2.hasEnclosingVertex(t));
  }
  EXPECT_NEAR(area, 9.0, 1e-12);
}

// The square of side 3 with random points inside, its sides recovered.
Triangulation2D constrainedSquare(std::size_t interior) {
  std::vector<Vec2> points{{-1.5, -1.5}, {1.5, -1.5}, {1.5, 1.5}, {-1.5, 1.5}};
  const std::vector<Vec2> inner = randomPoints(interior, 7);
  points.insert(points.end(), inner.begin(), inner.end());
  Triangulation2D tri = delaunayTriangulation(points);
  constexpr std::uint32_t f = Triangulation2D::kFirstVertex;
  std::vector<ConstrainedSegment> sides;
  for (std::uint32_t k = 0; k < 4; ++k) sides.push_back({f + k, f + (k + 1) % 4});
  EXPECT_EQ(recoverSegments(tri, sides), -1);
  return tri;
}

TEST(Triangulation2D, KeepTrianglesLeavesTheDomainWithItsBoundaryOnTheHull) {
  Triangulation2D tri = constrainedSquare(200);
  const std::vector<std::uint8_t> inside = classifyInside(tri);
  const auto count = static_cast<std::size_t>(std::count(inside.begin(), inside.end(), 1));
  Triangulation2D domain = tri;
  domain.keepTriangles(inside);
  ASSERT_EQ(domain.triangleCount(), count);
  expectValidTriangulation(domain);
  std::size_t hullEdges = 0;
  for (std::uint32_t c = 0; c < 3 * domain.triangleCount(); ++c) {
    EXPECT_TRUE(domain.alive(c / 3));
    EXPECT_EQ(domain.neighbour(c) == kNone, domain.kind(c) == EdgeKind::Boundary);
    hullEdges += domain.neighbour(c) == kNone;
  }
  EXPECT_EQ(hullEdges, 4u);
  for (std::uint32_t v = 0; v < Triangulation2D::kFirstVertex; ++v)
    EXPECT_FALSE(domain.inMesh(v));
  for (std::uint32_t v = Triangulation2D::kFirstVertex; v < domain.pointCount(); ++v) {
    ASSERT_TRUE(domain.inMesh(v));
    std::vector<std::uint32_t> ring;
    // Corners are on the hull; the random points are inside.
    EXPECT_EQ(domain.ring(v, ring), v >= Triangulation2D::kFirstVertex + 4) << v;
    for (std::uint32_t c : ring) EXPECT_EQ(domain.vertex(c), v);
  }
}

// Flips, splits and Bowyer-Watson insertion share the storage: a split after a collapse
// reuses the dead triangles, and the domain can still take Delaunay insertions.
TEST(Triangulation2D, LocalOperationsAndInsertionShareTheTriangles) {
  Triangulation2D tri = constrainedSquare(50);
  tri.keepTriangles(classifyInside(tri));
  const std::size_t triangles = tri.triangleCount();
  const std::uint32_t v = Triangulation2D::kFirstVertex + 4;  // a random interior point
  std::vector<std::uint32_t> ring;
  ASSERT_TRUE(tri.ring(v, ring));
  // Collapse onto the neighbour whose removal keeps every triangle positive.
  bool collapsed = false;
  for (std::uint32_t k = 0; k < ring.size() && !collapsed; ++k) {
    const std::uint32_t w = tri.vertex(Triangulation2D::nextCorner(ring[k]));
    bool valid = true;
    for (std::uint32_t c : ring) {
      const std::uint32_t b = tri.vertex(Triangulation2D::nextCorner(c));
      const std::uint32_t a = tri.vertex(Triangulation2D::prevCorner(c));
      if (a != w && b != w) valid = valid && orient2d(tri.point(w), tri.point(b), tri.point(a)) > 0;
    }
    if (!valid) continue;
    tri.collapse(v, w, ring);
    collapsed = true;
  }
  ASSERT_TRUE(collapsed);
  EXPECT_FALSE(tri.inMesh(v));
  std::size_t alive = 0;
  for (std::uint32_t t = 0; t < tri.triangleCount(); ++t) alive += tri.alive(t);
  EXPECT_EQ(alive, triangles - 2);
  // Split some free edge at its midpoint: the two dead triangles come back.
  std::uint32_t edge = kNone;
  for (std::uint32_t c = 0; c < 3 * tri.triangleCount() && edge == kNone; ++c)
    if (tri.alive(c / 3) && tri.neighbour(c) != kNone) edge = c;
  ASSERT_NE(edge, kNone);
  const Vec2 a = tri.point(tri.vertex(Triangulation2D::nextCorner(edge)));
  const Vec2 b = tri.point(tri.vertex(Triangulation2D::prevCorner(edge)));
  tri.split(edge, tri.addPoint({0.5 * (a.u + b.u), 0.5 * (a.v + b.v)}));
  EXPECT_EQ(tri.triangleCount(), triangles);
  for (std::uint32_t t = 0; t < tri.triangleCount(); ++t) EXPECT_TRUE(tri.alive(t));
  // Then a Delaunay insertion near the centre.
  const std::uint32_t p = tri.addPoint({0.01, 0.02});
  const std::uint32_t found = tri.locate(tri.point(p), 0);
  ASSERT_NE(found, kNone);
  ASSERT_EQ(tri.insert(p, found), Triangulation2D::InsertStatus::Inserted);
  EXPECT_TRUE(tri.inMesh(p));
  expectValidTriangulation(tri);
}

// Target sizes are stored per point: one value for each, whatever adds or cuts.
TEST(Triangulation2D, SizesStayInStepWithThePoints) {
  Triangulation2D tri = constrainedSquare(20);
  ASSERT_EQ(tri.sizes().size(), tri.pointCount());
  for (std::uint32_t v = 0; v < tri.pointCount(); ++v) {
    EXPECT_EQ(tri.size(v), 0);
    tri.setSize(v, 1.0 + v);
  }
  const std::uint32_t extra = tri.addPoint({0.25, 0.25});
  EXPECT_EQ(tri.sizes().size(), tri.pointCount());
  EXPECT_EQ(tri.size(extra), 0);
  tri.removeLastPoint();
  EXPECT_EQ(tri.sizes().size(), tri.pointCount());
  tri.keepTriangles(classifyInside(tri));
  ASSERT_EQ(tri.sizes().size(), tri.pointCount());
  for (std::uint32_t v = 0; v < tri.pointCount(); ++v) EXPECT_EQ(tri.size(v), 1.0 + v);
}

TEST(SpatialSort, IsADeterministicPermutationWithShortSteps) {
  const std::vector<Vec2> points = randomPoints(20000, 13);
  const std::vector<std::uint32_t> order = spatialOrder(points);
  EXPECT_EQ(order, spatialOrder(points));
  std::vector<std::uint32_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (std::uint32_t k = 0; k < sorted.size(); ++k) ASSERT_EQ(sorted[k], k);
  // Consecutive points are close on average (random order: about 1.04 on this square).
  double walk = 0;
  for (std::size_t k = 1; k < order.size(); ++k) {
    const Vec2 a = points[order[k - 1]], b = points[order[k]];
    walk += std::hypot(a.u - b.u, a.v - b.v);
  }
  EXPECT_LT(walk / static_cast<double>(order.size()), 0.1);
}

TEST(Predicates, ExactNearDegenerateDecisions) {
  // Points nearly collinear: plain double evaluation gets these wrong or zero.
  const Vec2 a{0.5, 0.5}, b{12, 12}, c{24, 24};
  EXPECT_EQ(orient2d(a, b, c), 0);
  EXPECT_EQ(orient2d(a, b, {24, 24 + 1e-14}), 1);
  EXPECT_EQ(orient2d(a, b, {24, 24 - 1e-14}), -1);
  EXPECT_EQ(incircle({0, 0}, {1, 0}, {0, 1}, {1, 1}), 0);
  EXPECT_EQ(incircle({0, 0}, {1, 0}, {0, 1}, {1, 1 - 1e-15}), 1);
  EXPECT_EQ(orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}), 1);
  EXPECT_EQ(insphere({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.2, 0.2, 0.2}), 1);
  EXPECT_EQ(insphere({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}), 0);
  EXPECT_EQ(insphere({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {2, 2, 2}), -1);
}

}  // namespace
}  // namespace geomesh
