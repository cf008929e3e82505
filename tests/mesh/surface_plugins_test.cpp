// Plugins Curvature and VertexNormals on a surface mesh or a merged triangulation, and the
// triangulation of a mesh's surface elements they work on.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "kernel/messages.h"
#include "mesh/core/mesh.h"
#include "mesh/discrete/mesh_triangles.h"
#include "mesh/views/plugins.h"

namespace geomesh::post {
namespace {

class CollectingSink final : public MessageSink {
 public:
  void info(std::string_view) override {}
  void warning(std::string_view m) override { warnings.emplace_back(m); }
  std::vector<std::string> warnings;
};

// A sphere of radius r: the octahedron's faces cut n x n, pushed onto the sphere; the
// triangles of the upper half (z > 0) on surface 1, the others on surface 2,
// nodes shared. With `inwards`, every triangle runs the other way.
void addSphere(Mesh& mesh, double r, int n, bool inwards = false) {
  std::map<std::array<long, 3>, NodeIndex> nodes;
  auto node = [&](Vec3 p) {
    const std::array<long, 3> key{std::lround(p.x * 4 * n), std::lround(p.y * 4 * n),
                                  std::lround(p.z * 4 * n)};
    const auto [it, added] = nodes.try_emplace(key, NodeIndex(mesh.nodeCount()));
    if (added) mesh.addNode(r * normalized(p));
    return it->second;
  };
  for (int sx : {-1, 1})
    for (int sy : {-1, 1})
      for (int sz : {-1, 1}) {
        const Vec3 a{double(sx), 0, 0}, b{0, double(sy), 0}, c{0, 0, double(sz)};
        const bool outward = sx * sy * sz > 0;  // a, b, c counter-clockwise seen from outside
        auto at = [&](int i, int j) {
          return a + (double(i) / n) * (b - a) + (double(j) / n) * (c - a);
        };
        for (int i = 0; i < n; ++i)
          for (int j = 0; i + j < n; ++j) {
            std::vector<std::array<Vec3, 3>> tris = {{at(i, j), at(i + 1, j), at(i, j + 1)}};
            if (i + j + 1 < n) tris.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
            for (auto& t : tris) {
              if (outward == inwards) std::swap(t[1], t[2]);
              const int surface = sz > 0 ? 1 : 2;
              ElementBlock& block = mesh.entity({2, surface}).block(ElementType::Triangle3);
              for (const Vec3& p : t) block.nodes.push_back(node(p));
            }
          }
      }
}

// Every value of a view's triangle list, and the node each belongs to.
struct ViewValues {
  std::vector<Vec3> points;
  std::vector<double> values;
};
ViewValues valuesOf(const View& view, FieldKind kind) {
  ViewValues v;
  for (const ElementList& list : view.lists) {
    if (list.size() == 0) continue;
    EXPECT_EQ(list.shape, ElementShape::Triangle);
    EXPECT_EQ(list.kind, kind);
    for (std::size_t k = 0; k < list.coordinates.size(); k += 3)
      v.points.push_back({list.coordinates[k], list.coordinates[k + 1], list.coordinates[k + 2]});
    v.values = list.values;
  }
  return v;
}

struct SurfacePlugins : ::testing::Test {
  ViewStore views;
  Mesh mesh;
  CollectingSink log;
  PluginContext context{views, mesh, log};
};

TEST_F(SurfacePlugins, MeanCurvatureOfASphereIsOneOverItsRadiusAtEveryNode) {
  addSphere(mesh, 2.0, 12);
  ASSERT_EQ(runPlugin("Curvature", {}, context), PluginOutcome::Ran);
  ASSERT_EQ(views.size(), 1u);
  EXPECT_EQ(views.at(0).name, "Mean curvature");
  const ViewValues v = valuesOf(views.at(0), FieldKind::Scalar);
  ASSERT_EQ(v.values.size(), 3 * mesh.elementCount(2));
  for (double h : v.values) EXPECT_NEAR(h, 0.5, 0.03);
  // Nodes shared by the two surfaces have one value, whichever triangle lists them.
  std::map<std::array<double, 3>, double> byNode;
  for (std::size_t k = 0; k < v.points.size(); ++k) {
    const auto [it, added] = byNode.try_emplace({v.points[k].x, v.points[k].y, v.points[k].z},
                                                v.values[k]);
    EXPECT_EQ(it->second, v.values[k]);
  }
  EXPECT_EQ(byNode.size(), mesh.nodeCount());
}

TEST_F(SurfacePlugins, CurvatureSignDoesNotDependOnHowTheTrianglesRun) {
  addSphere(mesh, 2.0, 8, true);
  ASSERT_EQ(runPlugin("Curvature", {}, context), PluginOutcome::Ran);
  const ViewValues v = valuesOf(views.at(0), FieldKind::Scalar);
  for (double h : v.values) EXPECT_NEAR(h, 0.5, 0.05);
}

TEST_F(SurfacePlugins, GaussianAndLargestPrincipalCurvatures) {
  addSphere(mesh, 2.0, 12);
  ASSERT_EQ(runPlugin("Curvature", {{{"Type", 1}}, {}}, context), PluginOutcome::Ran);
  ASSERT_EQ(runPlugin("Curvature", {{{"Type", 2}, {"View", -1}}, {}}, context),
            PluginOutcome::Ran);
  EXPECT_EQ(views.at(0).name, "Gaussian curvature");
  EXPECT_EQ(views.at(1).name, "Largest principal curvature");
  for (double k : valuesOf(views.at(0), FieldKind::Scalar).values) EXPECT_NEAR(k, 0.25, 0.03);
  for (double k : valuesOf(views.at(1), FieldKind::Scalar).values) EXPECT_NEAR(k, 0.5, 0.06);
}

TEST_F(SurfacePlugins, AnUnknownTypeIsAnErrorNamingIt) {
  addSphere(mesh, 1.0, 4);
  try {
    runPlugin("Curvature", {{{"Type", 3}}, {}}, context);
    FAIL() << "no error";
  } catch (const PluginError& e) {
    EXPECT_EQ(std::string(e.what()),
              "Plugin(Curvature): Type = 3: not 0 (mean), 1 (Gaussian) or 2 (largest principal "
              "curvature)");
  }
  EXPECT_EQ(views.size(), 0u);
}

TEST_F(SurfacePlugins, VertexNormalsAreUnitAndPointOutOfTheSphere) {
  addSphere(mesh, 2.0, 10, true);
  ASSERT_EQ(runPlugin("VertexNormals", {}, context), PluginOutcome::Ran);
  EXPECT_EQ(views.at(0).name, "Vertex normals");
  const ViewValues v = valuesOf(views.at(0), FieldKind::Vector);
  ASSERT_EQ(v.values.size(), 3 * v.points.size());
  for (std::size_t k = 0; k < v.points.size(); ++k) {
    const Vec3 n{v.values[3 * k], v.values[3 * k + 1], v.values[3 * k + 2]};
    EXPECT_NEAR(norm(n), 1, 1e-12);
    EXPECT_GT(dot(n, normalized(v.points[k])), 0.99);
  }
}

TEST_F(SurfacePlugins, WithoutSurfaceMeshTheMergedTrianglesAreUsed) {
  Mesh sphere;
  addSphere(sphere, 4.0, 10);
  const Triangulation merged = meshTriangles(sphere).triangulation;
  context.mergedTriangles = [&] { return &merged; };
  mesh.addNode({0, 0, 0});  // a mesh without surface elements
  ASSERT_EQ(runPlugin("Curvature", {}, context), PluginOutcome::Ran);
  const ViewValues v = valuesOf(views.at(0), FieldKind::Scalar);
  EXPECT_EQ(v.values.size(), 3 * merged.triangles.size());
  for (double h : v.values) EXPECT_NEAR(h, 0.25, 0.02);
}

TEST_F(SurfacePlugins, WithNeitherThereIsAWarningAndNoView) {
  context.mergedTriangles = [] { return static_cast<const Triangulation*>(nullptr); };
  EXPECT_EQ(runPlugin("Curvature", {}, context), PluginOutcome::Ran);
  EXPECT_EQ(runPlugin("VertexNormals", {}, context), PluginOutcome::Ran);
  EXPECT_EQ(views.size(), 0u);
  ASSERT_EQ(log.warnings.size(), 2u);
  EXPECT_EQ(log.warnings[0],
            "Plugin(Curvature): there is no surface mesh and no merged triangulation; nothing "
            "done");
  EXPECT_EQ(log.warnings[1].substr(0, 23), "Plugin(VertexNormals): ");
}

TEST(MeshTriangles, SurfacesShareTheirNodesAndQuadranglesAreSplit) {
  Mesh mesh;
  for (Vec3 p : {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, 1, 0}, Vec3{0, 1, 0}, Vec3{2, 0, 0},
                 Vec3{5, 5, 5}, Vec3{6, 5, 5}, Vec3{5, 6, 5}})
    mesh.addNode(p);
  mesh.entity({2, 1}).block(ElementType::Quad4).nodes = {0, 1, 2, 3};
  mesh.entity({2, 2}).block(ElementType::Triangle3).nodes = {1, 4, 2};
  mesh.entity({2, 3}).block(ElementType::Triangle3).nodes = {5, 6, 7};
  mesh.entity({1, 1}).block(ElementType::Line2).nodes = {0, 1};
  const MeshTriangles m = meshTriangles(mesh);
  EXPECT_EQ(m.triangulation.triangles.size(), 4u);
  EXPECT_EQ(m.triangulation.points.size(), 8u);
  EXPECT_EQ(m.node.size(), 8u);
  for (std::size_t v = 0; v < m.node.size(); ++v)
    EXPECT_EQ(m.triangulation.points[v], mesh.node(m.node[v]));
  const std::vector<Triangulation> parts = connectedParts(m.triangulation);
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0].triangles.size(), 3u);
  EXPECT_EQ(parts[0].points.size(), 5u);
  EXPECT_EQ(parts[1].triangles.size(), 1u);
  EXPECT_EQ(parts[1].points.size(), 3u);
}

}  // namespace
}  // namespace geomesh::post
