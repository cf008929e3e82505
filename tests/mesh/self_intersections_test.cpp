// selfIntersections: crossings between triangles that are not neighbours.
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/discrete/self_intersections.h"

namespace geomesh {
namespace {

// The closed surface of a tetrahedron, its corners at `o` and o + the three unit vectors.
void addTetrahedron(Triangulation& t, Vec3 o) {
  const auto first = static_cast<std::uint32_t>(t.points.size());
  t.points.insert(t.points.end(), {o, o + Vec3{1, 0, 0}, o + Vec3{0, 1, 0}, o + Vec3{0, 0, 1}});
  for (TriangleVertices f : {TriangleVertices{0, 2, 1}, TriangleVertices{0, 1, 3},
                             TriangleVertices{0, 3, 2}, TriangleVertices{1, 2, 3}})
    t.triangles.push_back({first + f[0], first + f[1], first + f[2]});
}

// A sphere of radius 1 as a latitude-longitude grid, poles included: closed, no crossing.
Triangulation sphere(int rings, int sectors) {
  constexpr double kPi = 3.14159265358979323846;
  Triangulation t;
  t.points.push_back({0, 0, 1});
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < sectors; ++j) {
      const double theta = kPi * i / rings, phi = 2 * kPi * j / sectors;
      t.points.push_back({std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                          std::cos(theta)});
    }
  t.points.push_back({0, 0, -1});
  const auto at = [&](int i, int j) {
    return static_cast<std::uint32_t>(1 + (i - 1) * sectors + (j % sectors));
  };
  const auto south = static_cast<std::uint32_t>(t.points.size() - 1);
  for (int j = 0; j < sectors; ++j) {
    t.triangles.push_back({0, at(1, j), at(1, j + 1)});
    for (int i = 1; i + 1 < rings; ++i) {
      t.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      t.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
    t.triangles.push_back({at(rings - 1, j), south, at(rings - 1, j + 1)});
  }
  return t;
}

// Distance from p to the plane of triangle k.
double planeDistance(const Triangulation& t, std::uint32_t k, Vec3 p) {
  const Vec3 a = t.points[t.triangles[k][0]], b = t.points[t.triangles[k][1]],
             c = t.points[t.triangles[k][2]];
  const Vec3 n = cross(b - a, c - a);
  return std::abs(dot(p - a, n)) / norm(n);
}

TEST(SelfIntersections, NeighboursOfAClosedSurfaceDoNotCount) {
  Triangulation t;
  addTetrahedron(t, {0, 0, 0});
  EXPECT_EQ(selfIntersections(t).count, 0u);
  const Triangulation ball = sphere(60, 120);
  ASSERT_EQ(ball.triangles.size(), 2u * 120 * 59);
  EXPECT_EQ(selfIntersections(ball).count, 0u);
}

TEST(SelfIntersections, TwoSurfacesPushedIntoEachOtherAreFound) {
  Triangulation apart, crossing;
  addTetrahedron(apart, {0, 0, 0});
  addTetrahedron(apart, {3, 0, 0});
  EXPECT_EQ(selfIntersections(apart).count, 0u);
  addTetrahedron(crossing, {0, 0, 0});
  addTetrahedron(crossing, {0.2, 0.2, 0.2});
  const SelfIntersections found = selfIntersections(crossing);
  ASSERT_GT(found.count, 0u);
  ASSERT_EQ(found.pairs.size(), found.points.size());
  for (std::size_t k = 0; k < found.pairs.size(); ++k) {
    const auto [i, j] = found.pairs[k];
    EXPECT_LT(i, 4u);  // one facet of each tetrahedron
    EXPECT_GE(j, 4u);
    EXPECT_LT(planeDistance(crossing, i, found.points[k]), 1e-12);
    EXPECT_LT(planeDistance(crossing, j, found.points[k]), 1e-12);
  }
  // The limit keeps the first pairs only, the count stays whole.
  const SelfIntersections first = selfIntersections(crossing, 1);
  EXPECT_EQ(first.count, found.count);
  ASSERT_EQ(first.pairs.size(), 1u);
  EXPECT_EQ(first.pairs[0], found.pairs[0]);
}

}  // namespace
}  // namespace geomesh
