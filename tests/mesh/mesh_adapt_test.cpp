// Tests of MeshAdapt and frontal-Delaunay for quadrangles: sizes, holes, curved surfaces.
#include "mesh/surfaces/mesh_adapt.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "kernel/geo/geo_factory.h"
#include "mesh/surfaces/constrained_delaunay.h"
#include "mesh/curves/curve_mesher.h"
#include "mesh/pipeline/generate.h"
#include "mesh/checks/mesh_check.h"
#include "mesh/surfaces/triangulation2d.h"
#include "mesh/core/quality.h"
#include "mesh/surfaces/surface_mesher.h"
#include "mesh_test_models.h"

namespace geomesh {
namespace {

using testing::PolygonModelBuilder;
using SizeAt = std::function<double(Vec3)>;
using Edge = std::pair<NodeIndex, NodeIndex>;

class RecordingSink final : public MessageSink {
 public:
  std::vector<std::string> lines;
  void info(std::string_view m) override { lines.emplace_back(m); }
  void warning(std::string_view m) override { lines.emplace_back(m); }
};

Mesh meshAdapt(const Model& model) {
  MeshOptions options;
  options.algorithm2D = findSurfaceAlgorithm("meshadapt")->code;
  Mesh mesh;
  SilentSink log;
  generateMesh(model, options, 2, mesh, log);
  return mesh;
}

// How many triangles hold each edge of a surface's mesh.
std::map<Edge, int> edgeUses(const ElementBlock& triangles) {
  std::map<Edge, int> uses;
  for (std::size_t e = 0; e < triangles.size(); ++e) {
    const auto n = triangles.element(e);
    for (int i = 0; i < 3; ++i)
      ++uses[{std::min(n[i], n[(i + 1) % 3]), std::max(n[i], n[(i + 1) % 3])}];
  }
  return uses;
}

// The segments of the given curves' meshes.
std::vector<Edge> curveSegments(const Mesh& mesh, const std::vector<int>& curves) {
  std::vector<Edge> segments;
  for (int c : curves) {
    const ElementBlock* lines = mesh.find({1, std::abs(c)})->findBlock(ElementType::Line2);
    for (std::size_t e = 0; e < lines->size(); ++e) {
      const auto n = lines->element(e);
      segments.emplace_back(std::min(n[0], n[1]), std::max(n[0], n[1]));
    }
  }
  return segments;
}

// The edges held by one triangle only are exactly the boundary curves' segments; embedded
// curves' segments are edges of two triangles.
void expectBoundaryIsTheCurveMeshes(const Model& model, const Mesh& mesh, int tag) {
  const ModelSurface& surface = *model.surface(tag);
  const std::map<Edge, int> uses =
      edgeUses(*mesh.find({2, tag})->findBlock(ElementType::Triangle3));
  std::vector<int> boundaryCurves;
  for (const std::vector<int>& loop : surface.loops)
    boundaryCurves.insert(boundaryCurves.end(), loop.begin(), loop.end());
  std::vector<Edge> expected = curveSegments(mesh, boundaryCurves);
  std::vector<Edge> single;
  for (const auto& [edge, count] : uses)
    if (count == 1) single.push_back(edge);
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(single, expected);
  for (const Edge& e : curveSegments(mesh, surface.embeddedCurves)) {
    const auto it = uses.find(e);
    ASSERT_NE(it, uses.end());
    EXPECT_EQ(it->second, 2);
  }
}

// Fraction of the triangle edges of a surface within [0.5, 2] times the size at their middle.
double fractionNearSize(const Mesh& mesh, int tag, const SizeAt& size) {
  const std::map<Edge, int> uses =
      edgeUses(*mesh.find({2, tag})->findBlock(ElementType::Triangle3));
  std::size_t near = 0;
  for (const auto& [edge, count] : uses) {
    const Vec3 p = mesh.node(edge.first), q = mesh.node(edge.second);
    const double ratio = distance(p, q) / size(0.5 * (p + q));
    if (ratio >= 0.5 && ratio <= 2) ++near;
  }
  return static_cast<double>(near) / static_cast<double>(uses.size());
}

// Valid, counter-clockwise seen from +z (plane surfaces of the builder), bounded by the curve
// meshes, covering `area`, with edges near the size and a good mean quality.
void expectGoodPlaneMesh(const Model& model, const Mesh& mesh, double area, const SizeAt& size) {
  const MeshCheckReport report = checkMesh(model, mesh);
  ASSERT_TRUE(report.ok()) << report.summary();
  const ElementBlock* triangles = mesh.find({2, 1})->findBlock(ElementType::Triangle3);
  ASSERT_GT(triangles->size(), 0u);
  for (std::size_t e = 0; e < triangles->size(); ++e) {
    const auto n = triangles->element(e);
    const Vec3 a = mesh.node(n[0]), b = mesh.node(n[1]), c = mesh.node(n[2]);
    ASSERT_GT(cross(b - a, c - a).z, 0);
  }
  expectBoundaryIsTheCurveMeshes(model, mesh, 1);
  EXPECT_NEAR(testing::meshArea(mesh, 1), area, 1e-9 * area);
  EXPECT_GE(fractionNearSize(mesh, 1, size), 0.97);
  const QualityStats gamma = meshQuality(mesh, 2, QualityMeasure::Gamma);
  EXPECT_GT(gamma.min, 0.45);
  EXPECT_GT(gamma.mean, 0.92);
}

// The area of a surface over its parameter box (midpoint rule, fine enough for 1e-5).
double surfaceArea(const SurfaceGeometry& g) {
  constexpr int kSteps = 400;
  const ParamBox box = g.bounds();
  const double du = (box.u.max - box.u.min) / kSteps, dv = (box.v.max - box.v.min) / kSteps;
  double area = 0;
  for (int i = 0; i < kSteps; ++i)
    for (int j = 0; j < kSteps; ++j) {
      const SurfaceDerivatives d =
          g.firstDerivatives({box.u.min + (i + 0.5) * du, box.v.min + (j + 0.5) * dv});
      area += norm(cross(d.du, d.dv)) * du * dv;
    }
  return area;
}

SizeAt uniform(double h) {
  return [h](Vec3) { return h; };
}

TEST(MeshAdapt, UnitSquareAtUniformSize) {
  for (double h : {0.1, 0.02}) {
    PolygonModelBuilder b;
    b.surface({b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, h)});
    const Mesh mesh = meshAdapt(b.model);
    expectGoodPlaneMesh(b.model, mesh, 1, uniform(h));
    // Between a square and an equilateral lattice of side h.
    EXPECT_GT(static_cast<double>(mesh.nodeCount()), 0.9 / (h * h));
    EXPECT_LT(static_cast<double>(mesh.nodeCount()), 1.5 * 2 / (std::sqrt(3.0) * h * h));
  }
}

TEST(MeshAdapt, LShapeGradedTowardsItsReentrantCorner) {
  // Size h / 5 at the re-entrant corner (0.5, 0.5), h at the other corners.
  const double h = 0.1;
  PolygonModelBuilder b;
  const std::vector<Vec2> corners{{0, 0}, {1, 0}, {1, 0.5}, {0.5, 0.5}, {0.5, 1}, {0, 1}};
  std::vector<int> points, loop;
  for (Vec2 c : corners) points.push_back(b.point(c.u, c.v, c.u == 0.5 && c.v == 0.5 ? h / 5 : h));
  for (std::size_t k = 0; k < points.size(); ++k)
    loop.push_back(b.line(points[k], points[(k + 1) % points.size()]));
  b.surface({loop});
  const Mesh mesh = meshAdapt(b.model);
  const SizeAt graded = [h](Vec3 p) {
    const double d = std::max(std::abs(p.x - 0.5), std::abs(p.y - 0.5));
    return h / 5 + 0.8 * h * std::min(1.0, d / 0.5);
  };
  expectGoodPlaneMesh(b.model, mesh, 0.75, graded);
  // The fine corner is resolved: its nearest nodes are about h / 5 away.
  double nearest = 1;
  for (NodeIndex n : mesh.find({2, 1})->nodes)
    nearest = std::min(nearest, distance(mesh.node(n), {0.5, 0.5, 0}));
  EXPECT_LT(nearest, 0.5 * h);
}

TEST(MeshAdapt, HolesEmbeddedPointAndEmbeddedCurveAreKept) {
  const double h = 0.05;
  PolygonModelBuilder b;
  const std::vector<int> outer = b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, h);
  const std::vector<int> round = b.circle({0.3, 0.3}, 0.1, h);
  const std::vector<int> square = b.polygon({{0.6, 0.6}, {0.6, 0.8}, {0.8, 0.8}, {0.8, 0.6}}, h);
  const int lonely = b.point(0.25, 0.75, h);
  const int crack = b.line(b.point(0.5, 0.15, h), b.point(0.85, 0.4, h));
  ModelSurface& s = b.surface({outer, round, square});
  s.embeddedPoints.push_back(lonely);
  s.embeddedCurves.push_back(crack);
  const Mesh mesh = meshAdapt(b.model);

