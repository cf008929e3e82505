// Tests of recombination (simple, blossom), subdivision into quadrangles, Delaunay density.
#include "mesh/quads/recombine.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

#include "mesh/pipeline/generate.h"
#include "mesh/checks/mesh_check.h"
#include "mesh/core/quality.h"
#include "mesh_test_models.h"

namespace geomesh {
namespace {

using testing::PolygonModelBuilder;

class SilentSink final : public MessageSink {
 public:
  void info(std::string_view) override {}
  void warning(std::string_view) override {}
};

struct Counts {
  std::size_t triangles = 0, quads = 0;
  double minQuality = 1, area = 0;
};

Counts count(const Mesh& mesh, int surface) {
  Counts c;
  const EntityMesh* em = mesh.find({2, surface});
  if (const ElementBlock* t = em->findBlock(ElementType::Triangle3)) {
    c.triangles = t->size();
    for (std::size_t e = 0; e < t->size(); ++e) {
      const auto n = t->element(e);
      c.area += 0.5 * norm(cross(mesh.node(n[1]) - mesh.node(n[0]),
                                 mesh.node(n[2]) - mesh.node(n[0])));
    }
  }
  if (const ElementBlock* q = em->findBlock(ElementType::Quad4)) {
    c.quads = q->size();
    for (std::size_t e = 0; e < q->size(); ++e) {
      const auto n = q->element(e);
      const Vec3 a = mesh.node(n[0]), b = mesh.node(n[1]), cc = mesh.node(n[2]),
                 d = mesh.node(n[3]);
      c.minQuality = std::min(c.minQuality, quadAngleQuality(a, b, cc, d, {0, 0, 1}));
      c.area += 0.5 * norm(cross(cc - a, d - b));
    }
  }
  return c;
}

Model recombinedSquare(double size) {
  PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, size)});
  b.model.meshConstraints().recombinedSurfaces[1] = 45;
  return std::move(b.model);
}

TEST(Recombine, QuadAngleQualityOfARectangleIsOne) {
  EXPECT_NEAR(quadAngleQuality({0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}, {0, 0, 1}), 1, 1e-12);
  EXPECT_LT(quadAngleQuality({0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}, {0, 0, -1}), 0);
  // A dart (non-convex) is rejected.
  EXPECT_LT(quadAngleQuality({0, 0, 0}, {2, 0, 0}, {0.5, 0.5, 0}, {0, 2, 0}, {0, 0, 1}), 0);
}

TEST(Recombine, SimpleAlgorithmPairsMostTriangles) {
  const Model model = recombinedSquare(0.05);
  MeshOptions options;
  options.recombinationAlgorithm = 0;
  Mesh mesh;
  SilentSink log;
  generateMesh(model, options, 2, mesh, log);
  const Counts c = count(mesh, 1);
  // The reference mesher leaves 417 quadrangles and 108 triangles here.
  EXPECT_GT(c.quads, 350u);
  EXPECT_LT(c.triangles, 250u);
  EXPECT_GT(c.minQuality, 0.3);
  EXPECT_NEAR(c.area, 1.0, 1e-9);
  const MeshCheckReport report = checkMesh(model, mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
}

TEST(Recombine, BlossomLeavesAtMostAFewTriangles) {
  const Model model = recombinedSquare(0.05);
  Mesh mesh;
  SilentSink log;
  generateMesh(model, {}, 2, mesh, log);
  const Counts c = count(mesh, 1);
  // The reference mesher makes 463 quadrangles and no triangle here.
  EXPECT_GT(c.quads, 420u);
  EXPECT_LT(c.quads, 510u);
  EXPECT_LE(c.triangles, 4u);
  EXPECT_GT(c.minQuality, 0.3);
  EXPECT_NEAR(c.area, 1.0, 1e-9);
  const MeshCheckReport report = checkMesh(model, mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
}

TEST(Recombine, RecombineAllAppliesToEverySurface) {
  PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.1)});
  MeshOptions options;
  options.recombineAll = true;
  Mesh mesh;
  SilentSink log;
  generateMesh(b.model, options, 2, mesh, log);
  EXPECT_GT(count(mesh, 1).quads, 80u);
  EXPECT_TRUE(checkMesh(b.model, mesh).ok());
}

