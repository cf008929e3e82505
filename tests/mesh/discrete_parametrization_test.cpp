// Tests of parametrizePatch (maps of triangulation patches to the plane) and of the
// DiscreteSurfaceGeometry built on such a map.
#include "mesh/discrete/parametrization.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <numeric>
#include <thread>

#include "mesh/discrete/discrete_surface_geometry.h"
#include "mesh/sizes/size_rules.h"

namespace geomesh {
namespace {

constexpr double kPi = std::numbers::pi;

using Surface = std::function<Vec3(double, double)>;

// The grid (i, j), 0 <= i <= nu, 0 <= j <= nv, of f(i / nu, j / nv), two triangles a cell,
// counter-clockwise in (i, j). Columns and rows that wrap (periodic) reuse the first vertices;
// `keep(i, j)` chooses the cells.
Triangulation gridSurface(int nu, int nv, bool wrapU, bool wrapV, const Surface& f,
                          const std::function<bool(int, int)>& keep = nullptr) {
  Triangulation t;
  const int columns = wrapU ? nu : nu + 1, rows = wrapV ? nv : nv + 1;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) t.points.push_back(f(double(i) / nu, double(j) / nv));
  auto at = [&](int i, int j) {
    return static_cast<std::uint32_t>((j % rows) * columns + (i % columns));
  };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      if (keep && !keep(i, j)) continue;
      t.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      t.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return t;
}

// The upper half of the unit sphere: a pole, then rings down to the equator; normals outward.
Triangulation hemisphere(int rings, int sectors) {
  Triangulation t;
  t.points.push_back({0, 0, 1});
  for (int r = 1; r <= rings; ++r)
    for (int s = 0; s < sectors; ++s) {
      const double polar = 0.5 * kPi * r / rings, azimuth = 2 * kPi * s / sectors;
      t.points.push_back({std::sin(polar) * std::cos(azimuth),
                          std::sin(polar) * std::sin(azimuth), std::cos(polar)});
    }
  auto at = [&](int r, int s) {
    return r == 0 ? 0u : static_cast<std::uint32_t>(1 + (r - 1) * sectors + s % sectors);
  };
  for (int s = 0; s < sectors; ++s) t.triangles.push_back({0, at(1, s), at(1, s + 1)});
  for (int r = 1; r < rings; ++r)
    for (int s = 0; s < sectors; ++s) {
      t.triangles.push_back({at(r, s), at(r + 1, s), at(r + 1, s + 1)});
      t.triangles.push_back({at(r, s), at(r + 1, s + 1), at(r, s + 1)});
    }
  return t;
}

// The whole unit sphere: the hemisphere and its mirror image, sharing the equator.
Triangulation sphere(int rings, int sectors) {
  Triangulation t = hemisphere(rings, sectors);
  const auto count = static_cast<std::uint32_t>(t.points.size());
  const auto equator = count - static_cast<std::uint32_t>(sectors);
  auto mirror = [&](std::uint32_t v) { return v >= equator ? v : v + count; };
  const std::vector<Vec3> upper = t.points;
  for (Vec3 p : upper) t.points.push_back({p.x, p.y, -p.z});
  const std::vector<TriangleVertices> upperTriangles = t.triangles;
  for (const TriangleVertices& v : upperTriangles)
    t.triangles.push_back({mirror(v[0]), mirror(v[2]), mirror(v[1])});
  return t;
}

Vec3 bumpyHeight(double s, double r) {
  const double x = 2 * s - 1, y = 2 * r - 1;
  return {x, y, 0.1 * std::sin(3 * x) * std::cos(2 * y)};
}

Vec3 cylinderSide(double s, double r) {
  return {std::cos(2 * kPi * s), std::sin(2 * kPi * s), 2 * r};
}

Vec3 torusPoint(double s, double r) {
  const double a = 2 * kPi * s, b = 2 * kPi * r, radius = 2 + 0.5 * std::cos(b);
  return {radius * std::cos(a), radius * std::sin(a), 0.5 * std::sin(b)};
}

std::vector<std::uint32_t> allTriangles(const Triangulation& t) {
  std::vector<std::uint32_t> all(t.triangles.size());
  std::iota(all.begin(), all.end(), 0u);
  return all;
}

ParametrizationResult parametrizeAll(const Triangulation& t,
                                     std::vector<std::vector<std::uint32_t>> loops) {
  return parametrizePatch(t, allTriangles(t), loops);
}

ParametrizationResult parametrizeAll(const Triangulation& t) {
  return parametrizeAll(t, boundaryLoops(t.triangles));
}

double signedArea(const PatchMap& map, const TriangleVertices& v) {
  const Vec2 a = map.uv[v[0]], b = map.uv[v[1]], c = map.uv[v[2]];
  return 0.5 * ((b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u));
}

int invertedCount(const PatchMap& map) {
  int inverted = 0;
  for (const TriangleVertices& v : map.triangles) inverted += signedArea(map, v) <= 0;
  return inverted;
}

double radius(Vec2 p) { return std::hypot(p.u, p.v); }

// Local indices of the vertices of a loop of the triangulation.
std::vector<std::uint32_t> localLoop(const PatchMap& map, const std::vector<std::uint32_t>& loop) {
  std::vector<std::uint32_t> local;
  for (std::uint32_t v : loop)
    local.push_back(static_cast<std::uint32_t>(
        std::find(map.vertices.begin(), map.vertices.end(), v) - map.vertices.begin()));
  return local;
}

void expectDiskMap(const Triangulation& t) {
  const std::vector<std::vector<std::uint32_t>> loops = boundaryLoops(t.triangles);
  ASSERT_EQ(loops.size(), 1u);
  const ParametrizationResult r = parametrizeAll(t, loops);
  ASSERT_TRUE(r.map) << r.failure;
  const PatchMap& map = *r.map;
  EXPECT_FALSE(map.planar);
  EXPECT_EQ(map.vertices.size(), t.points.size());
  ASSERT_EQ(map.triangles.size(), t.triangles.size());
  for (std::size_t k = 0; k < t.triangles.size(); ++k)
    for (int i = 0; i < 3; ++i) EXPECT_EQ(map.vertices[map.triangles[k][i]], t.triangles[k][i]);
  EXPECT_EQ(invertedCount(map), 0);
  const std::vector<std::uint32_t> boundary = localLoop(map, loops[0]);
  std::vector<bool> onBoundary(map.uv.size(), false);
  for (std::uint32_t v : boundary) {
    EXPECT_NEAR(radius(map.uv[v]), 1, 1e-12);
    onBoundary[v] = true;
  }
  for (std::size_t v = 0; v < map.uv.size(); ++v)
    if (!onBoundary[v]) {
      EXPECT_LT(radius(map.uv[v]), 1 - 1e-9);
    }
}

TEST(DiscreteParametrization, HemisphereMapsOntoTheDiskWithoutFolds) {
  expectDiskMap(hemisphere(12, 32));
}

TEST(DiscreteParametrization, BumpyHeightFieldMapsOntoTheDiskWithoutFolds) {
  expectDiskMap(gridSurface(24, 20, false, false, bumpyHeight));
}

TEST(DiscreteParametrization, BoundaryRunsCounterClockwiseByChordLength) {
  const Triangulation t = gridSurface(8, 8, false, false, bumpyHeight);
  const std::vector<std::vector<std::uint32_t>> loops = boundaryLoops(t.triangles);
  const ParametrizationResult r = parametrizeAll(t, loops);
  ASSERT_TRUE(r.map) << r.failure;
  const std::vector<std::uint32_t> loop = localLoop(*r.map, loops[0]);
  std::vector<double> chord;
  for (std::size_t i = 0; i < loop.size(); ++i)
    chord.push_back(distance(t.points[loops[0][i]], t.points[loops[0][(i + 1) % loop.size()]]));
  const double perimeter = std::accumulate(chord.begin(), chord.end(), 0.0);
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec2 a = r.map->uv[loop[i]], b = r.map->uv[loop[(i + 1) % loop.size()]];
    const double turn = std::atan2(a.u * b.v - a.v * b.u, a.u * b.u + a.v * b.v);
    EXPECT_NEAR(turn, 2 * kPi * chord[i] / perimeter, 1e-9);
  }
}

