// Tests of the toolbox for merged triangulations: vertex normals and curvatures, quadric-error
// simplification, fairing and the topology report.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iostream>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <unordered_map>

#include "mesh/discrete/surface_curvature.h"
#include "mesh/discrete/surface_fairing.h"
#include "mesh/discrete/surface_simplification.h"
#include "mesh/discrete/surface_topology.h"

namespace geomesh {
namespace {

constexpr double kPi = std::numbers::pi;

Triangulation icosahedron(double radius, Vec3 centre = {}) {
  const double g = (1 + std::sqrt(5.0)) / 2;
  Triangulation t;
  for (Vec3 p : {Vec3{-1, g, 0}, Vec3{1, g, 0}, Vec3{-1, -g, 0}, Vec3{1, -g, 0}, Vec3{0, -1, g},
                 Vec3{0, 1, g}, Vec3{0, -1, -g}, Vec3{0, 1, -g}, Vec3{g, 0, -1}, Vec3{g, 0, 1},
                 Vec3{-g, 0, -1}, Vec3{-g, 0, 1}})
    t.points.push_back(centre + radius * normalized(p));
  t.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  return t;
}

// The icosahedron's faces each cut into frequency^2 triangles, projected to the sphere. A grid
// point is named by its integer weights on the icosahedron's corners, so that faces share it.
Triangulation geodesicSphere(int frequency, double radius) {
  const Triangulation base = icosahedron(1);
  Triangulation t;
  std::map<std::vector<std::pair<std::uint32_t, int>>, std::uint32_t> named;
  auto point = [&](const TriangleVertices& face, int i, int j) {
    const int n = frequency;
    std::vector<std::pair<std::uint32_t, int>> key;
    for (auto [corner, w] : {std::pair{face[0], n - i - j}, {face[1], i}, {face[2], j}})
      if (w > 0) key.emplace_back(corner, w);
    std::sort(key.begin(), key.end());
    const auto [it, added] = named.try_emplace(key, static_cast<std::uint32_t>(t.points.size()));
    if (added) {
      Vec3 p;
      for (auto [corner, w] : key) p += static_cast<double>(w) * base.points[corner];
      t.points.push_back(radius * normalized(p));
    }
    return it->second;
  };
  for (const TriangleVertices& face : base.triangles)
    for (int i = 0; i < frequency; ++i)
      for (int j = 0; i + j < frequency; ++j) {
        t.triangles.push_back({point(face, i, j), point(face, i + 1, j), point(face, i, j + 1)});
        if (i + j + 2 <= frequency)
          t.triangles.push_back(
              {point(face, i + 1, j), point(face, i + 1, j + 1), point(face, i, j + 1)});
      }
  return t;
}

// The grid f(i / nu, j / nv), 0 <= i <= nu, 0 <= j <= nv, two triangles a cell; wrapped
// directions reuse their first vertices.
Triangulation grid(int nu, int nv, bool wrapU, bool wrapV,
                   const std::function<Vec3(double, double)>& f) {
  Triangulation t;
  const int columns = wrapU ? nu : nu + 1, rows = wrapV ? nv : nv + 1;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) t.points.push_back(f(double(i) / nu, double(j) / nv));
  auto id = [&](int i, int j) {
    return static_cast<std::uint32_t>((j % rows) * columns + (i % columns));
  };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      t.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      t.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return t;
}

double enclosedVolume(const Triangulation& t) {
  double sixTimes = 0;
  for (const TriangleVertices& v : t.triangles)
    sixTimes += dot(t.points[v[0]], cross(t.points[v[1]], t.points[v[2]]));
  return sixTimes / 6;
}

double rmsRadialDeviation(const Triangulation& t, double radius) {
  double sum = 0;
  for (Vec3 p : t.points) sum += std::pow(norm(p) - radius, 2);
  return std::sqrt(sum / t.points.size());
}

// The point of triangle abc closest to p, by the Voronoi region of p among the triangle's
// corners, edges and face.
Vec3 closestPointOnTriangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 ab = b - a, ac = c - a;
  const double d1 = dot(ab, p - a), d2 = dot(ac, p - a);
  if (d1 <= 0 && d2 <= 0) return a;
  const double d3 = dot(ab, p - b), d4 = dot(ac, p - b);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const double d5 = dot(ab, p - c), d6 = dot(ac, p - c);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double sum = va + vb + vc;
  return a + (vb / sum) * ab + (vc / sum) * ac;
}

