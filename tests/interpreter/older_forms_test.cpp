// Tests of the older and rarer statement forms: {a ... b}, tags 0 and negative, Nurbs,
// CatmullRom, Ellipsis, Using Power, Circle Plane{..}, Split Curve, Curve "*", text constants.
#include <gtest/gtest.h>

#include <string>

#include "script_runner.h"

namespace geomesh {
namespace {

using testing::firstLineOf;
using testing::printed;
using testing::ScriptRun;

constexpr const char* kFourPoints =
    "Point(1) = {0, 0, 0}; Point(2) = {1, 1, 0}; Point(3) = {2, 1, 0}; Point(4) = {3, 0, 0};\n";

TEST(OlderForms, DotsRangeIsAColonRange) {
  EXPECT_EQ(printed("x() = {1 ... 3, 7}; Printf(\"%g %g %g %g\", x(0), x(1), x(2), x(3));"),
            "1 2 3 7\n");
  EXPECT_EQ(printed("x() = {3 ... 1}; Printf(\"%g %g\", #x(), x(2));"), "3 1\n");
  EXPECT_EQ(firstLineOf("x() = {1 ... };"), "test.geo:1:14: error: unexpected '}', expected an expression");
  EXPECT_EQ(printed("x() = {1 ... 10 : 2}; Printf(\"%g %g %g\", #x(), x(1), x(4));"), "5 3 9\n");
}

TEST(OlderForms, PrintfWithoutConversionListsTheValues) {
  EXPECT_EQ(printed("x() = {1, 2, 3.5}; Printf(\"x = \", x());"), "x =  [0]1 [1]2 [2]3.5\n");
  EXPECT_EQ(printed("Printf(\"w\", 5);"), "w [0]5\n");
  EXPECT_EQ(firstLineOf("x() = {1, 2}; Printf(\"y %g\", x());"),
            "test.geo:1:15: error: 1 extra argument for the format");
}

TEST(OlderForms, RecombineWithAValueInsideAnExtrusion) {
  EXPECT_EQ(printed("Point(1) = {0, 0, 0, 0.5}; Point(2) = {1, 0, 0, 0.5}; Line(1) = {1, 2};\n"
                    "Extrude {0, 1, 0} { Line{1}; Layers{2}; Recombine 0; }\n"
                    "r = 1; Extrude {0, -1, 0} { Line{1}; Layers{2}; Recombine r; }\n"
                    "Mesh 2; Printf(\"%g %g\", Mesh.NbTriangles, Mesh.NbQuadrangles);"),
            "8 4\n");
}

// A list may be written in parentheses where it has two items or more: Point(2) = (1, 2, 0);
TEST(OlderForms, ListsInParentheses) {
  EXPECT_EQ(printed("Point(2) = (1, 2, 0); p() = Point{2}; Printf(\"%g %g %g\", p(0), p(1), p(2));"),
            "1 2 0\n");
  EXPECT_EQ(printed("x() = (1, 2) + 1; Printf(\"%g %g\", x(0), x(1));"), "2 3\n");
  EXPECT_EQ(printed("x = (1 + 2) * 2; Printf(\"%g\", x);"), "6\n");
}

// A fifth value after the size, a Nurbs weight in older scripts, is ignored with a warning.
TEST(OlderForms, PointWeightIsIgnored) {
  ScriptRun run;
  EXPECT_EQ(run.run("Point(2) = {1, 2, 0, 0.1, 0.7071}; p() = Point{2};\n"
                    "Printf(\"%g %g %g\", p(0), p(1), p(2));"),
            "1 2 0\n");
  ASSERT_EQ(run.log.warnings.size(), 1u);
  EXPECT_NE(run.log.warnings[0].find("Point 2: its weight (fifth value) is ignored"),
            std::string::npos)
      << run.log.warnings[0];
  EXPECT_EQ(firstLineOf("Point(2) = {1, 2, 0, 0.1, 0.7, 3};"),
            "test.geo:1:12: error: Point takes {x, y, z}, {x, y, z, size} or {x, y, z, size, "
            "weight}, not 6 values");
}

TEST(OlderForms, SingleQuotedStrings) {
  EXPECT_EQ(printed("s = 'wall'; t = 'it\\'s'; Printf(\"%s %s %g\", s, t, StrLen('ab'));"),
            "wall it's 2\n");
  EXPECT_EQ(firstLineOf("s = 'wall;"), "test.geo:1:5: error: unterminated string");
}

TEST(OlderForms, CircleBackToItsStartIsAWholeCircle) {
  ScriptRun run;
  run.run("Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1};\n"
          "Circle(1) = {2, 1, 2}; Curve Loop(1) = {1}; Plane Surface(1) = {1};\n"
          "Line(2) = {1, 1};\nPrintf(\"%g %g\", #Curve{:}, newl);\nMesh 2;\n"
          "Printf(\"%g\", Mesh.NbTriangles > 300);");
  EXPECT_EQ(run.out.str(), "1 3\n1\n");
  ASSERT_EQ(run.log.warnings.size(), 2u);
  EXPECT_NE(run.log.warnings[0].find("Circle 1 goes a whole turn from point 2"), std::string::npos);
  EXPECT_NE(run.log.warnings[1].find("Line 2: both ends are point 1"), std::string::npos);
  const auto& circle = *run.session.model().curve(1)->geometry;
  EXPECT_NEAR(circle.arcAngle(), 2 * 3.14159265358979, 1e-12);
  const Vec3 half = circle.point((circle.range().min + circle.range().max) / 2);
  EXPECT_NEAR(half.x, -1, 1e-12);
}

TEST(OlderForms, SyntaxErrorsInBranchesNotTakenAreNotReached) {
  // The reference skips the text of a branch it does not take: an error there is none.
  EXPECT_EQ(printed("a = 1;\nIf (a == 1)\n  Printf(\"taken\");\nElse\n  x = {1, 2 +};\n"
                    "  If (a) y = 3 EndIf\nEndIf\nIf (a == 2)\n  Point(1) = (0, 0, 0);\n"
                    "ElseIf (a == 3)\n  z = 1 2;\nEndIf\nPrintf(\"end\");"),
            "taken\nend\n");
  // Taken, the branch fails where its error is, with the parser's message.
  EXPECT_EQ(firstLineOf("a = 1;\nIf (a == 1)\n  z = 1 2;\nEndIf\n"),
            "test.geo:3:8: error: expected ';' after '1' (found '2')");
  // Nor in a macro never called; called, it fails at the error.
  EXPECT_EQ(printed("Macro Unused\n  x = {1, 2 +};\nReturn\nPrintf(\"end\");"), "end\n");
  EXPECT_EQ(firstLineOf("Macro Bad\n  z = 1 2;\nReturn\nCall Bad;\n"),
            "test.geo:2:8: error: expected ';' after '1' (found '2')");
  // Outside any branch, as before.
  EXPECT_EQ(firstLineOf("z = 1 2;\nIf (0)\nEndIf\n"),
            "test.geo:1:6: error: expected ';' after '1' (found '2')");
}

TEST(OlderForms, ZeroAndNegativeTags) {
  EXPECT_EQ(printed("Point(0) = {0, 0, 0}; Point(-1) = {1, 0, 0}; Point(-5) = {2, 0, 0};\n"
                    "Line(0) = {0, -1}; Line(-2) = {1, 2};\n"
                    "p() = Point{:}; c() = Curve{:}; b() = Boundary{Curve{0};};\n"
                    "Printf(\"%g %g %g | %g %g | %g %g\", p(0), p(1), p(2), c(0), c(1), b(0), "
                    "b(1));"),
            "0 1 2 | 0 1 | 0 1\n");
  EXPECT_EQ(printed("Point(1) = {0, 0, 0}; Physical Point(-5) = {1}; Physical Point(0) = {1};\n"
                    "g() = Physical Point{:}; Printf(\"%g %g\", g(0), g(1));"),
            "0 5\n");
  EXPECT_EQ(printed(std::string(kFourPoints) +
                    "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};\n"
                    "Curve Loop(-1) = {1, 2, 3}; Plane Surface(-7) = {1};\n"
                    "s() = Surface{:}; Printf(\"%g %g %g\", s(0), newll, news);"),
            "1 4 4\n");
}

TEST(OlderForms, CurvesOfOlderNames) {
  ScriptRun run;
  run.run(std::string(kFourPoints) +
          "Nurbs(1) = {1, 2, 3, 4} Knots {0, 0, 0, 0, 1, 1, 1, 1} Order 3;\n"
          "CatmullRom(2) = {1, 2, 3};\n"
          "Ellipsis(3) = {4, 1, 4, 2};\n"
          "Line(4) = {1, 2, 3, 4};\n"
          "Transfinite Line{4} = 5 Using Power 1.5;\n");
  const auto& curves = run.session.model().meshConstraints().transfiniteCurves;
  ASSERT_TRUE(curves.contains(4));
  EXPECT_EQ(curves.at(4).law, TransfiniteCurve::Law::Progression);
  EXPECT_EQ(curves.at(4).coefficient, 1.5);
  EXPECT_EQ(firstLineOf(std::string(kFourPoints) + "Nurbs(1) = {1, 2, 3, 4} Order 3;"),
            "test.geo:2:12: error: expected Nurbs(tag) = {points} Knots {knots} Order degree;");
  EXPECT_EQ(firstLineOf(std::string(kFourPoints) +
                        "Nurbs(1) = {1, 2, 3, 4} Knots {0, 1} Order 3;"),
            "test.geo:2:1: error: Nurbs 1: 4 points of order 3 need 8 knots, not 2");
  EXPECT_EQ(firstLineOf(std::string(kFourPoints) + "Line(1) = {1};"),
            "test.geo:2:11: error: Line takes 2 points or more, not 1");
}

TEST(OlderForms, CirclePlaneAndSplitCurve) {
  EXPECT_EQ(printed("Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {-1, 0, 0};\n"
                    "Circle(1) = {2, 1, 3} Plane{0, 0, -1};\n"
                    "b() = BoundingBox Curve{1}; Printf(\"%g %g\", b(1), b(4));"),
            "-1 0\n");
  EXPECT_EQ(firstLineOf("Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {-1, 0, 0};\n"
                        "Circle(1) = {2, 1, 3} Plane{0, 1};"),
            "test.geo:2:28: error: Plane takes {nx, ny, nz}, not 2 values");
  EXPECT_EQ(printed(std::string(kFourPoints) +
                    "Spline(5) = {1, 2, 3, 4};\nSplit Curve{5} Point{2, 3};\n"
                    "c() = Curve{:}; Printf(\"%g %g %g %g\", #c(), c(0), c(2), newl);"),
            "3 6 8 9\n");
  EXPECT_EQ(firstLineOf("Point(1) = {0, 0, 0}; Split Curve{5} Point{1};"),
            "test.geo:1:23: error: Split Curve: curve 5 is not defined");
}

TEST(OlderForms, IntersectCurveWithSurfaceMakesPoints) {
  EXPECT_EQ(printed("Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0};\n"
                    "Point(4) = {0, 1, 0};\n"
                    "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
                    "Curve Loop(1) = {1, 2, 3, 4}; Surface(1) = {1};\n"
                    "Point(5) = {0.5, 0.3, -1}; Point(6) = {0.5, 0.3, 1}; Line(5) = {5, 6};\n"
                    "Point(8) = {5, 5, -1}; Point(9) = {5, 5, 1}; Line(6) = {8, 9};\n"
                    "x[] = Intersect Curve{5, 6} Surface{1}; p[] = Point{x[0]};\n"
                    "Printf(\"%g %g: %g %g %g\", #x[], x[0], p[0], p[1], p[2]);"),
            "1 10: 0.5 0.3 0\n");
  EXPECT_EQ(firstLineOf("Point(1) = {0, 0, 0};\nx[] = Intersect Curve{1} Surface{3};"),
            "test.geo:2:7: error: Intersect: surface 3 is not defined");
}

TEST(OlderForms, CoherencePointMergesIntoTheFirst) {
  EXPECT_EQ(printed("Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0};\n"
                    "Point(4) = {0, 1, 0}; Line(1) = {1, 2}; Line(2) = {3, 4};\n"
                    "Coherence Point{2, 3};\n"
                    "p[] = Point{:}; b[] = Boundary{Curve{2};}; q[] = Point{2};\n"
                    "Printf(\"%g | %g %g | %g %g\", #p[], b[0], b[1], q[0], q[1]);"),
            "3 | 2 4 | 1 0\n");
}

TEST(OlderForms, SelectionByStringAndPolarSphere) {
  EXPECT_EQ(printed(std::string(kFourPoints) +
                    "PolarSphere(1) = {1, 2};\nPhysical Point(3) = {1};\n"
                    "p() = Point \"*\"; g() = Physical Point \"*\"; s() = Surface \"*\";\n"
                    "Printf(\"%g %g %g\", #p(), g(0), #s());"),
            "4 3 0\n");
  EXPECT_EQ(firstLineOf(std::string(kFourPoints) + "x() = Physical Point \"wall\";"),
            "test.geo:2:7: error: 'Physical Point \"wall\"': only \"*\" (every group) may follow; "
            "use {tags} to select groups");
}

TEST(OlderForms, TextConstantsAndFunctions) {
  EXPECT_EQ(printed("Printf(StrCat(CurrentFileName, \" \", Sprintf(\"%g\", StrLen(Today))));"),
            "test.geo 24\n");
  EXPECT_EQ(printed("Printf(StrCat(\"[\", OnelabAction, \"]\", LowerCaseIn(\"ABC\")));"),
            "[]Abc\n");
  EXPECT_EQ(printed("Printf(GetStringValue(\"question\", \"answer\"));"),
            "question (default=answer): answer\n");
  const std::string directory = printed("Printf(CurrentDirectory);");
  EXPECT_EQ(directory.substr(directory.size() - 2), "/\n");
}

TEST(OlderForms, NearlyPlaneSurfaceWarns) {
  ScriptRun run;
  run.run("Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0.01}; Point(3) = {1, 1, 0};\n"
          "Point(4) = {0, 1, 0.01};\n"
          "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
          "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n");
  ASSERT_EQ(run.log.warnings.size(), 1u);
  EXPECT_EQ(run.log.warnings[0],
            "test.geo:4:31: warning: Plane Surface 1: its loops are not exactly plane (up to "
            "0.005 off their mean plane); meshed on that plane");
}

TEST(OlderForms, OlderPeriodicSurfaceFormWithTagsInVariablesAndLists) {
  const std::string box =
      "Point(1) = {0, 0, 0, 0.3}; Point(2) = {1, 0, 0, 0.3}; Point(3) = {1, 1, 0, 0.3};\n"
      "Point(4) = {0, 1, 0, 0.3}; Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};\n"
      "Line(4) = {4, 1}; Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
      "e[] = Extrude {0, 0, 1} { Surface{1}; };\n"
      "b1[] = Boundary{ Surface{1}; }; b2[] = Boundary{ Surface{e[0]}; };\n";
  for (const char* form : {"Periodic Surface e[0] {b2[]} = 1 {b1[]};\n",
                           "top = e[0]; bottom = 1; Periodic Surface top {b2[]} = bottom {b1[]};\n"}) {
    ScriptRun run;
    run.run(box + form);
    run.session.synchronize();
    const auto& top = *run.session.model().surface(26);
    ASSERT_TRUE(top.periodic.has_value()) << form;
    EXPECT_EQ(top.periodic->master, 1) << form;
  }
}

TEST(OlderForms, PeriodicCurveWithoutTransform) {
  ScriptRun run;
  run.run("Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};\n"
          "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
          "Periodic Curve{3} = {-1};\n");
  EXPECT_TRUE(run.log.warnings.empty());
  EXPECT_NE(firstLineOf("Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {3, 1, 0};\n"
                        "Line(1) = {1, 2}; Line(2) = {2, 3};\nPeriodic Curve{2} = {1};\n")
                .find("is not a translate of curve 1"),
            std::string::npos);
}

TEST(OlderForms, StarSelectsEveryEntityInCommands) {
  ScriptRun run;
  run.run("Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};\n"
          "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
          "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
          "Transfinite Line \"*\" = 5 Using Progression 1.1; Transfinite Surface \"*\";\n"
          "Recombine Surface \"*\";\n");
  EXPECT_TRUE(run.log.warnings.empty());
  const auto& constraints = run.session.model().meshConstraints();
  EXPECT_EQ(constraints.transfiniteCurves.size(), 4u);
  EXPECT_EQ(constraints.transfiniteCurves.at(3).coefficient, 1.1);
  EXPECT_EQ(firstLineOf("Transfinite Line \"a\" = 5;"),
            "test.geo:1:18: error: only \"*\" (every entity) may stand here");
}

TEST(OlderForms, FormsNoLongerReadAreLocatedErrors) {
  EXPECT_EQ(firstLineOf("Point(1) = {0, 0, 0};\nExtrude Point {1, {0, 0, 1}};"),
            "test.geo:2:1: error: 'Extrude Point {tag, {dx, dy, dz}}' is an older form that is "
            "no longer read; write Extrude {dx, dy, dz} { Point{tag}; }");
  EXPECT_EQ(firstLineOf("Point(1) = {0, 0, 0};\nx[] = Extrude Point {1, {0, 0, 1}};"),
            "test.geo:2:7: error: 'Extrude Point {tag, {dx, dy, dz}}' is an older form that is "
            "no longer read; write Extrude {dx, dy, dz} { Point{tag}; }");
  EXPECT_EQ(firstLineOf("Hole(1) = {1};"),
            "test.geo:1:1: error: 'Hole' is a reserved word that starts no statement");
  EXPECT_EQ(firstLineOf("Compound Line(10) = {1, 2};"),
            "test.geo:1:1: error: 'Compound Line(tag) = {..}' is an older form that is no longer "
            "read; write the meshing constraint Compound Curve{..};");
  EXPECT_EQ(firstLineOf("Point(1) = {0, 0, 0};\nPhysical Point(1) = {1};\n"
                        "Delete Physical Point{1};"),
            "test.geo:3:1: error: 'Delete Physical Point{..}' is not a statement; write Physical "
            "Point(tag) -= {..}; or Delete Physicals;");
  EXPECT_EQ(firstLineOf("Point(1) = {0, 0, 0};\nPhysical Point{\"a\"} = {1};"),
            "test.geo:2:1: error: a physical group is defined as Physical Point(tag) = {..}; or "
            "Physical Point(\"name\") = {..};, not with braces");
}

}  // namespace
}  // namespace geomesh
