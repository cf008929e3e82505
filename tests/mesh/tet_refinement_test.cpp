// Tests of the boundary's tetrahedralization from the Delaunay kernel and of the refinement to
// sizes: conformity, volume, sizes followed, kept faces and determinism.
#include "mesh/volumes/tet_refinement.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <vector>

#include "delaunay_tets_fixtures.h"
#include "mesh/core/predicates.h"
#include "mesh/volumes/boundary_delaunay.h"
#include "mesh/volumes/volume_estimate.h"

namespace geomesh {
namespace {

using Key = std::array<std::uint32_t, 3>;

Key sorted(Key k) {
  std::sort(k.begin(), k.end());
  return k;
}

// The surface of the unit cube as a complex: points on its faces (an n x n grid, the points
// off the cube's edges moved in their face's plane so that no four are cocircular), triangulated
// as the kernel's Delaunay tetrahedralization of them has them on its hull.
struct CubeComplex {
  VolumePlc plc;
  std::vector<Vec3> xyz;
};

CubeComplex cubeComplex(int n) {
  CubeComplex c;
  std::set<std::array<int, 3>> seen;
  unsigned state = 12345;
  auto jitter = [&] {
    state = state * 1103515245u + 12345u;
    return ((state >> 8) % 1000) / 1000.0 - 0.5;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side)
      for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
          std::array<int, 3> g{};
          g[axis] = side * n;
          g[(axis + 1) % 3] = i;
          g[(axis + 2) % 3] = j;
          if (!seen.insert(g).second) continue;
          double x[3] = {double(g[0]) / n, double(g[1]) / n, double(g[2]) / n};
          const bool inside = i > 0 && i < n && j > 0 && j < n;
          if (inside) {
            x[(axis + 1) % 3] += 0.3 * jitter() / n;
            x[(axis + 2) % 3] += 0.3 * jitter() / n;
          }
          c.xyz.push_back({x[0], x[1], x[2]});
        }
  const DelaunayTets hull = DelaunayTets::build(c.xyz);
  for (std::uint32_t t = 0; t < hull.slotCount(); ++t) {
    if (!hull.alive(t)) continue;
    for (int f = 0; f < 4; ++f)
      if (hull.neighbours[4 * t + f] == kNoTet) {
        const int* face = DelaunayTets::kFace[f];
        c.plc.triangles.push_back({int(hull.vertices[4 * t + face[0]]),
                                   int(hull.vertices[4 * t + face[1]]),
                                   int(hull.vertices[4 * t + face[2]])});
      }
  }
  c.plc.shellStart = {0};
  c.plc.shellEnd = c.plc.triangles.size();
  c.plc.nodes.assign(c.xyz.size(), 0);
  return c;
}


// Faces by how many alive tetrahedra use them.
std::map<Key, int> faceUses(const DelaunayTets& mesh) {
  std::map<Key, int> uses;
  for (std::uint32_t t = 0; t < mesh.slotCount(); ++t) {
    if (!mesh.alive(t)) continue;
    const std::uint32_t* v = &mesh.vertices[4 * t];
    for (int f = 0; f < 4; ++f) {
      const int* face = DelaunayTets::kFace[f];
      ++uses[sorted({v[face[0]], v[face[1]], v[face[2]]})];
    }
  }
  return uses;
}

// Every tetrahedron positive; the faces used once are exactly the shells' triangles, and each
// embedded triangle is a face of two tetrahedra.
void expectConforming(const DelaunayTets& mesh, const VolumePlc& plc) {
  for (std::uint32_t t = 0; t < mesh.slotCount(); ++t) {
    if (!mesh.alive(t)) continue;
    const std::uint32_t* v = &mesh.vertices[4 * t];
    ASSERT_EQ(orient3d(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]], mesh.points[v[3]]),
              1);
  }
  const std::map<Key, int> uses = faceUses(mesh);
  std::set<Key> shell, embedded;
  for (std::size_t t = 0; t < plc.triangles.size(); ++t) {
    const PlcTriangle& c = plc.triangles[t];
    (plc.isEmbedded(t) ? embedded : shell)
        .insert(sorted({std::uint32_t(c[0]), std::uint32_t(c[1]), std::uint32_t(c[2])}));
  }
  std::set<Key> once;
  for (const auto& [face, count] : uses) {
    ASSERT_LE(count, 2);
    if (count == 1) once.insert(face);
  }
  EXPECT_EQ(once, shell);
  for (const Key& k : embedded) {
    const auto it = uses.find(k);
    ASSERT_NE(it, uses.end());
    EXPECT_EQ(it->second, 2);
  }
}

