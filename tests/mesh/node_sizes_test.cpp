// Target sizes stored on the mesh, one per node: set by each dimension, read by the next.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "mesh/pipeline/generate.h"
#include "mesh_test_models.h"

namespace geomesh {
namespace {

class SilentSink final : public MessageSink {
 public:
  void info(std::string_view) override {}
  void warning(std::string_view) override {}
};

TEST(NodeSizes, StayInStepWithTheNodesOnceSet) {
  Mesh mesh;
  mesh.addNode({0, 0, 0});
  const NodeIndex b = mesh.addNode({1, 0, 0});
  EXPECT_TRUE(mesh.nodeSizes().empty());
  EXPECT_EQ(mesh.nodeSize(b), 0);
  mesh.setNodeSize(b, 0.5);
  ASSERT_EQ(mesh.nodeSizes().size(), 2u);
  EXPECT_EQ(mesh.nodeSize(0), 0);
  EXPECT_EQ(mesh.nodeSize(b), 0.5);
  const NodeIndex c = mesh.addNode({2, 0, 0});
  EXPECT_EQ(mesh.nodeSizes().size(), 3u);
  EXPECT_EQ(mesh.nodeSize(c), 0);
  mesh.clear();
  EXPECT_TRUE(mesh.nodeSizes().empty());
}

// Points get their mesh size, curve nodes the size their segments aim at (between the sizes
// of their ends), surface nodes the size extended from the boundary: all of them one.
TEST(NodeSizes, EveryMeshedNodeHasATargetSize) {
  testing::PolygonModelBuilder b;
  const int corner = b.point(0, 0, 0.05);
  std::vector<int> loop;
  int previous = corner;
  for (Vec2 c : {Vec2{1, 0}, Vec2{1, 1}, Vec2{0, 1}}) {
    const int next = b.point(c.u, c.v, 0.2);
    loop.push_back(b.line(previous, next));
    previous = next;
  }
  loop.push_back(b.line(previous, corner));
  b.surface({loop});
  Mesh mesh;
  SilentSink log;
  generateMesh(b.model, {}, 2, mesh, log);
  ASSERT_EQ(mesh.nodeSizes().size(), mesh.nodeCount());
  EXPECT_DOUBLE_EQ(mesh.nodeSize(mesh.find({0, corner})->nodes[0]), 0.05);
  EXPECT_DOUBLE_EQ(mesh.nodeSize(mesh.find({0, previous})->nodes[0]), 0.2);
  for (NodeIndex n = 0; n < mesh.nodeCount(); ++n) {
    EXPECT_GT(mesh.nodeSize(n), 0.04) << "node " << n;
    EXPECT_LT(mesh.nodeSize(n), 0.25) << "node " << n;
  }
  EXPECT_GT(mesh.find({2, 1})->nodes.size(), 10u);
}

}  // namespace
}  // namespace geomesh
