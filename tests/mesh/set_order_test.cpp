// Tests of setOrder: node counts per order, shared edge and face nodes, nodes on the geometry,
// the convergence of a P2 disk's area, serendipity types, straight nodes, and going back to 1.
#include "mesh/high_order/set_order.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "mesh/checks/mesh_check.h"
#include "mesh/high_order/jacobian.h"
#include "mesh/pipeline/generate.h"
#include "mesh_test_models.h"

namespace geomesh {
namespace {

using testing::PolygonModelBuilder;

Model diskModel(double h) {
  PolygonModelBuilder b;
  b.surface({b.circle({0, 0}, 1.0, h)});
  return std::move(b.model);
}

Mesh firstOrderMesh(const Model& model, MeshOptions options = {}) {
  Mesh mesh;
  SilentSink log;
  options.elementOrder = 1;
  generateMesh(model, options, 2, mesh, log);
  return mesh;
}

void raise(const Model& model, Mesh& mesh, int order, MeshOptions options = {}) {
  SilentSink log;
  options.elementOrder = order;
  setOrder(model, options, mesh, log);
}

std::vector<Vec3> coordinates(const Mesh& mesh, std::span<const NodeIndex> nodes) {
  std::vector<Vec3> x;
  for (NodeIndex n : nodes) x.push_back(mesh.node(n));
  return x;
}

double surfaceMeasure(const Mesh& mesh, int tag) {
  double area = 0;
  for (const ElementBlock& b : mesh.find({2, tag})->blocks)
    for (std::size_t e = 0; e < b.size(); ++e)
      area += elementMeasure(b.type, coordinates(mesh, b.element(e)));
  return area;
}

// Edges of a triangle mesh: (3 triangles + boundary edges) / 2.
std::size_t edgeCount(std::size_t triangles, std::size_t boundaryEdges) {
  return (3 * triangles + boundaryEdges) / 2;
}

TEST(SetOrder, NodeCountsFollowTheOrder) {
  const Model model = diskModel(0.2);
  const Mesh linear = firstOrderMesh(model);
  const std::size_t v = linear.nodeCount(), t = linear.elementCount(2);
  const std::size_t e = edgeCount(t, linear.elementCount(1));
  for (int p = 2; p <= 4; ++p) {
    Mesh mesh = linear;
    raise(model, mesh, p);
    const std::size_t interior = (p - 1) * (p - 2) / 2;
    EXPECT_EQ(mesh.nodeCount(), v + (p - 1) * e + interior * t) << "order " << p;
    EXPECT_EQ(mesh.find({2, 1})->blocks[0].type, *elementTypeOf(ElementFamily::Triangle, p));
    EXPECT_EQ(mesh.find({1, 1})->blocks[0].type, *elementTypeOf(ElementFamily::Line, p));
    EXPECT_TRUE(checkMesh(model, mesh).ok()) << "order " << p;
  }
}

TEST(SetOrder, CurveNodesLieOnTheCircleAndAreSharedWithTheTriangles) {
  const Model model = diskModel(0.3);
  Mesh mesh = firstOrderMesh(model);
  raise(model, mesh, 3);
  const ElementBlock& lines = mesh.find({1, 1})->blocks[0];
  std::set<NodeIndex> curveNodes;
  for (std::size_t e = 0; e < lines.size(); ++e)
    for (NodeIndex n : lines.element(e)) {
      EXPECT_NEAR(norm(mesh.node(n)), 1.0, 1e-12);
      curveNodes.insert(n);
    }
  std::size_t onCurve = 0;
  const ElementBlock& triangles = mesh.find({2, 1})->blocks[0];
  for (NodeIndex n : triangles.nodes) onCurve += curveNodes.contains(n);
  // Each boundary node of order 3 (vertex or edge node) belongs to at least one triangle.
  std::set<NodeIndex> seen;
  for (NodeIndex n : triangles.nodes)
    if (curveNodes.contains(n)) seen.insert(n);
  EXPECT_EQ(seen.size(), curveNodes.size());
  EXPECT_GT(onCurve, 0u);
}

TEST(SetOrder, QuadraticDiskAreaConvergesAtLeastEightfoldPerHalving) {
  double previous = 0;
  double previousLinear = 0;
  for (const double h : {0.4, 0.2, 0.1}) {
    const Model model = diskModel(h);
    Mesh mesh = firstOrderMesh(model);
    const double linearError = std::abs(surfaceMeasure(mesh, 1) - std::numbers::pi);
    raise(model, mesh, 2);
    const double error = std::abs(surfaceMeasure(mesh, 1) - std::numbers::pi);
    EXPECT_LT(error, linearError / 10) << "h " << h;
    if (previous > 0) {
      EXPECT_GE(previous / error, 8.0) << "h " << h << ": " << previous << " -> " << error;
      EXPECT_GE(previousLinear / linearError, 3.0);
    }
    previous = error, previousLinear = linearError;
  }
}

TEST(SetOrder, StraightOptionPutsEdgeNodesAtMidpoints) {
  const Model model = diskModel(0.3);
  Mesh mesh = firstOrderMesh(model);
  MeshOptions options;
  options.secondOrderLinear = true;
  raise(model, mesh, 2, options);
  const ElementBlock& lines = mesh.find({1, 1})->blocks[0];
  ASSERT_EQ(lines.type, ElementType::Line3);
  for (std::size_t e = 0; e < lines.size(); ++e) {
    const auto n = lines.element(e);
    const Vec3 mid = (mesh.node(n[0]) + mesh.node(n[1])) / 2;
    EXPECT_NEAR(distance(mesh.node(n[2]), mid), 0, 1e-14);
  }
}

TEST(SetOrder, RecombinedSurfacesGetSerendipityOrCompleteQuadrangles) {
  PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {2, 0}, {2, 1}, {0, 1}}, 0.25)});
  MeshOptions options;
  options.recombineAll = true;
  const Mesh linear = firstOrderMesh(b.model, options);
  ASSERT_NE(linear.find({2, 1})->findBlock(ElementType::Quad4), nullptr);
  Mesh complete = linear, incomplete = linear;
  raise(b.model, complete, 2);
  options.secondOrderIncomplete = true;
  raise(b.model, incomplete, 2, options);
  EXPECT_NE(complete.find({2, 1})->findBlock(ElementType::Quad9), nullptr);
  EXPECT_NE(incomplete.find({2, 1})->findBlock(ElementType::Quad8), nullptr);
  EXPECT_EQ(complete.nodeCount() - incomplete.nodeCount(),
            complete.find({2, 1})->findBlock(ElementType::Quad9)->size());
  EXPECT_NEAR(surfaceMeasure(complete, 1), 2.0, 1e-12);
  EXPECT_NEAR(surfaceMeasure(incomplete, 1), 2.0, 1e-12);
  EXPECT_TRUE(checkMesh(b.model, incomplete).ok());
}