// An all-quadrangle mesh needs an even number of boundary edges: curves bounding a surface
// recombined by Blossom get an even number of segments (5 -> 6 at size 0.2), except one
// shorter than its size (curve 3), which keeps its one segment; Simple leaves the counts
// alone.
TEST(Recombine, BlossomCurvesGetEvenSegmentCounts) {
  PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {1, 0}, {1, 1}, {0.9, 1.05}, {0, 1}}, 0.2)});
  b.model.meshConstraints().recombinedSurfaces[1] = 45;
  for (int algorithm : {1, 0}) {
    MeshOptions options;
    options.recombinationAlgorithm = algorithm;
    Mesh mesh;
    SilentSink log;
    generateMesh(b.model, options, 2, mesh, log);
    EXPECT_EQ(mesh.find({1, 1})->findBlock(ElementType::Line2)->size(), algorithm ? 6u : 5u);
    EXPECT_EQ(mesh.find({1, 3})->findBlock(ElementType::Line2)->size(), 1u);
  }
}

// A plate with holes of several sizes recombined by default: only quadrangles.
TEST(Recombine, BlossomGivesOnlyQuadranglesAroundHoles) {
  PolygonModelBuilder b;
  std::vector<std::vector<int>> loops{b.polygon({{0, 0}, {3, 0}, {3, 2}, {0, 2}}, 0.08)};
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 3; ++j)
      loops.push_back(b.circle({0.4 + 0.55 * i, 0.4 + 0.6 * j}, 0.1 + 0.01 * (i + j), 0.04));
  b.surface(loops);
  b.model.meshConstraints().recombinedSurfaces[1] = 45;
  Mesh mesh;
  SilentSink log;
  generateMesh(b.model, {}, 2, mesh, log);
  const Counts c = count(mesh, 1);
  EXPECT_EQ(c.triangles, 0u);
  EXPECT_GT(c.quads, 1500u);
  EXPECT_GT(c.minQuality, 0.2);
  const MeshCheckReport report = checkMesh(b.model, mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
}

// Two triangles three quadrangles apart: the elements between are split along the path, so
// that only quadrangles remain, convex, covering the same area, sharing every inner side.
TEST(Recombine, LeftoverTrianglesArePairedAlongAPath) {
  Mesh mesh;
  const Vec3 at[] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {0, 1, 0},
                     {1, 1, 0}, {2, 1, 0}, {3, 1, 0}, {0, 0.5, 0}, {3, 0.5, 0}};
  for (Vec3 p : at) mesh.addNode(p);
  EntityMesh& em = mesh.entity({2, 1});
  em.block(ElementType::Triangle3).nodes = {8, 0, 1, 2, 3, 9};
  em.block(ElementType::Quad4).nodes = {8, 1, 5, 4, 1, 2, 6, 5, 2, 9, 7, 6};
  const testing::FlatGeometry plane;
  EXPECT_EQ(pairLeftoverTriangles(plane, mesh, em), 1u);
  EXPECT_EQ(em.findBlock(ElementType::Triangle3), nullptr);
  const ElementBlock* quads = em.findBlock(ElementType::Quad4);
  ASSERT_NE(quads, nullptr);
  double area = 0;
  std::map<std::uint64_t, int> sides;
  for (std::size_t e = 0; e < quads->size(); ++e) {
    const auto n = quads->element(e);
    const Vec3 a = mesh.node(n[0]), b = mesh.node(n[1]), c = mesh.node(n[2]), d = mesh.node(n[3]);
    EXPECT_GT(quadAngleQuality(a, b, c, d, {0, 0, 1}), 0) << "quadrangle " << e;
    area += 0.5 * norm(cross(c - a, d - b));
    for (int k = 0; k < 4; ++k) ++sides[edgeKey(n[k], n[(k + 1) % 4])];
  }
  EXPECT_NEAR(area, 3, 1e-12);
  int outer = 0;
  for (const auto& [key, uses] : sides) {
    EXPECT_LE(uses, 2);
    outer += uses == 1;
  }
  EXPECT_EQ(outer, 10);  // the outline, unchanged: no node was added on it
  EXPECT_EQ(em.nodes.size() * 2, em.parametric.size());
}

// Full-quad recombination (Mesh.RecombinationAlgorithm 3) of one surface meshes it twice as
// coarse, then splits every element, as the reference does: every curve has an even number
// of segments, about as many as at the size asked for (the reference: 168 quadrangles on a
// square with a hole drawn as two arcs).
TEST(Recombine, FullQuadOfOneSurfaceHalvesThenSplits) {
  PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.1), b.circle({0.5, 0.5}, 0.2, 0.1)});
  b.model.meshConstraints().recombinedSurfaces[1] = 45;
  MeshOptions options;
  options.recombinationAlgorithm = 3;
  Mesh mesh;
  SilentSink log;
  generateMesh(b.model, options, 2, mesh, log);
  const Counts c = count(mesh, 1);
  EXPECT_EQ(c.triangles, 0u);
  EXPECT_GT(c.quads, 110u);
  EXPECT_LT(c.quads, 210u);
  for (int curve : {1, 2, 3, 4, 5})
    EXPECT_EQ(mesh.find({1, curve})->findBlock(ElementType::Line2)->size() % 2, 0u);
  EXPECT_GE(mesh.elementCount(1), 50u);
  EXPECT_LE(mesh.elementCount(1), 60u);
}