// Triangles bucketed by their bounding boxes in a uniform grid of cubes.
class TriangleGrid {
 public:
  TriangleGrid(const Triangulation& t, double cell) : t_(t), cell_(cell) {
    for (std::uint32_t tri = 0; tri < t.triangles.size(); ++tri) {
      Vec3 low = t.points[t.triangles[tri][0]], high = low;
      for (std::uint32_t v : t.triangles[tri])
        low = min(low, t.points[v]), high = max(high, t.points[v]);
      forCells(low, high, [&](std::int64_t key) { cells_[key].push_back(tri); });
    }
  }
  // The exact distance from p to the triangles when below cap, else cap.
  double distanceUpTo(Vec3 p, double cap) const {
    double best = cap;
    const Vec3 reach{cap, cap, cap};
    forCells(p - reach, p + reach, [&](std::int64_t key) {
      const auto it = cells_.find(key);
      if (it == cells_.end()) return;
      for (std::uint32_t tri : it->second) {
        const TriangleVertices& v = t_.triangles[tri];
        const Vec3 q = closestPointOnTriangle(p, t_.points[v[0]], t_.points[v[1]], t_.points[v[2]]);
        best = std::min(best, distance(p, q));
      }
    });
    return best;
  }

 private:
  static Vec3 min(Vec3 a, Vec3 b) {
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
  }
  static Vec3 max(Vec3 a, Vec3 b) {
    return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
  }
  void forCells(Vec3 low, Vec3 high, const std::function<void(std::int64_t)>& visit) const {
    auto index = [&](double x) { return static_cast<std::int64_t>(std::floor(x / cell_)); };
    for (std::int64_t i = index(low.x); i <= index(high.x); ++i)
      for (std::int64_t j = index(low.y); j <= index(high.y); ++j)
        for (std::int64_t k = index(low.z); k <= index(high.z); ++k)
          visit(((i + 100000) * 200000 + (j + 100000)) * 200000 + (k + 100000));
  }
  const Triangulation& t_;
  double cell_;
  std::unordered_map<std::int64_t, std::vector<std::uint32_t>> cells_;
};

// The largest distance from points sampled on `from`'s triangles (corners, edge midpoints,
// centroid and three inner points each) to the triangles of `to`, capped.
double sampledDistance(const Triangulation& from, const TriangleGrid& to, double cap) {
  static const std::array<std::array<double, 3>, 10> weights{
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.5, 0.5, 0}, {0, 0.5, 0.5}, {0.5, 0, 0.5},
       {1.0 / 3, 1.0 / 3, 1.0 / 3}, {4.0 / 6, 1.0 / 6, 1.0 / 6}, {1.0 / 6, 4.0 / 6, 1.0 / 6},
       {1.0 / 6, 1.0 / 6, 4.0 / 6}}};
  double largest = 0;
  for (const TriangleVertices& v : from.triangles)
    for (const auto& w : weights) {
      const Vec3 p = w[0] * from.points[v[0]] + w[1] * from.points[v[1]] + w[2] * from.points[v[2]];
      largest = std::max(largest, to.distanceUpTo(p, cap));
    }
  return largest;
}

TEST(SurfaceProcessingCurvature, SphereMeanAndGaussianCurvature) {
  const double radius = 2.5;
  const Triangulation sphere = geodesicSphere(32, radius);
  ASSERT_EQ(sphere.triangles.size(), 20480u);
  const VertexCurvatures c = vertexCurvatures(sphere);
  double worstMean = 0, worstGaussian = 0, worstMaxAbs = 0;
  for (std::size_t i = 0; i < sphere.points.size(); ++i) {
    worstMean = std::max(worstMean, std::abs(c.mean[i] * radius - 1));
    worstGaussian = std::max(worstGaussian, std::abs(c.gaussian[i] * radius * radius - 1));
    worstMaxAbs = std::max(worstMaxAbs, std::abs(c.maxAbs[i] * radius - 1));
  }
  std::cout << "relative errors: H " << worstMean << ", K " << worstGaussian << ", max |k| "
            << worstMaxAbs << '\n';
  EXPECT_LT(worstMean, 0.02);
  EXPECT_LT(worstGaussian, 0.02);
  EXPECT_LT(worstMaxAbs, 0.02);
}

