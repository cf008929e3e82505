// Tests of the recombination options: the simple (greedy) algorithm, the minimum quadrangle
// quality, the topological clean-up passes and node repositioning; figures of the reference
// mesher on the same L-shaped plate in comments.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>

#include "mesh/checks/mesh_check.h"
#include "mesh/pipeline/generate.h"
#include "mesh/quads/recombine.h"
#include "mesh_measures.h"
#include "mesh_test_models.h"

namespace geomesh {
namespace {

using testing::PolygonModelBuilder;
using testing::QuietSink;
using testing::totalArea;

// The L-shaped plate of the golden scripts recomb_*.geo: area 3, size 0.08, recombined.
Model recombinedPlate() {
  PolygonModelBuilder b;
  b.surface({b.polygon({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, 0.08)});
  b.model.meshConstraints().recombinedSurfaces[1] = 45;
  return std::move(b.model);
}

struct Shape {
  std::size_t triangles = 0, quads = 0, nodes = 0;
  double minQuality = 1, meanQuality = 0;  // of the quadrangles, by quadAngleQuality
};

Shape shapeOf(const Mesh& mesh) {
  Shape s;
  s.nodes = mesh.nodeCount();
  const EntityMesh* em = mesh.find({2, 1});
  if (const ElementBlock* t = em->findBlock(ElementType::Triangle3)) s.triangles = t->size();
  if (const ElementBlock* q = em->findBlock(ElementType::Quad4)) {
    s.quads = q->size();
    for (std::size_t e = 0; e < q->size(); ++e) {
      const auto n = q->element(e);
      const double quality = quadAngleQuality(mesh.node(n[0]), mesh.node(n[1]), mesh.node(n[2]),
                                              mesh.node(n[3]), {0, 0, 1});
      s.minQuality = std::min(s.minQuality, quality);
      s.meanQuality += quality / static_cast<double>(q->size());
    }
  }
  return s;
}

Shape meshPlate(const MeshOptions& options, const Model& model = recombinedPlate()) {
  Mesh mesh;
  QuietSink log;
  generateMesh(model, options, 2, mesh, log);
  EXPECT_NEAR(totalArea(mesh), 3, 1e-9);
  const MeshCheckReport report = checkMesh(model, mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
  return shapeOf(mesh);
}

MeshOptions withAlgorithm(int algorithm) {
  MeshOptions options;
  options.recombinationAlgorithm = algorithm;
  return options;
}

// The reference's simple algorithm pairs greedily and leaves triangles: 512 quadrangles and
// 146 triangles here; no blossom matching completes it.
TEST(RecombineOptions, SimpleAlgorithmIsGreedyAndLeavesTriangles) {
  const Shape s = meshPlate(withAlgorithm(0));
  EXPECT_GE(s.quads, 343u);
  EXPECT_LE(s.quads, 768u);
  EXPECT_GE(s.triangles, 98u);
  EXPECT_LE(s.triangles, 219u);
}

// The reference's simple algorithm does not read the angle of Recombine Surface{..} = angle.
TEST(RecombineOptions, SimpleAlgorithmIgnoresTheRecombineAngle) {
  Model tight = recombinedPlate(), loose = recombinedPlate();
  tight.meshConstraints().recombinedSurfaces[1] = 10;
  loose.meshConstraints().recombinedSurfaces[1] = 89;
  const Shape a = meshPlate(withAlgorithm(0), tight), b = meshPlate(withAlgorithm(0), loose);
  EXPECT_EQ(a.quads, b.quads);
  EXPECT_EQ(a.triangles, b.triangles);
}

// Mesh.RecombineMinimumQuality by corner-angle quality: the reference keeps 483 quadrangles
// (340 triangles) at 0.7 and 103 (1100 triangles) at 0.9 with Blossom; 348 (474) and 14 (1142)
// with the simple algorithm.
TEST(RecombineOptions, MinimumQualityCutsPoorQuadranglesBackIntoTriangles) {
  struct Case {
    int algorithm;
    double minQuality;
    std::size_t quads, triangles;  // the reference's
  };
  for (const Case c : {Case{1, 0.7, 483, 340}, Case{1, 0.9, 103, 1100}, Case{0, 0.7, 348, 474},
                       Case{0, 0.9, 14, 1142}}) {
    MeshOptions options = withAlgorithm(c.algorithm);
    options.recombineMinQuality = c.minQuality;
    const Shape s = meshPlate(options);
    const auto near = [](std::size_t ours, std::size_t reference) {
      return ours * 3 >= reference * 2 && ours * 2 <= reference * 3;
    };
    EXPECT_TRUE(near(s.quads, c.quads)) << c.algorithm << " " << c.minQuality << ": " << s.quads;
    EXPECT_TRUE(near(s.triangles, c.triangles))
        << c.algorithm << " " << c.minQuality << ": " << s.triangles;
  }
}

TEST(RecombineOptions, SplitPoorQuadranglesKeepsTheGoodOnesAndTheArea) {
  Mesh mesh;
  for (Vec3 p :
       {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, 1, 0}, Vec3{0, 1, 0}, Vec3{2, 0, 0}, Vec3{3, 1, 0}})
    mesh.addNode(p);
  EntityMesh& em = mesh.entity({2, 1});
  // A unit square (quality 1) and a trapezoid with corners of 45 and 135 degrees (0.5).
  em.block(ElementType::Quad4).nodes = {0, 1, 2, 3, 1, 4, 5, 2};
  EXPECT_EQ(splitPoorQuadrangles(mesh, em, 0.4), 0u);
  EXPECT_EQ(splitPoorQuadrangles(mesh, em, 0.6), 1u);
  ASSERT_NE(em.findBlock(ElementType::Triangle3), nullptr);
  const ElementBlock& triangles = *em.findBlock(ElementType::Triangle3);
  EXPECT_EQ(triangles.size(), 2u);
  EXPECT_EQ(em.findBlock(ElementType::Quad4)->size(), 1u);
  double area = 0;
  for (std::size_t e = 0; e < triangles.size(); ++e) {
    const auto n = triangles.element(e);
    const Vec3 normal = cross(mesh.node(n[1]) - mesh.node(n[0]), mesh.node(n[2]) - mesh.node(n[0]));
    EXPECT_GT(normal.z, 0) << "triangle " << e;
    area += 0.5 * normal.z;
  }
  EXPECT_NEAR(area, 1.5, 1e-12);
}

// A node held by two quadrangles only goes; the two become the quadrangle around them.
TEST(RecombineOptions, TwoQuadNodeIsRemoved) {
  Mesh mesh;
  for (Vec3 p : {Vec3{0, 0, 0}, Vec3{2, 0, 0}, Vec3{2, 2, 0}, Vec3{0, 2, 0}, Vec3{1.2, 0.8, 0}})
    mesh.addNode(p);
  EntityMesh& em = mesh.entity({2, 1});
  em.nodes = {4};
  em.parametric = {1.2, 0.8};
  em.block(ElementType::Quad4).nodes = {4, 0, 1, 2, 4, 2, 3, 0};
  EXPECT_EQ(removeTwoQuadNodes(mesh, em), 1u);
  EXPECT_TRUE(em.nodes.empty());
  EXPECT_TRUE(em.parametric.empty());
  const ElementBlock& quads = *em.findBlock(ElementType::Quad4);
  ASSERT_EQ(quads.size(), 1u);
  EXPECT_GT(quadAngleQuality(mesh.node(quads.nodes[0]), mesh.node(quads.nodes[1]),
                             mesh.node(quads.nodes[2]), mesh.node(quads.nodes[3]), {0, 0, 1}),
            0.9);
}

// The clean-up passes remove nodes where too few quadrangles meet (the reference: 719 nodes
// without, 708 with) and keep the mesh valid.
TEST(RecombineOptions, TopologyPassesRemoveNodes) {
  MeshOptions without;
  without.recombineOptimizeTopology = 0;
  const Shape before = meshPlate(without), after = meshPlate({});
  EXPECT_LT(after.nodes, before.nodes);
  EXPECT_GT(after.nodes + 40, before.nodes);
  EXPECT_EQ(after.triangles, 0u);

  // Each pass on its own, on the mesh made without them.
  const Model model = recombinedPlate();
  Mesh mesh;
  QuietSink log;
  generateMesh(model, without, 2, mesh, log);
  EntityMesh& em = *mesh.findMutable({2, 1});
  const std::size_t removed =
      removeTwoQuadNodes(mesh, em) + removeDiamonds(*model.surface(1)->geometry, mesh, em);
  EXPECT_GT(removed, 0u);
  EXPECT_EQ(mesh.dropUnheldNodes(), removed);
  const MeshCheckReport report = checkMesh(model, mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
}

// Node repositioning smooths the recombined mesh (the reference's mean gamma of quadrangles,
// which is this corner-angle quality: 0.787 with, 0.643 without).
TEST(RecombineOptions, NodeRepositioningImprovesTheQuadrangles) {
  MeshOptions fixed;
  fixed.recombineNodeRepositioning = false;
  const Shape still = meshPlate(fixed), moved = meshPlate({});
  EXPECT_GT(moved.meanQuality, still.meanQuality + 0.08);
  EXPECT_GT(moved.meanQuality, 0.7);
  EXPECT_GT(still.meanQuality, 0.55);
}

}  // namespace
}  // namespace geomesh
