// callMathFunction: the numeric built-in functions of scripts, with a per-session Rand().
#pragma once

#include <cstddef>
#include <random>
#include <span>
#include <string_view>

namespace geomesh {

// Where Rand() draws from: one generator per session, so runs are reproducible.
using RandomEngine = std::mt19937_64;

// A numeric built-in function (Sin, Atan2, Max, Round, Rand, ...), one row of the math
// library: its name, how many numbers it takes, and what it computes from them.
struct MathFunction {
  std::string_view name;
  std::size_t arguments;
  double (*apply)(std::span<const double> args, RandomEngine& random);
};

// Every numeric built-in function, in the order of the library's table.
std::span<const MathFunction> mathFunctions();

// The row of the numeric built-in `name`, or null when there is none.
const MathFunction* findMathFunction(std::string_view name);

// Applies `function` to `args`. Throws std::invalid_argument when the number of arguments is
// wrong (the message says how many are expected).
double applyMathFunction(const MathFunction& function, std::span<const double> args,
                         RandomEngine& random);

}  // namespace geomesh