TEST(SurfaceProcessingCurvature, VertexNormalsAreRadial) {
  const Triangulation sphere = geodesicSphere(32, 2.5);
  const std::vector<Vec3> normals = vertexNormals(sphere);
  double worst = 0;
  for (std::size_t i = 0; i < sphere.points.size(); ++i)
    worst = std::max(worst,
                     std::acos(std::min(1.0, dot(normals[i], normalized(sphere.points[i])))));
  std::cout << "largest normal deviation: " << worst * 180 / kPi << " degrees\n";
  EXPECT_LT(worst * 180 / kPi, 1.0);
}

TEST(SurfaceProcessingCurvature, OpenCylinderBoundaryTakesInteriorValues) {
  const double r = 1.5;
  const Triangulation cylinder = grid(96, 20, true, false, [&](double u, double v) {
    return Vec3{r * std::cos(2 * kPi * u), r * std::sin(2 * kPi * u), 3 * v};
  });
  const VertexCurvatures c = vertexCurvatures(cylinder);
  const std::vector<bool> onBoundary = boundaryVertices(cylinder);
  ASSERT_EQ(std::count(onBoundary.begin(), onBoundary.end(), true), 2 * 96);
  for (std::size_t i = 0; i < cylinder.points.size(); ++i) {
    EXPECT_NEAR(c.mean[i], 1 / (2 * r), 0.02 / (2 * r)) << i;
    EXPECT_NEAR(c.gaussian[i], 0, 1e-9) << i;
    EXPECT_NEAR(c.maxAbs[i], 1 / r, 0.02 / r) << i;
  }
}

TEST(SurfaceProcessingSimplify, SphereTo5kTrianglesStaysClosedAndClose) {
  const double radius = 3;
  const Triangulation sphere = geodesicSphere(71, radius);
  ASSERT_EQ(sphere.triangles.size(), 100820u);
  const auto start = std::chrono::steady_clock::now();
  const Triangulation simplified = simplify(sphere, {.targetTriangles = 5000});
  const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
  EXPECT_LE(simplified.triangles.size(), 5000u);
  EXPECT_GE(simplified.triangles.size(), 4500u);

  const SurfaceTopologyReport report = surfaceTopology(simplified);
  EXPECT_EQ(report.vertices, simplified.points.size());
  EXPECT_EQ(report.components, 1);
  EXPECT_EQ(report.genus, 0);
  EXPECT_EQ(report.boundaryLoops, 0);
  EXPECT_EQ(report.nonManifoldEdges, 0u);
  EXPECT_EQ(report.inconsistentEdges, 0u);
  EXPECT_EQ(report.degenerateTriangles, 0u);
  for (std::uint32_t tri = 0; tri < simplified.triangles.size(); ++tri) {
    const TriangleVertices& v = simplified.triangles[tri];
    const std::vector<Vec3>& p = simplified.points;
    ASSERT_GT(dot(triangleNormal(simplified, tri), p[v[0]] + p[v[1]] + p[v[2]]), 0) << tri;
  }

  const double cap = 0.012 * radius, cell = 0.02 * radius;  // exact below the cap
  const double there = sampledDistance(sphere, TriangleGrid(simplified, cell), cap);
  const double back = sampledDistance(simplified, TriangleGrid(sphere, cell), cap);
  std::cout << "simplified to " << simplified.triangles.size() << " triangles in " << took.count()
            << " s; Hausdorff distance / R: " << std::max(there, back) / radius << '\n';
  EXPECT_LT(std::max(there, back), 0.01 * radius);
}

