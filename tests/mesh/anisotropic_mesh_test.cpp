// Tests of the anisotropic 2D algorithm (Mesh.Algorithm 7): metric algebra, gradation, meshes.
#include "mesh/surfaces/anisotropic_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <utility>
#include <vector>

#include "geo_unit_square.h"
#include "kernel/geo/geo_factory.h"
#include "mesh/checks/mesh_check.h"
#include "mesh/core/predicates.h"
#include "mesh/pipeline/generate.h"
#include "mesh/surfaces/anisotropic_gradation.h"
#include "mesh/surfaces/anisotropic_metric.h"
#include "mesh/surfaces/constrained_delaunay.h"
#include "size_field_fixtures.h"

namespace geomesh {
namespace {

constexpr double kSqrt3Over4 = 0.4330127018922193;

void expectMetricNear(Metric2 m, Metric2 expected, double tolerance) {
  EXPECT_NEAR(m.a, expected.a, tolerance);
  EXPECT_NEAR(m.b, expected.b, tolerance);
  EXPECT_NEAR(m.c, expected.c, tolerance);
}

TEST(AnisotropicMetric, EigenDecompositionAndBack) {
  const MetricEigen e = eigen({2, 1, 2});
  EXPECT_NEAR(e.large, 3, 1e-14);
  EXPECT_NEAR(e.small, 1, 1e-14);
  EXPECT_NEAR(std::abs(e.direction.u), std::sqrt(0.5), 1e-14);
  EXPECT_NEAR(e.direction.u, e.direction.v, 1e-14);
  expectMetricNear(fromEigen(e), {2, 1, 2}, 1e-14);
  const MetricEigen diagonal = eigen({1, 0, 4});
  EXPECT_EQ(diagonal.large, 4);
  EXPECT_EQ(diagonal.small, 1);
  EXPECT_NEAR(std::abs(diagonal.direction.v), 1, 1e-15);
}

TEST(AnisotropicMetric, IntersectionKeepsTheSmallerSizeInEveryDirection) {
  expectMetricNear(intersect({1, 0, 4}, {4, 0, 1}), {4, 0, 4}, 1e-12);
  expectMetricNear(intersect({9, 0, 9}, {1, 0, 100}), {9, 0, 100}, 1e-12);
  // A rotated pair: the result asks for no larger size than either, in any direction, and
  // its unit ball touches theirs (it is the largest such metric, not any smaller one).
  const Metric2 a = fromEigen({100, 1, {1, 0}});
  const Metric2 b = fromEigen({50, 2, {std::sqrt(0.5), std::sqrt(0.5)}});
  const Metric2 m = intersect(a, b);
  double tightest = 1e300;
  for (int k = 0; k < 360; ++k) {
    const Vec2 d{std::cos(k * std::numbers::pi / 180), std::sin(k * std::numbers::pi / 180)};
    const double need = std::max(lengthSquared(a, d), lengthSquared(b, d));
    EXPECT_GE(lengthSquared(m, d), need * (1 - 1e-12));
    tightest = std::min(tightest, lengthSquared(m, d) / need);
  }
  EXPECT_NEAR(tightest, 1, 1e-3);
  Metric2 same = a;
  EXPECT_FALSE(intersectInto(same, scaled(a, 0.5), 0.01));
  EXPECT_TRUE(intersectInto(same, scaled(a, 4), 0.01));
  expectMetricNear(same, scaled(a, 4), 1e-9);
}

TEST(AnisotropicMetric, RestrictionFramesAndSizeClamps) {
  expectMetricNear(restrictMetric({1, 0, 0, 2, 0, 3}, {1, 0, 0}, {0, 0, 1}), {1, 0, 3}, 0);
  expectMetricNear(restrictMetric({1, 0, 0, 2, 0, 3}, {2, 0, 0}, {0, 1, 0}), {4, 0, 2}, 0);
  // In the frame of lengths diag(4, 1), the metric diag(4, 1) is the identity, and back.
  const MetricFrame frame(Metric2{4, 0, 1});
  expectMetricNear(inFrame({4, 0, 1}, frame), {1, 0, 1}, 1e-15);
  expectMetricNear(outOfFrame({1, 0, 1}, frame), {4, 0, 1}, 1e-15);
  // Sizes 0.01 and 1: capped at 0.5, then the ratio brought down to 10.
  const Metric2 clamped =
      mapSizes(Metric2{1, 0, 1e4}, [](double h) { return std::min(h, 0.5); }, 10);
  expectMetricNear(clamped, {1e2, 0, 1e4}, 1e-9);
}

// Points 0, 1, 2, ... on a line, one apart; vertex 0 asks for size 1, the others for 1000.
TEST(AnisotropicGradation, SizesGrowLinearlyWithDistance) {
  constexpr int n = 6;
  std::vector<Vec2> points;
  std::vector<Metric2> metrics;
  std::vector<std::uint32_t> offsets{0}, neighbours;
  for (int k = 0; k < n; ++k) {
    points.push_back({static_cast<double>(k), 0});
    metrics.push_back(isotropicMetric(k == 0 ? 1 : 1000));
    if (k > 0) neighbours.push_back(k - 1);
    if (k + 1 < n) neighbours.push_back(k + 1);
    offsets.push_back(static_cast<std::uint32_t>(neighbours.size()));
  }
  gradeMetrics(points, {offsets, neighbours}, metrics, 1.5);
  // h grows by ratio - 1 per unit of Euclidean distance: h_k = 1 + k / 2.
  for (int k = 0; k < n; ++k) expectMetricNear(metrics[k], isotropicMetric(1 + 0.5 * k), 1e-12);
  // A ratio of 1 or less grades nothing.
  std::vector<Metric2> untouched(n, isotropicMetric(1000));
  untouched[0] = isotropicMetric(1);
  gradeMetrics(points, {offsets, neighbours}, untouched, 1);
  expectMetricNear(untouched[1], isotropicMetric(1000), 0);
}

// The constrained triangulation of a w x h rectangle whose sides have nx and ny segments,
// each boundary vertex asking for the mean length of its two segments.
struct Rectangle {
  Triangulation2D tri{{0, 0}, {1, 1}};
  std::vector<std::uint8_t> inside;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> segments;
  std::uint32_t firstMovable = 0;
};

Rectangle rectangle(double w, double h, int nx, int ny, Vec2 corner = {0, 0}) {
  std::vector<Vec2> points;
  for (int i = 0; i < nx; ++i) points.push_back({w * i / nx, 0});
  for (int j = 0; j < ny; ++j) points.push_back({w, h * j / ny});
  for (int i = 0; i < nx; ++i) points.push_back({w - w * i / nx, h});
  for (int j = 0; j < ny; ++j) points.push_back({0, h - h * j / ny});
  for (Vec2& p : points) p = {p.u + corner.u, p.v + corner.v};
  Rectangle r;
  r.tri = delaunayTriangulation(points);
  constexpr std::uint32_t first = Triangulation2D::kFirstVertex;
  const auto count = static_cast<std::uint32_t>(points.size());
  std::vector<ConstrainedSegment> segments;
  for (std::uint32_t k = 0; k < count; ++k) {
    segments.push_back({first + k, first + (k + 1) % count, EdgeKind::Boundary});
    r.segments.emplace_back(first + k, first + (k + 1) % count);
  }
  EXPECT_EQ(recoverSegments(r.tri, segments), -1);
  r.inside = classifyInside(r.tri);
  for (std::uint32_t k = 0; k < count; ++k) {
    const Vec2 p = points[k], next = points[(k + 1) % count], prev = points[(k + count - 1) % count];
    r.tri.setSize(first + k, 0.5 * (std::hypot(next.u - p.u, next.v - p.v) +
                                     std::hypot(prev.u - p.u, prev.v - p.v)));
  }
  r.firstMovable = first + count;
  return r;
}

struct Figures {
  std::size_t triangles = 0, nodes = 0;
  double area = 0;
  double meanLength = 0;          // of the edges, in the metric
  double fractionInRange = 0;     // of the edges within [1/sqrt 2, sqrt 2]
  double elongation = 0;          // mean |dx| over mean |dy| of the edges
};

// Checks that every triangle is counter-clockwise (exactly) and the boundary segments are
// edges, and measures the mesh in a constant metric.
Figures measure(const PlanarMesh& mesh, const Rectangle& r, Metric2 metric) {
  Figures f;
  f.triangles = mesh.triangles.size() / 3;
  std::set<std::pair<std::uint32_t, std::uint32_t>> directed, edges;
  std::set<std::uint32_t> used;
  for (std::size_t t = 0; t < mesh.triangles.size(); t += 3) {
    const std::uint32_t v[3] = {mesh.triangles[t], mesh.triangles[t + 1], mesh.triangles[t + 2]};
    const Vec2 a = mesh.points[v[0]], b = mesh.points[v[1]], c = mesh.points[v[2]];
    EXPECT_GT(orient2d(a, b, c), 0);
    f.area += 0.5 * ((b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u));
    for (int i = 0; i < 3; ++i) {
      used.insert(v[i]);
      directed.insert({v[i], v[(i + 1) % 3]});
      edges.insert({std::min(v[i], v[(i + 1) % 3]), std::max(v[i], v[(i + 1) % 3])});
    }
  }
  for (const auto& s : r.segments) EXPECT_TRUE(directed.contains(s));
  f.nodes = used.size();
  double sumX = 0, sumY = 0;
  std::size_t inRange = 0;
  for (const auto& [a, b] : edges) {
    const Vec2 d{mesh.points[b].u - mesh.points[a].u, mesh.points[b].v - mesh.points[a].v};
    const double l = std::sqrt(lengthSquared(metric, d));
    f.meanLength += l;
    inRange += l >= 1 / std::sqrt(2.0) && l <= std::sqrt(2.0);
    sumX += std::abs(d.u), sumY += std::abs(d.v);
  }
  f.meanLength /= static_cast<double>(edges.size());
  f.fractionInRange = static_cast<double>(inRange) / static_cast<double>(edges.size());
  f.elongation = sumX / sumY;
  return f;
}

PlanarMesh meshWith(Rectangle& r, const WorkPlaneMetric& metric, AnisotropicSettings settings) {
  return anisotropicMesh(r.tri, r.inside, r.firstMovable, 0, nullptr, &metric, nullptr, settings);
}

// M = diag(1/hx^2, 1/hy^2) on the unit square, hx = 0.1, hy = 0.01, the sides meshed at those
// sizes. The metric area is 1/(hx hy) = 1000, and a unit equilateral triangle's sqrt(3)/4:
// about 2309 triangles. The reference (BAMG) gives 2210 triangles and 1216 nodes.
TEST(AnisotropicMesh, ConstantMetricGivesUnitEdgesElongatedAlongX) {
  Rectangle r = rectangle(1, 1, 10, 100);
  const Metric2 metric{1 / (0.1 * 0.1), 0, 1 / (0.01 * 0.01)};
  const PlanarMesh mesh = meshWith(r, [&](Vec2) { return metric; }, {});
  const Figures f = measure(mesh, r, metric);
  EXPECT_NEAR(f.area, 1, 1e-12);
  const double expected = 1000 / kSqrt3Over4;
  EXPECT_GT(f.triangles, 0.8 * expected);
  EXPECT_LT(f.triangles, 1.25 * expected);
  EXPECT_GT(f.meanLength, 0.85);
  EXPECT_LT(f.meanLength, 1.15);
  EXPECT_GT(f.fractionInRange, 0.9);
  EXPECT_GT(f.elongation, 8);
  EXPECT_LT(f.elongation, 12.5);
}

// Mesh.AnisoMax = 2: the size along x comes down to twice that along y.
TEST(AnisotropicMesh, AnisoMaxBoundsTheElongation) {
  Rectangle r = rectangle(1, 0.2, 50, 20);
  const Metric2 metric{1 / (0.1 * 0.1), 0, 1 / (0.01 * 0.01)};
  AnisotropicSettings settings;
  settings.anisoMax = 2;
  const PlanarMesh mesh = meshWith(r, [&](Vec2) { return metric; }, settings);
  const Metric2 clamped{1 / (0.02 * 0.02), 0, 1 / (0.01 * 0.01)};
  const Figures f = measure(mesh, r, clamped);
  EXPECT_NEAR(f.area, 0.2, 1e-12);
  EXPECT_GT(f.meanLength, 0.85);
  EXPECT_LT(f.meanLength, 1.15);
  EXPECT_GT(f.elongation, 1.6);
  EXPECT_LT(f.elongation, 2.5);
}

// A metric turning with the place: sizes 0.02 along circles round the origin, 0.2 across
// them, on [0.5, 1.5] x [0.5, 1.5] (the sides meshed at 0.05).
TEST(AnisotropicMesh, TurningMetricIsFollowedEverywhere) {
  Rectangle r = rectangle(1, 1, 20, 20, {0.5, 0.5});
  const auto metricAt = [](Vec2 p) {
    const double n = std::hypot(p.u, p.v);
    return fromEigen({1 / (0.02 * 0.02), 1 / (0.2 * 0.2), {-p.v / n, p.u / n}});
  };
  const PlanarMesh mesh = meshWith(r, metricAt, {});
  double sum = 0, count = 0, inRange = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); t += 3)
    for (int i = 0; i < 3; ++i) {
      const Vec2 a = mesh.points[mesh.triangles[t + i]];
      const Vec2 b = mesh.points[mesh.triangles[t + (i + 1) % 3]];
      ASSERT_GT(orient2d(a, b, mesh.points[mesh.triangles[t + (i + 2) % 3]]), 0);
      const Vec2 mid{0.5 * (a.u + b.u), 0.5 * (a.v + b.v)};
      const double l = std::sqrt(lengthSquared(metricAt(mid), {b.u - a.u, b.v - a.v}));
      sum += l, ++count, inRange += l >= 0.5 && l <= 2;
    }
  EXPECT_GT(sum / count, 0.8);
  EXPECT_LT(sum / count, 1.2);
  EXPECT_GT(inRange / count, 0.9);
  // Metric area: 1 / (0.02 * 0.2) = 250 per unit area.
  const double expected = 250 / kSqrt3Over4, triangles = mesh.triangles.size() / 3.0;
  EXPECT_GT(triangles, 0.75 * expected);
  EXPECT_LT(triangles, 1.33 * expected);
}

