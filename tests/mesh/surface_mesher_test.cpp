// Tests of the surface mesher: squares, holes, L-shapes, graded sizes, embedded entities.
#include "mesh/surfaces/surface_mesher.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>

#include "mesh/curves/curve_mesher.h"
#include "mesh/pipeline/generate.h"
#include "mesh/checks/mesh_check.h"
#include "mesh/core/quality.h"
#include "mesh_test_models.h"

namespace geomesh {
namespace {

using testing::PolygonModelBuilder;
using SizeAt = std::function<double(Vec3)>;

Mesh meshModel(const Model& model, const MeshOptions& options = {}) {
  Mesh mesh;
  SilentSink log;
  generateMesh(model, options, 2, mesh, log);
  return mesh;
}

// Signed area enclosed by a loop of meshed curves (shoelace over its nodes).
double loopArea(const Model& model, const Mesh& mesh, const std::vector<int>& loop) {
  double twice = 0;
  for (int curve : loop) {
    const std::vector<NodeIndex> chain = curveNodeChain(model, mesh, curve);
    for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
      const Vec3 a = mesh.node(chain[k]), b = mesh.node(chain[k + 1]);
      twice += a.x * b.y - a.y * b.x;
    }
  }
  return 0.5 * twice;
}

// Everything the surface mesher promises, for a surface of the plane z = 0 with normal +z.
void expectGoodSurfaceMesh(const Model& model, const Mesh& mesh, int tag, const SizeAt& size) {
  const MeshCheckReport report = checkMesh(model, mesh);
  ASSERT_TRUE(report.ok()) << report.summary();
  const ModelSurface& surface = *model.surface(tag);

  // Area of the polygon bounded by the boundary nodes.
  double polygon = std::abs(loopArea(model, mesh, surface.loops[0]));
  for (std::size_t k = 1; k < surface.loops.size(); ++k)
    polygon -= std::abs(loopArea(model, mesh, surface.loops[k]));
  EXPECT_NEAR(testing::meshArea(mesh, tag), polygon, 1e-9 * polygon);

  // Triangles counter-clockwise seen from +z; edges near the target size; boundary edges are
  // exactly the curve segments (each appears in exactly one triangle).
  const ElementBlock* triangles = mesh.find({2, tag})->findBlock(ElementType::Triangle3);
  std::size_t boundarySegments = 0;
  for (const std::vector<int>& loop : surface.loops)
    for (int c : loop) boundarySegments += mesh.find({1, std::abs(c)})->elementCount();
  std::vector<std::pair<NodeIndex, NodeIndex>> edges;
  for (std::size_t e = 0; e < triangles->size(); ++e) {
    const auto n = triangles->element(e);
    const Vec3 a = mesh.node(n[0]), b = mesh.node(n[1]), c = mesh.node(n[2]);
    ASSERT_GT(cross(b - a, c - a).z, 0);
    for (int i = 0; i < 3; ++i) {
      const Vec3 p = mesh.node(n[i]), q = mesh.node(n[(i + 1) % 3]);
      const double target = size(0.5 * (p + q));
      EXPECT_GE(distance(p, q), 0.5 * target);
      EXPECT_LE(distance(p, q), 2.0 * target);
      edges.emplace_back(std::min(n[i], n[(i + 1) % 3]), std::max(n[i], n[(i + 1) % 3]));
    }
  }
  std::sort(edges.begin(), edges.end());
  std::size_t single = 0;
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const bool sameAsPrevious = k > 0 && edges[k] == edges[k - 1];
    const bool sameAsNext = k + 1 < edges.size() && edges[k] == edges[k + 1];
    if (!sameAsPrevious && !sameAsNext) ++single;
  }
  EXPECT_EQ(single, boundarySegments);

  const QualityStats gamma = meshQuality(mesh, 2, QualityMeasure::Gamma);
  EXPECT_GT(gamma.min, 0.3);
  EXPECT_GT(gamma.mean, 0.85);
}

SizeAt uniform(double h) {
  return [h](Vec3) { return h; };
}

