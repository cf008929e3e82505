// OpenCASCADE statements in scripts: primitives, Booleans (as statements and as values),
// lofts, fillets, CAD files; their errors point at the statement and give the reason.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "kernel/occ/occ_factory.h"
#include "script_runner.h"
#include "tests/scratch.h"

namespace geomesh::testing {
namespace {

const std::string kOcc = "SetFactory(\"OpenCASCADE\");\n";

TEST(OccStatements, PrimitivesTakeTheirOptionalArguments) {
  ScriptRun run;
  run.run(kOcc +
          "Sphere(1) = {0, 0, 0, 1, 0, Pi/2, Pi};\nCylinder(2) = {3, 0, 0, 0, 0, 1, 0.5, Pi};\n"
          "Cone(3) = {6, 0, 0, 0, 0, 1, 1, 0};\nTorus(4) = {9, 0, 0, 1, 0.2};\n"
          "Wedge(5) = {12, 0, 0, 1, 1, 1, 0.5};\nRectangle(100) = {0, 5, 0, 2, 1, 0.2};\n"
          "Disk(101) = {5, 5, 0, 1, 0.5};\nDisk(102) = {8, 5, 0, 1};\n"
          "Circle(200) = {0, 9, 0, 1, 0, Pi/2};\nEllipse(201) = {3, 9, 0, 2, 1};\n"
          "v() = Volume{:}; s() = Surface{:};\nPrintf(\"%g %g\", #v(), s(#s() - 1));\n");
  EXPECT_TRUE(run.log.warnings.empty()) << run.log.warnings.front();
  EXPECT_EQ(run.out.str(), "5 102\n");
}

TEST(OccStatements, BooleansAsStatementsAndValues) {
  EXPECT_EQ(printed(kOcc +
                    "Box(1) = {0, 0, 0, 1, 1, 1};\nBox(2) = {0.5, 0.5, 0.5, 1, 1, 1};\n"
                    "BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };\n"
                    "v() = Volume{:};\nPrintf(\"%g %g\", #v(), v(0));\n"
                    "Box(4) = {5, 0, 0, 1, 1, 1};\nSphere(5) = {5.5, 0.5, 1, 0.3};\n"
                    "r() = BooleanFragments{ Volume{4}; Delete; }{ Volume{5}; Delete; };\n"
                    "Printf(\"%g %g %g %g\", #r(), r(0), r(1), r(2));\n"
                    "BooleanUnion{ Volume{r(0)}; Delete; }{ Volume{r(1)}; Delete; }\n"
                    "v() = Volume{:};\nPrintf(\"%g\", #v());\n"),
            "1 3\n3 4 5 6\n3\n");
}

// An empty tool block `{}`, as the reference takes it: fragments of the objects alone (the
// usual way to glue many volumes), tagged or not; the other operations fail without a tool.
TEST(OccStatements, BooleansWithAnEmptyToolBlock) {
  const std::string boxes = "Box(1) = {0, 0, 0, 1, 1, 1};\nBox(2) = {0.5, 0, 0, 1, 1, 1};\n"
                            "Box(3) = {3, 0, 0, 1, 1, 1};\n";
  const std::string list = "For i In {0:#r()-1}\n  Printf(\"%g\", r(i));\nEndFor\n";
  EXPECT_EQ(printed(kOcc + boxes + "r() = BooleanFragments{ Volume{1, 2, 3}; Delete; }{};\n" +
                    list),
            "4\n5\n6\n3\n");
  EXPECT_EQ(printed(kOcc + boxes + "BooleanFragments{ Volume{1:3}; Delete; }{ }\n"
                                   "r() = Volume{:};\n" + list),
            "3\n4\n5\n6\n");
  EXPECT_EQ(printed(kOcc + boxes + "Box(4) = {3, 0, 0, 1, 1, 1};\n"
                                   "BooleanFragments(10) = { Volume{3, 4}; Delete; }{};\n"
                                   "r() = Volume{:};\n" + list),
            "1\n2\n10\n");
  for (const std::string word : {"BooleanUnion", "BooleanDifference", "BooleanIntersection"}) {
    EXPECT_EQ(firstLineOf(kOcc + boxes + word + "{ Volume{1, 2}; Delete; }{}\n"),
              "test.geo:5:1: error: " + word + ": no tool to operate with");
    EXPECT_EQ(firstLineOf(kOcc + boxes + "r() = " + word + "{ Volume{1, 2}; Delete; }{};\n"),
              "test.geo:5:7: error: " + word + ": no tool to operate with");
    EXPECT_EQ(firstLineOf(kOcc + boxes + word + "(7) = { Volume{1, 2}; Delete; }{};\n"),
              "test.geo:5:1: error: " + word + ": no tool to operate with");
  }
  EXPECT_EQ(firstLineOf(kOcc + boxes + "BooleanFragments(10) = { Volume{1, 2}; Delete; }{};\n")
                .rfind("test.geo:5:1: error: BooleanFragments 10: its result has 3 Volume", 0),
            0u);
}

// As the reference: nothing done, nothing deleted and an empty result for a Boolean without
// objects, or for fragments of a single shape; geomesh warns of it.
TEST(OccStatements, BooleansWithNothingToDoAreWarnedOf) {
  const std::string boxes = "Box(1) = {0, 0, 0, 1, 1, 1};\nBox(2) = {0.5, 0, 0, 1, 1, 1};\n";
  ScriptRun run;
  run.run(kOcc + boxes +
          "r() = BooleanFragments{ Volume{1}; Delete; }{};\n"
          "s() = BooleanDifference{}{ Volume{2}; Delete; };\n"
          "BooleanUnion{ Volume{r()}; }{}\n"
          "v() = Volume{:};\nPrintf(\"%g %g %g %g %g\", #r(), #s(), #v(), v(0), v(1));\n");
  EXPECT_EQ(run.out.str(), "0 0 2 1 2\n");
  EXPECT_EQ(run.log.warnings,
            (std::vector<std::string>{
                "test.geo:4:7: warning: BooleanFragments of a single shape: nothing done",
                "test.geo:5:7: warning: BooleanDifference has no object to operate on: nothing "
                "done",
                "test.geo:6:1: warning: BooleanUnion has no object to operate on: nothing done"}));
}

// Geometry.OCCBooleanPreserveNumbering = 0: the result takes a new tag; Geometry.OCCUnionUnify
// (OCCBooleanSimplify) = 0: a union keeps the faces of its arguments; as the reference.
TEST(OccStatements, BooleanOptions) {
  const std::string boxes = "Box(1) = {0, 0, 0, 1, 1, 1};\nBox(2) = {5, 0, 0, 1, 1, 1};\n"
                            "Box(3) = {5.5, 0.5, 0.5, 1, 1, 1};\nBox(4) = {10, 0, 0, 1, 1, 1};\n";
  EXPECT_EQ(printed(kOcc + "Geometry.OCCBooleanPreserveNumbering = 0;\n" + boxes +
                    "r() = BooleanDifference{ Volume{2}; Delete; }{ Volume{3}; Delete; };\n"
                    "Printf(\"%g\", r(0));\n"),
            "5\n");
  const std::string three = "Box(1) = {0, 0, 0, 1, 1, 1};\nBox(2) = {1, 0, 0, 1, 1, 1};\n"
                            "Box(3) = {0.5, 0.5, 0.5, 1, 1, 1};\n"
                            "BooleanUnion{ Volume{1}; Delete; }{ Volume{2, 3}; Delete; }\n"
                            "s() = Surface{:};\nPrintf(\"%g\", #s());\n";
  EXPECT_EQ(printed(kOcc + three), "12\n");
  EXPECT_EQ(printed(kOcc + "Geometry.OCCUnionUnify = 0;\n" + three), "16\n");
}

TEST(OccStatements, LoftsFilletsAndWires) {
  ScriptRun run;
  run.run(kOcc +
          "Circle(1) = {0, 0, 0, 0.5};\nCurve Loop(1) = 1;\nCircle(2) = {0, 0, 1, 0.3};\n"
          "Curve Loop(2) = 2;\nThruSections(1) = {1, 2};\n"
          "Circle(11) = {3, 0, 0, 0.5};\nWire(11) = {11};\nCircle(12) = {3, 0, 1, 0.3};\n"
          "Wire(12) = {12};\nRuled ThruSections(11) = {11, 12};\n"
          "Box(20) = {6, 0, 0, 1, 1, 1};\nf() = Boundary{Volume{20};};\n"
          "e() = Boundary{Surface{f(0)};};\nr() = Fillet{20}{e(0)}{0.1};\n"
          "Chamfer{r(0)}{e(2)}{f(0)}{0.05}\n"
          "v() = Volume{:};\nPrintf(\"%g %g %g %g\", #v(), v(0), v(1), r(0));\n");
  EXPECT_TRUE(run.log.warnings.empty()) << run.log.warnings.front();
  EXPECT_EQ(run.out.str(), "3 1 11 12\n");  // as the reference numbers them
}

TEST(OccStatements, ExtrudeAlongAWire) {
  ScriptRun run;
  run.run(kOcc + "Point(1) = {0, 0, 0};\nPoint(2) = {0, 0, 2};\nLine(1) = {1, 2};\n"
                 "Wire(1) = {1};\nDisk(1) = {0, 0, 0, 0.5};\n"
                 "Extrude { Surface{1}; } Using Wire {1}\nv() = Volume{:};\n"
                 "Printf(\"%g %g\", #v(), v(0));\n");
  EXPECT_TRUE(run.log.warnings.empty()) << run.log.warnings.front();
  EXPECT_EQ(run.out.str(), "1 1\n");
}

// Beyond the reference, which renumbers silently: a physical group naming an entity a Boolean
// replaced gets a warning at the Boolean, and each replacement is logged.
TEST(OccStatements, PhysicalGroupsOfReplacedEntitiesAreWarnedOf) {
  ScriptRun run;
  run.run(kOcc + "Box(1) = {0, 0, 0, 1, 1, 1};\nBox(2) = {0.5, 0.5, 0.5, 1, 1, 1};\n"
                 "Box(5) = {5, 0, 0, 1, 1, 1};\nPhysical Volume(\"block\", 7) = {1, 5};\n"
                 "BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }\n"
                 "Box(9) = {9, 0, 0, 1, 1, 1};\nPhysical Volume(8) = {9};\n"
                 "BooleanDifference{ Volume{9}; Delete; }{ Volume{6}; Delete; }\n");
  ASSERT_EQ(run.log.warnings.size(), 1u);
  EXPECT_EQ(run.log.warnings[0],
            "test.geo:6:1: warning: Physical Volume 7 (\"block\") names Volume 1, which "
            "BooleanFragments replaced by Volume 6, Volume 7");
  ASSERT_GE(run.log.infos.size(), 2u);
  EXPECT_NE(std::find(run.log.infos.begin(), run.log.infos.end(),
                      "BooleanFragments (test.geo:6): Volume 2 -> Volume 7, Volume 8"),
            run.log.infos.end());
  // Volume 9 keeps its tag through the difference: nothing to warn of.
  EXPECT_NE(std::find(run.log.infos.begin(), run.log.infos.end(),
                      "BooleanDifference (test.geo:9): Volume 6 -> nothing"),
            run.log.infos.end());
}

TEST(OccStatements, ShapeFromFileAndMerge) {
  const std::filesystem::path part = scratch::path("occ-statements-part.brep");
  OccFactory maker;
  maker.addBox(1, {0, 0, 0}, {1, 2, 3});
  maker.exportShapes(part.string());
  EXPECT_EQ(printed(kOcc + "Box(1) = {5, 0, 0, 1, 1, 1};\nv() = ShapeFromFile(\"" +
                    part.string() + "\");\nb() = BoundingBox Volume{v(0)};\n"
                    "Printf(\"%g %g %.3g\", #v(), v(0), b(5));\n"),
            "1 2 3\n");
  ScriptRun run;  // Merge reads into the OpenCASCADE model, whichever factory is selected
  run.run("Point(100) = {9, 9, 9};\nMerge \"" + part.string() + "\";\n");
  EXPECT_TRUE(run.log.warnings.empty()) << run.log.warnings.front();
  run.session.synchronize();
  EXPECT_EQ(run.session.model().volumes().size(), 1u);
  EXPECT_EQ(run.session.model().points().size(), 9u);
  std::filesystem::remove(part);
}

TEST(OccStatements, SaveWritesWhatShapeFromFileReads) {
  const std::filesystem::path step = scratch::path("occ-statements-saved.step");
  ScriptRun writer;
  writer.run(kOcc + "Box(1) = {0, 0, 0, 1, 1, 1};\nSphere(2) = {3, 0, 0, 1};\nSave \"" +
             step.string() + "\";\n");
  EXPECT_EQ(printed(kOcc + "v() = ShapeFromFile(\"" + step.string() +
                    "\");\nPrintf(\"%g %g %g\", #v(), v(0), v(1));\n"),
            "2 1 2\n");
  std::filesystem::remove(step);
  EXPECT_NE(firstLineOf(kOcc + "Box(1) = {0, 0, 0, 1, 1, 1};\nSave \"/no/such/dir/x.brep\";\n")
                .find("test.geo:3:1: error:"),
            std::string::npos);
}

TEST(OccStatements, ErrorsPointAtTheStatementWithTheReason) {
  EXPECT_EQ(firstLineOf(kOcc + "Box(1) = {0, 0, 0, 1, 1, 1};\n"
                               "BooleanUnion{ Volume{1}; Delete; }{ Volume{7}; Delete; }\n"),
            "test.geo:3:1: error: Volume 7 is not defined");
  EXPECT_EQ(firstLineOf(kOcc + "Sphere(1) = {0, 0, 0};"),
            "test.geo:2:13: error: Sphere takes {x, y, z, r <, polar angle min, polar angle "
            "max> <, opening>}, not 3 values");
  EXPECT_EQ(firstLineOf(kOcc + "Disk(1) = {0, 0, 0, 1, 2};"),
            "test.geo:2:1: error: Disk 1: its radius along x must not be smaller than the one "
            "along y");
  const std::string fillet = firstLineOf(kOcc + "Box(1) = {0, 0, 0, 1, 1, 1};\n"
                                                "r() = Fillet{1}{1}{1.5};\n");
  EXPECT_EQ(fillet, "test.geo:3:7: error: Fillet: radius 1.5 is too large for curve 1 "
                    "(OpenCASCADE could not round them)");
  const std::string missing = firstLineOf(kOcc + "v() = ShapeFromFile(\"/no/such/part.step\");");
  EXPECT_NE(missing.find("/no/such/part.step"), std::string::npos) << missing;
  EXPECT_EQ(firstLineOf(kOcc + "BooleanFragments(9) = { Volume{1}; }{ Volume{2}; };\n"),
            "test.geo:2:1: error: Volume 1 is not defined");
}

// HealShapes; heals everything and renumbers from 1; HealShapes{..} (beyond the reference)
// heals the shapes given; the options are the Geometry.OCC* healing options.
TEST(OccStatements, HealShapes) {
  EXPECT_EQ(printed(kOcc + "Box(5) = {0, 0, 0, 1, 1, 1};\nSphere(9) = {3, 0, 0, 0.5};\n"
                    "HealShapes;\nv() = Volume{:}; c() = Curve{:};\n"
                    "Printf(\"%g %g %g\", v(0), v(1), #c());\n"
                    "Geometry.OCCFixSmallEdges = 1;\nHealShapes{ Volume{2}; }\n"
                    "v() = Volume{:}; c() = Curve{:};\n"
                    "Printf(\"%g %g %g\", v(0), v(1), #c());\n"),
            "1 2 15\n1 2 13\n");  // the sphere, of the largest tag, takes it again
  ScriptRun builtIn;
  builtIn.run("Point(1) = {0, 0, 0};\nHealShapes;\n");
  ASSERT_EQ(builtIn.log.warnings.size(), 1u);
  EXPECT_NE(builtIn.log.warnings[0].find("needs SetFactory(\"OpenCASCADE\")"), std::string::npos);
  EXPECT_EQ(firstLineOf(kOcc + "HealShapes{ Volume{4}; }\n"),
            "test.geo:2:1: error: Volume 4 is not defined");
  EXPECT_EQ(firstLineOf(kOcc + "Box(1) = {0, 0, 0, 1, 1, 1};\n"
                               "Geometry.OCCTargetUnit = \"LY\";\n"
                               "v() = ShapeFromFile(\"/no/such/part.step\");\n")
                .rfind("test.geo:4:7: error:", 0),
            0u);
}

// The older form of Periodic Surface on OpenCASCADE surfaces: the translation follows from
// the curves, whichever way each runs; curves that match no rigid motion are an error.
TEST(OccStatements, PeriodicSurfaceByCurves) {
  ScriptRun run;
  run.run(kOcc + "Box(1) = {0, 0, 0, 1, 1, 1};\n"
                 "Periodic Surface 2 {5, 8, 7, 6} = 1 {1, 4, 3, 2};\n");
  EXPECT_TRUE(run.log.warnings.empty()) << run.log.warnings.front();
  run.session.synchronize();
  const ModelSurface* slave = run.session.model().surface(2);
  ASSERT_TRUE(slave && slave->periodic);
  EXPECT_EQ(slave->periodic->master, 1);
  const std::vector<double> translation{1, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  ASSERT_EQ(slave->periodic->affine.size(), 16u);
  for (std::size_t i = 0; i < 16; ++i)
    EXPECT_NEAR(slave->periodic->affine[i], translation[i], 1e-12) << i;
  EXPECT_EQ(firstLineOf(kOcc + "Box(1) = {0, 0, 0, 1, 1, 1};\n"
                               "Periodic Surface 2 {5, 8, 7, 6} = 1 {1, 9, 3, 2};\n"),
            "test.geo:3:1: error: Periodic Surface 2: its curves are not the image of those of "
            "surface 1 by a translation or a rotation");
}

// Points fragmented with a surface and a volume are embedded in them (or in the face they lie
// on) and keep their tags; a point outside stays free.
TEST(OccStatements, FragmentsOfPointsEmbedThem) {
  ScriptRun run;
  run.run(kOcc + "Rectangle(1) = {0, 0, 0, 1, 1};\nPoint(10) = {0.5, 0.5, 0};\n"
                 "Point(11) = {0.2, 0.7, 0};\nPoint(12) = {3, 3, 3};\n"
                 "r() = BooleanFragments{ Surface{1}; Delete; }{ Point{10, 11, 12}; Delete; };\n"
                 "Box(5) = {5, 0, 0, 1, 1, 1};\nPoint(30) = {5.5, 0.5, 0.5};\n"
                 "Point(31) = {5.25, 0.5, 1};\n"
                 "q() = BooleanFragments{ Volume{5}; Delete; }{ Point{30, 31}; Delete; };\n"
                 "Printf(\"%g %g %g %g %g %g %g %g %g\", #r(), r(0), r(4), r(7), r(9), #q(), "
                 "q(1), q(7), q(10));\n");
  // The lists as the reference gives them: 1 1 2 3 4 10 11 12 10 11 (the surface, its new
  // curves, the points, those inside it again) and 5 2 3 4 5 6 7 30 31 31 30.
  EXPECT_EQ(run.out.str(), "10 1 4 12 11 11 2 30 30\n");
  run.session.synchronize();
  const Model& model = run.session.model();
  std::vector<int> inSurface = model.surface(1)->embeddedPoints;
  std::sort(inSurface.begin(), inSurface.end());
  EXPECT_EQ(inSurface, (std::vector<int>{10, 11}));
  EXPECT_EQ(model.volume(5)->embeddedPoints, std::vector<int>{30});
  int onFace = 0;
  for (const auto& [tag, surface] : model.surfaces())
    if (surface.embeddedPoints == std::vector<int>{31}) onFace = tag;
  EXPECT_NE(onFace, 0) << "point 31 is embedded in no face of the box";
  EXPECT_TRUE(model.points().contains(12));
}

TEST(OccStatements, BuiltInEntitiesAreRefusedByOpenCascadeOperations) {
  const std::string message =
      firstLineOf("Point(100) = {0, 0, 0};\nSetFactory(\"OpenCASCADE\");\n"
                  "Box(1) = {0, 0, 0, 1, 1, 1};\nBooleanUnion{ Volume{1}; }{ Point{100}; }\n");
  EXPECT_EQ(message, "test.geo:4:1: error: BooleanUnion: Point 100 was made by the built-in "
                     "kernel; OpenCASCADE operations take OpenCASCADE entities only");
  EXPECT_EQ(firstLineOf(kOcc + "Box(1) = {0, 0, 0, 1, 1, 1};\nPoint(100) = {0, 0, 0};\n"
                               "BooleanUnion{ Volume{1}; }{ Point{100}; }\n"),
            "test.geo:4:1: error: BooleanUnion failed: this operation is not defined for shapes "
            "of these dimensions (a union of a volume and a point, say)");
}

}  // namespace
}  // namespace geomesh::testing
