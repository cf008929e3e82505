// Assignments to variables and list elements: = += -= *= /= ++ --
#include <algorithm>
#include <cmath>

#include "grammar/keywords.h"
#include "interpreter/script_interpreter.h"
#include "stdlib/edit_distance.h"

namespace geomesh {

namespace {

constexpr double kMaxListSize = 10'000'000;

double combine(double old, double operand, const std::string& op) {
  if (op == "+=" || op == "++") return old + operand;
  if (op == "-=" || op == "--") return old - operand;
  if (op == "*=") return old * operand;
  if (op == "/=") return old / operand;
  return operand;
}

// a[] -= {x, y}: removes the first occurrence of each value.
void removeValues(std::vector<double>& list, const std::vector<double>& values) {
  for (double value : values) {
    auto it = std::find(list.begin(), list.end(), value);
    if (it != list.end()) list.erase(it);
  }
}

// A number becomes a list of one number, in place (no copy of long lists).
void makeList(Value& value) {
  if (value.kind() == Value::Kind::Number) value = Value::list(std::move(value.numbers()));
  if (value.kind() == Value::Kind::String) value = Value::stringList(std::move(value.strings()));
}

Value asList(const Value& value) {
  if (value.kind() == Value::Kind::Number) return Value::list(value.numbers());
  if (value.kind() == Value::Kind::String) return Value::stringList(value.strings());
  return value;
}

}  // namespace

void Interpreter::executeAssign(const ast::AssignStmt& assign, const SourceLocation& where) {
  const std::string name = resolveName(assign.target.name);
  const std::string& op = assign.op;
  if (op == "++" || op == "--") {
    Value& updated = requireVariable(name, where);
    if (!updated.isNumeric())
      fail(where, "'" + name + "' is " + updated.describe() + ", not a number");
    for (double& x : updated.numbers()) x = combine(x, 1, op);
    return;
  }
  if (assign.target.parenthesized && assign.target.form == ast::LValue::Form::Element &&
      assign.value->kind == ast::ExprKind::List && !variables_.contains(name))
    rejectMisspelledCommand(name, where);
  Value value = evaluate(*assign.value);
  if (assign.target.form == ast::LValue::Form::Element) {
    assignElements(assign.target, name, value, op, where);
    return;
  }
  const bool listForm = assign.target.form == ast::LValue::Form::List;
  if (op == "=") {
    variables_[name] = listForm ? asList(value) : std::move(value);
    return;
  }
  auto existing = variables_.find(name);
  if (existing == variables_.end() && (op == "+=" || op == "-=") && listForm) {
    variables_[name] = op == "+=" ? asList(value) : Value::list({});
    return;
  }
  Value& updated = requireVariable(name, where);
  if (updated.isText() || value.isText()) {
    if (op != "+=" || !updated.isText() || !value.isText())
      fail(where, "'" + op + "' cannot combine " + std::string(updated.describe()) + " and " +
                      value.describe());
    makeList(updated);
    for (const auto& s : value.strings()) updated.strings().push_back(s);
  } else if (listForm && op == "+=") {
    makeList(updated);
    for (double x : value.numbers()) updated.numbers().push_back(x);
  } else if (listForm && op == "-=") {
    makeList(updated);
    removeValues(updated.numbers(), value.numbers());
  } else {
    if (value.numbers().size() != 1)
      fail(assign.value->loc, "'" + op + "' needs a single number on its right, not " +
                                  value.describe());
    for (double& x : updated.numbers()) x = combine(x, value.numbers()[0], op);
  }
}

// `Pont(1) = {0, 0, 0};` reads as the old list syntax `Pont[1] = ...`: when the name is no
// variable yet and looks like a command keyword, it is far more likely a typo.
void Interpreter::rejectMisspelledCommand(const std::string& name, const SourceLocation& where) {
  std::vector<std::string> keywords(commandWords().begin(), commandWords().end());
  auto close = closestNames(name, keywords, 1);
  if (!close.empty() && close.front().front() == name.front())
    fail(where, "unknown command '" + name + "'; did you mean '" + close.front() + "'?");
}

void Interpreter::assignElements(const ast::LValue& target, const std::string& name,
                                 const Value& value, const std::string& op,
                                 const SourceLocation& where) {
  std::vector<double> indices = evaluateNumbers(*target.index);
  auto existing = variables_.find(name);
  if (existing == variables_.end())
    existing =
        variables_.emplace(name, value.isText() ? Value::stringList({}) : Value::list({})).first;
  Value& list = existing->second;
  makeList(list);
  if (list.isText() != value.isText())
    fail(where, "cannot store " + std::string(value.describe()) + " in '" + name + "', which is " +
                    list.describe());
  if (value.size() != indices.size() && value.size() != 1)
    fail(where, std::to_string(indices.size()) + " indices but " + std::to_string(value.size()) +
                    " values");
  for (std::size_t i = 0; i < indices.size(); ++i) {
    if (indices[i] < 0) fail(target.index->loc, "negative index in '" + name + "'");
    if (indices[i] >= kMaxListSize)
      fail(target.index->loc, "index " + std::to_string(clampedInteger<long long>(indices[i])) +
                                  " is beyond the largest list size");
    const auto index = clampedInteger<std::size_t>(indices[i]);
    const std::size_t from = value.size() == 1 ? 0 : i;
    if (list.isText()) {
      if (index >= list.strings().size()) list.strings().resize(index + 1);
      list.strings()[index] = value.strings()[from];
    } else {
      if (index >= list.numbers().size()) list.numbers().resize(index + 1, 0.0);
      list.numbers()[index] = combine(list.numbers()[index], value.numbers()[from], op);
    }
  }
}

}  // namespace geomesh