MeshOptions algorithm7() {
  MeshOptions options;
  options.algorithm2D = 7;
  return options;
}

// No background: sizes grow from the boundary's 0.1 at Mesh.SmoothRatio 1.8. The reference
// (Gmsh 4.15, Mesh.Algorithm = 7) gives 56 nodes and 70 triangles.
TEST(AnisotropicMesh, WithoutBackgroundSizesGrowFromTheBoundary) {
  Mesh mesh;
  testing::RecordingSink log;
  const Model model = geoUnitSquare(0.1);
  generateMesh(model, algorithm7(), 2, mesh, log);
  EXPECT_TRUE(log.warnings.empty());
  const MeshCheckReport report = checkMesh(model, mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
  EXPECT_GE(mesh.nodeCount(), 48u);
  EXPECT_LE(mesh.nodeCount(), 64u);
}

// The mean length in a constant metric of the edges of surface 1's triangles, and their mean
// |dx| over their mean |dy|.
std::pair<double, double> lengthAndElongation(const Mesh& mesh, Metric2 metric) {
  const ElementBlock& triangles = *mesh.find({2, 1})->findBlock(ElementType::Triangle3);
  std::set<std::pair<NodeIndex, NodeIndex>> edges;
  for (std::size_t e = 0; e < triangles.size(); ++e) {
    const auto n = triangles.element(e);
    for (int i = 0; i < 3; ++i)
      edges.insert({std::min(n[i], n[(i + 1) % 3]), std::max(n[i], n[(i + 1) % 3])});
  }
  double sum = 0, sumX = 0, sumY = 0;
  for (const auto& [a, b] : edges) {
    const Vec3 d = mesh.node(b) - mesh.node(a);
    sum += std::sqrt(lengthSquared(metric, {d.x, d.y}));
    sumX += std::abs(d.x), sumY += std::abs(d.y);
  }
  return {sum / static_cast<double>(edges.size()), sumX / sumY};
}

// A MathEvalAniso background asking for 0.1 along x and 0.01 along y: about 1000 / (sqrt 3 / 4)
// = 2309 triangles. The reference (Gmsh 4.15, with Mesh.MeshSizeExtendFromBoundary = 0) gives
// 2210 triangles and 1216 nodes, its curves along x cut in 10 segments; the 1D stage here cuts
// them at the metric's smallest size (100 segments), which adds nodes along them.
TEST(AnisotropicMesh, MathEvalAnisoBackgroundIsFollowed) {
  Model model = geoUnitSquare(0.1);
  SizeFieldDefinition field{"MathEvalAniso", {}, {}};
  for (const char* name : {"M12", "M13", "M23"}) field.strings[name] = "0";
  field.strings["M11"] = "100";
  field.strings["M22"] = "10000";
  field.strings["M33"] = "1";
  model.meshConstraints().sizeFields[1] = field;
  model.meshConstraints().backgroundField = 1;
  Mesh mesh;
  testing::RecordingSink log;
  generateMesh(model, algorithm7(), 2, mesh, log);
  const MeshCheckReport report = checkMesh(model, mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
  const double expected = 1000 / kSqrt3Over4;
  EXPECT_GT(mesh.elementCount(2), 0.9 * expected);
  EXPECT_LT(mesh.elementCount(2), 1.3 * expected);
  const auto [length, elongation] = lengthAndElongation(mesh, {100, 0, 10000});
  EXPECT_GT(length, 0.85);
  EXPECT_LT(length, 1.15);
  EXPECT_GT(elongation, 6);
}

}  // namespace
}  // namespace geomesh