  // The hole of the circle is the polygon of its nodes.
  double circlePolygon = 0;
  const std::vector<NodeIndex> chain = curveNodeChain(b.model, mesh, round[0]);
  for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
    const Vec3 p = mesh.node(chain[k]), q = mesh.node(chain[k + 1]);
    circlePolygon += 0.5 * (p.x * q.y - p.y * q.x);
  }
  expectGoodPlaneMesh(b.model, mesh, 1 - std::abs(circlePolygon) - 0.04, uniform(h));

  const ElementBlock* triangles = mesh.find({2, 1})->findBlock(ElementType::Triangle3);
  const NodeIndex lonelyNode = mesh.find({0, lonely})->nodes[0];
  EXPECT_NE(std::find(triangles->nodes.begin(), triangles->nodes.end(), lonelyNode),
            triangles->nodes.end());
  for (NodeIndex n : mesh.find({2, 1})->nodes) {
    const Vec3 p = mesh.node(n);
    EXPECT_GT(distance(p, {0.3, 0.3, 0}), 0.1 - 1e-3);
    EXPECT_FALSE(p.x > 0.6 && p.x < 0.8 && p.y > 0.6 && p.y < 0.8);
  }
}

TEST(MeshAdapt, SpherePatchIsMeshedWithItsOwnLengths) {
  const double h = 0.05;
  const Model model = testing::spherePatchModel(h);
  const Mesh mesh = meshAdapt(model);
  const MeshCheckReport report = checkMesh(model, mesh);  // orientation: outward normals
  ASSERT_TRUE(report.ok()) << report.summary();
  expectBoundaryIsTheCurveMeshes(model, mesh, 1);
  EXPECT_GE(fractionNearSize(mesh, 1, uniform(h)), 0.97);
  const double exactArea = testing::SphereGeometry::kPi / 2 * std::sin(1.2);
  EXPECT_NEAR(testing::meshArea(mesh, 1), exactArea, 2e-3 * exactArea);
  const QualityStats gamma = meshQuality(mesh, 2, QualityMeasure::Gamma);
  EXPECT_GT(gamma.min, 0.45);
  EXPECT_GT(gamma.mean, 0.92);
}