TEST(DiscreteParametrization, IsDeterministic) {
  const Triangulation t = hemisphere(8, 20);
  const ParametrizationResult a = parametrizeAll(t), b = parametrizeAll(t);
  ASSERT_TRUE(a.map && b.map);
  EXPECT_EQ(a.map->uv, b.map->uv);
}

// A square of side 1 with a square hole, in a tilted plane far from the origin.
Triangulation tiltedSquareWithHole() {
  auto inPlane = [](double s, double r) {
    const Vec3 e1 = normalized({1, 2, 2}), e2 = normalized(cross({0, 0, 1}, e1));
    return Vec3{5, -3, 7} + s * e1 + r * e2;
  };
  auto outsideHole = [](int i, int j) { return i < 4 || i >= 6 || j < 4 || j >= 6; };
  return gridSurface(10, 10, false, false, inPlane, outsideHole);
}

TEST(DiscreteParametrization, PlanePatchWithHoleIsItsProjection) {
  const Triangulation t = tiltedSquareWithHole();
  ASSERT_EQ(boundaryLoops(t.triangles).size(), 2u);
  const ParametrizationResult r = parametrizeAll(t);
  ASSERT_TRUE(r.map) << r.failure;
  const PatchMap& map = *r.map;
  EXPECT_TRUE(map.planar);
  EXPECT_EQ(invertedCount(map), 0);
  for (std::size_t a = 0; a < map.uv.size(); a += 7)
    for (std::size_t b = 0; b < map.uv.size(); b += 3) {
      const double inPlane = std::hypot(map.uv[a].u - map.uv[b].u, map.uv[a].v - map.uv[b].v);
      EXPECT_NEAR(inPlane, distance(t.points[map.vertices[a]], t.points[map.vertices[b]]), 1e-12);
    }
}

