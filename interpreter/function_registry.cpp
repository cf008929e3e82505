// The registry of built-in functions: the families' rows in one sorted list.
#include "interpreter/function_registry.h"

#include <algorithm>
#include <stdexcept>

namespace geomesh {

namespace {

// Names sort alphabetically, except that Sin comes just before Sign: a misspelling as close to
// both ("Sinn") more likely means the sine, and suggestions keep the first of equally close names.
std::string_view sortKey(std::string_view name) { return name == "Sin" ? "Sig" : name; }

bool byName(const BuiltinFunction& a, const BuiltinFunction& b) {
  return sortKey(a.name) < sortKey(b.name);
}

}  // namespace

std::string wrongArgumentCount(const ScriptFunction& function, std::size_t given) {
  if (!function.usage.empty()) return std::string(function.usage);
  const std::size_t low = function.minArgs, high = function.maxArgs;
  return "'" + std::string(function.name) + "' takes " + std::to_string(low) +
         (high != low ? " to " + std::to_string(high) : std::string()) + " arguments, not " +
         std::to_string(given);
}

FunctionRegistry::FunctionRegistry(std::span<const std::span<const ScriptFunction>> families) {
  for (const MathFunction& function : mathFunctions())
    functions_.push_back(BuiltinFunction{function.name, &function, nullptr});
  for (const auto& family : families)
    for (const ScriptFunction& function : family)
      functions_.push_back(BuiltinFunction{function.name, nullptr, &function});
  std::sort(functions_.begin(), functions_.end(), byName);
  auto sameName = [](const auto& a, const auto& b) { return a.name == b.name; };
  const auto twice = std::adjacent_find(functions_.begin(), functions_.end(), sameName);
  if (twice != functions_.end())
    throw std::logic_error("built-in function '" + std::string(twice->name) + "' defined twice");
  for (const auto& function : functions_) names_.emplace_back(function.name);
}

const BuiltinFunction* FunctionRegistry::find(std::string_view name) const {
  const BuiltinFunction key{name};
  auto it = std::lower_bound(functions_.begin(), functions_.end(), key, byName);
  return it != functions_.end() && it->name == name ? &*it : nullptr;
}

}  // namespace geomesh
