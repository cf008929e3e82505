// Tests of generateMesh: stages, timing lines, unavailable algorithms, determinism, errors.
#include "mesh/pipeline/generate.h"

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "kernel/plane_geometry.h"
#include "mesh/checks/mesh_check.h"
#include "mesh_test_models.h"

namespace geomesh {
namespace {

using testing::PolygonModelBuilder;

class RecordingSink final : public MessageSink {
 public:
  std::vector<std::string> lines;
  void info(std::string_view m) override { lines.emplace_back(m); }
  void warning(std::string_view m) override { lines.emplace_back(m); }
};

Model squareModel(double h) {
  PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, h)});
  return std::move(b.model);
}

TEST(GenerateMesh, DimensionZeroMeshesPointsOnly) {
  const Model model = squareModel(0.1);
  Mesh mesh;
  RecordingSink log;
  generateMesh(model, {}, 0, mesh, log);
  EXPECT_EQ(mesh.nodeCount(), 4u);
  EXPECT_EQ(mesh.elementCount(0), 4u);
  EXPECT_EQ(mesh.elementCount(1), 0u);
  for (int p = 1; p <= 4; ++p) {
    const EntityMesh* em = mesh.find({0, p});
    ASSERT_NE(em, nullptr);
    ASSERT_EQ(em->nodes.size(), 1u);
    EXPECT_EQ(mesh.node(em->nodes[0]), model.point(p)->xyz);
  }
}

TEST(GenerateMesh, StagesReportTheirTimeAndCounts) {
  const Model model = squareModel(0.1);
  Mesh mesh;
  RecordingSink log;
  generateMesh(model, {}, 2, mesh, log);
  ASSERT_EQ(log.lines.size(), 2u);
  EXPECT_EQ(log.lines[0].rfind("Meshing 1D... done (", 0), 0u);
  EXPECT_NE(log.lines[0].find("40 lines)"), std::string::npos);
  EXPECT_EQ(log.lines[1].rfind("Meshing 2D... done (", 0), 0u);
  EXPECT_NE(log.lines[1].find(std::to_string(mesh.elementCount(2)) + " triangles)"),
            std::string::npos);
  EXPECT_TRUE(checkMesh(model, mesh).ok());
}

TEST(GenerateMesh, UnavailableSurfaceAlgorithmIsAWarning) {
  const Model model = squareModel(0.1);
  Mesh mesh;
  RecordingSink log;
  MeshOptions options;
  options.algorithm2D = 9;
  generateMesh(model, options, 2, mesh, log);
  ASSERT_EQ(log.lines.size(), 3u);
  EXPECT_EQ(log.lines[1],
            "Mesh.Algorithm 9 (Packing of Parallelograms) is not available: surfaces are meshed "
            "with Frontal-Delaunay (6)");
  EXPECT_GT(mesh.elementCount(2), 0u);
}

TEST(GenerateMesh, ElementOrderTwoEndsWithAnOrderLineAndQuadraticElements) {
  const Model model = squareModel(0.1);
  Mesh mesh;
  RecordingSink log;
  MeshOptions options;
  options.elementOrder = 2;
  generateMesh(model, options, 2, mesh, log);
  ASSERT_EQ(log.lines.size(), 3u);
  EXPECT_EQ(log.lines[2].rfind("Meshing order 2 (curved)... done (", 0), 0u);
  const EntityMesh* surface = mesh.find({2, 1});
  ASSERT_NE(surface, nullptr);
  ASSERT_EQ(surface->blocks.size(), 1u);
  EXPECT_EQ(surface->blocks[0].type, ElementType::Triangle6);
  EXPECT_TRUE(checkMesh(model, mesh).ok());
}

TEST(GenerateMesh, UnsupportedElementOrderFailsBeforeMeshing) {
  const Model model = squareModel(0.1);
  Mesh mesh;
  RecordingSink log;
  MeshOptions options;
  options.elementOrder = 5;
  EXPECT_THROW(generateMesh(model, options, 2, mesh, log), std::invalid_argument);
  EXPECT_TRUE(log.lines.empty());
  EXPECT_EQ(mesh.nodeCount(), 0u);
}

TEST(GenerateMesh, ReplacesThePreviousMesh) {
  const Model model = squareModel(0.1);
  Mesh mesh;
  SilentSink log;
  generateMesh(model, {}, 2, mesh, log);
  const std::size_t nodes = mesh.nodeCount();
  generateMesh(model, {}, 2, mesh, log);
  EXPECT_EQ(mesh.nodeCount(), nodes);
  generateMesh(model, {}, 1, mesh, log);
  EXPECT_EQ(mesh.nodeCount(), 40u);
  EXPECT_EQ(mesh.elementCount(2), 0u);
}

