#include "stdlib/math_functions.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace geomesh {

namespace {

struct Unary {
  std::string_view name;
  double (*apply)(double);
};

struct Binary {
  std::string_view name;
  double (*apply)(double, double);
};

double roundHalfUp(double x) { return std::floor(x + 0.5); }
double heaviside(double x) { return x >= 0 ? 1 : 0; }
double sign(double x) { return x > 0 ? 1 : (x < 0 ? -1 : 0); }

constexpr Unary kUnary[] = {
    {"Exp", [](double x) { return std::exp(x); }},
    {"Log", [](double x) { return std::log(x); }},
    {"Log10", [](double x) { return std::log10(x); }},
    {"Sqrt", [](double x) { return std::sqrt(x); }},
    {"Sin", [](double x) { return std::sin(x); }},
    {"Cos", [](double x) { return std::cos(x); }},
    {"Tan", [](double x) { return std::tan(x); }},
    {"Asin", [](double x) { return std::asin(x); }},
    {"ArcSin", [](double x) { return std::asin(x); }},
    {"Acos", [](double x) { return std::acos(x); }},
    {"ArcCos", [](double x) { return std::acos(x); }},
    {"Atan", [](double x) { return std::atan(x); }},
    {"ArcTan", [](double x) { return std::atan(x); }},
    {"Sinh", [](double x) { return std::sinh(x); }},
    {"Cosh", [](double x) { return std::cosh(x); }},
    {"Tanh", [](double x) { return std::tanh(x); }},
    {"Asinh", [](double x) { return std::asinh(x); }},
    {"Acosh", [](double x) { return std::acosh(x); }},
    {"Atanh", [](double x) { return std::atanh(x); }},
    {"Fabs", [](double x) { return std::fabs(x); }},
    {"Abs", [](double x) { return std::fabs(x); }},
    {"Floor", [](double x) { return std::floor(x); }},
    {"Ceil", [](double x) { return std::ceil(x); }},
    {"Round", roundHalfUp},
    {"Step", heaviside},
    {"Sign", sign},
};

constexpr Binary kBinary[] = {
    {"Atan2", [](double y, double x) { return std::atan2(y, x); }},
    {"ArcTan2", [](double y, double x) { return std::atan2(y, x); }},
    {"Fmod", [](double a, double b) { return std::fmod(a, b); }},
    {"Modulo", [](double a, double b) { return std::fmod(a, b); }},
    {"Hypot", [](double a, double b) { return std::hypot(a, b); }},
    {"Max", [](double a, double b) { return std::fmax(a, b); }},
    {"Min", [](double a, double b) { return std::fmin(a, b); }},
};

void requireCount(std::string_view name, std::span<const double> args, std::size_t count) {
  if (args.size() != count)
    throw std::invalid_argument("'" + std::string(name) + "' takes " + std::to_string(count) +
                                " argument" + (count == 1 ? "" : "s") + ", not " +
                                std::to_string(args.size()));
}

}  // namespace

bool isMathFunction(std::string_view name) {
  for (const auto& f : kUnary)
    if (f.name == name) return true;
  for (const auto& f : kBinary)
    if (f.name == name) return true;
  return name == "Rand";
}

std::optional<double> callMathFunction(std::string_view name, std::span<const double> args,
                                       RandomEngine& random) {
  for (const auto& f : kUnary) {
    if (f.name != name) continue;
    requireCount(name, args, 1);
    return f.apply(args[0]);
  }
  for (const auto& f : kBinary) {
    if (f.name != name) continue;
    requireCount(name, args, 2);
    return f.apply(args[0], args[1]);
  }
  if (name == "Rand") {
    requireCount(name, args, 1);
    return std::uniform_real_distribution<double>(0.0, 1.0)(random) * args[0];
  }
  return std::nullopt;
}

}  // namespace geomesh