TEST(SurfaceProcessingSimplify, OpenPatchKeepsItsBoundary) {
  const Triangulation patch = grid(40, 40, false, false, [](double u, double v) {
    return Vec3{u, v, 0.3 * std::sin(3 * u) * std::cos(2 * v)};
  });
  const Triangulation simplified = simplify(patch, {.targetTriangles = 400});
  EXPECT_LE(simplified.triangles.size(), 400u);
  std::set<std::pair<double, double>> before, after;
  const std::vector<bool> was = boundaryVertices(patch), is = boundaryVertices(simplified);
  for (std::size_t i = 0; i < patch.points.size(); ++i)
    if (was[i]) before.emplace(patch.points[i].x, patch.points[i].y);
  for (std::size_t i = 0; i < simplified.points.size(); ++i)
    if (is[i]) after.emplace(simplified.points[i].x, simplified.points[i].y);
  EXPECT_EQ(before, after);
  const SurfaceTopologyReport report = surfaceTopology(simplified);
  EXPECT_EQ(report.boundaryLoops, 1);
  EXPECT_EQ(report.euler, 1);
  EXPECT_EQ(report.inconsistentEdges, 0u);

  const Triangulation free = simplify(patch, {.targetTriangles = 400, .keepBoundary = false});
  EXPECT_LE(free.triangles.size(), 400u);
  const SurfaceTopologyReport freeReport = surfaceTopology(free);
  EXPECT_EQ(freeReport.boundaryLoops, 1);
  EXPECT_EQ(freeReport.euler, 1);
  EXPECT_EQ(freeReport.nonManifoldEdges + freeReport.inconsistentEdges, 0u);
}

TEST(SurfaceProcessingSimplify, ErrorBoundStopsAtCurvedButNotFlatParts) {
  const Triangulation flat = grid(20, 20, false, false, [](double u, double v) {
    return Vec3{u, v, 0};
  });
  const Triangulation sphere = geodesicSphere(10, 1);
  const SimplifyOptions options{.maxError = 1e-12};
  const Triangulation flatter = simplify(flat, options);
  EXPECT_LT(flatter.triangles.size(), flat.triangles.size() / 4);
  EXPECT_EQ(surfaceTopology(flatter).boundaryLoops, 1);
  EXPECT_EQ(simplify(sphere, options).triangles.size(), sphere.triangles.size());
  EXPECT_EQ(simplify(sphere, {}).triangles.size(), sphere.triangles.size());
}

TEST(SurfaceProcessingFairing, NoisySphereGetsSmootherAndKeepsVolume) {
  const double radius = 2;
  Triangulation sphere = geodesicSphere(32, radius);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> noise(-0.02 * radius, 0.02 * radius);
  for (Vec3& p : sphere.points) p = (radius + noise(random)) * normalized(p);
  const double rmsBefore = rmsRadialDeviation(sphere, radius), volume = enclosedVolume(sphere);
  fair(sphere, {});
  const double rmsAfter = rmsRadialDeviation(sphere, radius);
  std::cout << "RMS deviation / R: " << rmsBefore / radius << " -> " << rmsAfter / radius
            << "; volume change " << enclosedVolume(sphere) / volume - 1 << '\n';
  EXPECT_LT(rmsAfter, 0.5 * rmsBefore);
  EXPECT_NEAR(enclosedVolume(sphere), volume, 0.01 * volume);
}

TEST(SurfaceProcessingFairing, OpenPatchBoundaryStaysFixed) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> noise(-0.01, 0.01);
  Triangulation patch = grid(30, 30, false, false, [&](double u, double v) {
    return Vec3{u, v, noise(random)};
  });
  const Triangulation original = patch;
  fair(patch, {.iterations = 5});
  const std::vector<bool> onBoundary = boundaryVertices(patch);
  double interiorBefore = 0, interiorAfter = 0;
  for (std::size_t i = 0; i < patch.points.size(); ++i) {
    if (onBoundary[i]) {
      EXPECT_EQ(patch.points[i], original.points[i]) << i;
      continue;
    }
    interiorBefore += std::pow(original.points[i].z, 2);
    interiorAfter += std::pow(patch.points[i].z, 2);
  }
  EXPECT_LT(interiorAfter, 0.25 * interiorBefore);
}