TEST(GenerateMesh, IsDeterministic) {
  const Model model = squareModel(0.03);
  Mesh first, second;
  SilentSink log;
  generateMesh(model, {}, 2, first, log);
  generateMesh(model, {}, 2, second, log);
  ASSERT_EQ(first.nodeCount(), second.nodeCount());
  EXPECT_TRUE(std::equal(first.coordinates().begin(), first.coordinates().end(),
                         second.coordinates().begin()));
  EXPECT_EQ(first.find({2, 1})->blocks[0].nodes, second.find({2, 1})->blocks[0].nodes);
}

TEST(GenerateMesh, SeveralSurfacesShareTheirCommonCurve) {
  PolygonModelBuilder b;
  const int p1 = b.point(0, 0, 0.1), p2 = b.point(1, 0, 0.1), p3 = b.point(1, 1, 0.1),
            p4 = b.point(0, 1, 0.1), p5 = b.point(2, 0, 0.1), p6 = b.point(2, 1, 0.1);
  const int bottom = b.line(p1, p2), shared = b.line(p2, p3), top = b.line(p3, p4),
            left = b.line(p4, p1);
  const int bottom2 = b.line(p2, p5), right = b.line(p5, p6), top2 = b.line(p6, p3);
  b.surface({{bottom, shared, top, left}});
  b.surface({{bottom2, right, top2, -shared}});
  Mesh mesh;
  SilentSink log;
  generateMesh(b.model, {}, 2, mesh, log);
  const MeshCheckReport report = checkMesh(b.model, mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
  EXPECT_NEAR(testing::meshArea(mesh, 1) + testing::meshArea(mesh, 2), 2.0, 1e-12);
}

using testing::cubeModel;

TEST(GenerateMesh, CubeSurfacesFollowTheirLoopsAndTheVolumeIsFilled) {
  const Model model = cubeModel(0.25);
  Mesh mesh;
  RecordingSink log;
  generateMesh(model, {}, 3, mesh, log);
  const MeshCheckReport report = checkMesh(model, mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
  ASSERT_EQ(log.lines.size(), 3u);
  EXPECT_EQ(log.lines[2].rfind("Meshing 3D... done (", 0), 0u);
  // Every face's triangles point out of the cube.
  for (int f = 1; f <= 6; ++f) {
    const ElementBlock* triangles = mesh.find({2, f})->findBlock(ElementType::Triangle3);
    const Vec3 normal = cross(model.surface(f)->geometry->firstDerivatives({0, 0}).du,
                              model.surface(f)->geometry->firstDerivatives({0, 0}).dv);
    const Vec3 outward = model.surface(f)->geometry->point({0, 0}) - Vec3{0.5, 0.5, 0.5};
    EXPECT_GT(dot(normal, outward), 0) << "face " << f;
    for (std::size_t e = 0; e < triangles->size(); ++e) {
      const auto n = triangles->element(e);
      const Vec3 a = mesh.node(n[0]), b = mesh.node(n[1]), c = mesh.node(n[2]);
      ASSERT_GT(dot(cross(b - a, c - a), outward), 0) << "face " << f;
    }
  }
  const ElementBlock* tets = mesh.find({3, 1})->findBlock(ElementType::Tet4);
  ASSERT_NE(tets, nullptr);
  double volume = 0;
  for (std::size_t e = 0; e < tets->size(); ++e) {
    const auto n = tets->element(e);
    const Vec3 a = mesh.node(n[0]);
    volume += dot(cross(mesh.node(n[1]) - a, mesh.node(n[2]) - a), mesh.node(n[3]) - a) / 6;
  }
  EXPECT_NEAR(volume, 1.0, 1e-9);
}

TEST(GenerateMesh, MissingGeometryIsAnErrorNamingTheEntity) {
  Model model;
  model.addPoint({1, {0, 0, 0}, 0.1});
  model.addPoint({2, {1, 0, 0}, 0.1});
  model.addCurve({7, 1, 2, nullptr});
  Mesh mesh;
  SilentSink log;
  try {
    generateMesh(model, {}, 1, mesh, log);
    FAIL() << "expected MeshError";
  } catch (const MeshError& e) {
    EXPECT_EQ(e.entity, (EntityId{1, 7}));
    EXPECT_EQ(std::string(e.what()), "cannot mesh curve 7: curve has no geometry");
  }
}

}  // namespace
}  // namespace geomesh
