// The built-in functions of the scripting language, each one row, found by name in one registry.
#pragma once

#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "stdlib/math_functions.h"

namespace geomesh {

class Interpreter;
class Value;
namespace ast {
struct Expr;
}

// A built-in function of the interpreter (strings, lists, queries, Structs), one row: its name,
// how many arguments it takes, and its body. The body gets the call with its arguments not yet
// evaluated: some functions take names, not values (Exists, NameToString).
struct ScriptFunction {
  static constexpr std::size_t kAnyCount = std::numeric_limits<std::size_t>::max();

  std::string_view name;
  std::size_t minArgs;
  std::size_t maxArgs;     // kAnyCount: no limit
  std::string_view usage;  // the error for a wrong count; empty: the generic one
                           // ("'StrSub' takes 2 to 3 arguments, not 4")
  Value (*body)(Interpreter& interpreter, const ast::Expr& call);
};

// The error for a call of `function` with `given` arguments.
std::string wrongArgumentCount(const ScriptFunction& function, std::size_t given);

// A built-in function found by name: a numeric one of the math library, whose arguments are
// numbers, or one of the interpreter's.
struct BuiltinFunction {
  std::string_view name;
  const MathFunction* math = nullptr;
  const ScriptFunction* script = nullptr;

  std::size_t minArgs() const { return math ? math->arguments : script->minArgs; }
  std::size_t maxArgs() const { return math ? math->arguments : script->maxArgs; }
};

// Every built-in function: the math library's and the interpreter's families. Names are
// unique; the order is the order of "did you mean" suggestions.
class FunctionRegistry {
 public:
  explicit FunctionRegistry(std::span<const std::span<const ScriptFunction>> families);

  const BuiltinFunction* find(std::string_view name) const;
  std::span<const BuiltinFunction> all() const { return functions_; }
  const std::vector<std::string>& names() const { return names_; }

 private:
  std::vector<BuiltinFunction> functions_;  // sorted for find()
  std::vector<std::string> names_;          // in the same order
};

}  // namespace geomesh
