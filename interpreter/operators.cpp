// Unary and binary operators, with Gmsh's semantics: % works on integers, comparisons and
// logical operators give 1 or 0, arithmetic applies item by item to lists.
#include <cmath>

#include "interpreter/script_interpreter.h"

namespace geomesh {

namespace {

bool isArithmetic(const std::string& op) {
  return op == "+" || op == "-" || op == "*" || op == "/" || op == "^" || op == "%";
}

double arithmetic(const std::string& op, double a, double b) {
  if (op == "+") return a + b;
  if (op == "-") return a - b;
  if (op == "*") return a * b;
  if (op == "/") return a / b;
  if (op == "^") return std::pow(a, b);
  const long long x = clampedInteger<long long>(a), y = clampedInteger<long long>(b);
  return y == -1 ? 0.0 : static_cast<double>(x % y);  // the lowest value % -1 overflows
}

double comparison(const std::string& op, double a, double b) {
  if (op == "<") return a < b;
  if (op == ">") return a > b;
  if (op == "<=") return a <= b;
  if (op == ">=") return a >= b;
  if (op == "==") return a == b;
  return a != b;
}

}  // namespace

Value Interpreter::unaryValue(const ast::Expr& expr) {
  if (expr.text == "!") return Value::number(evaluateNumber(*expr.args[0]) == 0 ? 1 : 0);
  if (expr.text == "post++" || expr.text == "post--") {  // a++ in an expression
    const std::string name = resolveName(expr.args[0]->name);
    Value& variable = requireVariable(name, expr.loc);
    if (!variable.isNumeric())
      fail(expr.loc, "'" + name + "' is " + variable.describe() + ", not a number");
    const Value before = variable;
    for (double& x : variable.numbers()) x += expr.text == "post++" ? 1 : -1;
    return before;
  }
  Value value = evaluate(*expr.args[0]);
  if (!value.isNumeric())
    fail(expr.loc, "'" + expr.text + "' needs a number, not " + value.describe());
  if (expr.text == "-")
    for (double& x : value.numbers()) x = -x;
  return value;
}

Value Interpreter::binaryValue(const ast::Expr& expr) {
  const std::string& op = expr.text;
  if (op == "&&" || op == "||") {
    const bool left = evaluateNumber(*expr.args[0]) != 0;
    if (op == "&&" && !left) return Value::number(0);
    if (op == "||" && left) return Value::number(1);
    return Value::number(evaluateNumber(*expr.args[1]) != 0 ? 1 : 0);
  }
  Value left = evaluate(*expr.args[0]);
  Value right = evaluate(*expr.args[1]);
  if (left.kind() == Value::Kind::String && right.kind() == Value::Kind::String &&
      (op == "==" || op == "!="))
    return Value::number((left.strings()[0] == right.strings()[0]) == (op == "=="));
  if (!left.isNumeric() || !right.isNumeric())
    fail(expr.loc, "'" + op + "' cannot combine " + std::string(left.describe()) + " and " +
                       right.describe());
  const auto& a = left.numbers();
  const auto& b = right.numbers();
  for (double divisor : b) {
    if (op == "%" && clampedInteger<long long>(divisor) == 0) fail(expr.loc, "modulo by zero");
    if (op == "/" && divisor == 0) fail(expr.loc, "division by zero");
  }
  if (left.kind() == Value::Kind::Number && right.kind() == Value::Kind::Number)
    return Value::number(isArithmetic(op) ? arithmetic(op, a[0], b[0])
                                          : comparison(op, a[0], b[0]));
  if (!isArithmetic(op)) fail(expr.loc, "'" + op + "' compares numbers, not lists");
  if (a.empty() || b.empty()) fail(expr.loc, "'" + op + "' on an empty list");
  if (a.size() != b.size() && a.size() != 1 && b.size() != 1)
    fail(expr.loc, "'" + op + "' on lists of different lengths (" + std::to_string(a.size()) +
                       " and " + std::to_string(b.size()) + ")");
  std::vector<double> result(std::max(a.size(), b.size()));
  for (std::size_t i = 0; i < result.size(); ++i)
    result[i] = arithmetic(op, a[a.size() == 1 ? 0 : i], b[b.size() == 1 ? 0 : i]);
  return Value::list(std::move(result));
}

}  // namespace geomesh