TEST(SurfaceMesher, UnitSquare) {
  for (double h : {0.1, 0.02}) {
    PolygonModelBuilder b;
    b.surface({b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, h)});
    const Mesh mesh = meshModel(b.model);
    expectGoodSurfaceMesh(b.model, mesh, 1, uniform(h));
    // An equilateral lattice of side h has 2 / (sqrt(3) h^2) nodes per unit area.
    const double lattice = 2 / (std::sqrt(3.0) * h * h);
    EXPECT_GT(static_cast<double>(mesh.nodeCount()), 0.9 * lattice);
    EXPECT_LT(static_cast<double>(mesh.nodeCount()), 1.5 * lattice);
  }
}

TEST(SurfaceMesher, SquareWithOneHole) {
  PolygonModelBuilder b;
  const std::vector<int> outer = b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.05);
  const std::vector<int> hole = b.circle({0.5, 0.5}, 0.2, 0.05);
  b.surface({outer, hole});
  const Mesh mesh = meshModel(b.model);
  expectGoodSurfaceMesh(b.model, mesh, 1, uniform(0.05));
  // No node inside the hole.
  for (NodeIndex n : mesh.find({2, 1})->nodes)
    EXPECT_GT(distance(mesh.node(n), {0.5, 0.5, 0}), 0.2);
}

TEST(SurfaceMesher, RectangleWithTenHoles) {
  PolygonModelBuilder b;
  std::vector<std::vector<int>> loops{b.polygon({{0, 0}, {5, 0}, {5, 2}, {0, 2}}, 0.1)};
  for (int i = 0; i < 5; ++i) {
    loops.push_back(b.circle({0.5 + i, 0.5}, 0.25, 0.1));
    loops.push_back(
        b.polygon({{0.3 + i, 1.3}, {0.3 + i, 1.7}, {0.7 + i, 1.7}, {0.7 + i, 1.3}}, 0.1));
  }
  b.surface(loops);
  const Mesh mesh = meshModel(b.model);
  expectGoodSurfaceMesh(b.model, mesh, 1, uniform(0.1));
}

TEST(SurfaceMesher, LShape) {
  PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {1, 0}, {1, 0.5}, {0.5, 0.5}, {0.5, 1}, {0, 1}}, 0.04)});
  const Mesh mesh = meshModel(b.model);
  expectGoodSurfaceMesh(b.model, mesh, 1, uniform(0.04));
}

TEST(SurfaceMesher, GradedSizesFollowTheBoundary) {
  // One corner 10x finer: the size grows linearly along the two sides leaving it.
  const double h = 0.1;
  PolygonModelBuilder b;
  const std::vector<int> corners{b.point(0, 0, h / 10), b.point(1, 0, h), b.point(1, 1, h),
                                 b.point(0, 1, h)};
  std::vector<int> loop;
  for (int k = 0; k < 4; ++k) loop.push_back(b.line(corners[k], corners[(k + 1) % 4]));
  b.surface({loop});
  const Mesh mesh = meshModel(b.model);
  const SizeAt graded = [h](Vec3 p) {
    return h / 10 + 0.9 * h * std::min(1.0, std::max(p.x, p.y));
  };
  expectGoodSurfaceMesh(b.model, mesh, 1, graded);
}

TEST(SurfaceMesher, ClockwiseLoopOnAFlippedPlaneGivesTrianglesAlongTheLoop) {
  // The outer loop turns clockwise seen from +z; the plane's normal (du x dv) is -z, as a
  // kernel fitting the plane to the loop makes it. Triangles follow the loop: normals -z.
  PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {0, 1}, {1, 1}, {1, 0}}, 0.2)}, true);
  const Mesh mesh = meshModel(b.model);
  const MeshCheckReport report = checkMesh(b.model, mesh);
  ASSERT_TRUE(report.ok()) << report.summary();
  const ElementBlock* triangles = mesh.find({2, 1})->findBlock(ElementType::Triangle3);
  ASSERT_GT(triangles->size(), 0u);
  for (std::size_t e = 0; e < triangles->size(); ++e) {
    const auto n = triangles->element(e);
    const Vec3 a = mesh.node(n[0]), b2 = mesh.node(n[1]), c = mesh.node(n[2]);
    EXPECT_LT(cross(b2 - a, c - a).z, 0);
  }
}

