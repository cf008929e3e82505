// Assignments to variables and list elements: = += -= *= /= ++ --
#include <algorithm>
#include <cmath>

#include "interpreter/script_interpreter.h"

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
    const Value& old = requireVariable(name, where);
    if (!old.isNumeric()) fail(where, "'" + name + "' is " + old.describe() + ", not a number");
    Value updated = old;
    for (double& x : updated.numbers()) x = combine(x, 1, op);
    variables_[name] = std::move(updated);
    return;
  }
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
  Value updated = requireVariable(name, where);
  if (updated.isText() || value.isText()) {
    if (op != "+=" || !updated.isText() || !value.isText())
      fail(where, "'" + op + "' cannot combine " + std::string(updated.describe()) + " and " +
                      value.describe());
    updated = asList(updated);
    for (const auto& s : value.strings()) updated.strings().push_back(s);
  } else if (listForm && op == "+=") {
    updated = asList(updated);
    for (double x : value.numbers()) updated.numbers().push_back(x);
  } else if (listForm && op == "-=") {
    updated = asList(updated);
    removeValues(updated.numbers(), value.numbers());
  } else {
    if (value.numbers().size() != 1)
      fail(assign.value->loc, "'" + op + "' needs a single number on its right, not " +
                                  value.describe());
    for (double& x : updated.numbers()) x = combine(x, value.numbers()[0], op);
  }
  variables_[name] = std::move(updated);
}

void Interpreter::assignElements(const ast::LValue& target, const std::string& name,
                                 const Value& value, const std::string& op,
                                 const SourceLocation& where) {
  std::vector<double> indices = evaluateNumbers(*target.index);
  auto existing = variables_.find(name);
  Value list = existing == variables_.end()
                   ? (value.isText() ? Value::stringList({}) : Value::list({}))
                   : asList(existing->second);
  if (list.isText() != value.isText())
    fail(where, "cannot store " + std::string(value.describe()) + " in '" + name + "', which is " +
                    list.describe());
  if (value.size() != indices.size() && value.size() != 1)
    fail(where, std::to_string(indices.size()) + " indices but " + std::to_string(value.size()) +
                    " values");
  for (std::size_t i = 0; i < indices.size(); ++i) {
    if (indices[i] < 0) fail(target.index->loc, "negative index in '" + name + "'");
    if (indices[i] >= kMaxListSize)
      fail(target.index->loc, "index " + std::to_string(static_cast<long long>(indices[i])) +
                                  " is beyond the largest list size");
    const auto index = static_cast<std::size_t>(indices[i]);
    const std::size_t from = value.size() == 1 ? 0 : i;
    if (list.isText()) {
      if (index >= list.strings().size()) list.strings().resize(index + 1);
      list.strings()[index] = value.strings()[from];
    } else {
      if (index >= list.numbers().size()) list.numbers().resize(index + 1, 0.0);
      list.numbers()[index] = combine(list.numbers()[index], value.numbers()[from], op);
    }
  }
  variables_[name] = std::move(list);
}

}  // namespace geomesh