TEST(MeshAdapt, BuiltInKernelSurfaceOnFourCurvedSides) {
  // A Coons patch bounded by four circle arcs bulging out of the plane z = 0.
  const double h = 0.05;
  GeoFactory geo;
  geo.addPoint(1, {0, 0, 0}, h);
  geo.addPoint(2, {1, 0, 0}, h);
  geo.addPoint(3, {1, 1, 0}, h);
  geo.addPoint(4, {0, 1, 0}, h);
  geo.addPoint(5, {0.5, 0.5, -0.6}, h);  // centre of the two arcs along x
  geo.addPoint(6, {0.5, 0.5, -0.8}, h);  // centre of the two arcs along y
  geo.addCircleArc(1, 1, 5, 2);
  geo.addCircleArc(2, 2, 6, 3);
  geo.addCircleArc(3, 3, 5, 4);
  geo.addCircleArc(4, 4, 6, 1);
  geo.addCurveLoop(1, {1, 2, 3, 4});
  geo.addFillingSurface(1, {1}, {});
  Model model;
  geo.synchronize(model);
  const Mesh mesh = meshAdapt(model);
  const MeshCheckReport report = checkMesh(model, mesh);
  ASSERT_TRUE(report.ok()) << report.summary();
  expectBoundaryIsTheCurveMeshes(model, mesh, 1);
  EXPECT_GE(fractionNearSize(mesh, 1, uniform(h)), 0.97);
  const double area = surfaceArea(*model.surface(1)->geometry);
  EXPECT_NEAR(testing::meshArea(mesh, 1), area, 2e-3 * area);
  const QualityStats gamma = meshQuality(mesh, 2, QualityMeasure::Gamma);
  EXPECT_GT(gamma.min, 0.45);
  EXPECT_GT(gamma.mean, 0.92);
}

