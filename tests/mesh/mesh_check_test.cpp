// Tests of checkMesh: each kind of defect it must report, and none on a generated mesh.
#include "mesh/checks/mesh_check.h"

#include <gtest/gtest.h>

#include "mesh/pipeline/generate.h"
#include "mesh_test_models.h"

namespace geomesh {
namespace {

using testing::PolygonModelBuilder;

struct Fixture {
  PolygonModelBuilder builder;
  Mesh mesh;
  Fixture() {
    builder.surface({builder.polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.25)});
    SilentSink log;
    generateMesh(builder.model, {}, 2, mesh, log);
  }
  ElementBlock& triangles() { return mesh.entity({2, 1}).block(ElementType::Triangle3); }
  bool reports(const MeshCheckReport& r, EntityId e, const std::string& text) const {
    for (const MeshProblem& p : r.problems)
      if (p.entity == e && p.message.find(text) != std::string::npos) return true;
    return false;
  }
};

TEST(MeshCheck, GeneratedMeshIsValid) {
  Fixture f;
  const MeshCheckReport r = checkMesh(f.builder.model, f.mesh);
  EXPECT_TRUE(r.ok()) << r.summary();
}

TEST(MeshCheck, InvertedTriangleIsReported) {
  Fixture f;
  std::swap(f.triangles().nodes[0], f.triangles().nodes[1]);
  const MeshCheckReport r = checkMesh(f.builder.model, f.mesh);
  EXPECT_TRUE(f.reports(r, {2, 1}, "triangle 1 is inverted")) << r.summary();
  EXPECT_NE(r.summary().find("surface 1: "), std::string::npos);
}

TEST(MeshCheck, MissingTriangleBreaksConformity) {
  Fixture f;
  f.triangles().nodes.resize(f.triangles().nodes.size() - 3);
  const MeshCheckReport r = checkMesh(f.builder.model, f.mesh);
  EXPECT_TRUE(f.reports(r, {2, 1}, "borders 1 triangles instead of 2") ||
              f.reports(r, {2, 1}, "of the boundary is not a triangle edge"))
      << r.summary();
}

TEST(MeshCheck, DuplicatedTriangleIsReported) {
  Fixture f;
  ElementBlock& t = f.triangles();
  t.nodes.insert(t.nodes.end(), {t.nodes[0], t.nodes[1], t.nodes[2]});
  const MeshCheckReport r = checkMesh(f.builder.model, f.mesh);
  EXPECT_TRUE(f.reports(r, {2, 1}, "triangles instead of")) << r.summary();
}

TEST(MeshCheck, NodeIndexOutOfRange) {
  Fixture f;
  f.triangles().nodes[4] = 100000;
  const MeshCheckReport r = checkMesh(f.builder.model, f.mesh);
  EXPECT_TRUE(f.reports(r, {2, 1}, "uses missing node 100001")) << r.summary();
}

TEST(MeshCheck, DuplicateNodesAreReported) {
  Fixture f;
  const NodeIndex copy = f.mesh.addNode(f.mesh.node(f.mesh.find({2, 1})->nodes[0]));
  f.mesh.entity({2, 1}).nodes.push_back(copy);
  f.mesh.entity({2, 1}).parametric.clear();
  const MeshCheckReport r = checkMesh(f.builder.model, f.mesh);
  EXPECT_TRUE(f.reports(r, {-1, 0}, "coincide")) << r.summary();
}

TEST(MeshCheck, NodeOffTheSurfaceIsReported) {
  Fixture f;
  const NodeIndex n = f.mesh.find({2, 1})->nodes[0];
  Vec3 p = f.mesh.node(n);
  p.z = 0.01;
  f.mesh.setNode(n, p);
  const MeshCheckReport r = checkMesh(f.builder.model, f.mesh);
  EXPECT_TRUE(f.reports(r, {2, 1}, "lies off the surface")) << r.summary();
}

TEST(MeshCheck, MovedPointNodeIsReported) {
  Fixture f;
  f.mesh.setNode(f.mesh.find({0, 3})->nodes[0], {1, 1, 1e-3});
  const MeshCheckReport r = checkMesh(f.builder.model, f.mesh);
  EXPECT_TRUE(f.reports(r, {0, 3}, "is not at the point")) << r.summary();
}

TEST(MeshCheck, BrokenCurveChainIsReported) {
  Fixture f;
  ElementBlock& lines = f.mesh.entity({1, 2}).block(ElementType::Line2);
  std::swap(lines.nodes[0], lines.nodes[1]);
  const MeshCheckReport r = checkMesh(f.builder.model, f.mesh);
  EXPECT_TRUE(f.reports(r, {1, 2}, "line elements")) << r.summary();
}

TEST(MeshCheck, NodeOwnedTwiceIsReported) {
  Fixture f;
  f.mesh.entity({1, 1}).nodes.push_back(f.mesh.find({0, 1})->nodes[0]);
  const MeshCheckReport r = checkMesh(f.builder.model, f.mesh);
  EXPECT_TRUE(f.reports(r, {1, 1}, "also belongs to another entity")) << r.summary();
}

TEST(MeshCheck, InvertedTetrahedronIsReported) {
  Fixture f;
  const NodeIndex apex = f.mesh.addNode({0.5, 0.5, 1});
  EntityMesh& volume = f.mesh.entity({3, 1});
  volume.nodes.push_back(apex);
  const auto t = f.triangles().element(0);
  volume.block(ElementType::Tet4).nodes = {t[0], t[2], t[1], apex, t[0], t[1], t[2], apex};
  const MeshCheckReport r = checkMesh(f.builder.model, f.mesh);
  EXPECT_TRUE(f.reports(r, {3, 1}, "tetrahedron 1 has a non-positive Jacobian")) << r.summary();
  EXPECT_FALSE(f.reports(r, {3, 1}, "tetrahedron 2 "));
}

// A tetrahedron flat to rounding (apex 1e-13 above its base, positive but of scaled Jacobian
// about 1e-13) is refused like an inverted one; one of ordinary height is not.
TEST(MeshCheck, TetrahedronFlatToRoundingIsReported) {
  for (const double height : {1e-13, 1e-3}) {
    Fixture f;
    const auto t = f.triangles().element(0);
    const Vec3 a = f.mesh.node(t[0]), b = f.mesh.node(t[1]), c = f.mesh.node(t[2]);
    const Vec3 centre = (a + b + c) / 3;
    const NodeIndex apex = f.mesh.addNode({centre.x, centre.y, height});
    EntityMesh& volume = f.mesh.entity({3, 1});
    volume.nodes.push_back(apex);
    volume.block(ElementType::Tet4).nodes = {t[0], t[1], t[2], apex};
    const MeshCheckReport r = checkVolumeElements(f.builder.model, f.mesh);
    EXPECT_EQ(f.reports(r, {3, 1}, "tetrahedron 1 has a non-positive Jacobian"), height < 1e-6)
        << height << ": " << r.summary();
  }
}

}  // namespace
}  // namespace geomesh