// The same size at every node of the complex.
RefinementSizes uniformSizes(const CubeComplex& c, double size) {
  RefinementSizes sizes;
  sizes.atVertex.assign(c.xyz.size(), size);
  return sizes;
}

double meanEdge(const DelaunayTets& mesh, std::uint32_t firstInterior) {
  double sum = 0;
  int count = 0;
  for (std::uint32_t t = 0; t < mesh.slotCount(); ++t) {
    if (!mesh.alive(t)) continue;
    const std::uint32_t* v = &mesh.vertices[4 * t];
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        if (v[i] >= firstInterior || v[j] >= firstInterior) {
          sum += distance(mesh.points[v[i]], mesh.points[v[j]]);
          ++count;
        }
  }
  return sum / count;
}

TEST(BoundaryDelaunay, CubeSurfaceGivesTheCubesTetrahedra) {
  const CubeComplex c = cubeComplex(4);
  ASSERT_GT(c.plc.triangles.size(), 6u * 2 * 16 - 1);
  const auto mesh = boundaryDelaunay(c.plc, c.xyz, {});
  ASSERT_TRUE(mesh);
  expectConforming(*mesh, c.plc);
  EXPECT_NEAR(testing::volumeOf(*mesh), 1, 1e-12);
  EXPECT_EQ(mesh->points.size(), c.xyz.size());  // no node added
  // A hole point inside leaves nothing: the whole cube is the hole.
  EXPECT_FALSE(boundaryDelaunay(c.plc, c.xyz, {{0.5, 0.5, 0.5}}));
}

TEST(BoundaryDelaunay, TwistedPrismIsLeftToTheGeneralRecovery) {
  // A triangular prism whose top is turned by 30 degrees, each side split along its reflex
  // diagonal: no tetrahedralization of its six corners has those triangles as faces.
  VolumePlc plc;
  std::vector<Vec3> xyz;
  const double pi = 3.14159265358979323846;
  for (int k = 0; k < 3; ++k) xyz.push_back({std::cos(2 * pi * k / 3), std::sin(2 * pi * k / 3), 0});
  for (int k = 0; k < 3; ++k)
    xyz.push_back({std::cos(2 * pi * k / 3 + pi / 6), std::sin(2 * pi * k / 3 + pi / 6), 1});
  plc.triangles = {{0, 2, 1}, {3, 4, 5}};
  for (int k = 0; k < 3; ++k) {
    const int a = k, b = (k + 1) % 3, ta = 3 + k, tb = 3 + (k + 1) % 3;
    plc.triangles.push_back({a, b, tb});
    plc.triangles.push_back({a, tb, ta});
  }
  plc.shellStart = {0};
  plc.shellEnd = plc.triangles.size();
  plc.nodes.assign(xyz.size(), 0);
  EXPECT_FALSE(boundaryDelaunay(plc, xyz, {}));
}

TEST(TetRefinement, UniformSizeIsFollowedInsideTheCube) {
  const CubeComplex c = cubeComplex(5);
  auto mesh = boundaryDelaunay(c.plc, c.xyz, {});
  ASSERT_TRUE(mesh);
  RefinementSizes sizes = uniformSizes(c, 0.2);
  const RefinementStats stats = refineToSizes(*mesh, sizes);
  EXPECT_GT(stats.inserted, 20u);
  EXPECT_EQ(sizes.atVertex.size(), mesh->points.size());
  expectConforming(*mesh, c.plc);
  EXPECT_NEAR(testing::volumeOf(*mesh), 1, 1e-12);
  // Edges at an inserted vertex are about the size asked for: a tetrahedron is split while its
  // circumradius exceeds 1.05 times the size, and a regular one's is 0.61 times its edge, so
  // edges up to about 1.7 times the size are left, as the reference's Delaunay leaves them.
  const double edge = meanEdge(*mesh, static_cast<std::uint32_t>(c.xyz.size()));
  EXPECT_GT(edge, 0.9 * 0.2);
  EXPECT_LT(edge, 1.6 * 0.2);
}