TEST(DiscreteParametrization, CylinderSideMapsThroughItsFilledHole) {
  const Triangulation t = gridSurface(32, 6, true, false, cylinderSide);
  const std::vector<std::vector<std::uint32_t>> loops = boundaryLoops(t.triangles);
  ASSERT_EQ(loops.size(), 2u);
  const ParametrizationResult r = parametrizeAll(t, loops);
  ASSERT_TRUE(r.map) << r.failure;
  EXPECT_FALSE(r.map->planar);
  EXPECT_EQ(invertedCount(*r.map), 0);
  for (std::uint32_t v : localLoop(*r.map, loops[0])) EXPECT_NEAR(radius(r.map->uv[v]), 1, 1e-12);
  for (std::uint32_t v : localLoop(*r.map, loops[1])) EXPECT_LT(radius(r.map->uv[v]), 1 - 1e-6);
}

TEST(DiscreteParametrization, SubsetOfTrianglesIsNumberedLocally) {
  const Triangulation t = gridSurface(10, 10, false, false, bumpyHeight);
  std::vector<std::uint32_t> patch(20);  // the fourth row of cells
  std::iota(patch.begin(), patch.end(), 60u);
  std::vector<TriangleVertices> chosen;
  for (std::uint32_t k : patch) chosen.push_back(t.triangles[k]);
  const ParametrizationResult r = parametrizePatch(t, patch, boundaryLoops(chosen));
  ASSERT_TRUE(r.map) << r.failure;
  EXPECT_EQ(r.map->vertices.size(), 22u);  // one row of 10 cells
  EXPECT_EQ(r.map->triangles.size(), 20u);
  EXPECT_EQ(invertedCount(*r.map), 0);
}

TEST(DiscreteParametrization, ClosedSphereFails) {
  const ParametrizationResult r = parametrizeAll(sphere(6, 12));
  EXPECT_FALSE(r.map);
  EXPECT_NE(r.failure.find("closed"), std::string::npos) << r.failure;
}

TEST(DiscreteParametrization, TorusWithOneCellRemovedFailsWithAHandle) {
  const Triangulation t =
      gridSurface(16, 8, true, true, torusPoint, [](int i, int j) { return i != 0 || j != 0; });
  const std::vector<std::vector<std::uint32_t>> loops = boundaryLoops(t.triangles);
  ASSERT_EQ(loops.size(), 1u);
  const ParametrizationResult r = parametrizeAll(t, loops);
  EXPECT_FALSE(r.map);
  EXPECT_NE(r.failure.find("handle"), std::string::npos) << r.failure;
}

TEST(DiscreteParametrization, WrongLoopCountFails) {
  const Triangulation t = gridSurface(32, 6, true, false, cylinderSide);
  const ParametrizationResult r = parametrizeAll(t, {boundaryLoops(t.triangles)[0]});
  EXPECT_FALSE(r.map);
  EXPECT_FALSE(r.failure.empty());
}