TEST(SurfaceProcessingTopology, TorusHasGenusOne) {
  const Triangulation torus = grid(32, 16, true, true, [](double u, double v) {
    const double r = 2 + 0.5 * std::cos(2 * kPi * v);
    return Vec3{r * std::cos(2 * kPi * u), r * std::sin(2 * kPi * u), 0.5 * std::sin(2 * kPi * v)};
  });
  const SurfaceTopologyReport report = surfaceTopology(torus);
  EXPECT_EQ(report.vertices, 32u * 16u);
  EXPECT_EQ(report.edges, 3u * 32u * 16u);
  EXPECT_EQ(report.euler, 0);
  EXPECT_EQ(report.genus, 1);
  EXPECT_EQ(report.components, 1);
  EXPECT_EQ(report.boundaryLoops, 0);
}

TEST(SurfaceProcessingTopology, CubeIsASphere) {
  Triangulation cube;
  for (int i = 0; i < 8; ++i)
    cube.points.push_back({double(i & 1), double(i >> 1 & 1), double(i >> 2)});
  cube.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                    {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  const SurfaceTopologyReport report = surfaceTopology(cube);
  EXPECT_EQ(report.edges, 18u);
  EXPECT_EQ(report.euler, 2);
  EXPECT_EQ(report.genus, 0);
  EXPECT_EQ(report.inconsistentEdges, 0u);
  EXPECT_GT(enclosedVolume(cube), 0);
}

TEST(SurfaceProcessingTopology, TwoDisjointSpheres) {
  Triangulation both = icosahedron(1);
  const Triangulation other = icosahedron(1, {5, 0, 0});
  for (TriangleVertices v : other.triangles) {
    for (std::uint32_t& k : v) k += static_cast<std::uint32_t>(both.points.size());
    both.triangles.push_back(v);
  }
  both.points.insert(both.points.end(), other.points.begin(), other.points.end());
  const SurfaceTopologyReport report = surfaceTopology(both);
  EXPECT_EQ(report.components, 2);
  EXPECT_EQ(report.euler, 4);
  EXPECT_EQ(report.genus, 0);
  EXPECT_EQ(report.triangles, 40u);
}

TEST(SurfaceProcessingTopology, OpenDiskHasOneBoundaryLoop) {
  Triangulation disk{{{0, 0, 0}}, {}};
  for (std::uint32_t i = 0; i < 12; ++i) {
    disk.points.push_back({std::cos(i * kPi / 6), std::sin(i * kPi / 6), 0});
    disk.triangles.push_back({0, i + 1, (i + 1) % 12 + 1});
  }
  const SurfaceTopologyReport report = surfaceTopology(disk);
  EXPECT_EQ(report.boundaryLoops, 1);
  EXPECT_EQ(report.euler, 1);
  EXPECT_EQ(report.genus, 0);
}

TEST(SurfaceProcessingTopology, FlippedFacetIsInconsistent) {
  Triangulation sphere = icosahedron(1);
  std::swap(sphere.triangles[4][1], sphere.triangles[4][2]);
  const SurfaceTopologyReport report = surfaceTopology(sphere);
  EXPECT_EQ(report.inconsistentEdges, 3u);
  EXPECT_EQ(report.boundaryLoops, 0);
  EXPECT_EQ(report.genus, 0);
  EXPECT_EQ(surfaceTopology(icosahedron(1)).inconsistentEdges, 0u);
}

TEST(SurfaceProcessingTopology, NonManifoldEdgeAndDegenerateTriangle) {
  const Triangulation fin{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {2, 0, 0}},
                          {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}, {0, 1, 5}}};
  const SurfaceTopologyReport report = surfaceTopology(fin);
  EXPECT_EQ(report.nonManifoldEdges, 1u);
  EXPECT_EQ(report.degenerateTriangles, 1u);
  EXPECT_EQ(report.vertices, 6u);
}

// A boundary chain that ends at a non-manifold edge's vertex, with no unwalked edge left
// there: the walk stops (it once ran on with an edge index of -1 read as unsigned).
TEST(SurfaceTopology, ABoundaryChainEndingAtANonManifoldEdgeIsOneOpenLoop) {
  Triangulation t;
  t.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, -1, 0}};
  t.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 3}};  // edge 0-1 on all three
  const SurfaceTopologyReport report = surfaceTopology(t);
  EXPECT_EQ(report.nonManifoldEdges, 1u);
  EXPECT_EQ(report.boundaryLoops, 1);
  EXPECT_EQ(report.euler, 2);
}

}  // namespace
}  // namespace geomesh
