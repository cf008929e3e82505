// Tests of For, If, macros and Call, recursion and loop limits, Exit, Abort and Error.
#include <gtest/gtest.h>

#include "script_runner.h"

namespace geomesh::testing {
namespace {

TEST(ControlFlow, ForLoopsOverRanges) {
  EXPECT_EQ(printed("For i In {1:3}\n  Printf(\"i=%g\", i);\nEndFor\nPrintf(\"after %g\", i);"),
            "i=1\ni=2\ni=3\nafter 4\n");
  EXPECT_EQ(printed("For j In {5:1:-2}\n Printf(\"%g\", j);\nEndFor\nPrintf(\"%g\", j);"),
            "5\n3\n1\n-1\n");
  EXPECT_EQ(printed("For (1:2)\n Printf(\"x\");\nEndFor"), "x\nx\n");
  // A loop from 1 to 0 with the default step does not run.
  EXPECT_EQ(printed("For i In {1:0}\nPrintf(\"never\");\nEndFor\nPrintf(\"i=%g\", i);"), "i=1\n");
}

TEST(ControlFlow, ForLoopOverAList) {
  EXPECT_EQ(printed("l[] = {4, 8}; For i In {l[]}\n Printf(\"%g\", i);\nEndFor"), "4\n8\n");
}

TEST(ControlFlow, IfElseIfElse) {
  EXPECT_EQ(printed("t = 0;\nFor i In {1:10}\n  If (i % 2 == 0) t += i; ElseIf (i == 5) t += 100; "
                    "Else t -= 1; EndIf\nEndFor\nPrintf(\"t=%g\", t);"),
            "t=126\n");
}

TEST(ControlFlow, MacrosAndCalls) {
  EXPECT_EQ(printed("Macro Add\n  cnt = cnt + 1;\nReturn\ncnt = 0;\nCall Add;\nCall Add;\n"
                    "Call \"Add\";\nPrintf(\"cnt=%g\", cnt);"),
            "cnt=3\n");
  EXPECT_EQ(printed("Function F\n  r = 2 * x;\nReturn\nx = 4; Call F; Printf(\"%g\", r);"), "8\n");
}

// As in Gmsh, Call Name; means the macro Name even when a variable holds another name.
TEST(ControlFlow, CallByNameIgnoresVariables) {
  EXPECT_EQ(printed("Macro A\n Printf(\"A\");\nReturn\nMacro B\n Printf(\"B\");\nReturn\n"
                    "A = \"B\";\nCall A;\nwhich = \"B\";\nCall StrCat(which);\n"),
            "A\nB\n");
  EXPECT_EQ(firstLineOf("Macro B\nReturn\nname = \"B\";\nCall name;\n"),
            "test.geo:4:6: error: unknown macro 'name'");
}

TEST(ControlFlow, UnknownMacroIsAnError) {
  EXPECT_EQ(firstLineOf("Macro Add\nReturn\nCall Ad;"),
            "test.geo:3:6: error: unknown macro 'Ad'; did you mean 'Add'?");
}

TEST(ControlFlow, RecursionDepthIsLimited) {
  std::string error = firstLineOf("Macro R\n  Call R;\nReturn\nCall R;");
  EXPECT_NE(error.find("error: macro calls nested deeper than"), std::string::npos) << error;
  EXPECT_EQ(error.substr(0, 14), "test.geo:2:3: ");
}

TEST(ControlFlow, LoopIterationLimit) {
  std::string error = firstLineOf("For i In {1:1e9}\nEndFor");
  EXPECT_NE(error.find("loop has more than"), std::string::npos) << error;
}

TEST(ControlFlow, ExitStopsWithoutError) {
  ScriptRun run;
  EXPECT_THROW(run.run("Printf(\"a\");\nExit;\nPrintf(\"b\");"), ScriptExit);
  EXPECT_EQ(run.out.str(), "a\n");
}

TEST(ControlFlow, AbortStopsTheScriptQuietly) {
  EXPECT_EQ(printed("Printf(\"a\");\nAbort;\nPrintf(\"b\");"), "a\n");
}

TEST(ControlFlow, ErrorStatementFailsAtItsLocation) {
  EXPECT_EQ(firstLineOf("x = 3;\nError(\"bad value %g\", x);"),
            "test.geo:2:1: error: bad value 3");
}

}  // namespace
}  // namespace geomesh::testing
