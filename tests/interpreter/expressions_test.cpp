// Tests of expressions: operator precedence, modulo, comparisons, variables, math functions.
#include <gtest/gtest.h>

#include "script_runner.h"

namespace geomesh::testing {
namespace {

TEST(Expressions, ArithmeticPrecedence) {
  EXPECT_EQ(printed("Printf(\"%g\", 1 + 2 * 3);"), "7\n");
  EXPECT_EQ(printed("Printf(\"%g\", (1 + 2) * 3);"), "9\n");
  EXPECT_EQ(printed("Printf(\"%g\", 10 - 2 - 3);"), "5\n");
  EXPECT_EQ(printed("Printf(\"%g\", 5 / 2);"), "2.5\n");
}

TEST(Expressions, PowerBindsTighterThanUnaryMinusAndIsRightAssociative) {
  EXPECT_EQ(printed("Printf(\"%g\", -2^2);"), "-4\n");
  EXPECT_EQ(printed("Printf(\"%g\", 2^3^2);"), "512\n");
  EXPECT_EQ(printed("Printf(\"%g\", 2^-1);"), "0.5\n");
}

TEST(Expressions, ModuloWorksOnIntegers) {
  EXPECT_EQ(printed("Printf(\"%g\", 7 % 3);"), "1\n");
  EXPECT_EQ(printed("Printf(\"%g\", 7.5 % 2);"), "1\n");
  EXPECT_EQ(printed("Printf(\"%g\", -3 % 2);"), "-1\n");
  EXPECT_EQ(printed("Printf(\"%g\", 2 * 3 % 4);"), "2\n");
}

TEST(Expressions, ComparisonsAndLogic) {
  EXPECT_EQ(printed("Printf(\"%g %g\", 1 < 2 == 1, 3);"), "1 3\n");
  EXPECT_EQ(printed("Printf(\"%g\", 1 && 0 || 1);"), "1\n");
  EXPECT_EQ(printed("Printf(\"%g\", !0 + 1);"), "2\n");
  EXPECT_EQ(printed("Printf(\"%g %g %g %g\", 2 >= 2, 2 <= 1, 3 != 3, 2 > 1);"), "1 0 0 1\n");
}

TEST(Expressions, TernaryIsRightAssociative) {
  EXPECT_EQ(printed("Printf(\"%g\", 1 ? 2 : 3);"), "2\n");
  EXPECT_EQ(printed("Printf(\"%g\", 2 ? 3 : 4 ? 5 : 6);"), "3\n");
  EXPECT_EQ(printed("Printf(\"%g\", 0 ? 3 : 0 ? 5 : 6);"), "6\n");
}

TEST(Expressions, PrecedenceMatrixAsTheReferencePrintsIt) {
  EXPECT_EQ(printed("a = 3; b = 0;\n"
                    "Printf(\"%g %g %g %g\", -1 ? 2 : 3, !a == b, 1 < 2 < 3, 2 * -3);\n"
                    "Printf(\"%g %g %g %g\", - - 2, 3 - -2, 2^0.5, 7 % -3);\n"
                    "Printf(\"%g %g %g %g\", 5 / 2 * 2, 1 == 1 && 2, 0 || 0, 2 + 3 * 4 ^ 2 / 8 % 5);\n"
                    "Printf(\"%g %g %g\", 1 ? 0 ? 5 : 6 : 7, (1 + 2) * (3 - 4), 10 % 4 * 3);\n"
                    "Printf(\"%g %g\", -2 ^ -2, !0 * 5);\n"
                    "Printf(\"%g %g\", 1 + (a > 2), a >= 3 == 1);"),
            "2 1 1 -6\n2 5 1.41421 1\n5 1 0 3\n6 -3 6\n-0.25 5\n2 1\n");
}

TEST(Expressions, DivisionByZeroIsAnError) {
  EXPECT_EQ(firstLineOf("x = 1;\ny = x / 0;"), "test.geo:2:7: error: division by zero");
}

TEST(Expressions, Variables) {
  EXPECT_EQ(printed("a = 2; b = a * 3; Printf(\"%g\", b);"), "6\n");
  EXPECT_EQ(printed("a = 1; a += 2; a *= 4; a -= 1; a /= 11; Printf(\"%g\", a);"), "1\n");
  EXPECT_EQ(printed("i = 1; i++; i++; i--; Printf(\"%g\", i);"), "2\n");
}

TEST(Expressions, UndefinedVariableIsAnErrorWithSuggestion) {
  std::string error = errorOf("length = 1;\nx = lenght * 2;");
  EXPECT_EQ(error,
            "test.geo:2:5: error: undefined variable 'lenght'; did you mean 'length'?\n"
            "x = lenght * 2;\n"
            "    ^");
}

TEST(Expressions, MathFunctions) {
  EXPECT_EQ(printed("Printf(\"%g %g %g\", Fabs(-2), Floor(2.5), Ceil(2.5));"), "2 2 3\n");
  EXPECT_EQ(printed("Printf(\"%g %g\", Round(2.5), Round(-2.5));"), "3 -2\n");
  EXPECT_EQ(printed("Printf(\"%g %g\", Fmod(7.5, 2), Modulo(-7, 3));"), "1.5 -1\n");
  EXPECT_EQ(printed("Printf(\"%g %g\", Hypot(3,4), Atan2(1,1));"), "5 0.785398\n");
  EXPECT_EQ(printed("Printf(\"%g %g\", Max(2,3), Min(2,3));"), "3 2\n");
  EXPECT_EQ(printed("Printf(\"%g %g\", Step(0.5), Log10(100));"), "1 2\n");
  EXPECT_EQ(printed("Printf(\"%g %g %g\", Asin(1), Acos(1), Atan(1));"), "1.5708 0 0.785398\n");
  EXPECT_EQ(printed("Printf(\"%g %g\", Exp(1), Sqrt(16));"), "2.71828 4\n");
  EXPECT_EQ(printed("Printf(\"%g %g %g\", Sinh(1), Cosh(1), Tanh(1));"), "1.1752 1.54308 0.761594\n");
  EXPECT_EQ(printed("Printf(\"%g\", Rand(1) < 1);"), "1\n");
}

TEST(Expressions, UnknownFunctionIsAnError) {
  EXPECT_EQ(firstLineOf("x = Sinn(1);"),
            "test.geo:1:5: error: unknown function 'Sinn'; did you mean 'Sin'?");
}

TEST(Expressions, Constants) {
  EXPECT_EQ(printed("Printf(\"%.5f\", Pi);"), "3.14159\n");
  EXPECT_EQ(printed("Printf(\"%g %g %g\", GMSH_MAJOR_VERSION, MPI_Size, MPI_Rank);"), "4 1 0\n");
}

}  // namespace
}  // namespace geomesh::testing
