// Meshing imported OpenCASCADE parts whose faces have seams and poles: cylinder, sphere, cone,
// torus and a box with a cylindrical hole, in 2D and 3D, measured against their exact area and
// volume.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "kernel/occ/occ_factory.h"
#include "mesh/checks/mesh_check.h"
#include "mesh/pipeline/generate.h"
#include "mesh_measures.h"
#include "mesh_test_models.h"
#include "tests/occ_fixtures.h"

namespace geomesh {
namespace {

using namespace occ_fixtures;
using testing::QuietSink;
using testing::totalArea;
using testing::totalVolume;

Model importedModel(const std::string& path) {
  OccFactory occ;
  occ.importShapes(path);
  Model model;
  occ.synchronize(model);
  return model;
}

struct Measured {
  std::size_t nodes2D, triangles, nodes3D, tets;
};

// Meshes the part at size h in 2D, then 3D; checks validity and measures on the way.
Measured meshPart(const Part& part, const std::string& path, double h, double tolerance,
                  int algorithm = 6) {
  const Model model = importedModel(path);
  MeshOptions options;
  options.sizeMax = h;
  options.algorithm2D = algorithm;
  QuietSink log;
  Mesh mesh;
  generateMesh(model, options, 2, mesh, log);
  MeshCheckReport report = checkMesh(model, mesh);
  EXPECT_TRUE(report.ok()) << part.name << " 2D:\n" << report.summary();
  EXPECT_NEAR(totalArea(mesh), part.area, tolerance * part.area) << part.name;
  Measured m{mesh.nodeCount(), mesh.elementCount(2), 0, 0};
  Mesh volume;
  generateMesh(model, options, 3, volume, log);
  report = checkMesh(model, volume);
  EXPECT_TRUE(report.ok()) << part.name << " 3D:\n" << report.summary();
  EXPECT_NEAR(totalVolume(volume), part.volume, tolerance * part.volume) << part.name;
  m.nodes3D = volume.nodeCount();
  m.tets = volume.elementCount(3);
  return m;
}

// Triangles that keep to the size: as many as an equilateral tiling of the area needs, within
// a factor of 2 either way.
void expectSensibleCount(const Part& part, const Measured& m, double h) {
  const double ideal = part.area / (std::sqrt(3.0) / 4 * h * h);
  EXPECT_GT(static_cast<double>(m.triangles), 0.5 * ideal) << part.name;
  EXPECT_LT(static_cast<double>(m.triangles), 2.0 * ideal) << part.name;
}

TEST(OccSurfaceMesh, CylinderSeam) {
  const Part part = cylinder();
  const Measured m = meshPart(part, writeBrep(part), 0.1, 0.01);
  expectSensibleCount(part, m, 0.1);
}

TEST(OccSurfaceMesh, SpherePoles) {
  const Part part = sphere();
  const Measured m = meshPart(part, writeBrep(part), 0.1, 0.01);
  expectSensibleCount(part, m, 0.1);
}

TEST(OccSurfaceMesh, ConeApex) {
  const Part part = cone();
  const Measured m = meshPart(part, writeBrep(part), 0.1, 0.01);
  expectSensibleCount(part, m, 0.1);
}

TEST(OccSurfaceMesh, TorusTwoSeams) {
  const Part part = torus();
  const Measured m = meshPart(part, writeBrep(part), 0.1, 0.01);
  expectSensibleCount(part, m, 0.1);
}

TEST(OccSurfaceMesh, BoxWithCylindricalHoleFromStep) {
  const Part part = boxWithHole();
  const Measured m = meshPart(part, writeStep(part), 0.1, 0.01);
  expectSensibleCount(part, m, 0.1);
}

TEST(OccSurfaceMesh, CoarseSphereStaysValid) {
  const Part part = sphere();
  meshPart(part, writeBrep(part), 0.5, 0.2);
}

// Coarse, a cone's apex would be closed by two triangles spanning half a turn each, flat in
// space; the ring of points around the pole prevents it, with every algorithm.
TEST(OccSurfaceMesh, CoarseConeApexWithEveryAlgorithm) {
  const Part part = cone();
  const std::string path = writeBrep(part);
  for (int algorithm : {6, 5, 1, 2, 8}) {
    SCOPED_TRACE("Mesh.Algorithm " + std::to_string(algorithm));
    meshPart(part, path, 0.3, 0.05, algorithm);
  }
}

// Each triangle of a pole's fan has its own corners: none with two at the pole.
TEST(OccSurfaceMesh, PoleFanHasNoCollapsedTriangle) {
  const Model model = importedModel(writeBrep(sphere()));
  MeshOptions options;
  options.sizeMax = 0.2;
  QuietSink log;
  Mesh mesh;
  generateMesh(model, options, 2, mesh, log);
  const ElementBlock* t = mesh.find({2, 1})->findBlock(ElementType::Triangle3);
  ASSERT_NE(t, nullptr);
  int atPoles = 0;
  const NodeIndex poles[2] = {mesh.find({0, 1})->nodes[0], mesh.find({0, 2})->nodes[0]};
  for (std::size_t e = 0; e < t->size(); ++e) {
    const auto n = t->element(e);
    EXPECT_TRUE(n[0] != n[1] && n[1] != n[2] && n[2] != n[0]);
    for (NodeIndex p : poles) atPoles += (n[0] == p) + (n[1] == p) + (n[2] == p);
  }
  EXPECT_GE(atPoles, 12);  // at least six triangles around each pole
}

// With Mesh.MeshSizeFromCurvature, the surfaces' curvature bounds the size too: on the
// saddle's straight edges and inside it, about 2 pi / (N k) where its curvature is k (1 at
// its centre, less towards its corners).
TEST(OccSurfaceMesh, SurfaceCurvatureBoundsTheSize) {
  OccFactory occ;
  occ.importShapes(writeBrep(saddle()));
  occ.setMeshSize(occ.tags(0), 1.0);  // alone, one segment per edge
  Model model;
  occ.synchronize(model);
  ASSERT_EQ(model.surfaces().size(), 1u);
  MeshOptions options;
  options.sizeFromCurvature = 32;
  QuietSink log;
  Mesh mesh;
  generateMesh(model, options, 2, mesh, log);
  const double bound = 2 * std::numbers::pi / 32;  // at the centre
  for (const auto& [tag, curve] : model.curves())
    EXPECT_GE(mesh.find({1, tag})->findBlock(ElementType::Line2)->size(), 3u);
  const ElementBlock* t = mesh.find({2, 1})->findBlock(ElementType::Triangle3);
  ASSERT_NE(t, nullptr);
  EXPECT_GT(t->size(), 0.5 / (std::sqrt(3.0) / 4 * 4 * bound * bound));
  EXPECT_TRUE(checkMesh(model, mesh).ok());
}

// The unit square, whose curves on the surface are off by the CAD model's tolerance (1e-4 times
// the curve's tag along u): neighbouring curves of a loop do not quite meet in its parameters.
class ToleranceOffPlane final : public SurfaceGeometry {
 public:
  explicit ToleranceOffPlane(const Model& model) : model_(model) {}
  ParamBox bounds() const override { return {{0, 1}, {0, 1}}; }
  Vec3 point(Vec2 uv) const override { return {uv.u, uv.v, 0}; }
  SurfaceDerivatives firstDerivatives(Vec2) const override { return {{1, 0, 0}, {0, 1, 0}}; }
  Vec2 project(Vec3 p) const override { return {p.x, p.y}; }
  bool isPlane() const override { return true; }
  std::optional<Vec2> curveParameters(int signedCurve, double t) const override {
    const int tag = std::abs(signedCurve);
    const Vec3 p = model_.curve(tag)->geometry->point(t);
    return Vec2{p.x + 1e-4 * tag, p.y};
  }

 private:
  const Model& model_;
};

TEST(OccSurfaceMesh, LoopsCloseWhereCurvesOnTheSurfaceMissEachOther) {
  testing::PolygonModelBuilder b;
  ModelSurface& surface = b.surface({b.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.1)});
  surface.geometry = std::make_shared<ToleranceOffPlane>(b.model);
  QuietSink log;
  Mesh mesh;
  generateMesh(b.model, {}, 2, mesh, log);
  const MeshCheckReport report = checkMesh(b.model, mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
  EXPECT_NEAR(totalArea(mesh), 1.0, 1e-3);
}

}  // namespace
}  // namespace geomesh
