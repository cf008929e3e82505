#pragma once

#include <optional>
#include <random>
#include <span>
#include <string_view>

namespace geomesh {

// Where Rand() draws from: one generator per session, so runs are reproducible.
using RandomEngine = std::mt19937_64;

// Evaluates the numeric built-in function `name` (Sin, Atan2, Max, Round, ...) on `args`.
// Returns nullopt when `name` is not a numeric built-in. Throws std::invalid_argument when
// the number of arguments is wrong (the message says how many are expected).
std::optional<double> callMathFunction(std::string_view name, std::span<const double> args,
                                       RandomEngine& random);

// Whether `name` is a numeric built-in function.
bool isMathFunction(std::string_view name);

}  // namespace geomesh
