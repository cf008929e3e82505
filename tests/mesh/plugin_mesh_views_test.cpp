// Plugins on the session's mesh: ElementSize, AnalyseMeshQuality and NewView.
#include <gtest/gtest.h>

#include <cmath>

#include "kernel/messages.h"
#include "mesh/core/mesh.h"
#include "mesh/views/element_size.h"
#include "mesh/views/plugins.h"

namespace geomesh::post {
namespace {

struct MeshPluginsTest : ::testing::Test {
  ViewStore views;
  Mesh mesh;
  SilentSink log;
  PluginContext context{views, mesh, log};

  // An equilateral triangle of side a in z = 0 and a regular tetrahedron of edge a.
  void addRegularElements(double a) {
    const double h = a * std::sqrt(3.0) / 2;
    const NodeIndex p0 = mesh.addNode({0, 0, 0}), p1 = mesh.addNode({a, 0, 0}),
                    p2 = mesh.addNode({a / 2, h, 0});
    const NodeIndex apex = mesh.addNode({a / 2, h / 3, a * std::sqrt(2.0 / 3.0)});
    mesh.entity({2, 1}).block(ElementType::Triangle3).nodes = {p0, p1, p2};
    mesh.entity({3, 1}).block(ElementType::Tet4).nodes = {p0, p1, p2, apex};
  }
};

TEST(ElementSizeRule, RegularElementsMeasureTheirEdge) {
  const double a = 0.7;
  EXPECT_DOUBLE_EQ(equivalentElementSize(ElementFamily::Line, a), a);
  EXPECT_NEAR(equivalentElementSize(ElementFamily::Triangle, std::sqrt(3.0) / 4 * a * a), a, 1e-15);
  EXPECT_NEAR(equivalentElementSize(ElementFamily::Tet, a * a * a / (6 * std::sqrt(2.0))), a,
              1e-15);
  EXPECT_NEAR(equivalentElementSize(ElementFamily::Quad, a * a), a, 1e-15);
  EXPECT_NEAR(equivalentElementSize(ElementFamily::Hex, a * a * a), a, 1e-15);
}

TEST_F(MeshPluginsTest, ElementSizeOfRegularElementsIsTheirEdgeLength) {
  addRegularElements(1.5);
  ASSERT_EQ(runPlugin("ElementSize", {}, context), PluginOutcome::Ran);  // highest: 3
  ASSERT_EQ(runPlugin("ElementSize", {{{"Dimension", 2}}, {}}, context), PluginOutcome::Ran);
  const ElementList& tets = views.at(0).lists.at(0);
  const ElementList& triangles = views.at(1).lists.at(0);
  EXPECT_EQ(views.at(0).name, "ElementSize");
  ASSERT_EQ(tets.shape, ElementShape::Tetrahedron);
  ASSERT_EQ(triangles.shape, ElementShape::Triangle);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(tets.value(0, 0, i, 0), 1.5, 1e-12);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(triangles.value(0, 0, i, 0), 1.5, 1e-12);
}

TEST_F(MeshPluginsTest, ElementSizeWithoutMeshIsAnError) {
  EXPECT_THROW(runPlugin("ElementSize", {}, context), PluginError);
}

TEST_F(MeshPluginsTest, QualityOfRegularElementsIsOne) {
  addRegularElements(2.0);
  const PluginOptions options{{{"JacobianDeterminant", 1},
                               {"ICNMeasure", 1},
                               {"CreateView", 1},
                               {"DimensionOfElements", 4}},
                              {}};
  ASSERT_EQ(runPlugin("AnalyseMeshQuality", options, context), PluginOutcome::Ran);
  ASSERT_EQ(views.size(), 4u);
  EXPECT_EQ(views.at(0).name, "minJ/maxJ 2D");
  EXPECT_EQ(views.at(1).name, "ICN 2D");
  EXPECT_EQ(views.at(3).name, "ICN 3D");
  for (std::size_t v = 0; v < 4; ++v)
    EXPECT_NEAR(views.at(v).lists.at(0).value(0, 0, 0, 0), 1.0, 1e-12) << views.at(v).name;
}

TEST_F(MeshPluginsTest, IcnOfARightIsoscelesTriangleIsTheReferences) {
  const NodeIndex a = mesh.addNode({0, 0, 0}), b = mesh.addNode({1, 0, 0}),
                  c = mesh.addNode({0, 1, 0});
  mesh.entity({2, 1}).block(ElementType::Triangle3).nodes = {a, b, c};
  ASSERT_EQ(runPlugin("AnalyseMeshQuality", {{{"ICNMeasure", 1}, {"CreateView", 1}}, {}}, context),
            PluginOutcome::Ran);
  EXPECT_NEAR(views.at(0).lists.at(0).value(0, 0, 0, 0), std::sqrt(3.0) / 2, 1e-12);  // Gmsh 4.15
}

TEST_F(MeshPluginsTest, NewViewHoldsZeroAtEveryNode) {
  addRegularElements(1.0);
  ASSERT_EQ(runPlugin("NewView", {}, context), PluginOutcome::Ran);
  const View& view = views.at(0);
  EXPECT_EQ(view.name, "New view");
  ASSERT_TRUE(view.meshData.has_value());
  EXPECT_EQ(view.meshData->steps.at(0).tags.size(), 4u);
  EXPECT_EQ(view.lists.at(0).shape, ElementShape::Tetrahedron);
  EXPECT_EQ(view.maximum(), 0.0);
  EXPECT_THROW(runPlugin("NewView", {{{"NumComp", 2}}, {}}, context), PluginError);
}

}  // namespace
}  // namespace geomesh::post