TEST(MeshAdapt, BackgroundFieldIsHonoured) {
  // A field asking for h / 4 everywhere: the interior follows it, not the boundary's h.
  const double h = 0.2;
  PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, h)});
  b.model.meshConstraints().sizeFields[1] = SizeFieldDefinition{"MathEval", {}, {{"F", "0.05"}}};
  b.model.meshConstraints().backgroundField = 1;
  const Mesh coarse = [&] {
    PolygonModelBuilder plain;
    plain.surface({plain.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.05)});
    return meshAdapt(plain.model);
  }();
  const Mesh mesh = meshAdapt(b.model);
  ASSERT_TRUE(checkMesh(b.model, mesh).ok());
  EXPECT_NEAR(testing::meshArea(mesh, 1), 1, 1e-9);
  // The field also refines the curves, so the whole mesh is that of size 0.05.
  EXPECT_GT(static_cast<double>(mesh.nodeCount()), 0.8 * static_cast<double>(coarse.nodeCount()));
  EXPECT_GE(fractionNearSize(mesh, 1, uniform(0.05)), 0.97);
}

// The square of side 1 turned by `degrees` around the origin, at size 0.1.
Model turnedSquare(double degrees) {
  const double a = degrees * testing::CircleGeometry::kPi / 180, c = std::cos(a), s = std::sin(a);
  PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {c, s}, {c - s, s + c}, {-s, c}}, 0.1)});
  return std::move(b.model);
}

TEST(FrontalQuads, SquareCellsFollowTheBoundary) {
  // Right isosceles triangles of legs 0.1 on the 11 x 11 lattice, whatever the square's
  // direction: gamma is 2 (sqrt 2 - 1) for each.
  for (double degrees : {0.0, 30.0}) {
    const Model model = turnedSquare(degrees);
    MeshOptions options;
    options.algorithm2D = findSurfaceAlgorithm("delquad")->code;
    Mesh mesh;
    SilentSink log;
    generateMesh(model, options, 2, mesh, log);
    ASSERT_TRUE(checkMesh(model, mesh).ok());
    EXPECT_EQ(mesh.nodeCount(), 121u) << degrees;
    EXPECT_EQ(mesh.elementCount(2), 200u) << degrees;
    const QualityStats gamma = meshQuality(mesh, 2, QualityMeasure::Gamma);
    EXPECT_NEAR(gamma.min, 2 * (std::sqrt(2.0) - 1), 1e-6) << degrees;
    EXPECT_NEAR(gamma.mean, 2 * (std::sqrt(2.0) - 1), 1e-6) << degrees;
  }
}

TEST(FrontalQuads, RecombinedOnlyWhenAsked) {
  Model model = turnedSquare(0);
  model.meshConstraints().recombinedSurfaces[1] = 45;
  MeshOptions options;
  options.algorithm2D = findSurfaceAlgorithm("delquad")->code;
  Mesh mesh;
  SilentSink log;
  generateMesh(model, options, 2, mesh, log);
  ASSERT_TRUE(checkMesh(model, mesh).ok());
  const EntityMesh& em = *mesh.find({2, 1});
  EXPECT_EQ(em.findBlock(ElementType::Triangle3), nullptr);
  ASSERT_NE(em.findBlock(ElementType::Quad4), nullptr);
  EXPECT_EQ(em.findBlock(ElementType::Quad4)->size(), 100u);
}

