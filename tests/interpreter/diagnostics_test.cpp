// Tests of script diagnostics: caret lines, syntax errors, include chains.
#include <gtest/gtest.h>

#include "interpreter/diagnostics.h"
#include "script_runner.h"

namespace geomesh::testing {
namespace {

TEST(Diagnostics, FormatWithCaretUnderTheColumn) {
  EXPECT_EQ(formatDiagnostic({"f.geo", 3, 5}, "error", "bad", "a = b;"),
            "f.geo:3:5: error: bad\na = b;\n    ^");
}

TEST(Diagnostics, TabsAreKeptInTheCaretLine) {
  EXPECT_EQ(errorOf("\tx = \ty;"),
            "test.geo:1:7: error: undefined variable 'y'\n\tx = \ty;\n\t    \t^");
}

TEST(Diagnostics, SyntaxErrorsBecomeScriptErrors) {
  EXPECT_EQ(errorOf("a = 1;\nb = (2;\n"),
            "test.geo:2:7: error: unexpected ';', expected ')' or ','\nb = (2;\n      ^");
  EXPECT_EQ(errorOf("a = 1\nb = 2;"),
            "test.geo:1:6: error: expected ';' after '1' (found 'b')\na = 1\n     ^");
}

TEST(Diagnostics, UnterminatedCommentPointsAtItsStart) {
  EXPECT_EQ(errorOf("a = 1;\n  /* open\nb = 2;"),
            "test.geo:2:3: error: unterminated block comment\n  /* open\n  ^");
}

TEST(Diagnostics, IncludedFromLinesAreAppended) {
  ScriptError error({"in.geo", 1, 2}, "oops", "xyz");
  error.addIncludedFrom({"main.geo", 4, 1});
  EXPECT_STREQ(error.what(), "in.geo:1:2: error: oops\nxyz\n ^\n  included from main.geo:4:1");
  EXPECT_EQ(error.message(), "oops");
}

TEST(Diagnostics, DivisionByZeroInModulo) {
  EXPECT_EQ(firstLineOf("x = 5 % 0;"), "test.geo:1:7: error: modulo by zero");
}

}  // namespace
}  // namespace geomesh::testing
