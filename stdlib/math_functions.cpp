// The table of numeric built-in functions (Sin, Atan2, Round, Rand, ...) and their arities.
#include "stdlib/math_functions.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace geomesh {

namespace {

using Args = std::span<const double>;

// A number drawn uniformly from [0, x).
double drawUpTo(Args x, RandomEngine& random) {
  return std::uniform_real_distribution<double>(0.0, 1.0)(random) * x[0];
}

// One row per function: name, number of arguments, body. Round rounds halves up (-2.5 -> -2),
// Step is 1 from 0 on, Sign is 0 at 0.
constexpr MathFunction kMathFunctions[] = {
    {"Exp", 1, [](Args x, RandomEngine&) { return std::exp(x[0]); }},
    {"Log", 1, [](Args x, RandomEngine&) { return std::log(x[0]); }},
    {"Log10", 1, [](Args x, RandomEngine&) { return std::log10(x[0]); }},
    {"Sqrt", 1, [](Args x, RandomEngine&) { return std::sqrt(x[0]); }},
    {"Sin", 1, [](Args x, RandomEngine&) { return std::sin(x[0]); }},
    {"Cos", 1, [](Args x, RandomEngine&) { return std::cos(x[0]); }},
    {"Tan", 1, [](Args x, RandomEngine&) { return std::tan(x[0]); }},
    {"Asin", 1, [](Args x, RandomEngine&) { return std::asin(x[0]); }},
    {"ArcSin", 1, [](Args x, RandomEngine&) { return std::asin(x[0]); }},
    {"Acos", 1, [](Args x, RandomEngine&) { return std::acos(x[0]); }},
    {"ArcCos", 1, [](Args x, RandomEngine&) { return std::acos(x[0]); }},
    {"Atan", 1, [](Args x, RandomEngine&) { return std::atan(x[0]); }},
    {"ArcTan", 1, [](Args x, RandomEngine&) { return std::atan(x[0]); }},
    {"Sinh", 1, [](Args x, RandomEngine&) { return std::sinh(x[0]); }},
    {"Cosh", 1, [](Args x, RandomEngine&) { return std::cosh(x[0]); }},
    {"Tanh", 1, [](Args x, RandomEngine&) { return std::tanh(x[0]); }},
    {"Asinh", 1, [](Args x, RandomEngine&) { return std::asinh(x[0]); }},
    {"Acosh", 1, [](Args x, RandomEngine&) { return std::acosh(x[0]); }},
    {"Atanh", 1, [](Args x, RandomEngine&) { return std::atanh(x[0]); }},
    {"Fabs", 1, [](Args x, RandomEngine&) { return std::fabs(x[0]); }},
    {"Abs", 1, [](Args x, RandomEngine&) { return std::fabs(x[0]); }},
    {"Floor", 1, [](Args x, RandomEngine&) { return std::floor(x[0]); }},
    {"Ceil", 1, [](Args x, RandomEngine&) { return std::ceil(x[0]); }},
    {"Round", 1, [](Args x, RandomEngine&) { return std::floor(x[0] + 0.5); }},
    {"Step", 1, [](Args x, RandomEngine&) { return x[0] >= 0 ? 1.0 : 0.0; }},
    {"Sign", 1, [](Args x, RandomEngine&) { return x[0] > 0 ? 1.0 : (x[0] < 0 ? -1.0 : 0.0); }},
    {"Atan2", 2, [](Args x, RandomEngine&) { return std::atan2(x[0], x[1]); }},
    {"ArcTan2", 2, [](Args x, RandomEngine&) { return std::atan2(x[0], x[1]); }},
    {"Fmod", 2, [](Args x, RandomEngine&) { return std::fmod(x[0], x[1]); }},
    {"Modulo", 2, [](Args x, RandomEngine&) { return std::fmod(x[0], x[1]); }},
    {"Hypot", 2, [](Args x, RandomEngine&) { return std::hypot(x[0], x[1]); }},
    {"Max", 2, [](Args x, RandomEngine&) { return std::fmax(x[0], x[1]); }},
    {"Min", 2, [](Args x, RandomEngine&) { return std::fmin(x[0], x[1]); }},
    {"Rand", 1, drawUpTo},
};

}  // namespace

std::span<const MathFunction> mathFunctions() { return kMathFunctions; }

const MathFunction* findMathFunction(std::string_view name) {
  for (const auto& function : kMathFunctions)
    if (function.name == name) return &function;
  return nullptr;
}

double applyMathFunction(const MathFunction& function, std::span<const double> args,
                         RandomEngine& random) {
  const std::size_t count = function.arguments;
  if (args.size() != count)
    throw std::invalid_argument("'" + std::string(function.name) + "' takes " +
                                std::to_string(count) + " argument" + (count == 1 ? "" : "s") +
                                ", not " + std::to_string(args.size()));
  return function.apply(args, random);
}

}  // namespace geomesh