// ---- DiscreteSurfaceGeometry ----

DiscreteSurfaceGeometry geometryOf(const Triangulation& t, std::map<int, CurveTrace> curves = {},
                                   std::vector<double> curvature = {}) {
  ParametrizationResult r = parametrizeAll(t);
  EXPECT_TRUE(r.map) << r.failure;
  std::vector<Vec3> points;
  for (std::uint32_t v : r.map->vertices) points.push_back(t.points[v]);
  return DiscreteSurfaceGeometry(std::move(points), std::move(*r.map), std::move(curves),
                                 std::move(curvature));
}

Vec2 centroid(const DiscreteSurfaceGeometry& g, const TriangleVertices& v) {
  const std::vector<Vec2>& uv = g.map().uv;
  return {(uv[v[0]].u + uv[v[1]].u + uv[v[2]].u) / 3, (uv[v[0]].v + uv[v[1]].v + uv[v[2]].v) / 3};
}

TEST(DiscreteSurfaceGeometry, PointAtAVertexIsThatVertex) {
  const DiscreteSurfaceGeometry g = geometryOf(hemisphere(10, 24));
  for (std::size_t v = 0; v < g.map().uv.size(); ++v)
    EXPECT_LT(distance(g.point(g.map().uv[v]), g.points()[v]), 1e-12) << v;
  EXPECT_EQ(g.kind(), SurfaceKind::Other);
  EXPECT_FALSE(g.isPlane());
  const ParamBox box = g.bounds();
  EXPECT_NEAR(box.u.min, -1, 1e-3);
  EXPECT_NEAR(box.u.max, 1, 1e-12);
}

TEST(DiscreteSurfaceGeometry, PointOfProjectionIsThePoint) {
  const Triangulation t = gridSurface(16, 16, false, false, bumpyHeight);
  const DiscreteSurfaceGeometry g = geometryOf(t);
  for (const TriangleVertices& v : t.triangles) {
    const Vec3 p = 0.2 * t.points[v[0]] + 0.3 * t.points[v[1]] + 0.5 * t.points[v[2]];
    EXPECT_LT(distance(g.point(g.project(p)), p), 1e-10);
  }
  // A point just off the surface goes to the surface point below it.
  const Vec3 on = bumpyHeight(0.65, 0.4);
  EXPECT_LT(distance(g.point(g.project(on + Vec3{0, 0, 1e-3})), on), 2e-3);
}

TEST(DiscreteSurfaceGeometry, DerivativesMatchFiniteDifferences) {
  const DiscreteSurfaceGeometry g = geometryOf(hemisphere(8, 20));
  for (const TriangleVertices& v : g.map().triangles) {
    const Vec2 c = centroid(g, v);
    const double h = 1e-7;
    const SurfaceDerivatives d = g.firstDerivatives(c);
    const Vec3 du = (g.point({c.u + h, c.v}) - g.point({c.u - h, c.v})) / (2 * h);
    const Vec3 dv = (g.point({c.u, c.v + h}) - g.point({c.u, c.v - h})) / (2 * h);
    EXPECT_LT(distance(du, d.du), 1e-5 * (1 + norm(d.du)));
    EXPECT_LT(distance(dv, d.dv), 1e-5 * (1 + norm(d.dv)));
  }
}

TEST(DiscreteSurfaceGeometry, ParametrizationKeepsTheTrianglesOrientation) {
  const Triangulation t = hemisphere(8, 20);
  const DiscreteSurfaceGeometry g = geometryOf(t);
  for (std::uint32_t k = 0; k < t.triangles.size(); ++k) {
    const SurfaceDerivatives d = g.firstDerivatives(centroid(g, g.map().triangles[k]));
    EXPECT_GT(dot(cross(d.du, d.dv), triangleNormal(t, k)), 0) << k;
  }
}