TEST(FrontalQuads, CurvedBoundaryAndHole) {
  PolygonModelBuilder b;
  const std::vector<int> disc = b.circle({0, 0}, 1, 0.05);
  const std::vector<int> hole =
      b.polygon({{-0.3, -0.2}, {0.3, -0.2}, {0.3, 0.2}, {-0.3, 0.2}}, 0.05);
  b.surface({disc, hole});
  MeshOptions options;
  options.algorithm2D = findSurfaceAlgorithm("delquad")->code;
  Mesh mesh;
  SilentSink log;
  generateMesh(b.model, options, 2, mesh, log);
  ASSERT_TRUE(checkMesh(b.model, mesh).ok());
  expectBoundaryIsTheCurveMeshes(b.model, mesh, 1);
  double discPolygon = 0;
  const std::vector<NodeIndex> chain = curveNodeChain(b.model, mesh, disc[0]);
  for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
    const Vec3 p = mesh.node(chain[k]), q = mesh.node(chain[k + 1]);
    discPolygon += 0.5 * (p.x * q.y - p.y * q.x);
  }
  EXPECT_NEAR(testing::meshArea(mesh, 1), discPolygon - 0.24, 1e-9);
  EXPECT_GE(fractionNearSize(mesh, 1, uniform(0.05)), 0.97);
  // Smoothing that never lowers the worst quality around a node mends where fronts meet.
  const QualityStats gamma = meshQuality(mesh, 2, QualityMeasure::Gamma);
  EXPECT_GT(gamma.min, 0.5);
  EXPECT_GT(gamma.mean, 0.88);
}

// Every neighbour link goes both ways across the same two vertices.
void expectConsistent(const Triangulation2D& m) {
  using T = Triangulation2D;
  for (std::uint32_t t = 0; t < m.triangleCount(); ++t) {
    if (!m.alive(t)) continue;
    for (std::uint32_t c = 3 * t; c < 3 * t + 3; ++c) {
      const std::uint32_t across = m.neighbour(c);
      if (across == kNone) continue;
      ASSERT_TRUE(m.alive(across / 3));
      EXPECT_EQ(m.neighbour(across), c);
      EXPECT_EQ(m.vertex(T::nextCorner(c)), m.vertex(T::prevCorner(across)));
      EXPECT_EQ(m.vertex(T::prevCorner(c)), m.vertex(T::nextCorner(across)));
    }
  }
}

std::size_t aliveCount(const Triangulation2D& m) {
  std::size_t n = 0;
  for (std::uint32_t t = 0; t < m.triangleCount(); ++t) n += m.alive(t);
  return n;
}

TEST(Triangulation2D, SplitFlipAndCollapseKeepTheLinks) {
  // The unit square in two triangles.
  const std::vector<Vec2> corners{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  Triangulation2D tri = delaunayTriangulation(corners);
  std::vector<ConstrainedSegment> sides;
  constexpr std::uint32_t first = Triangulation2D::kFirstVertex;
  for (std::uint32_t k = 0; k < 4; ++k) sides.push_back({k + first, (k + 1) % 4 + first});
  ASSERT_EQ(recoverSegments(tri, sides), -1);
  Triangulation2D m = tri;
  m.keepTriangles(classifyInside(tri));
  ASSERT_EQ(aliveCount(m), 2u);
  std::uint32_t diagonal = kNone;
  for (std::uint32_t c = 0; c < 6 && diagonal == kNone; ++c)
    if (m.neighbour(c) != kNone) diagonal = c;
  ASSERT_NE(diagonal, kNone);
  const std::uint32_t a = m.vertex(Triangulation2D::nextCorner(diagonal));
  const std::uint32_t b = m.vertex(Triangulation2D::prevCorner(diagonal));
  const std::uint32_t centre = m.addPoint({0.5, 0.5});
  m.split(diagonal, centre);
  expectConsistent(m);
  EXPECT_EQ(aliveCount(m), 4u);
  std::vector<std::uint32_t> ring;
  EXPECT_TRUE(m.ring(centre, ring));  // interior
  EXPECT_EQ(ring.size(), 4u);
  EXPECT_FALSE(m.ring(a, ring));      // on the boundary
  EXPECT_EQ(m.findUndirectedEdge(a, b), kNone);
  const std::uint32_t spoke = m.findUndirectedEdge(centre, a);
  ASSERT_NE(spoke, kNone);
  m.flip(spoke);  // links only: the new edge runs through the centre, which is flat here
  expectConsistent(m);
  EXPECT_EQ(m.findUndirectedEdge(centre, a), kNone);
  EXPECT_TRUE(m.ring(centre, ring));
  EXPECT_EQ(ring.size(), 3u);
  const std::uint32_t into = m.vertex(Triangulation2D::nextCorner(ring[0]));
  m.collapse(centre, into, ring);
  expectConsistent(m);
  EXPECT_EQ(aliveCount(m), 2u);
  EXPECT_FALSE(m.inMesh(centre));
}

TEST(MeshAdapt, InitialMeshOnlyAddsNoNode) {
  PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.1)});
  MeshOptions options;
  options.algorithm2D = findSurfaceAlgorithm("initial2d")->code;
  Mesh mesh;
  SilentSink log;
  generateMesh(b.model, options, 2, mesh, log);
  ASSERT_TRUE(checkMesh(b.model, mesh).ok());
  EXPECT_EQ(mesh.find({2, 1})->nodes.size(), 0u);
  EXPECT_EQ(mesh.elementCount(2), 38u);  // 40 boundary nodes: n - 2 triangles
  EXPECT_NEAR(testing::meshArea(mesh, 1), 1, 1e-12);
}

