// Tests of ranges, math functions, printf formatting and edit distance.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "stdlib/edit_distance.h"
#include "stdlib/format.h"
#include "stdlib/math_functions.h"
#include "stdlib/ranges.h"

namespace geomesh {
namespace {

std::vector<double> range(double a, double b, std::optional<double> step = std::nullopt) {
  return expandRange(a, b, step);
}

TEST(Ranges, DirectionAndStep) {
  EXPECT_EQ(range(1, 3), (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(range(3, 1), (std::vector<double>{3, 2, 1}));
  EXPECT_EQ(range(10, 6, -2), (std::vector<double>{10, 8, 6}));
  EXPECT_TRUE(range(1, 3, -1).empty());
  EXPECT_EQ(range(0, 1, 0.3).size(), 4u);
  EXPECT_EQ(range(0, 1, 0.1).size(), 11u);
  EXPECT_THROW(range(0, 1, 0), std::invalid_argument);
}

// Values grow by repeated addition and stop once past the end, without tolerance (Gmsh's
// rule): 0:0.3:0.1 stops before 0.30000000000000004.
TEST(Ranges, FractionalStepsAccumulateLikeGmsh) {
  EXPECT_EQ(range(0, 0.3, 0.1).size(), 3u);
  EXPECT_EQ(range(0, 1, 0.1).back(), 0.1 + 0.1 + 0.1 + 0.1 + 0.1 + 0.1 + 0.1 + 0.1 + 0.1 + 0.1);
  EXPECT_EQ(range(0.1, 0.35, 0.05).size(), 6u);
  EXPECT_EQ(range(1, 0, -0.25), (std::vector<double>{1, 0.75, 0.5, 0.25, 0}));
  EXPECT_THROW(range(0, 1e9, 1), std::invalid_argument);
}

TEST(Ranges, LinAndLogSpace) {
  EXPECT_EQ(linSpace(0, 1, 5), (std::vector<double>{0, 0.25, 0.5, 0.75, 1}));
  EXPECT_DOUBLE_EQ(logSpace(0, 2, 3)[2], 100);
}

TEST(MathFunctions, GmshSemantics) {
  RandomEngine random;
  auto call = [&](std::string_view name, std::vector<double> args) {
    const MathFunction* function = findMathFunction(name);
    if (!function) throw std::logic_error("no math function " + std::string(name));
    return applyMathFunction(*function, args, random);
  };
  EXPECT_EQ(call("Round", {2.5}), 3);
  EXPECT_EQ(call("Round", {-2.5}), -2);
  EXPECT_EQ(call("Modulo", {-7, 3}), -1);
  EXPECT_EQ(call("Step", {0.5}), 1);
  EXPECT_EQ(call("Step", {-0.5}), 0);
  EXPECT_DOUBLE_EQ(call("Atan2", {1, 1}), M_PI / 4);
  EXPECT_EQ(call("Hypot", {3, 4}), 5);
  double r = call("Rand", {2});
  EXPECT_GE(r, 0);
  EXPECT_LT(r, 2);
  EXPECT_EQ(findMathFunction("Nope"), nullptr);
  EXPECT_THROW(call("Sin", {1, 2}), std::invalid_argument);
}

// Each row's body takes as many numbers as the row says: a wrong count is refused before the
// body could read past its arguments, with the row's count in the message.
TEST(MathFunctions, EveryRowChecksItsArgumentCount) {
  RandomEngine random;
  for (const MathFunction& function : mathFunctions()) {
    EXPECT_EQ(findMathFunction(function.name), &function) << function.name;
    ASSERT_TRUE(function.arguments == 1 || function.arguments == 2) << function.name;
    const std::vector<double> right(function.arguments, 0.5);
    EXPECT_NO_THROW(applyMathFunction(function, right, random)) << function.name;
    const std::vector<double> wrong(function.arguments + 1, 0.5);
    try {
      applyMathFunction(function, wrong, random);
      ADD_FAILURE() << function.name << " accepted " << wrong.size() << " arguments";
    } catch (const std::invalid_argument& error) {
      const std::string expected = "'" + std::string(function.name) + "' takes " +
                                   std::to_string(function.arguments) + " argument" +
                                   (function.arguments == 1 ? "" : "s") + ", not " +
                                   std::to_string(wrong.size());
      EXPECT_EQ(error.what(), expected);
    }
  }
}

std::string fmt(std::string_view format, std::vector<FormatArgument> args) {
  return formatPrintf(format, args);
}

TEST(Format, CConversions) {
  EXPECT_EQ(fmt("%g %f %e", {1.5, 2.0, 3.0}), "1.5 2.000000 3.000000e+00");
  EXPECT_EQ(fmt("%d|%5.2f|%-4d|%03d", {3.7, 2.0, 7.0, 5.0}), "3| 2.00|7   |005");
  EXPECT_EQ(fmt("%x %o %c", {255.0, 8.0, 65.0}), "ff 10 A");
  EXPECT_EQ(fmt("%s=%g", {std::string("a"), 1.0}), "a=1");
  EXPECT_EQ(fmt("100%%", {}), "100%");
  EXPECT_EQ(fmt("%ld %lf", {4.0, 0.5}), "4 0.500000");
}

TEST(Format, ArgumentCountMismatchesThrow) {
  EXPECT_THROW(fmt("%g %g", {1.0}), std::invalid_argument);
  EXPECT_THROW(fmt("%g", {1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(fmt("%y", {1.0}), std::invalid_argument);
  EXPECT_THROW(fmt("%d", {std::string("x")}), std::invalid_argument);
}

TEST(EditDistance, DistancesAndSuggestions) {
  EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
  EXPECT_EQ(editDistance("abc", "ABC"), 0u);
  std::vector<std::string> names{"length", "width", "height"};
  EXPECT_EQ(closestNames("lenght", names).front(), "length");
  EXPECT_EQ(closestNames("widht", names, 1), (std::vector<std::string>{"width"}));
  EXPECT_TRUE(closestNames("zzz", names).empty());
}

}  // namespace
}  // namespace geomesh