TEST(SurfaceMesher, EmbeddedPointAndCurveBecomeMeshNodesAndEdges) {
  PolygonModelBuilder b;
  const std::vector<int> outer = b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.1);
  const int lonely = b.point(0.3, 0.7, 0.1);
  const int from = b.point(0.2, 0.2, 0.1);
  const int crack = b.line(from, b.point(0.8, 0.4, 0.1));
  ModelSurface& s = b.surface({outer});
  s.embeddedPoints.push_back(lonely);
  s.embeddedCurves.push_back(crack);
  const Mesh mesh = meshModel(b.model);
  const MeshCheckReport report = checkMesh(b.model, mesh);  // embedded segments: 2 triangles
  ASSERT_TRUE(report.ok()) << report.summary();
  const ElementBlock* triangles = mesh.find({2, 1})->findBlock(ElementType::Triangle3);
  const NodeIndex lonelyNode = mesh.find({0, lonely})->nodes[0];
  EXPECT_NE(std::find(triangles->nodes.begin(), triangles->nodes.end(), lonelyNode),
            triangles->nodes.end());
  EXPECT_GT(mesh.find({1, crack})->elementCount(), 5u);
  EXPECT_NEAR(testing::meshArea(mesh, 1), 1.0, 1e-12);
}

TEST(SurfaceMesher, ManyEmbeddedPointsSomeOnTheBoundaryOrTwice) {
  PolygonModelBuilder b;
  const std::vector<int> outer = b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.05);
  ModelSurface& s = b.surface({outer});
  for (int i = 1; i < 40; ++i)
    for (int j = 1; j < 40; ++j) s.embeddedPoints.push_back(b.point(i / 40.0, j / 40.0, 0.05));
  s.embeddedPoints.push_back(b.point(0.5, 0.5, 0.05));  // twice at one place
  s.embeddedPoints.push_back(b.point(0.5, 0, 0.05));    // at a node of the bottom side
  s.embeddedPoints.push_back(b.point(0, 0.25, 0.05));   // at a node of the left side
  const Mesh mesh = meshModel(b.model);
  // The points' own nodes stay where the script put them, on the boundary's nodes and on each
  // other (as in the reference); the surface itself is sound.
  const MeshCheckReport report = checkMesh(b.model, mesh);
  for (const MeshProblem& problem : report.problems) {
    EXPECT_NE(problem.entity.dim, 2) << problem.message;
    EXPECT_NE(problem.message.find("coincide"), std::string::npos) << problem.message;
  }
  const EntityMesh* em = mesh.find({2, 1});
  EXPECT_EQ(em->nodes.size(), 0u);  // every interior node is an embedded point
  // Euler: 2 per interior node (39 x 39 embedded points) + 1 per boundary node (80) - 2.
  EXPECT_EQ(em->findBlock(ElementType::Triangle3)->size(), 2u * 39 * 39 + 80 - 2);
  EXPECT_NEAR(testing::meshArea(mesh, 1), 1.0, 1e-12);
}

TEST(SurfaceMesher, EmbeddedPointBetweenTwoBoundaryNodesIsALocatedError) {
  PolygonModelBuilder b;
  const std::vector<int> outer = b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.1);
  const int between = b.point(0.55, 0, 0.1);
  b.surface({outer}).embeddedPoints.push_back(between);
  try {
    meshModel(b.model);
    FAIL() << "no error";
  } catch (const MeshError& e) {
    EXPECT_EQ(e.entity.dim, 2);
    EXPECT_NE(std::string(e.what()).find("embedded point 5 lies on curve 1"), std::string::npos)
        << e.what();
  }
}

