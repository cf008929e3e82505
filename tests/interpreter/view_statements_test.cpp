// Views in scripts: records of the parsed format, options, queries, deletion, background mesh.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "script_runner.h"

namespace geomesh::testing {
namespace {

TEST(ViewStatements, RecordsBecomeElementListsWithTheirTimeSteps) {
  ScriptRun run;
  run.run(
      "View \"sizes\" {\n"
      "  ST(0,0,0, 1,0,0, 0,1,0){0.1, 0.2, 0.3, 1.1, 1.2, 1.3};\n"
      "  ST(1,0,0, 1,1,0, 0,1,0){0.2, 0.4, 0.3, 1.2, 1.4, 1.3};\n"
      "  VP(0.5,0.5,0){1,2,3};\n"
      "  SL2(0,0,0, 1,0,0, 0.5,0,0){1, 2, 3};\n"
      "  TIME{0, 0.5};\n"
      "  T2(10, 20, 0){\"title\"};\n"
      "  T3(0, 0, 1, 0){\"label\"};\n"
      "};\n");
  const post::ViewStore& views = run.session.views();
  ASSERT_EQ(views.size(), 1u);
  const post::View& view = views.at(0);
  EXPECT_EQ(view.name, "sizes");
  ASSERT_EQ(view.lists.size(), 3u);
  const post::ElementList& triangles = view.lists[0];
  EXPECT_EQ(triangles.shape, post::ElementShape::Triangle);
  EXPECT_EQ(triangles.size(), 2u);
  EXPECT_EQ(triangles.steps, 2);
  EXPECT_DOUBLE_EQ(triangles.value(1, 1, 1, 0), 1.4);
  EXPECT_EQ(view.lists[1].kind, post::FieldKind::Vector);
  EXPECT_EQ(view.lists[2].order, 2);
  EXPECT_EQ(view.lists[2].nodesPerElement, 3);
  EXPECT_EQ(view.times, (std::vector<double>{0, 0.5}));
  ASSERT_EQ(view.texts.size(), 2u);
  EXPECT_EQ(view.texts[0].text.front(), "title");
  EXPECT_EQ(view.texts[1].dimension, 3);
  EXPECT_EQ(view.stepCount(), 2);
}

TEST(ViewStatements, OptionsAreKeptAndQueriesReadTheData) {
  const std::string out = printed(
      "View \"a\" { SP(0,0,0){2, 5}; SP(1,0,0){-1, 3}; };\n"
      "View \"b\" { SL(0,0,0, 1,0,0){1, 1}; };\n"
      "n = PostProcessing.NbViews;\n"
      "View[n-1].Name = \"renamed\";\n"
      "View[0].RaiseZ = 1; View[0].RaiseZ += 0.5;\n"
      "Printf(\"%g %g %g %g %g\", n, View[0].Max, View[0].Min, View[0].NbTimeStep, "
      "View[0].RaiseZ);\n"
      "Printf(View[1].Name);\n");
  EXPECT_EQ(out, "2 5 -1 2 1.5\nrenamed\n");
}

TEST(ViewStatements, DeleteViewRenumbersTheFollowingOnes) {
  ScriptRun run;
  run.run(
      "View \"a\" { SP(0,0,0){1}; };\nView \"b\" { SP(0,0,0){2}; };\n"
      "Delete View[0];\nPrintf(\"%g %g\", PostProcessing.NbViews, View[0].Max);\n");
  EXPECT_EQ(run.out.str(), "1 2\n");
  EXPECT_EQ(run.session.views().at(0).name, "b");
}

TEST(ViewStatements, BackgroundMeshViewNamesTheView) {
  ScriptRun run;
  run.run(
      "View \"a\" { SP(0,0,0){1}; };\n"
      "View \"h\" { ST(0,0,0, 1,0,0, 0,1,0){0.1, 0.1, 0.1}; };\n"
      "Background Mesh View[1];\n");
  EXPECT_EQ(run.session.model().meshConstraints().backgroundView, 1);
}

TEST(ViewStatements, ErrorsAreLocated) {
  EXPECT_EQ(firstLineOf("View \"a\" {\n  ST(0,0,0, 1,0,0){1,2,3};\n};\n"),
            "test.geo:2:3: error: ST takes the coordinates of 3 nodes (9 values), not 6");
  EXPECT_EQ(firstLineOf("View \"a\" {\n  ST(0,0,0, 1,0,0, 0,1,0){1,2};\n};\n"),
            "test.geo:2:3: error: ST takes 3 values per time step, not 2");
  EXPECT_EQ(firstLineOf("View \"a\" {\n  SX(0,0,0){1};\n};\n"),
            "test.geo:2:3: error: 'SX' is not a view record (SP, VL, TT, ST2, T2, T3, TIME, ...)");
  EXPECT_EQ(firstLineOf("View \"a\" {\n  SP(0,0,0){1};\n  SP(1,0,0){1,2};\n};\n"),
            "test.geo:3:3: error: SP has 2 time steps where the view's earlier SP records have 1");
  EXPECT_EQ(firstLineOf("Background Mesh View[2];\n"),
            "test.geo:1:22: error: no view 2 (there is no view)");
  EXPECT_EQ(firstLineOf("View \"a\" { SP(0,0,0){1}; };\nx = View[3].Max;\n"),
            "test.geo:2:10: error: no view 3 (views are numbered 0 to 0)");
  EXPECT_EQ(firstLineOf("View \"a\" { SP(0,0,0){1}; };\nDelete View[1];\n"),
            "test.geo:2:13: error: no view 1 (views are numbered 0 to 0)");
}

TEST(ViewStatements, BadSizesAndMissingViewsAreLocated) {
  EXPECT_EQ(firstLineOf("View \"h\" { ST(0,0,0, 1,0,0, 0,1,0){0.1, -0.5, 0.1}; };\n"
                        "Background Mesh View[0];\n"),
            "test.geo:2:22: error: view 'h' holds the size -0.5 at (1, 0, 0): background sizes "
            "must be positive numbers");
  EXPECT_EQ(firstLineOf("View \"h\" { SP(0,0,0){1}; };\nField[1] = PostView;\n"
                        "Field[1].ViewIndex = 2;\n"),
            "test.geo:3:22: error: Field PostView.ViewIndex = 2: no view has index 2 (1 views "
            "defined so far)");
  EXPECT_EQ(firstLineOf("Field[1] = PostView;\nField[1].ViewTag = 4;\n"),
            "test.geo:2:20: error: Field PostView.ViewTag = 4: no view has tag 4 (0 views "
            "defined so far)");
}

TEST(ViewStatements, ViewBoundsAreReadable) {
  EXPECT_EQ(printed("View \"h\" { SL(0.5,-1,2, 3,4,0){1,1}; };\n"
                    "Printf(\"%g %g %g %g %g %g\", View[0].MinX, View[0].MinY, View[0].MinZ, "
                    "View[0].MaxX, View[0].MaxY, View[0].MaxZ);\n"),
            "0.5 -1 0 3 4 2\n");
}

// Save View then Merge: the parsed .pos file gives back every record, value and text.
TEST(ViewStatements, SavedPosFilesMergeBackUnchanged) {
  const auto dir = std::filesystem::temp_directory_path() / "geomesh-view-roundtrip";
  std::filesystem::create_directories(dir);
  const std::string file = (dir / "v.pos").string();
  ScriptRun run;
  run.run(
      "View \"data\" {\n"
      "  ST(0,0,0, 1,0,0, 0,1,0){0.1, 0.2, 1e-17, 1.5, 2.5, 3.5};\n"
      "  VL(0,0,0, 1,1,1){1,2,3, 4,5,6, 7,8,9, 10,11,12};\n"
      "  SS(0,0,0, 1,0,0, 0,1,0, 0,0,1){1,2,3,4, 5,6,7,8};\n"
      "  TIME{0, 0.25};\n"
      "  T2(5, 6, 0){\"first\", \"second\"};\n"
      "};\n"
      "Save View[0] \"" + file + "\";\n"
      "Merge \"" + file + "\";\n");
  const post::ViewStore& views = run.session.views();
  ASSERT_EQ(views.size(), 2u);
  const post::View& a = views.at(0);
  const post::View& b = views.at(1);
  EXPECT_EQ(b.name, "data");
  EXPECT_EQ(b.times, a.times);
  ASSERT_EQ(b.lists.size(), a.lists.size());
  for (std::size_t k = 0; k < a.lists.size(); ++k) {
    EXPECT_EQ(b.lists[k].shape, a.lists[k].shape);
    EXPECT_EQ(b.lists[k].kind, a.lists[k].kind);
    EXPECT_EQ(b.lists[k].steps, a.lists[k].steps);
    EXPECT_EQ(b.lists[k].coordinates, a.lists[k].coordinates);
    EXPECT_EQ(b.lists[k].values, a.lists[k].values);
  }
  ASSERT_EQ(b.texts.size(), 1u);
  EXPECT_EQ(b.texts[0].text, (std::vector<std::string>{"first", "second"}));
  std::filesystem::remove_all(dir);
}

// A view saved as .msh (its own nodes and elements, element-node data) merges back into an
// empty model as a mesh and a view with the same values at the same places.
TEST(ViewStatements, SavedMshFilesMergeBackWithTheirData) {
  const auto dir = std::filesystem::temp_directory_path() / "geomesh-view-msh-roundtrip";
  std::filesystem::create_directories(dir);
  const std::string file = (dir / "v.msh").string();
  {
    ScriptRun run;
    run.run("View \"h\" {\n  ST(0,0,0, 1,0,0, 0,1,0){1, 2, 3};\n"
            "  ST(1,0,0, 1,1,0, 0,1,0){2, 4, 3};\n};\n"
            "Save View[0] \"" + file + "\";\n");
  }
  ScriptRun run;
  run.run("Merge \"" + file + "\";\nPrintf(\"%g %g %g\", PostProcessing.NbViews, View[0].Min, "
          "View[0].Max);\n");
  EXPECT_EQ(run.out.str(), "1 1 4\n");
  const post::View& view = run.session.views().at(0);
  EXPECT_EQ(view.name, "h");
  ASSERT_EQ(view.elementCount(), 2u);
  // The value at node (1,1,0) is 4 wherever the element list holds it.
  bool found = false;
  for (const post::ElementList& list : view.lists)
    for (std::size_t n = 0; n < list.coordinates.size() / 3; ++n)
      if (list.coordinates[3 * n] == 1 && list.coordinates[3 * n + 1] == 1) {
        EXPECT_EQ(list.values[n], 4);
        found = true;
      }
  EXPECT_TRUE(found);
  std::filesystem::remove_all(dir);
}

TEST(ViewStatements, CombineJoinsElementsOrTimeStepsByName) {
  ScriptRun run;
  run.run(
      "View \"a\" { SP(0,0,0){1}; };\nView \"a\" { SP(1,0,0){2}; ST(0,0,0, 1,0,0, 0,1,0){1,1,1}; };\n"
      "View \"b\" { SP(1,0,0){2}; };\n"
      "Combine ElementsByViewName;\n"
      "View \"c\" { SL(0,0,0, 1,0,0){1,2}; TIME{0.5}; };\n"
      "View \"c\" { SL(0,0,0, 1,0,0){3,4}; TIME{1.5}; };\n"
      "Combine TimeStepsByViewName;\n");
  const post::ViewStore& views = run.session.views();
  ASSERT_EQ(views.size(), 3u);
  EXPECT_EQ(views.at(0).elementCount(), 3u);
  EXPECT_EQ(views.at(0).lists[0].coordinates, (std::vector<double>{0, 0, 0, 1, 0, 0}));
  const post::View& c = views.at(2);
  EXPECT_EQ(c.stepCount(), 2);
  EXPECT_EQ(c.lists[0].values, (std::vector<double>{1, 2, 3, 4}));
  EXPECT_EQ(c.times, (std::vector<double>{0.5, 1.5}));
}

// A view on the mesh's nodes changed in place keeps its node data in step: saved as .msh,
// it holds the new values.
TEST(ViewStatements, NodeDataFollowChangesInPlace) {
  ScriptRun run;
  run.run(
      "Point(1) = {0,0,0,0.3}; Point(2) = {1,0,0,0.3}; Point(3) = {1,1,0,0.3};\n"
      "Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,1};\n"
      "Curve Loop(1) = {1,2,3}; Plane Surface(1) = {1};\nMesh 2;\n"
      "Plugin(NewView).Run;\n"
      "Plugin(ModifyComponents).Expression0 = \"x + 2*y\";\nPlugin(ModifyComponents).Run;\n");
  const post::View& view = run.session.views().at(0);
  ASSERT_TRUE(view.meshData.has_value());
  const post::MeshData::Step& step = view.meshData->steps.at(0);
  ASSERT_EQ(step.tags.size(), run.session.mesh().nodeCount());
  for (std::size_t k = 0; k < step.tags.size(); ++k) {
    const Vec3 p = run.session.mesh().node(static_cast<NodeIndex>(step.tags[k] - 1));
    EXPECT_DOUBLE_EQ(step.values[k], p.x + 2 * p.y) << "node " << step.tags[k];
  }
}

// A name longer than the system takes is no file: a located error, never an escaped exception.
TEST(ViewStatements, OverlongFileNamesAreLocatedErrors) {
  const std::string name(5000, 'a');
  for (const std::string& script :
       {"Merge \"" + name + ".pos\";\n",
        "SetFactory(\"OpenCASCADE\");\nMerge \"" + name + ".step\";\n"}) {
    const std::string error = firstLineOf(script);
    EXPECT_EQ(error.rfind("test.geo:", 0), 0u) << error.substr(0, 80);
    EXPECT_NE(error.find("cannot open"), std::string::npos) << error.substr(0, 80);
  }
}

TEST(ViewStatements, ViewsOutliveNewModel) {
  ScriptRun run;
  run.run("View \"a\" { SP(0,0,0){1}; };\nNewModel;\nPoint(1) = {0,0,0};\n");
  EXPECT_EQ(run.session.views().size(), 1u);
}

TEST(ViewStatements, DisplayOnlyPluginsAndOptionsNeedNoWarning) {
  ScriptRun run;
  run.run(
      "View \"a\" { SP(0,0,0){1}; };\n"
      "View[0].ColorTable = {1, 2, 3};\nView.Light = 0;\n"
      "Plugin(Annotate).Text = \"title\";\nPlugin(Annotate).Run;\n");
  EXPECT_TRUE(run.log.warnings.empty()) << run.log.warnings.front();
}

}  // namespace
}  // namespace geomesh::testing
