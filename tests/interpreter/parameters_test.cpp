// Tests of DefineConstant, DefineNumber, SetNumber/GetNumber and command-line overrides.
#include <gtest/gtest.h>

#include "script_runner.h"

namespace geomesh::testing {
namespace {

constexpr const char* kDefines =
    "DefineConstant[ a = 1, b = {2, Min 0, Max 5, Name \"Parameters/b\"},\n"
    "  s = {\"str\", Name \"P/s\"} ];\n"
    "Printf(\"a=%g b=%g\", a, b);\nPrintf(s);\n";

TEST(Parameters, DefineConstantDefaults) { EXPECT_EQ(printed(kDefines), "a=1 b=2\nstr\n"); }

TEST(Parameters, CommandLineValuesOverride) {
  ScriptRun run;
  run.session.numberOverrides()["a"] = 9;
  run.session.numberOverrides()["Parameters/b"] = 4;
  run.session.stringOverrides()["s"] = "other";
  EXPECT_EQ(run.run(kDefines), "a=9 b=4\nother\n");
}

TEST(Parameters, ExistingVariablesAreKept) {
  EXPECT_EQ(printed("a = 5;\nDefineConstant[ a = 1 ];\nPrintf(\"%g\", a);"), "5\n");
}

TEST(Parameters, DefineNumberAndGetNumber) {
  ScriptRun run;
  run.session.numberOverrides()["Parameters/c"] = 11;
  EXPECT_EQ(run.run("c = DefineNumber[3, Name \"Parameters/c\"];\n"
                    "d = DefineNumber[4, Name \"Parameters/d\"];\n"
                    "Printf(\"%g %g %g\", c, d, GetNumber(\"Parameters/c\"));"),
            "11 4 11\n");
  EXPECT_EQ(printed("t = DefineString[\"x\", Name \"P/t\"]; Printf(StrCat(t, GetString(\"P/t\")));"),
            "xx\n");
}

TEST(Parameters, SetAndGet) {
  EXPECT_EQ(printed("SetNumber(\"P/z\", 5); Printf(\"%g %g\", GetNumber(\"P/z\"), GetNumber(\"P/q\", 7));"),
            "5 7\n");
  EXPECT_EQ(printed("SetString(\"P/w\", \"hi\"); Printf(GetString(\"P/w\"));"), "hi\n");
  // Parameters and options are apart, as in Gmsh: SetNumber leaves the option alone and
  // GetNumber does not read options.
  EXPECT_EQ(printed("SetNumber(\"Mesh.Algorithm\", 5);\n"
                    "Printf(\"%g %g\", Mesh.Algorithm, GetNumber(\"Mesh.Algorithm\"));"),
            "6 5\n");
  EXPECT_EQ(printed("Printf(\"%g\", GetNumber(\"Mesh.Algorithm\"));"), "0\n");
  EXPECT_EQ(printed("x = GetValue(\"Size?\", 0.5); Printf(\"%g\", x);"),
            "Size? (default=0.5): 0.5\n");
}

TEST(Parameters, ExistsAndFileExists) {
  EXPECT_EQ(printed("a = 1; Printf(\"%g %g\", Exists(a), Exists(bb));"), "1 0\n");
  EXPECT_EQ(printed("Printf(\"%g\", FileExists(\"surely/not/here.geo\"));"), "0\n");
}

}  // namespace
}  // namespace geomesh::testing
