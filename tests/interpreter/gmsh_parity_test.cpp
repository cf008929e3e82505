// Details where a script's meaning follows Gmsh's behaviour closely; each was a difference once.
#include <gtest/gtest.h>

#include "script_runner.h"

namespace geomesh::testing {
namespace {

TEST(GmshParity, SetNumberOnTheCommandLineDefinesTheVariable) {
  ScriptRun run;
  run.session.numberOverrides()["zz"] = 3;
  run.session.numberOverrides()["Parameters/n"] = 8;
  run.session.stringOverrides()["label"] = "beam";
  EXPECT_EQ(run.run(R"(
DefineConstant[ zz = {1, Name "Parameters/zz"}, n = {2, Name "Parameters/n"} ];
Printf("%g %g %g %g", zz, n, GetNumber("Parameters/zz"), GetNumber("Parameters/n"));
Printf(label);
)"),
            "3 8 0 8\nbeam\n");
}

TEST(GmshParity, ASecondMacroOfTheSameNameIsIgnored) {
  ScriptRun run;
  EXPECT_EQ(run.run("Macro M\n Printf(\"first\");\nReturn\nMacro M\n Printf(\"second\");\n"
                    "Return\nCall M;\n"),
            "first\n");
  ASSERT_EQ(run.log.warnings.size(), 1u);
  EXPECT_EQ(run.log.warnings[0],
            "test.geo:4:1: warning: macro 'M' is already defined; this definition is ignored");
}

TEST(GmshParity, PointsAllGivesTagsAndPointGivesCoordinates) {
  EXPECT_EQ(printed("Point(1) = {0, 0, 0}; Point(2) = {1, 2, 3}; Point(7) = {4, 5, 6};\n"
                    "a[] = Point{2}; c[] = Point{:};\n"
                    "Printf(\"%g %g %g | %g %g %g\", a[], c[]);\n"),
            "1 2 3 | 1 2 7\n");
}

TEST(GmshParity, PhysicalGroupQueriesAndNewregAfterDeletePhysicals) {
  EXPECT_EQ(printed(R"(
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {2, 0, 0};
Line(1) = {1, 2}; Line(2) = {2, 3};
Physical Curve("all", 20) = {1, 2};
Physical Curve(7) = {2};
Physical Point(3) = {1};
g[] = Physical Curve{:};
m[] = Physical Curve{20};
Printf("%g groups: %g %g; group 20: %g %g; unknown: %g", #g[], g[], m[], #Physical Curve{99});
Delete Physicals;
Printf("newreg %g", newreg);
)"),
            "2 groups: 7 20; group 20: 1 2; unknown: 0\nnewreg 21\n");
}

}  // namespace
}  // namespace geomesh::testing
