// Tests of options set and read by scripts: old names, strings, colours, unknown options.
#include <gtest/gtest.h>

#include "script_runner.h"

namespace geomesh::testing {
namespace {

TEST(ScriptOptions, SetAndReadIncludingOldNames) {
  ScriptRun run;
  run.run("Mesh.CharacteristicLengthMax = 0.3;\nMesh.MeshSizeMin = 0.01;\n"
          "Geometry.Tolerance *= 2;\nMesh.Algorithm = 5;\n"
          "Printf(\"%g %g %g\", Mesh.MeshSizeMax, Mesh.CharacteristicLengthMin, Geometry.Tolerance);");
  EXPECT_EQ(run.out.str(), "0.3 0.01 2e-08\n");
  EXPECT_EQ(run.session.options().number("Mesh.Algorithm"), 5);
  EXPECT_EQ(run.session.meshOptions().sizeMax, 0.3);
}

TEST(ScriptOptions, GeometryToleranceReachesTheKernel) {
  ScriptRun run;
  run.run("Geometry.Tolerance = 1e-5;");
  EXPECT_EQ(run.session.factory().tolerance(), 1e-5);
  // SetNumber sets a parameter of that name, not the option (as in Gmsh).
  run.run("SetNumber(\"Geometry.Tolerance\", 1e-3);");
  EXPECT_EQ(run.session.factory().tolerance(), 1e-5);
  run.run("Geometry.Tolerance = 1e-3;");
  EXPECT_EQ(run.session.factory().tolerance(), 1e-3);
}

TEST(ScriptOptions, StringsAndColours) {
  ScriptRun run;
  run.run("Geometry.OCCTargetUnit = \"M\";\nGeneral.Color.Background = {255, 0, 0};\n"
          "Mesh.Color.Nodes = Red;\n");
  EXPECT_EQ(run.session.options().string("Geometry.OCCTargetUnit"), "M");
  EXPECT_EQ(run.session.options().number("General.Color.Background"), 255 * 65536);
}

// Colour names are X11's, one capitalized word per part, and case matters (as in Gmsh).
TEST(ScriptOptions, ColourNames) {
  ScriptRun run;
  run.run("Mesh.Color.Triangles = LightBlue;\nGeometry.Color.Points = Gray50;\n"
          "Mesh.Color.Lines = lightblue;\n");
  EXPECT_EQ(run.session.options().number("Mesh.Color.Triangles"), 173 * 65536 + 216 * 256 + 230);
  EXPECT_EQ(run.session.options().number("Geometry.Color.Points"), 127 * 65536 + 127 * 256 + 127);
  EXPECT_EQ(run.session.options().number("Mesh.Color.Lines"), 0);
  ASSERT_EQ(run.log.warnings.size(), 1u);
  EXPECT_EQ(run.log.warnings[0], "test.geo:3:20: warning: unknown colour 'lightblue'; ignored; "
                                 "did you mean 'LightBlue'?");
}

TEST(ScriptOptions, SettingAnUnknownOptionWarnsWithTheClosest) {
  ScriptRun run;
  run.run("Mesh.MeshSizeMn = 1;\nPrintf(\"on\");");
  EXPECT_EQ(run.out.str(), "on\n");
  ASSERT_EQ(run.log.warnings.size(), 1u);
  EXPECT_NE(run.log.warnings[0].find("test.geo:1:1:"), std::string::npos) << run.log.warnings[0];
  EXPECT_NE(run.log.warnings[0].find("did you mean 'Mesh.MeshSizeMin'?"), std::string::npos)
      << run.log.warnings[0];
  EXPECT_EQ(run.session.options().number("Mesh.MeshSizeMin"), 0);
}

TEST(ScriptOptions, ReadingAnUnknownOptionIsAnError) {
  EXPECT_EQ(firstLineOf("x = Mesh.Algoritm;"),
            "test.geo:1:5: error: unknown option 'Mesh.Algoritm'; did you mean 'Mesh.Algorithm'?");
}

TEST(ScriptOptions, WrongValueTypes) {
  EXPECT_EQ(firstLineOf("Mesh.Algorithm = \"x\";"),
            "test.geo:1:18: error: option 'Mesh.Algorithm' takes a number");
  EXPECT_EQ(firstLineOf("Geometry.OCCTargetUnit = 3;"),
            "test.geo:1:26: error: option 'Geometry.OCCTargetUnit' takes a string");
}

TEST(ScriptOptions, PostProcessingOptionsAreIgnoredQuietly) {
  ScriptRun run;
  run.run("View \"v\" { SP(0,0,0){1}; };\nView[0].Visible = 0;\nPrint.Width = 100;\n"
          "View.Light = 0;\n");
  EXPECT_TRUE(run.log.warnings.empty());
  EXPECT_EQ(run.session.views().at(0).numbers.at("Visible"), 0);
}

TEST(ScriptOptions, OptionsOfAMissingViewWarn) {
  ScriptRun run;
  run.run("View[0].Visible = 0;\n");
  ASSERT_EQ(run.log.warnings.size(), 1u);
  EXPECT_EQ(run.log.warnings[0], "test.geo:1:1: warning: no view 0 (there is no view); option "
                                 "'View.Visible' ignored");
}

TEST(ScriptOptions, FieldOptionsWarn) {
  ScriptRun run;
  run.run("Field[1].PointsList = {1};\n");
  EXPECT_EQ(run.log.warnings.size(), 1u);
}

}  // namespace
}  // namespace geomesh::testing