TEST(SurfaceMesher, SmoothingKeepsTheMeshValid) {
  PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {2, 0}, {2, 0.3}, {0.3, 0.3}, {0.3, 1}, {0, 1}}, 0.03)});
  for (int passes : {0, 1, 5}) {
    MeshOptions options;
    options.smoothing = passes;
    const Mesh mesh = meshModel(b.model, options);
    expectGoodSurfaceMesh(b.model, mesh, 1, uniform(0.03));
  }
}

TEST(SurfaceMesher, CurvedSurfaceIsMeshedWithItsOwnLengths) {
  const double h = 0.05;
  const Model model = testing::spherePatchModel(h);
  const Mesh mesh = meshModel(model);
  const MeshCheckReport report = checkMesh(model, mesh);  // orientation: outward normals
  ASSERT_TRUE(report.ok()) << report.summary();
  const ElementBlock* triangles = mesh.find({2, 1})->findBlock(ElementType::Triangle3);
  for (std::size_t e = 0; e < triangles->size(); ++e) {
    const auto n = triangles->element(e);
    for (int i = 0; i < 3; ++i) {
      const double l = distance(mesh.node(n[i]), mesh.node(n[(i + 1) % 3]));
      EXPECT_GE(l, 0.5 * h);
      EXPECT_LE(l, 2.0 * h);
    }
  }
  const double exactArea = testing::SphereGeometry::kPi / 2 * std::sin(1.2);
  EXPECT_NEAR(testing::meshArea(mesh, 1), exactArea, 2e-3 * exactArea);
  const QualityStats gamma = meshQuality(mesh, 2, QualityMeasure::Gamma);
  EXPECT_GT(gamma.min, 0.3);
  EXPECT_GT(gamma.mean, 0.85);
}

TEST(SurfaceMesher, NotExtendingBoundarySizesUsesSizeMaxInside) {
  PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.1)});
  MeshOptions options;
  options.sizeExtendFromBoundary = false;
  const Mesh coarse = meshModel(b.model, options);  // no size inside: boundary nodes only
  EXPECT_TRUE(checkMesh(b.model, coarse).ok());
  EXPECT_EQ(coarse.find({2, 1})->nodes.size(), 0u);
  options.sizeMax = 0.05;  // boundary at 0.05 too (40 -> 80 segments), interior at 0.05
  const Mesh fine = meshModel(b.model, options);
  expectGoodSurfaceMesh(b.model, fine, 1, uniform(0.05));
  EXPECT_GT(fine.nodeCount(), 450u);
}

TEST(SurfaceMesher, SelfIntersectingBoundaryIsAnErrorNamingTheSurface) {
  PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {1, 1}, {1, 0}, {0, 1}}, 0.1)});  // a bow tie
  try {
    meshModel(b.model);
    FAIL() << "expected MeshError";
  } catch (const MeshError& e) {
    EXPECT_EQ(e.entity.dim, 2);
    EXPECT_EQ(e.entity.tag, 1);
    EXPECT_NE(std::string(e.what()).find("cannot mesh surface 1: cannot recover the edge"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find(" of curve "), std::string::npos);
  }
}

TEST(SurfaceMesher, LargeMeshScalesWithArea) {
  // Not timed: checks that a 1e5+ triangle mesh is valid and that the triangle count follows
  // 1 / h^2 (no runaway refinement).
  std::size_t counts[2];
  const double sizes[2] = {0.008, 0.004};
  for (int k = 0; k < 2; ++k) {
    PolygonModelBuilder b;
    b.surface({b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, sizes[k])});
    const Mesh mesh = meshModel(b.model);
    counts[k] = mesh.elementCount(2);
    const QualityStats gamma = meshQuality(mesh, 2, QualityMeasure::Gamma);
    EXPECT_GT(gamma.min, 0.3);
    EXPECT_GT(gamma.mean, 0.95);
  }
  EXPECT_GT(counts[1], 100000u);
  const double ratio = static_cast<double>(counts[1]) / static_cast<double>(counts[0]);
  EXPECT_GT(ratio, 3.6);
  EXPECT_LT(ratio, 4.4);
}

}  // namespace
}  // namespace geomesh
