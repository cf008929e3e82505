// Plugins on analytic data: cuts, isosurfaces, integrals, formulas and skins of views.
#include <gtest/gtest.h>

#include <cmath>

#include "kernel/messages.h"
#include "mesh/core/mesh.h"
#include "mesh/views/plugins.h"
#include "plugin_fixtures.h"

namespace geomesh::post {
namespace {

using testing::addTetCube;
using testing::surfaceArea;

using testing::linearField;
using testing::nodeOf;

struct PluginsTest : ::testing::Test {
  ViewStore views;
  Mesh mesh;
  SilentSink log;
  PluginContext context{views, mesh, log, testing::compileWithMathExpression};

  View& field(int n = 2, double (*f)(Vec3) = linearField) {
    View& view = views.add("field");
    addTetCube(view, n, f);
    return view;
  }
  PluginOutcome run(const std::string& name, PluginOptions options) {
    return runPlugin(name, options, context);
  }
};

TEST_F(PluginsTest, CutPlaneInterpolatesTheLinearFieldAtTheCutPoints) {
  field();
  ASSERT_EQ(run("CutPlane", {{{"A", 1}, {"D", -0.3}}, {}}), PluginOutcome::Ran);
  ASSERT_EQ(views.size(), 2u);
  const View& cut = views.at(1);
  EXPECT_EQ(cut.name, "field_Levelset");
  EXPECT_NEAR(surfaceArea(cut), 1.0, 1e-12);
  std::size_t nodes = 0;
  for (const ElementList& list : cut.lists)
    for (std::size_t e = 0; e < list.size(); ++e)
      for (int i = 0; i < list.nodesPerElement; ++i, ++nodes) {
        const Vec3 p = nodeOf(list, e, i);
        EXPECT_NEAR(p.x, 0.3, 1e-12);
        EXPECT_NEAR(list.value(e, 0, i, 0), linearField(p), 1e-12);
      }
  EXPECT_GT(nodes, 0u);
}

TEST_F(PluginsTest, CutSphereCutsWhereTheInterpolatedLevelIsZero) {
  View& view = views.add("one");
  ElementList& tet = view.list(ElementShape::Tetrahedron, FieldKind::Scalar);
  tet.coordinates = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  tet.values = {0, 1, 2, 3};
  ASSERT_EQ(run("CutSphere", {{{"R", 0.5}}, {}}), PluginOutcome::Ran);
  // The level (|p|^2 - R^2) is -0.25 at the origin and 0.75 at the other corners: the cut
  // is a quarter of the way along each edge from the origin.
  const ElementList& cut = views.at(1).lists.at(0);
  ASSERT_EQ(cut.shape, ElementShape::Triangle);
  ASSERT_EQ(cut.size(), 1u);
  for (int i = 0; i < 3; ++i) {
    const Vec3 p = nodeOf(cut, 0, i);
    EXPECT_NEAR(p.x + p.y + p.z, 0.25, 1e-15);
    EXPECT_NEAR(cut.value(0, 0, i, 0), linearField(p), 1e-15);
  }
}

TEST_F(PluginsTest, IsosurfaceOfAPlaneThroughTheCubeHasUnitArea) {
  field(3, [](Vec3 p) { return p.x + p.y; });
  ASSERT_EQ(run("Isosurface", {{{"Value", 0.8}}, {}}), PluginOutcome::Ran);
  const View& iso = views.at(1);
  EXPECT_EQ(iso.name, "field_Levelset_0");
  EXPECT_NEAR(surfaceArea(iso), std::sqrt(2.0) * 0.8, 1e-12);  // the plane x + y = 0.8
  for (const ElementList& list : iso.lists)
    for (std::size_t e = 0; e < list.size(); ++e)
      for (int i = 0; i < list.nodesPerElement; ++i)
        EXPECT_NEAR(list.value(e, 0, i, 0), 0.8, 1e-12);
}

TEST_F(PluginsTest, IsosurfaceOfATriangleViewGivesLines) {
  View& view = views.add("square");
  ElementList& tri = view.list(ElementShape::Triangle, FieldKind::Scalar);
  tri.coordinates = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0};
  tri.values = {0, 1, 1, 0, 1, 0};  // x
  ASSERT_EQ(run("Isosurface", {{{"Value", 0.25}}, {}}), PluginOutcome::Ran);
  const ElementList& lines = views.at(1).lists.at(0);
  ASSERT_EQ(lines.shape, ElementShape::Line);
  double length = 0;
  for (std::size_t e = 0; e < lines.size(); ++e)
    length += distance(nodeOf(lines, e, 0), nodeOf(lines, e, 1));
  EXPECT_NEAR(length, 1.0, 1e-12);
}

TEST_F(PluginsTest, IntegrateOfOneAndOfXOverTheUnitCube) {
  field(2, [](Vec3) { return 1.0; });
  field(2, [](Vec3 p) { return p.x; });
  ASSERT_EQ(run("Integrate", {{{"View", 0}}, {}}), PluginOutcome::Ran);
  ASSERT_EQ(run("Integrate", {{{"View", 1}}, {}}), PluginOutcome::Ran);
  const ElementList& one = views.at(2).lists.at(0);
  const ElementList& x = views.at(3).lists.at(0);
  EXPECT_EQ(views.at(2).name, "field_Integrate");
  ASSERT_EQ(one.shape, ElementShape::Point);
  EXPECT_NEAR(one.value(0, 0, 0, 0), 1.0, 1e-14);
  EXPECT_NEAR(x.value(0, 0, 0, 0), 0.5, 1e-14);
  EXPECT_EQ(nodeOf(one, 0, 0), (Vec3{0.5, 0.5, 0.5}));
}

TEST_F(PluginsTest, IntegrateOverTheUnitSquareAndTheFluxOfAVector) {
  View& square = views.add("square");
  ElementList& tri = square.list(ElementShape::Triangle, FieldKind::Scalar);
  tri.coordinates = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0};
  tri.values = {0, 1, 1, 0, 1, 0};  // x
  View& flow = views.add("flow");
  ElementList& vec = flow.list(ElementShape::Triangle, FieldKind::Vector);
  vec.coordinates = tri.coordinates;
  for (int i = 0; i < 6; ++i)
    vec.values.insert(vec.values.end(), {0, 0, 2 + tri.values[std::size_t(i)]});
  ASSERT_EQ(run("Integrate", {{{"View", 0}}, {}}), PluginOutcome::Ran);
  ASSERT_EQ(run("Integrate", {{{"View", 1}}, {}}), PluginOutcome::Ran);
  EXPECT_NEAR(views.at(2).lists.at(0).value(0, 0, 0, 0), 0.5, 1e-15);
  EXPECT_NEAR(views.at(3).lists.at(0).value(0, 0, 0, 0), 2.5, 1e-15);  // flux of (0, 0, 2 + x)
}

