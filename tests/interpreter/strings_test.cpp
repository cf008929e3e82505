// Tests of string functions, escapes, Printf formats and GetEnv.
#include <gtest/gtest.h>

#include "script_runner.h"

namespace geomesh::testing {
namespace {

TEST(Strings, Functions) {
  EXPECT_EQ(printed("Printf(StrPrefix(\"a/b.c.geo\"));"), "a/b.c\n");
  EXPECT_EQ(printed("Printf(StrRelative(\"a/b/c.geo\"));"), "c.geo\n");
  EXPECT_EQ(printed("Printf(StrSub(\"abcdef\", 2, 3));"), "cde\n");
  EXPECT_EQ(printed("Printf(StrSub(\"abcdef\", 2));"), "cdef\n");
  EXPECT_EQ(printed("Printf(\"%g\", StrLen(\"abc\"));"), "3\n");
  EXPECT_EQ(printed("Printf(\"%g %g\", StrFind(\"abcabc\", \"ca\"), StrFind(\"abc\", \"z\"));"),
            "1 0\n");
  EXPECT_EQ(printed("Printf(\"%g %g\", StrCmp(\"a\", \"b\"), StrCmp(\"b\",\"a\"));"), "-1 1\n");
  EXPECT_EQ(printed("Printf(StrChoice(0, \"yes\", \"no\"));"), "no\n");
  EXPECT_EQ(printed("Printf(UpperCase(\"aBc\"));"), "ABC\n");
  EXPECT_EQ(printed("Printf(DirName(\"x/y/z.geo\"));"), "x/y/\n");
  EXPECT_EQ(printed("Printf(Sprintf(\"v=%g w=%g\", 1.5, 2));"), "v=1.5 w=2\n");
  EXPECT_EQ(printed("Printf(StrCat(\"a\", \"b\", \"c\"));"), "abc\n");
  EXPECT_EQ(printed("a = 3; Printf(NameToString(a));"), "a\n");
  EXPECT_EQ(printed("Printf(StrReplace(\"a-b-c\", \"-\", \"+\"));"), "a+b+c\n");
}

TEST(Strings, VariablesAndEscapes) {
  EXPECT_EQ(printed("s = \"abc\"; Printf(StrCat(s, \"x\"));"), "abcx\n");
  // Backslash sequences are kept as written.
  EXPECT_EQ(printed("Printf(\"a\\tb\\\\n\");"), "a\\tb\\\\n\n");
}

TEST(Strings, PrintfFormats) {
  EXPECT_EQ(printed("Printf(\"%d %5.2f %e\", 3.7, 2, 3);"), "3  2.00 3.000000e+00\n");
  EXPECT_EQ(printed("Printf(\"%g%%\", 50);"), "50%\n");
}

TEST(Strings, GetEnv) {
  EXPECT_EQ(printed("Printf(GetEnv(\"GEOMESH_SURELY_UNSET_VARIABLE\"));"), "\n");
}

TEST(Strings, TypeErrorsAreReported) {
  EXPECT_EQ(firstLineOf("x = \"a\" + 1;"),
            "test.geo:1:9: error: '+' cannot combine a string and a number");
  EXPECT_EQ(firstLineOf("Printf(StrLen(3));"), "test.geo:1:15: error: expected a string, not a number");
}

}  // namespace
}  // namespace geomesh::testing
