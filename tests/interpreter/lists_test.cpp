// Tests of lists: ranges, indexing, append and removal, list functions, item-wise arithmetic.
#include <gtest/gtest.h>

#include "script_runner.h"

namespace geomesh::testing {
namespace {

TEST(Lists, RangesAscendingDescendingAndFractional) {
  EXPECT_EQ(printed("x[] = {1:3, 10:6:-2};\n"
                    "Printf(\"%g %g %g %g %g %g n=%g\", x[0], x[1], x[2], x[3], x[4], x[5], #x[]);"),
            "1 2 3 10 8 6 n=6\n");
  EXPECT_EQ(printed("z[] = {3:1}; Printf(\"%g %g %g\", z[0], z[1], z[2]);"), "3 2 1\n");
  EXPECT_EQ(printed("y[] = {0:1:0.3}; Printf(\"n %g\", #y[]);"), "n 4\n");
  EXPECT_EQ(printed("w[] = {0:1:0.1}; Printf(\"n %g\", #w[]);"), "n 11\n");
  EXPECT_EQ(printed("e[] = {1:3:-1}; Printf(\"n %g\", #e[]);"), "n 0\n");
}

TEST(Lists, IndexingWithListsAndOldSyntax) {
  EXPECT_EQ(printed("x[] = {5:9}; y[] = x[{1:3}]; Printf(\"%g %g %g\", y[0], y[1], y[2]);"),
            "6 7 8\n");
  EXPECT_EQ(printed("l[] = {1,2,3}; Printf(\"%g %g\", l(1), #l());"), "2 3\n");
}

// As the reference: f({i:j}) and f[{i, j}] are the items at those indices, wherever a list
// may stand.
TEST(Lists, OldSyntaxIndexedByAList) {
  const std::string f = "f() = {10, 20, 30, 40};\n";
  EXPECT_EQ(printed(f + "g() = f({1:2}); Printf(\"%g %g n=%g\", g(0), g(1), #g());"),
            "20 30 n=2\n");
  EXPECT_EQ(printed(f + "g() = f({3, 0, 3}); Printf(\"%g %g %g\", g(0), g(1), g(2));"),
            "40 10 40\n");
  EXPECT_EQ(printed(f + "i() = {1, 2}; g() = f({i()}); Printf(\"%g %g\", g(0), g(1));"), "20 30\n");
  EXPECT_EQ(printed(f + "g() = {f({1:2}), 5}; Printf(\"%g %g %g\", g(0), g(1), g(2));"),
            "20 30 5\n");
  EXPECT_EQ(printed(f + "g() = -f({0, 1}); Printf(\"%g %g\", g(0), g(1));"), "-10 -20\n");
  EXPECT_EQ(printed(f + "x = f({2}); Printf(\"%g\", x);"), "30\n");
  EXPECT_EQ(firstLineOf(f + "g() = f({1:4});"),
            "test.geo:2:9: error: index 4 out of range for 'f' (4 items)");
  EXPECT_EQ(firstLineOf(f + "g() = f(4);"),
            "test.geo:2:9: error: index 4 out of range for 'f' (4 items)");
}

TEST(Lists, AppendRemoveAndGrow) {
  EXPECT_EQ(printed("z[] = {}; z[] += {4, 5}; z[] += 6; Printf(\"n=%g last=%g\", #z[], z[2]);"),
            "n=3 last=6\n");
  EXPECT_EQ(printed("c[] = {1,2,3,2}; c[] -= {2}; Printf(\"n=%g %g\", #c[], c[1]);"), "n=3 3\n");
  EXPECT_EQ(printed("d = 3; d[] += {4}; Printf(\"n=%g\", #d[]);"), "n=2\n");
  EXPECT_EQ(printed("b[] = {1,2}; b[4] = 7; Printf(\"n=%g %g\", #b[], b[3]);"), "n=5 0\n");
  EXPECT_EQ(printed("b[] = {1,2}; b[{0,1}] = {5,6}; Printf(\"%g %g\", b[0], b[1]);"), "5 6\n");
  EXPECT_EQ(printed("b[] = {1,2}; b[1] += 3; Printf(\"%g\", b[1]);"), "5\n");
}

TEST(Lists, ListFunctions) {
  EXPECT_EQ(printed("l[] = LinSpace(0, 1, 5); Printf(\"%g %g\", l[1], #l[]);"), "0.25 5\n");
  EXPECT_EQ(printed("g[] = LogSpace(0, 2, 3); Printf(\"%g\", g[2]);"), "100\n");
  EXPECT_EQ(printed("v[] = {3,1,3,2}; w[] = Unique(v[]); "
                    "Printf(\"%g %g %g n=%g\", w[0], w[1], w[2], #w[]);"),
            "1 2 3 n=3\n");
}

TEST(Lists, ArithmeticItemByItem) {
  EXPECT_EQ(printed("a[] = {1,2} * 2; Printf(\"%g %g\", a[0], a[1]);"), "2 4\n");
  EXPECT_EQ(printed("a[] = {1,2} + {10,20}; Printf(\"%g %g\", a[0], a[1]);"), "11 22\n");
}

TEST(Lists, NameSuffixes) {
  EXPECT_EQ(printed("a~{1} = 3; a~{2}~{3} = 4; Printf(\"%g %g\", a_1, a_2_3);"), "3 4\n");
  EXPECT_EQ(printed("For i In {1:2}\n b~{i} = i * 10;\nEndFor\nPrintf(\"%g\", b~{2});"), "20\n");
}

TEST(Lists, OutOfRangeIndexIsAnErrorNamingTheList) {
  EXPECT_EQ(firstLineOf("x[] = {1, 2};\ny = x[2];"),
            "test.geo:2:7: error: index 2 out of range for 'x' (2 items)");
  EXPECT_EQ(firstLineOf("y = q[0];"), "test.geo:1:5: error: undefined variable 'q'");
}

TEST(Lists, PrintfWithAListConsumesItsItems) {
  EXPECT_EQ(printed("x[] = {1, 2}; Printf(\"%g-%g\", x[]);"), "1-2\n");
  EXPECT_EQ(firstLineOf("x[] = {1, 2, 3}; Printf(\"%g\", x[]);"),
            "test.geo:1:18: error: 2 extra arguments for the format");
}

}  // namespace
}  // namespace geomesh::testing