TEST(TetRefinement, FieldMakesOneHalfFiner) {
  const CubeComplex c = cubeComplex(4);
  auto mesh = boundaryDelaunay(c.plc, c.xyz, {});
  ASSERT_TRUE(mesh);
  RefinementSizes sizes = uniformSizes(c, 0.25);
  sizes.field = [](Vec3 p) { return p.x < 0.5 ? 0.08 : 0.25; };
  refineToSizes(*mesh, sizes);
  expectConforming(*mesh, c.plc);
  int fine = 0, coarse = 0;
  for (std::size_t i = c.xyz.size(); i < mesh->points.size(); ++i)
    ++(mesh->points[i].x < 0.5 ? fine : coarse);
  EXPECT_GT(fine, 10 * std::max(coarse, 1));
  // Without extension from the boundary, the field alone sets the sizes: the coarse half gets
  // its points too.
  auto alone = boundaryDelaunay(c.plc, c.xyz, {});
  RefinementSizes fieldOnly = uniformSizes(c, 1.0);
  fieldOnly.field = [](Vec3) { return 0.15; };
  fieldOnly.extendFromBoundary = false;
  refineToSizes(*alone, fieldOnly);
  EXPECT_GT(alone->points.size() - c.xyz.size(), 40u);
}

TEST(TetRefinement, Deterministic) {
  const CubeComplex c = cubeComplex(4);
  auto first = boundaryDelaunay(c.plc, c.xyz, {}), second = boundaryDelaunay(c.plc, c.xyz, {});
  ASSERT_TRUE(first && second);
  RefinementSizes a = uniformSizes(c, 0.15), b = a;
  refineToSizes(*first, a);
  refineToSizes(*second, b);
  expectConforming(*first, c.plc);
  EXPECT_NEAR(testing::volumeOf(*first), 1, 1e-12);
  EXPECT_EQ(first->liveTetrahedra(), second->liveTetrahedra());
  ASSERT_EQ(first->points.size(), second->points.size());
  for (std::size_t i = 0; i < first->points.size(); ++i)
    EXPECT_TRUE(first->points[i] == second->points[i]);
}

TEST(VolumeEstimate, CountsAreNearTheMeshedOnesAndTooManyAreRefused) {
  const CubeComplex c = cubeComplex(5);
  auto mesh = boundaryDelaunay(c.plc, c.xyz, {});
  ASSERT_TRUE(mesh);
  RefinementSizes sizes = uniformSizes(c, 0.2);
  // The cube's faces have edges of about 0.2 and more (diagonals; the points are moved a
  // little in their faces): within options.sizeMax = 0.2, the estimate takes about 0.2.
  MeshOptions options;
  options.sizeMax = 0.2;
  const double estimate = estimateTetrahedra(c.plc, c.xyz, options);
  EXPECT_NEAR(estimate, 4.7 / 0.008, 0.01 * 4.7 / 0.008);
  refineToSizes(*mesh, sizes);
  const double made = static_cast<double>(mesh->tetCount());
  EXPECT_GT(made, 0.5 * estimate);
  EXPECT_LT(made, 1.5 * estimate);
  EXPECT_EQ(tooManyTetrahedra(1e6), "");
  EXPECT_EQ(tooManyTetrahedra(2e10), "about 2e+10 tetrahedra: more than the 1e9 one volume can hold");
  EXPECT_NE(tooManyTetrahedra(9e8).find("GB of memory here"), std::string::npos);
}

}  // namespace
}  // namespace geomesh
