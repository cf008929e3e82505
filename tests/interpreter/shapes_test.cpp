// Tests of shape operations: Boundary, Duplicata, Extrude, transforms, Delete, Periodic.
#include <gtest/gtest.h>

#include "script_runner.h"

namespace geomesh::testing {
namespace {

constexpr const char* kSquare =
    "Point(1) = {0,0,0}; Point(2) = {1,0,0}; Point(3) = {1,1,0}; Point(4) = {0,1,0};\n"
    "Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,4}; Line(4) = {4,1};\n"
    "Curve Loop(1) = {1,2,3,4}; Plane Surface(1) = {1};\n";

std::string afterSquare(const std::string& script) { return printed(kSquare + script); }

// Expected values are those the reference implementation prints for the same script.
TEST(Shapes, BoundaryAndPointsOf) {
  EXPECT_EQ(afterSquare("b[] = Boundary{ Surface{1}; };\n"
                        "Printf(\"%g %g %g %g\", b[0], b[1], b[2], b[3]);\n"
                        "p[] = PointsOf{ Surface{1}; };\nPrintf(\"%g n=%g\", p[0], #p[]);"),
            "1 2 3 4\n1 n=4\n");
}

TEST(Shapes, TranslatedDuplicata) {
  EXPECT_EQ(afterSquare("d[] = Translate {2, 0, 0} { Duplicata { Surface{1}; } };\n"
                        "Printf(\"%g n=%g\", d[0], #d[]);\n"
                        "c[] = Point{6};\nPrintf(\"%g %g %g\", c[0], c[1], c[2]);"),
            "5 n=1\n3 0 0\n");
}

TEST(Shapes, ExtrudeWithLayers) {
  EXPECT_EQ(afterSquare("out[] = Extrude {0, 0, 1} { Surface{1}; Layers{4}; Recombine; };\n"
                        "Printf(\"n=%g: %g %g %g %g\", #out[], out[0], out[1], out[2], out[3]);\n"
                        "Printf(\"%g %g %g\", newp, newl, news);\n"
                        "v[] = Volume{:};\nPrintf(\"%g\", #v[]);"),
            "n=6: 26 1 13 17\n15 27 27\n1\n");
}

TEST(Shapes, EntitiesInABoundingBox) {
  EXPECT_EQ(afterSquare("s[] = Surface In BoundingBox {-0.1, -0.1, -0.1, 1.1, 1.1, 0.1};\n"
                        "Printf(\"n=%g %g\", #s[], s[0]);\n"
                        "b[] = BoundingBox Surface{1};\nPrintf(\"%g %g %g\", #b[], b[0], b[3]);"),
            "n=1 1\n6 0 1\n");
}

TEST(Shapes, TransformsMovePoints) {
  EXPECT_EQ(printed("Point(1) = {1, 0, 0};\nRotate {{0, 0, 1}, {0, 0, 0}, Pi / 2} { Point{1}; }\n"
                    "Translate {0, 0, 2} { Point{1}; }\nDilate {{0, 0, 0}, 2} { Point{1}; }\n"
                    "Symmetry {0, 0, 1, 0} { Point{1}; }\n"
                    "c[] = Point{1}; Printf(\"%g %g %g\", Round(c[0]), c[1], c[2]);"),
            "0 2 -4\n");
}

TEST(Shapes, DeleteAndCoherence) {
  ScriptRun run;
  run.run(std::string(kSquare) + "Point(9) = {1, 1, 0};\nCoherence;\n"
          "Recursive Delete { Surface{1}; }\n");
  run.session.synchronize();
  EXPECT_TRUE(run.session.model().surfaces().empty());
  EXPECT_TRUE(run.session.model().curves().empty());
}

TEST(Shapes, EmbeddingCompoundAndPeriodicity) {
  ScriptRun run;
  run.run(std::string(kSquare) + "Point(5) = {0.5, 0.5, 0};\nPoint{5} In Surface{1};\n"
          "Compound Curve{1, 2};\nPeriodic Curve{3} = {1} Translate{0, 1, 0};\n");
  // The compound is recorded on both curves; no warning.
  EXPECT_TRUE(run.log.warnings.empty());
  run.session.synchronize();
  EXPECT_EQ(run.session.model().surface(1)->embeddedPoints, (std::vector<int>{5}));
  EXPECT_EQ(run.session.model().curve(2)->compound, (std::vector<int>{1, 2}));
}

TEST(Shapes, CurvesAndSurfaces) {
  ScriptRun run;
  run.run("Point(1) = {0,0,0}; Point(2) = {2,0,0}; Point(3) = {0,1,0}; Point(4) = {-2,0,0};\n"
          "Point(5) = {1,1,0};\n"
          "Ellipse(1) = {2, 1, 2, 3};\nSpline(2) = {3, 5, 2};\nBSpline(3) = {2, 5, 3};\n"
          "Bezier(4) = {3, 5, 2};\nLine(5) = {3, 1}; Line(6) = {1, 2};\n"
          "Curve Loop(1) = {6, 1, 5};\nSurface(1) = {1};\n");
  EXPECT_TRUE(run.log.warnings.empty());
  run.session.synchronize();
  EXPECT_EQ(run.session.model().curves().size(), 6u);
  EXPECT_EQ(run.session.model().surfaces().size(), 1u);
}

TEST(Shapes, PhysicalRemovalAndDeletePhysicals) {
  ScriptRun run;
  run.run(std::string(kSquare) + "Physical Curve(1) = {1, 2, 3};\nPhysical Curve(1) -= {2};\n");
  EXPECT_EQ(run.session.factory().physicalGroups().at({1, 1}).entities, (std::vector<int>{1, 3}));
  run.run("Delete Physicals;\n");
  EXPECT_TRUE(run.session.factory().physicalGroups().empty());
}

TEST(Shapes, KernelErrorsPointAtTheShape) {
  std::string error = firstLineOf(std::string(kSquare) + "Translate {1, 0, 0} { Point{42}; }");
  EXPECT_EQ(error.substr(0, 21), "test.geo:4:1: error: ") << error;
  EXPECT_EQ(firstLineOf("Translate {1, 0} { Point{1}; }"),
            "test.geo:1:1: error: Translate takes {dx, dy, dz}, not 2 values");
}

}  // namespace
}  // namespace geomesh::testing