TEST(DiscreteSurfaceGeometry, CurveParametersInterpolateTheTrace) {
  CurveTrace trace{{0, 1, 3}, {{0, 0}, {0.5, 0}, {0.5, 0.5}}};
  const DiscreteSurfaceGeometry g = geometryOf(hemisphere(4, 12), {{7, trace}});
  const std::optional<Vec2> mid = g.curveParameters(7, 2);
  ASSERT_TRUE(mid);
  EXPECT_NEAR(mid->u, 0.5, 1e-15);
  EXPECT_NEAR(mid->v, 0.25, 1e-15);
  const std::optional<Vec2> reversed = g.curveParameters(-7, 0.25);
  ASSERT_TRUE(reversed);
  EXPECT_NEAR(reversed->u, 0.125, 1e-15);
  EXPECT_EQ(g.curveParameters(7, 3), (Vec2{0.5, 0.5}));
  EXPECT_FALSE(g.curveParameters(8, 0.5));
}

TEST(DiscreteSurfaceGeometry, PointsOutsideTheTrianglesUseTheClosestOne) {
  const Triangulation t = gridSurface(32, 6, true, false, cylinderSide);
  const DiscreteSurfaceGeometry g = geometryOf(t);
  for (Vec2 uv : {Vec2{0, 0}, Vec2{1.5, 0.2}, Vec2{-0.3, -1.2}}) {
    const Vec3 p = g.point(uv);
    const SurfaceDerivatives d = g.firstDerivatives(uv);
    EXPECT_TRUE(std::isfinite(p.x + p.y + p.z + norm(d.du) + norm(d.dv)));
  }
  // Just past the outer boundary, the boundary triangle's map extends to there.
  const Vec2 edge = g.map().uv[localLoop(g.map(), boundaryLoops(t.triangles)[0])[0]];
  const Vec2 past{edge.u * (1 + 1e-6), edge.v * (1 + 1e-6)};
  EXPECT_LT(distance(g.point(past), g.point(edge)), 1e-4);
}

TEST(DiscreteSurfaceGeometry, PlaneMapIsAPlane) {
  const Triangulation t = tiltedSquareWithHole();
  const DiscreteSurfaceGeometry g = geometryOf(t);
  EXPECT_TRUE(g.isPlane());
  const SurfaceDerivatives d = g.firstDerivatives(centroid(g, g.map().triangles[3]));
  EXPECT_NEAR(norm(d.du), 1, 1e-12);
  EXPECT_NEAR(norm(d.dv), 1, 1e-12);
  EXPECT_NEAR(dot(d.du, d.dv), 0, 1e-12);
}

TEST(DiscreteSurfaceGeometry, CurvatureInterpolatesVertexValues) {
  const Triangulation t = hemisphere(6, 16);
  const DiscreteSurfaceGeometry plain = geometryOf(t);
  EXPECT_FALSE(plain.curvature({0, 0}));
  std::vector<double> values(t.points.size());
  for (std::size_t v = 0; v < values.size(); ++v) values[v] = 1 + 0.01 * v;
  const DiscreteSurfaceGeometry g = geometryOf(t, {}, values);
  const TriangleVertices& tri = g.map().triangles[5];
  const std::optional<double> k = g.curvature(centroid(g, tri));
  ASSERT_TRUE(k);
  EXPECT_NEAR(*k, (values[tri[0]] + values[tri[1]] + values[tri[2]]) / 3, 1e-12);
  EXPECT_NEAR(surfaceCurvature(g, centroid(g, tri)), *k, 1e-12);
}

TEST(DiscreteSurfaceGeometry, ConcurrentQueriesAgreeWithSerialOnes) {
  const DiscreteSurfaceGeometry g = geometryOf(gridSurface(30, 30, false, false, bumpyHeight));
  std::vector<Vec2> queries;
  for (int k = 0; k < 4000; ++k)
    queries.push_back({0.99 * std::cos(0.37 * k) * std::sin(0.011 * k), 0.99 * std::sin(0.37 * k)});
  std::vector<Vec3> serial;
  for (Vec2 uv : queries) serial.push_back(g.point(uv));
  std::vector<std::vector<Vec3>> results(4);
  std::vector<std::thread> threads;
  for (std::size_t n = 0; n < results.size(); ++n)
    threads.emplace_back([&, n] {
      for (std::size_t k = 0; k < queries.size(); ++k)
        results[n].push_back(g.point(queries[(k + 997 * n) % queries.size()]));
    });
  for (std::thread& thread : threads) thread.join();
  for (std::size_t n = 0; n < results.size(); ++n)
    for (std::size_t k = 0; k < queries.size(); ++k)
      ASSERT_LT(distance(results[n][k], serial[(k + 997 * n) % queries.size()]), 1e-12);
}

}  // namespace
}  // namespace geomesh