TEST_F(PluginsTest, MathEvalEvaluatesAtEveryNode) {
  field();
  PluginOptions options;
  options.strings["Expression0"] = "v0*2+x";
  ASSERT_EQ(run("MathEval", options), PluginOutcome::Ran);
  const View& result = views.at(1);
  EXPECT_EQ(result.name, "field_MathEval");
  const ElementList& list = result.lists.at(0);
  ASSERT_EQ(list.size(), 48u);
  for (std::size_t e = 0; e < list.size(); ++e)
    for (int i = 0; i < 4; ++i) {
      const Vec3 p = nodeOf(list, e, i);
      EXPECT_DOUBLE_EQ(list.value(e, 0, i, 0), 2 * linearField(p) + p.x);
    }
}

TEST_F(PluginsTest, MathEvalWithThreeExpressionsMakesVectorsFromTheOtherView) {
  field();
  field(2, [](Vec3 p) { return p.z; });
  PluginOptions options{
      {{"View", 0}, {"OtherView", 1}},
      {{"Expression0", "w0"}, {"Expression1", "v0"}, {"Expression2", "Time + 1"}}};
  ASSERT_EQ(run("MathEval", options), PluginOutcome::Ran);
  const ElementList& list = views.at(2).lists.at(0);
  ASSERT_EQ(list.kind, FieldKind::Vector);
  const Vec3 p = nodeOf(list, 5, 2);
  EXPECT_DOUBLE_EQ(list.value(5, 0, 2, 0), p.z);
  EXPECT_DOUBLE_EQ(list.value(5, 0, 2, 1), linearField(p));
  EXPECT_DOUBLE_EQ(list.value(5, 0, 2, 2), 1.0);
}

TEST_F(PluginsTest, ModifyComponentsChangesTheViewInPlace) {
  field();
  ASSERT_EQ(run("ModifyComponents", {{}, {{"Expression0", "v0 - y"}}}), PluginOutcome::Ran);
  ASSERT_EQ(views.size(), 1u);
  const ElementList& list = views.at(0).lists.at(0);
  const Vec3 p = nodeOf(list, 7, 3);
  EXPECT_DOUBLE_EQ(list.value(7, 0, 3, 0), p.x + p.y + 3 * p.z);
}

