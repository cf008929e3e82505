// Built-in kernel statements driven by scripts: the result lists, tags and counters a script
// sees, as the built-in kernel of Gmsh gives them.
#include <gtest/gtest.h>

#include <cmath>

#include "script_runner.h"

namespace geomesh::testing {
namespace {

constexpr const char* kUnitSquare =
    "Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1};\n"
    "Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};\n"
    "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
    "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n";

TEST(KernelStatements, ExtrudedSurfaceListsTopVolumeAndSides) {
  const std::string out = printed(std::string(kUnitSquare) +
                                  "a[] = Extrude{0, 0, 1}{ Surface{1}; Layers{4}; Recombine; };\n"
                                  "Printf(\"%g %g %g %g %g %g\", a[0], a[1], a[2], a[3], a[4], "
                                  "a[5]);\nPrintf(\"%g %g\", newp, newl);\n");
  EXPECT_EQ(out, "26 1 13 17 21 25\n15 27\n");
}

TEST(KernelStatements, ExtrudedPointThenLineReusesTheSweptPoint) {
  const std::string out = printed(
      "Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Line(1) = {1, 2};\n"
      "a[] = Extrude{0, 1, 0}{ Point{1}; };\n"
      "b[] = Extrude{0, 1, 0}{ Curve{1}; };\n"
      "Printf(\"%g %g | %g %g %g %g | %g\", a[0], a[1], b[0], b[1], b[2], b[3], newp);\n");
  EXPECT_EQ(out, "3 2 | 3 6 5 -2 | 6\n");
}

TEST(KernelStatements, RevolvedLineMakesCircleArcs) {
  const std::string out = printed(
      "Point(1) = {1, 0, 0}; Point(2) = {2, 0, 0}; Line(1) = {1, 2};\n"
      "b[] = Extrude{{0, 0, 1}, {0, 0, 0}, Pi/2}{ Curve{1}; };\n"
      "Printf(\"%g %g %g %g %g\", b[0], b[1], b[2], b[3], newp);\n");
  EXPECT_EQ(out, "2 5 4 -3 9\n");
}

TEST(KernelStatements, TranslatedDuplicataGetsNewTags) {
  const std::string out = printed(std::string(kUnitSquare) +
                                  "a[] = Translate{2, 0, 0}{ Duplicata{ Surface{1}; } };\n"
                                  "Printf(\"%g %g %g\", a[0], newp, newl);\n"
                                  "b[] = Boundary{ Surface{a[0]}; };\n"
                                  "Printf(\"%g %g %g %g\", b[0], b[1], b[2], b[3]);\n");
  EXPECT_EQ(out, "5 15 10\n6 7 8 9\n");
}

TEST(KernelStatements, BoundariesAndPoints) {
  const std::string out =
      printed(std::string(kUnitSquare) +
              "b[] = Boundary{ Curve{-1, 2}; };\n"
              "c[] = CombinedBoundary{ Curve{2, 1}; };\n"
              "p[] = PointsOf{ Surface{1}; };\n"
              "Printf(\"%g %g %g %g | %g %g | %g\", b[0], b[1], b[2], b[3], c[0], c[1], #p[]);\n");
  EXPECT_EQ(out, "2 1 2 3 | 1 3 | 4\n");
}

TEST(KernelStatements, DeleteAndCoherence) {
  const std::string out = printed(std::string(kUnitSquare) +
                                  "Point(50) = {5, 5, 5}; Delete{ Point{50}; }\n"
                                  "Printf(\"%g\", newp);\n"
                                  "Point(60) = {1, 1, 0}; Coherence;\n"
                                  "Printf(\"%g\", newp);\n");
  EXPECT_EQ(out, "50\n5\n");
}

TEST(KernelStatements, CurvesOfEveryKind) {
  ScriptRun run;
  run.run(
      "Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {2, 1, 0}; Point(4) = {0, 0.5, 0};\n"
      "Spline(1) = {1, 2, 3}; BSpline(2) = {1, 4, 3}; Bezier(3) = {1, 4, 2};\n"
      "Ellipse(4) = {2, 1, 2, 4};\n");
  run.session.synchronize();
  const Model& model = run.session.model();
  ASSERT_EQ(model.curves().size(), 4u);
  const Vec3 p = model.curve(4)->geometry->point(0.5);
  EXPECT_NEAR(p.x, std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(p.y, 0.5 * std::sqrt(0.5), 1e-12);
}

}  // namespace
}  // namespace geomesh::testing
