// Tests of geometry statements: points, lines, arcs, loops, surfaces, physical groups, tags.
#include <gtest/gtest.h>

#include "script_runner.h"

namespace geomesh::testing {
namespace {

constexpr const char* kSquare =
    "lc = 0.1;\n"
    "Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc};\n"
    "Point(3) = {1, 1, 0, lc}; Point(4) = {0, 1, 0};\n"
    "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n";

TEST(Geometry, SquareSurface) {
  ScriptRun run;
  run.run(std::string(kSquare) + "Curve Loop(1) = {1, 2, 3, 4};\nPlane Surface(1) = {1};\n");
  run.session.synchronize();
  const Model& model = run.session.model();
  EXPECT_EQ(model.points().size(), 4u);
  EXPECT_EQ(model.curves().size(), 4u);
  EXPECT_EQ(model.surfaces().size(), 1u);
  EXPECT_EQ(model.point(2)->xyz, (Vec3{1, 0, 0}));
  EXPECT_EQ(model.point(1)->meshSize, 0.1);
}

TEST(Geometry, CircleArcs) {
  ScriptRun run;
  run.run("Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {0, 1, 0}; Point(4) = {-1, 0, 0};\n"
          "Circle(1) = {2, 1, 3}; Circle(2) = {3, 1, 4}; Line(3) = {4, 2};\n"
          "Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1};\n");
  EXPECT_TRUE(run.log.warnings.empty());
  run.session.synchronize();
  EXPECT_EQ(run.session.model().curves().size(), 3u);
  EXPECT_EQ(run.session.model().curve(1)->startPoint, 2);
  EXPECT_EQ(run.session.model().curve(1)->endPoint, 3);
}

// `In Sphere{c}` after a filling is accepted silently (the arcs already say which sphere);
// `Using Point` constrains OpenCASCADE fillings only, and says so under the built-in kernel.
TEST(Geometry, FillingTails) {
  ScriptRun run;
  run.run("Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {0, 1, 0};\n"
          "Point(4) = {0, 0, 1};\n"
          "Circle(1) = {2, 1, 3}; Circle(2) = {3, 1, 4}; Circle(3) = {4, 1, 2};\n"
          "Curve Loop(1) = {1, 2, 3};\n"
          "Surface(1) = {1} In Sphere{1};\n"
          "Surface(2) = {1} Using Point{1};\n");
  ASSERT_EQ(run.log.warnings.size(), 1u);
  EXPECT_NE(run.log.warnings[0].find("6:1: warning: 'Using Point' constrains OpenCASCADE"),
            std::string::npos)
      << run.log.warnings[0];
  run.session.synchronize();
  EXPECT_EQ(run.session.model().surfaces().size(), 2u);
}

// Geometry.CopyMeshingMethod = 1: a Duplicata's copies take their sources' transfinite and
// recombination constraints, curves included; without it they take none.
TEST(Geometry, CopyMeshingMethodCopiesConstraints) {
  for (int copyMethod : {1, 0}) {
    ScriptRun run;
    run.run("Geometry.CopyMeshingMethod = " + std::to_string(copyMethod) + ";\n" +
            std::string(kSquare) +
            "Curve Loop(1) = {1, 2, 3, 4};\nPlane Surface(1) = {1};\n"
            "Transfinite Curve{1, 3} = 5 Using Progression 1.2;\n"
            "Transfinite Curve{2, 4} = 3;\n"
            "Transfinite Surface{1};\nRecombine Surface{1};\n"
            "s[] = Translate{2, 0, 0}{ Duplicata{ Surface{1}; } };\n");
    const MeshConstraints& mc = run.session.model().meshConstraints();
    EXPECT_EQ(mc.transfiniteSurfaces.size(), copyMethod ? 2u : 1u);
    EXPECT_EQ(mc.recombinedSurfaces.size(), copyMethod ? 2u : 1u);
    EXPECT_EQ(mc.transfiniteCurves.size(), copyMethod ? 8u : 4u);
    if (copyMethod == 1) {
      // The copy's first curve copies curve 1: 5 nodes, progression 1.2.
      run.session.synchronize();
      const int copy = run.session.model().surfaces().rbegin()->first;
      ASSERT_NE(copy, 1);
      const int first = std::abs(run.session.factory().boundary({{2, copy}}, false)[0].tag);
      ASSERT_TRUE(mc.transfiniteCurves.contains(first));
      EXPECT_EQ(mc.transfiniteCurves.at(first).nodes, 5);
      EXPECT_DOUBLE_EQ(mc.transfiniteCurves.at(first).coefficient, 1.2);
    }
  }
}

TEST(Geometry, CircleErrorsCarryTheLocation) {
  std::string error = firstLineOf("Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0};\nCircle(1) = {2, 1, 7};");
  EXPECT_EQ(error.substr(0, 21), "test.geo:2:1: error: ") << error;
}

TEST(Geometry, OldLineLoopAndNegativeTags) {
  ScriptRun run;
  run.run(std::string(kSquare) + "Line Loop(5) = {-4, -3, -2, -1};\nPlane Surface(2) = {5};\n");
  run.session.synchronize();
  EXPECT_NE(run.session.model().surface(2), nullptr);
}

TEST(Geometry, NewTagCounters) {
  EXPECT_EQ(printed("Point(20) = {0,0,0};\n"
                    "Printf(\"%g %g %g %g\", newreg, newp, newl, news);"),
            "1 21 1 1\n");
  EXPECT_EQ(printed(std::string(kSquare) + "Curve Loop(7) = {1,2,3,4};\n"
                    "Printf(\"%g %g %g %g\", newreg, newll, newcl, news);"),
            "8 8 8 8\n");
}

TEST(Geometry, PointCoordinatesAsAValue) {
  EXPECT_EQ(printed("Point(3) = {1, 2, 3};\nc[] = Point{3};\nPrintf(\"%g %g %g\", c[0], c[1], c[2]);"),
            "1 2 3\n");
}

TEST(Geometry, KernelErrorsCarryTheStatementLocation) {
  std::string error = firstLineOf("Point(1) = {0,0,0};\n  Line(1) = {1, 9};");
  EXPECT_EQ(error.substr(0, 21), "test.geo:2:3: error: ") << error;
  EXPECT_NE(error.find('9'), std::string::npos) << error;
}

TEST(Geometry, MisspelledCommandIsNotTakenForAList) {
  EXPECT_EQ(firstLineOf("Pont(1) = {0, 0, 0};"),
            "test.geo:1:1: error: unknown command 'Pont'; did you mean 'Point'?");
  EXPECT_EQ(printed("abc(1) = 5; Printf(\"%g\", abc[1]);"), "5\n");
}

TEST(Geometry, BadArgumentsAreErrors) {
  EXPECT_EQ(firstLineOf("Point(1) = {0, 0};"),
            "test.geo:1:12: error: Point takes {x, y, z}, {x, y, z, size} or {x, y, z, size, "
            "weight}, not 2 values");
  EXPECT_EQ(firstLineOf("Point(1.5) = {0, 0, 0};"),
            "test.geo:1:7: error: tag of 'Point' must be an integer");
}

TEST(Geometry, PhysicalGroupsByTagAndName) {
  ScriptRun run;
  run.run(
      "Point(1) = {0,0,0}; Point(5) = {1,0,0};\n"
      "Physical Point(\"a\") = {1};\n"
      "Physical Point(7) = {1};\n"
      "Physical Point(\"b\") = {5};\n"
      "Physical Point(\"c\", 20) = {5};\n"
      "Physical Point(\"a\") += {5};\n"
      "Printf(\"%g\", newreg);\n");
  EXPECT_EQ(run.out.str(), "21\n");
  run.session.synchronize();
  const auto& groups = run.session.model().physicalGroups();
  ASSERT_TRUE(groups.contains({0, 1}));
  EXPECT_EQ(groups.at({0, 1}).name, "a");
  EXPECT_EQ(groups.at({0, 1}).entities, (std::vector<int>{1, 5}));
  EXPECT_EQ(groups.at({0, 8}).name, "b");
  EXPECT_EQ(groups.at({0, 20}).name, "c");
  EXPECT_TRUE(groups.contains({0, 7}));
}

TEST(Geometry, NamedPhysicalTagsCountAcrossDimensions) {
  ScriptRun run;
  run.run(std::string(kSquare) +
          "Physical Point(4) = {1};\nPhysical Curve(\"c\") = {1, 2};\nPhysical Line(\"d\") = {3};\n");
  run.session.synchronize();
  const auto& groups = run.session.model().physicalGroups();
  EXPECT_EQ(groups.at({1, 5}).name, "c");
  EXPECT_EQ(groups.at({1, 6}).name, "d");
}

TEST(Geometry, InterfaceStatementsAreAcceptedSilently) {
  ScriptRun run;
  run.run("Point(1) = {0,0,0};\nHide {Point{1};}\nShow \"*\";\nDraw;\nColor Red {Point{1};}\n"
          "View \"v\" { SP(0,0,0){1}; };\n");
  EXPECT_TRUE(run.log.warnings.empty());
}

}  // namespace
}  // namespace geomesh::testing