TEST_F(PluginsTest, SkinOfACubeOfTetrahedraHasTwoTrianglesPerSquareOfItsFaces) {
  field(2);
  ASSERT_EQ(run("Skin", {}), PluginOutcome::Ran);
  const View& skin = views.at(1);
  EXPECT_EQ(skin.name, "field_Skin");
  ASSERT_EQ(skin.lists.size(), 1u);
  EXPECT_EQ(skin.lists[0].shape, ElementShape::Triangle);
  EXPECT_EQ(skin.lists[0].size(), 6u * 4u * 2u);
  EXPECT_NEAR(surfaceArea(skin), 6.0, 1e-12);
  const ElementList& list = skin.lists[0];
  EXPECT_DOUBLE_EQ(list.value(3, 0, 1, 0), linearField(nodeOf(list, 3, 1)));
}

TEST_F(PluginsTest, SkinOfTwoQuadranglesIsTheirSixOuterEdges) {
  View& view = views.add("quads");
  ElementList& quads = view.list(ElementShape::Quadrangle, FieldKind::Scalar);
  quads.coordinates = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 1, 0, 0, 2, 0, 0, 2, 1, 0, 1, 1, 0};
  quads.values.assign(8, 1.0);
  ASSERT_EQ(run("Skin", {}), PluginOutcome::Ran);
  EXPECT_EQ(views.at(1).lists.at(0).shape, ElementShape::Line);
  EXPECT_EQ(views.at(1).lists.at(0).size(), 6u);
}

TEST_F(PluginsTest, WarpMovesNodesByTheOtherViewsVectors) {
  View& view = field(1);
  View& shift = views.add("shift");
  ElementList& vec = shift.list(ElementShape::Tetrahedron, FieldKind::Vector);
  vec.coordinates = view.lists[0].coordinates;
  for (std::size_t k = 0; k < vec.coordinates.size() / 3; ++k)
    vec.values.insert(vec.values.end(), {0, 0, 1});
  const Vec3 before = nodeOf(view.lists[0], 2, 2);
  ASSERT_EQ(run("Warp", {{{"View", 0}, {"OtherView", 1}, {"Factor", 0.5}}, {}}),
            PluginOutcome::Ran);
  const Vec3 expected = before + Vec3{0, 0, 0.5};
  EXPECT_EQ(nodeOf(views.at(0).lists[0], 2, 2), expected);
}

TEST_F(PluginsTest, CutGridSamplesTheViewOnQuadrangles) {
  field();
  const PluginOptions options{{{"X0", 0.1},
                               {"Y0", 0.1},
                               {"Z0", 0.5},
                               {"X1", 0.9},
                               {"Y1", 0.1},
                               {"Z1", 0.5},
                               {"X2", 0.1},
                               {"Y2", 0.9},
                               {"Z2", 0.5},
                               {"NumPointsU", 3},
                               {"NumPointsV", 3}},
                              {}};
  ASSERT_EQ(run("CutGrid", options), PluginOutcome::Ran);
  EXPECT_EQ(views.at(1).name, "field_CutGrid");
  const ElementList& quads = views.at(1).lists.at(0);
  ASSERT_EQ(quads.shape, ElementShape::Quadrangle);
  ASSERT_EQ(quads.size(), 4u);
  for (std::size_t e = 0; e < 4; ++e)
    for (int i = 0; i < 4; ++i)
      EXPECT_NEAR(quads.value(e, 0, i, 0), linearField(nodeOf(quads, e, i)), 1e-12);
  EXPECT_EQ(nodeOf(quads, 3, 2), (Vec3{0.9, 0.9, 0.5}));
}

TEST_F(PluginsTest, MissingViewsAndBadOptionsNameThePluginOptionAndValue) {
  EXPECT_THROW(run("CutPlane", {}), PluginError);  // no view at all
  field();
  try {
    run("Integrate", {{{"View", 5}}, {}});
    FAIL() << "no error";
  } catch (const PluginError& error) {
    EXPECT_NE(std::string(error.what()).find("Plugin(Integrate)"), std::string::npos);
    EXPECT_NE(std::string(error.what()).find("View = 5"), std::string::npos);
  }
  EXPECT_THROW(run("MathEval", {{}, {{"Expression0", "v0 +* 2"}}}), PluginError);
  EXPECT_THROW(run("CutGrid", {{{"NumPointsU", 0}}, {}}), PluginError);
  EXPECT_EQ(run("Annotate", {}), PluginOutcome::DisplayOnly);
  EXPECT_EQ(run("NoSuchPlugin", {}), PluginOutcome::Unknown);
}

TEST_F(PluginsTest, FormulaPluginsNeedAnEvaluator) {
  field();
  PluginContext bare{views, mesh, log};
  EXPECT_THROW(runPlugin("MathEval", {}, bare), PluginError);
}

}  // namespace
}  // namespace geomesh::post
