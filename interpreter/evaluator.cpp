// Expressions: numbers, strings, variables, lists, operators.
#include <cmath>
#include <stdexcept>

#include "interpreter/script_interpreter.h"
#include "api/session.h"
#include "stdlib/ranges.h"

namespace geomesh {

using ast::Expr;
using ast::ExprKind;

Value Interpreter::evaluate(const Expr& expr) {
  switch (expr.kind) {
    case ExprKind::Number: return Value::number(expr.number);
    case ExprKind::String: return Value::string(expr.text);
    case ExprKind::Variable: return variableValue(expr);
    case ExprKind::Element: return elementValue(expr);
    case ExprKind::WholeList: {
      Value value = requireVariable(resolveName(expr.name), expr.loc);
      if (value.kind() == Value::Kind::Number) return Value::list(value.numbers());
      if (value.kind() == Value::Kind::String) return Value::stringList(value.strings());
      return value;
    }
    case ExprKind::Count: return Value::number(static_cast<double>(evaluate(*expr.args[0]).size()));
    case ExprKind::Unary: return unaryValue(expr);
    case ExprKind::Binary: return binaryValue(expr);
    case ExprKind::Ternary:
      return evaluateNumber(*expr.args[0]) != 0 ? evaluate(*expr.args[1]) : evaluate(*expr.args[2]);
    case ExprKind::Call: return callFunction(expr);
    case ExprKind::List: return listValue(expr.args, expr.loc);
    case ExprKind::Range: return Value::list(rangeValues(expr));
    case ExprKind::All: fail(expr.loc, "':' (all entities) is only allowed in an entity list");
    case ExprKind::Option: return optionValue(expr);
    case ExprKind::Shape: return shapeValue(expr);
    case ExprKind::DefineNumber: return defineNumber(expr);
    case ExprKind::DefineString: return defineString(expr);
    case ExprKind::StructDef: return defineStruct(expr);
    case ExprKind::Member:
    case ExprKind::MemberItem:
    case ExprKind::MemberList: return memberValue(expr);
  }
  fail(expr.loc, "unknown expression");
}

double Interpreter::evaluateNumber(const Expr& expr) {
  Value value = evaluate(expr);
  if (!value.isNumeric()) fail(expr.loc, std::string("expected a number, not ") + value.describe());
  if (value.numbers().size() != 1)
    fail(expr.loc, "expected a single number, not a list of " +
                       std::to_string(value.numbers().size()) + " values");
  return value.numbers()[0];
}

std::string Interpreter::evaluateString(const Expr& expr) {
  Value value = evaluate(expr);
  if (value.kind() != Value::Kind::String && !(value.isText() && value.size() == 1))
    fail(expr.loc, std::string("expected a string, not ") + value.describe());
  return value.strings()[0];
}

std::vector<double> Interpreter::evaluateNumbers(const Expr& expr) {
  Value value = evaluate(expr);
  if (!value.isNumeric()) fail(expr.loc, std::string("expected numbers, not ") + value.describe());
  return std::move(value.numbers());
}

std::vector<double> Interpreter::evaluateNumbers(const ast::ExprList& items) {
  std::vector<double> result;
  for (const auto& item : items) {
    auto values = evaluateNumbers(*item);
    result.insert(result.end(), values.begin(), values.end());
  }
  return result;
}

// a~{i}~{j} names "a_<i>_<j>".
std::string Interpreter::resolveName(const ast::Name& name) {
  std::string result = name.base;
  for (const auto& suffix : name.suffixes) {
    Value value = evaluate(*suffix);
    if (value.kind() == Value::Kind::String) {
      result += "_" + value.strings()[0];
      continue;
    }
    result += "_" + std::to_string(clampedInteger<long long>(evaluateNumber(*suffix)));
  }
  return result;
}

Value& Interpreter::requireVariable(const std::string& name, const SourceLocation& where) {
  auto it = variables_.find(name);
  if (it != variables_.end()) return it->second;
  std::vector<std::string> known;
  for (const auto& [variable, value] : variables_) known.push_back(variable);
  fail(where, "undefined variable '" + name + "'" + didYouMean(name, known));
}

Value Interpreter::variableValue(const Expr& expr) {
  const std::string name = resolveName(expr.name);
  auto it = variables_.find(name);
  if (it != variables_.end()) return it->second;
  if (auto constant = builtinConstant(name)) return *constant;
  if (auto constant = textConstant(name, expr.loc)) return *constant;
  // A Struct of the global namespace stands for its tag.
  if (auto global = structSpaces_.find(""); global != structSpaces_.end())
    if (auto it = global->second.structs.find(name); it != global->second.structs.end())
      return Value::number(it->second.tag);
  return requireVariable(name, expr.loc);
}

Value Interpreter::elementValue(const Expr& expr) {
  return itemsAt(resolveName(expr.name), expr.loc, *expr.args[0]);
}

// a[i] or a(i): one item; a[{i, j}] or a({i:j}): the list of those items, in that order.
Value Interpreter::itemsAt(const std::string& name, const SourceLocation& where,
                           const Expr& indexExpr) {
  const Value index = evaluate(indexExpr);
  // A reference, not a copy: reading one item of a long list stays cheap. Evaluating the
  // index above cannot change variables, and map references survive insertions anyway.
  const Value& list = requireVariable(name, where);
  if (!index.isNumeric()) fail(indexExpr.loc, "an index must be a number");
  std::vector<double> numbers;
  std::vector<std::string> strings;
  for (double i : index.numbers()) {
    if (i < 0 || clampedInteger<std::size_t>(i) >= list.size())
      fail(indexExpr.loc, "index " + std::to_string(clampedInteger<long long>(i)) +
                              " out of range for '" + name + "' (" + std::to_string(list.size()) +
                              " item" + (list.size() == 1 ? "" : "s") + ")");
    const auto at = clampedInteger<std::size_t>(i);
    if (list.isText())
      strings.push_back(list.strings()[at]);
    else
      numbers.push_back(list.numbers()[at]);
  }
  if (index.kind() == Value::Kind::Number)
    return list.isText() ? Value::string(strings[0]) : Value::number(numbers[0]);
  return list.isText() ? Value::stringList(std::move(strings)) : Value::list(std::move(numbers));
}

// {a, b:c, list[]}: items are flattened into one list of numbers (or of strings).
Value Interpreter::listValue(const ast::ExprList& items, const SourceLocation& where) {
  std::vector<double> numbers;
  std::vector<std::string> strings;
  for (const auto& item : items) {
    Value value = evaluate(*item);
    if (value.isText())
      strings.insert(strings.end(), value.strings().begin(), value.strings().end());
    else
      numbers.insert(numbers.end(), value.numbers().begin(), value.numbers().end());
  }
  if (!strings.empty() && !numbers.empty()) fail(where, "a list cannot mix numbers and strings");
  if (!strings.empty()) return Value::stringList(std::move(strings));
  return Value::list(std::move(numbers));
}

std::vector<double> Interpreter::rangeValues(const Expr& range) {
  const double first = evaluateNumber(*range.args[0]);
  const double last = evaluateNumber(*range.args[1]);
  std::optional<double> step;
  if (range.args.size() > 2) step = evaluateNumber(*range.args[2]);
  try {
    return expandRange(first, last, step);
  } catch (const std::invalid_argument& error) {
    fail(range.loc, error.what());
  }
}

}  // namespace geomesh