TEST(SetOrder, OrderOneGivesBackTheFirstOrderMesh) {
  const Model model = diskModel(0.25);
  const Mesh linear = firstOrderMesh(model);
  Mesh mesh = linear;
  raise(model, mesh, 4);
  raise(model, mesh, 1);
  EXPECT_EQ(mesh.nodeCount(), linear.nodeCount());
  EXPECT_EQ(mesh.find({2, 1})->blocks[0].type, ElementType::Triangle3);
  EXPECT_EQ(mesh.find({2, 1})->blocks[0].nodes, linear.find({2, 1})->blocks[0].nodes);
  EXPECT_EQ(mesh.find({1, 1})->parametric, linear.find({1, 1})->parametric);
  raise(model, mesh, 2);  // and up again from there
  EXPECT_EQ(mesh.find({2, 1})->blocks[0].type, ElementType::Triangle6);
}

TEST(SetOrder, CurvedDiskElementsAreValidAtEveryOrder) {
  const Model model = diskModel(0.5);  // coarse: strongly curved boundary triangles
  for (int p = 2; p <= 4; ++p) {
    Mesh mesh = firstOrderMesh(model);
    raise(model, mesh, p);
    const ElementBlock& triangles = mesh.find({2, 1})->blocks[0];
    for (std::size_t e = 0; e < triangles.size(); ++e)
      EXPECT_GT(jacobianRange(triangles.type, coordinates(mesh, triangles.element(e))).min, 0);
  }
}

TEST(SetOrder, OrdersOutsideOneToFourAreRefused) {
  EXPECT_EQ(unsupportedOrderReason(2), "");
  EXPECT_EQ(unsupportedOrderReason(5), "element order 5 is not supported (1 to 4)");
  EXPECT_NE(unsupportedOrderReason(0), "");
}

}  // namespace
}  // namespace geomesh
