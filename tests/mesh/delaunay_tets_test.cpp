// Tests of the tetrahedral Delaunay kernel: predicates, the Delaunay property checked with
// exact predicates, neighbour links, constrained faces and refused insertions.
#include "mesh/volumes/delaunay_tets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include "delaunay_tets_fixtures.h"
#include "mesh/core/predicates.h"

namespace geomesh {
namespace {

std::vector<Vec3> randomPoints(std::size_t n, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Vec3> points(n);
  for (Vec3& p : points) p = {u(random), u(random), u(random)};
  return points;
}

std::vector<Vec3> gridPoints(int n) {
  std::vector<Vec3> points;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) points.push_back({i / 3.0, j / 3.0, k / 3.0});
  return points;
}

// Every alive tetrahedron positive (exactly), every link reciprocal and across the same three
// vertices, and no vertex strictly inside any circumsphere.
void expectValidDelaunay(const DelaunayTets& mesh, bool delaunay) {
  std::size_t alive = 0;
  for (std::uint32_t t = 0; t < mesh.slotCount(); ++t) {
    if (!mesh.alive(t)) continue;
    ++alive;
    const std::uint32_t* v = &mesh.vertices[4 * t];
    ASSERT_EQ(orient3d(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]], mesh.points[v[3]]),
              1)
        << "tetrahedron " << t;
    for (int f = 0; f < 4; ++f) {
      const std::uint32_t h = mesh.neighbours[4 * t + f];
      if (h == kNoTet) continue;
      ASSERT_TRUE(mesh.alive(h >> 2));
      ASSERT_EQ(mesh.neighbours[h], 4 * t + static_cast<std::uint32_t>(f));
      std::set<std::uint32_t> mine, theirs;
      for (int k = 0; k < 3; ++k) {
        mine.insert(v[DelaunayTets::kFace[f][k]]);
        theirs.insert(mesh.vertices[4 * (h >> 2) + DelaunayTets::kFace[h & 3][k]]);
      }
      ASSERT_EQ(mine, theirs);
    }
    if (!delaunay) continue;
    for (std::uint32_t p = 0; p < mesh.points.size(); ++p)
      ASSERT_LE(insphere(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]],
                         mesh.points[v[3]], mesh.points[p]),
                0)
          << "point " << p << " inside the sphere of tetrahedron " << t;
  }
  EXPECT_EQ(alive, mesh.tetCount());
}


TEST(DelaunayTets, FaceTableTurnsCounterClockwiseSeenFromTheOppositeVertex) {
  const Vec3 v[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  ASSERT_EQ(orient3d(v[0], v[1], v[2], v[3]), 1);
  for (int f = 0; f < 4; ++f) {
    const int* face = DelaunayTets::kFace[f];
    EXPECT_EQ(orient3d(v[face[0]], v[face[1]], v[face[2]], v[f]), 1) << "face " << f;
  }
}

TEST(DelaunayTets, RandomPointsGiveADelaunayTetrahedralizationOfTheirHull) {
  const std::vector<Vec3> points = randomPoints(400, 11);
  const DelaunayTets mesh = DelaunayTets::build(points);
  expectValidDelaunay(mesh, true);
  // Every point is a vertex, and the tetrahedra fill nearly all of the unit cube (the hull).
  std::set<std::uint32_t> used(mesh.vertices.begin(), mesh.vertices.end());
  std::size_t usedPoints = 0;
  for (std::uint32_t t = 0; t < mesh.slotCount(); ++t)
    if (mesh.alive(t))
      for (int k = 0; k < 4; ++k) usedPoints += mesh.vertices[4 * t + k] < points.size();
  EXPECT_GT(usedPoints, 0u);
  for (std::uint32_t p = 0; p < points.size(); ++p) EXPECT_TRUE(used.count(p)) << p;
  EXPECT_GT(testing::volumeOf(mesh), 0.85);
  EXPECT_LE(testing::volumeOf(mesh), 1.0);
}

TEST(DelaunayTets, CosphericalGridAndDuplicatesAreHandled) {
  std::vector<Vec3> points = gridPoints(5);
  points.push_back(points[17]);  // a duplicate is skipped
  const DelaunayTets mesh = DelaunayTets::build(points);
  expectValidDelaunay(mesh, true);
  EXPECT_NEAR(testing::volumeOf(mesh), (4 / 3.0) * (4 / 3.0) * (4 / 3.0), 1e-12);
}

TEST(DelaunayTets, ConstrainedFacesAreNeitherCrossedNorRemoved) {
  // Two tetrahedra sharing a kept face; a point near the face on one side cannot take the
  // other tetrahedron into its cavity, and a point beyond the outer faces is outside.
  std::vector<Vec3> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  std::vector<std::uint32_t> tets = {0, 1, 2, 3, 1, 2, 3, 4};
  if (orient3d(points[1], points[2], points[3], points[4]) < 0) std::swap(tets[4], tets[5]);
  const std::array<std::uint32_t, 3> shared[] = {{1, 2, 3}};
  DelaunayTets mesh = DelaunayTets::fromTetrahedra(points, tets, shared);
  expectValidDelaunay(mesh, false);
  EXPECT_EQ(mesh.locate({0.1, 0.1, 0.1}, 1), kNoTet);  // behind the kept face: not crossed
  EXPECT_EQ(mesh.locate({0.1, 0.1, 0.1}, 0), 0u);
  EXPECT_EQ(mesh.locate({-1, -1, -1}, 0), kNoTet);
  ASSERT_EQ(mesh.insert({0.3, 0.3, 0.3}, 0), DelaunayTets::Insertion::kInserted);
  expectValidDelaunay(mesh, false);
  // The kept face is still there, as a face of tetrahedra on both sides.
  int keptHalves = 0;
  for (std::uint32_t t = 0; t < mesh.slotCount(); ++t) {
    if (!mesh.alive(t)) continue;
    for (int f = 0; f < 4; ++f) {
      std::set<std::uint32_t> face;
      for (int k = 0; k < 3; ++k) face.insert(mesh.vertices[4 * t + DelaunayTets::kFace[f][k]]);
      if (face == std::set<std::uint32_t>{1, 2, 3}) {
        EXPECT_TRUE(mesh.constrained(t, f));
        ++keptHalves;
      }
    }
  }
  EXPECT_EQ(keptHalves, 2);
  EXPECT_NEAR(testing::volumeOf(mesh), 1 / 6.0 + 1 / 3.0, 1e-12);
  // A point nearer than the distance asked to a vertex of its cavity is refused.
  EXPECT_EQ(mesh.insert({0.05, 0.05, 0.05}, mesh.lastTet(), 0.2),
            DelaunayTets::Insertion::kTooClose);
}

TEST(DelaunayTets, KeptEdgesSurviveInsertion) {
  // An edge of the tetrahedron at the middle of random points: a point at its middle lies in
  // every tetrahedron around it, so its cavity would remove the edge.
  DelaunayTets mesh = DelaunayTets::build(randomPoints(200, 5));
  const std::uint32_t t = mesh.locate({0.5, 0.5, 0.5}, mesh.lastTet());
  ASSERT_NE(t, kNoTet);
  const std::array<std::uint32_t, 2> kept{mesh.vertices[4 * t], mesh.vertices[4 * t + 1]};
  mesh.keepEdges(std::span(&kept, 1));
  const Vec3 middle = (mesh.points[kept[0]] + mesh.points[kept[1]]) / 2;
  EXPECT_EQ(mesh.insert(middle, mesh.lastTet()), DelaunayTets::Insertion::kKeptEdge);
  expectValidDelaunay(mesh, true);
}

}  // namespace
}  // namespace geomesh
