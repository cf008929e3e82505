// DefineConstant, DefineNumber and DefineString: values that -setnumber / -setstring given on
// the command line override.
#include "interpreter/script_interpreter.h"
#include "api/session.h"

namespace geomesh {

std::optional<std::string> Interpreter::parameterName(
    const std::vector<ast::Attribute>& attributes) {
  for (const auto& attribute : attributes)
    if (attribute.name == "Name" && attribute.values.size() == 1)
      return evaluateString(*attribute.values[0]);
  return std::nullopt;
}

// Each constant is defined unless a variable of that name exists already (-setnumber /
// -setstring by variable name make it exist beforehand); a value given by its Name attribute
// on the command line wins over the script's.
void Interpreter::executeDefineConstant(const ast::DefineConstantStmt& define) {
  for (const auto& constant : define.constants) {
    const std::string name = resolveName(constant.name);
    if (variables_.contains(name)) continue;
    const auto label = parameterName(constant.attributes);
    const auto& numbers = session_.numberOverrides();
    const auto& strings = session_.stringOverrides();
    Value value;
    if (auto byLabel = label ? numbers.find(*label) : numbers.end(); byLabel != numbers.end()) {
      value = Value::number(byLabel->second);
    } else if (auto sl = label ? strings.find(*label) : strings.end(); sl != strings.end()) {
      value = Value::string(sl->second);
    } else {
      value = evaluate(*constant.value);
    }
    if (constant.isList && value.kind() == Value::Kind::Number)
      value = Value::list(value.numbers());
    const std::string key = label ? *label : name;
    if (value.kind() == Value::Kind::Number) parameterNumbers_[key] = value.numbers()[0];
    if (value.kind() == Value::Kind::String) parameterStrings_[key] = value.strings()[0];
    variables_[name] = std::move(value);
  }
}

Value Interpreter::defineNumber(const ast::Expr& expr) {
  const auto label = parameterName(expr.attributes);
  double value = 0;
  auto& overrides = session_.numberOverrides();
  if (auto it = label ? overrides.find(*label) : overrides.end(); it != overrides.end())
    value = it->second;
  else
    value = evaluateNumber(*expr.args[0]);
  if (label) parameterNumbers_[*label] = value;
  return Value::number(value);
}

Value Interpreter::defineString(const ast::Expr& expr) {
  const auto label = parameterName(expr.attributes);
  std::string value;
  auto& overrides = session_.stringOverrides();
  if (auto it = label ? overrides.find(*label) : overrides.end(); it != overrides.end())
    value = it->second;
  else
    value = evaluateString(*expr.args[0]);
  if (label) parameterStrings_[*label] = value;
  return Value::string(std::move(value));
}

}  // namespace geomesh