TEST(MeshAdapt, AutomaticIsDelaunayOnPlanesAndMeshAdaptElsewhere) {
  PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.1)});
  MeshOptions automatic, delaunay, adapt;
  automatic.algorithm2D = findSurfaceAlgorithm("auto")->code;
  delaunay.algorithm2D = findSurfaceAlgorithm("del2d")->code;
  adapt.algorithm2D = findSurfaceAlgorithm("meshadapt")->code;
  Mesh meshes[3];
  SilentSink log;
  generateMesh(b.model, automatic, 2, meshes[0], log);
  generateMesh(b.model, delaunay, 2, meshes[1], log);
  generateMesh(b.model, adapt, 2, meshes[2], log);
  const auto triangles = [&](int k) {
    return meshes[k].find({2, 1})->findBlock(ElementType::Triangle3)->nodes;
  };
  EXPECT_EQ(triangles(0), triangles(1));
  EXPECT_NE(triangles(0), triangles(2));
}

TEST(MeshAdapt, SurfaceAlgorithmOverridesTheOptionAndUnknownOnesWarn) {
  PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.1)});
  const Mesh frontal = meshAdapt([&] {
    PolygonModelBuilder other;
    other.surface({other.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.1)});
    other.model.meshConstraints().surfaceAlgorithms[1] = findSurfaceAlgorithm("front2d")->code;
    return other.model;
  }());
  Mesh byOption;
  SilentSink silent;
  generateMesh(b.model, {}, 2, byOption, silent);  // Mesh.Algorithm 6 by default
  EXPECT_EQ(frontal.nodeCount(), byOption.nodeCount());

  b.model.meshConstraints().surfaceAlgorithms[1] = 4;
  RecordingSink log;
  Mesh mesh;
  generateMesh(b.model, {}, 2, mesh, log);
  EXPECT_EQ(mesh.nodeCount(), byOption.nodeCount());
  const auto warning = std::find(log.lines.begin(), log.lines.end(),
                                 "MeshAlgorithm of surface 1: 4 is not a 2D meshing algorithm; "
                                 "meshed with Frontal-Delaunay (6)");
  EXPECT_NE(warning, log.lines.end());
}

TEST(MeshAdapt, IsDeterministic) {
  PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {2, 0}, {2, 0.3}, {0.3, 0.3}, {0.3, 1}, {0, 1}}, 0.03)});
  const Mesh first = meshAdapt(b.model), second = meshAdapt(b.model);
  EXPECT_EQ(first.nodeCount(), second.nodeCount());
  EXPECT_EQ(first.find({2, 1})->findBlock(ElementType::Triangle3)->nodes,
            second.find({2, 1})->findBlock(ElementType::Triangle3)->nodes);
}

}  // namespace
}  // namespace geomesh