// A square coarser than its size is cut into four triangles around its centre; recombined,
// it is one quadrangle (the centre goes), as in the reference.
TEST(Recombine, CoarseSquareIsOneQuadrangle) {
  PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 10)});
  b.model.meshConstraints().recombinedSurfaces[1] = 45;
  Mesh mesh;
  SilentSink log;
  generateMesh(b.model, {}, 2, mesh, log);
  const Counts c = count(mesh, 1);
  EXPECT_EQ(c.triangles, 0u);
  EXPECT_EQ(c.quads, 1u);
  EXPECT_TRUE(mesh.find({2, 1})->nodes.empty());
  EXPECT_NEAR(c.area, 1.0, 1e-12);
  const MeshCheckReport report = checkMesh(b.model, mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
}

}  // namespace
}  // namespace geomesh

namespace geomesh {
namespace {

TEST(Subdivision, SplitsEveryTriangleIntoThreeQuadrangles) {
  PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.1)});
  Mesh plain, split;
  SilentSink log;
  generateMesh(b.model, {}, 2, plain, log);
  MeshOptions options;
  options.subdivisionAlgorithm = 1;
  generateMesh(b.model, options, 2, split, log);
  const Counts before = count(plain, 1), after = count(split, 1);
  EXPECT_EQ(after.triangles, 0u);
  EXPECT_EQ(after.quads, 3 * before.triangles);
  EXPECT_EQ(split.elementCount(1), 2 * plain.elementCount(1));
  EXPECT_NEAR(after.area, 1.0, 1e-9);
  EXPECT_GT(after.minQuality, 0.0);
  const MeshCheckReport report = checkMesh(b.model, split);
  EXPECT_TRUE(report.ok()) << report.summary();
}

TEST(Subdivision, FullQuadRecombinationLeavesOnlyQuadrangles) {
  PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.1)});
  MeshOptions options;
  options.recombineAll = true;
  options.recombinationAlgorithm = 2;
  Mesh mesh;
  SilentSink log;
  generateMesh(b.model, options, 2, mesh, log);
  const Counts c = count(mesh, 1);
  EXPECT_EQ(c.triangles, 0u);
  // The reference mesher makes 142 quadrangles here.
  EXPECT_GT(c.quads, 110u);
  EXPECT_LT(c.quads, 180u);
  EXPECT_GT(c.minQuality, 0.3);
  EXPECT_NEAR(c.area, 1.0, 1e-9);
  const MeshCheckReport report = checkMesh(b.model, mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
}

}  // namespace
}  // namespace geomesh

namespace geomesh {
namespace {

TEST(DelaunayAlgorithm, RefinesToTheSameDensityAsTheReference) {
  PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.05)});
  MeshOptions options;
  options.algorithm2D = 5;
  Mesh mesh;
  SilentSink log;
  generateMesh(b.model, options, 2, mesh, log);
  // The reference mesher's Delaunay algorithm gives 568 nodes here.
  EXPECT_GT(mesh.nodeCount(), 530u);
  EXPECT_LT(mesh.nodeCount(), 610u);
  EXPECT_GT(meshQuality(mesh, 2, QualityMeasure::Gamma).min, 0.5);
  const MeshCheckReport report = checkMesh(b.model, mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
}

}  // namespace
}  // namespace geomesh

namespace geomesh {
namespace {

TEST(Recombine, KeepsEmbeddedCurves) {
  PolygonModelBuilder b;
  const std::vector<int> loop = b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.1);
  const int inner = b.line(b.point(0.3, 0.3, 0.1), b.point(0.7, 0.6, 0.1));
  ModelSurface& s = b.surface({loop});
  s.embeddedCurves.push_back(inner);
  s.embeddedPoints = {};
  b.model.meshConstraints().recombinedSurfaces[s.tag] = 45;
  Mesh mesh;
  SilentSink log;
  generateMesh(b.model, {}, 2, mesh, log);
  EXPECT_GT(count(mesh, 1).quads, 50u);
  const MeshCheckReport report = checkMesh(b.model, mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
}

}  // namespace
}  // namespace geomesh
