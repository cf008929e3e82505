// Runaway scripts end with a diagnostic; the limits are options a script can change.
#include <gtest/gtest.h>

#include "script_runner.h"

namespace geomesh::testing {
namespace {

TEST(ResourceLimits, LoopIterationLimitIsAnOption) {
  const std::string error = errorOf("General.MaxLoopIterations = 100;\nFor i In {1:101}\nEndFor\n");
  EXPECT_NE(error.find("test.geo:2:1: error: loop has more than 100 iterations"), std::string::npos)
      << error;
  EXPECT_EQ(printed("General.MaxLoopIterations = 100;\nn = 0;\nFor i In {1:100}\n n++;\nEndFor\n"
                    "Printf(\"%g\", n);"),
            "100\n");
}

TEST(ResourceLimits, DefaultLoopLimitStopsARunawayLoop) {
  const std::string error = errorOf("For i In {1:1e12}\nEndFor\n");
  EXPECT_NE(error.find("test.geo:1:1: error: loop has more than 10000000 iterations"),
            std::string::npos)
      << error;
}

// Numbers far outside the integers' range, where a script asks for an integer: clamped, never
// an overflow (the sanitizer build checks that no conversion overflows).
TEST(ResourceLimits, HugeNumbersWhereIntegersAreExpected) {
  EXPECT_EQ(printed("Printf(\"%g\", 4.4e60 % 7);"), "0\n");
  EXPECT_EQ(printed("Printf(\"%g\", -1e300 % -1);"), "0\n");
  EXPECT_EQ(printed("Printf(\"%g\", 7 % 1e300);"), "7\n");
  EXPECT_NE(firstLineOf("a[] = {1, 2};\nb = a[1e300];").find("out of range"), std::string::npos);
  EXPECT_NE(firstLineOf("a[] = {1, 2};\nb = a[-1e300];").find("out of range"), std::string::npos);
  EXPECT_EQ(printed("x~{1e300} = 3;\nPrintf(\"%g\", x~{1e300});"), "3\n");
  // Arithmetic with an empty list (found by fuzzing) is an error, not a read past its end.
  EXPECT_NE(firstLineOf("e[] = {};\nx = e[] + 1;").find("'+' on an empty list"), std::string::npos);
  EXPECT_NE(firstLineOf("e[] = {};\nx = 2 ^ e[];").find("'^' on an empty list"), std::string::npos);
  // Tags and layer counts beyond the integers: a diagnostic or a result, never a crash.
  for (const char* script :
       {"Point(1e300) = {0, 0, 0};", "Point(-1e300) = {0, 0, 0};",
        "Point(1) = {0, 0, 0};\nPoint(2) = {1, 0, 0};\nLine(1) = {1, 2};\n"
        "Extrude {0, 1, 0} { Curve{1}; Layers{1e300}; }",
        "Mesh.Algorithm = 1e300;\nMesh.MinimumCircleNodes = -1e300;"})
    EXPECT_NO_THROW(errorOf(script)) << script;
}

TEST(ResourceLimits, MacroDepthLimitIsAnOption) {
  const std::string script =
      "General.MaxMacroDepth = 5;\nn = 0;\nMacro m\n  n++;\n  If (n < LIMIT)\n    Call m;\n  EndIf\n"
      "Return\nCall m;\nPrintf(\"%g\", n);";
  auto with = [&](const std::string& limit) {
    std::string s = script;
    s.replace(s.find("LIMIT"), 5, limit);
    return s;
  };
  EXPECT_EQ(printed(with("5")), "5\n");
  const std::string error = errorOf(with("6"));
  EXPECT_NE(error.find("test.geo:6:5: error: macro calls nested deeper than 5"), std::string::npos)
      << error;
}

}  // namespace
}  // namespace geomesh::testing
