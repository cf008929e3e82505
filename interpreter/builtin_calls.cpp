// Built-in functions (math, strings, lists, queries) and constants (Pi, newp, ...).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "grammar/keywords.h"
#include "interpreter/script_interpreter.h"
#include "api/session.h"
#include "stdlib/format.h"
#include "stdlib/ranges.h"
#include "stdlib/system_info.h"

namespace geomesh {

Value Interpreter::callFunction(const ast::Expr& call) {
  const std::string& name = call.text;
  if (isMathFunction(name)) {
    try {
      // A one-argument function applies item by item to a list: Abs(a[]).
      if (call.args.size() == 1) {
        Value arg = evaluate(*call.args[0]);
        if (arg.kind() == Value::Kind::List) {
          for (double& x : arg.numbers()) x = *callMathFunction(name, std::span(&x, 1), random_);
          return arg;
        }
      }
      std::vector<double> args;
      for (const auto& arg : call.args) args.push_back(evaluateNumber(*arg));
      return Value::number(*callMathFunction(name, args, random_));
    } catch (const std::invalid_argument& error) {
      fail(call.loc, error.what());
    }
  }
  if (auto value = callStringFunction(call)) return *value;
  if (auto value = callListFunction(call)) return *value;
  if (auto value = callQueryFunction(call)) return *value;
  if (auto value = callStructFunction(call)) return *value;
  // The old list syntax: a() is the whole list a[], a(i) its item a[i].
  if (auto it = variables_.find(name); it != variables_.end() && call.args.size() <= 1) {
    const Value& list = it->second;
    if (call.args.empty())
      return list.isText() ? Value::stringList(list.strings()) : Value::list(list.numbers());
    const double index = evaluateNumber(*call.args[0]);
    if (index < 0 || clampedInteger<std::size_t>(index) >= list.size())
      fail(call.args[0]->loc, "index " + std::to_string(clampedInteger<long long>(index)) +
                                  " out of range for '" + name + "'");
    const auto at = clampedInteger<std::size_t>(index);
    return list.isText() ? Value::string(list.strings()[at]) : Value::number(list.numbers()[at]);
  }
  std::vector<std::string> known(functionNames().begin(), functionNames().end());
  fail(call.loc, "unknown function '" + name + "'" + didYouMean(name, known));
}

std::string Interpreter::format(const ast::ExprList& args, const SourceLocation& where) {
  const std::string pattern = evaluateString(*args[0]);
  std::vector<FormatArgument> values;
  for (std::size_t i = 1; i < args.size(); ++i) {
    Value value = evaluate(*args[i]);
    if (value.isText())
      for (auto& s : value.strings()) values.emplace_back(s);
    else
      for (double x : value.numbers()) values.emplace_back(x);
  }
  try {
    return formatPrintf(pattern, values);
  } catch (const std::invalid_argument& error) {
    fail(where, error.what());
  }
}

std::optional<Value> Interpreter::callListFunction(const ast::Expr& call) {
  const std::string& name = call.text;
  if (name == "LinSpace" || name == "LogSpace") {
    if (call.args.size() != 3) fail(call.loc, "'" + name + "' takes 3 arguments");
    const double a = evaluateNumber(*call.args[0]), b = evaluateNumber(*call.args[1]);
    const double count = evaluateNumber(*call.args[2]);
    if (count > 10'000'000) fail(call.args[2]->loc, "'" + name + "' asks for too many values");
    const int n = clampedInteger<int>(count);
    return Value::list(name == "LinSpace" ? linSpace(a, b, n) : logSpace(a, b, n));
  }
  if (name == "Find") {
    if (call.args.size() != 2) fail(call.loc, "Find takes 2 lists");
    const std::vector<double> in = evaluateNumbers(*call.args[0]);
    double found = 0;
    for (double x : evaluateNumbers(*call.args[1]))
      if (std::find(in.begin(), in.end(), x) != in.end()) ++found;
    return Value::number(found);
  }
  if (name == "ListFromFile") {
    if (call.args.size() != 1) fail(call.loc, "ListFromFile takes a file name");
    std::filesystem::path path = evaluateString(*call.args[0]);
    if (path.is_relative()) path = std::filesystem::path(directoryOf(call.loc.file)) / path;
    std::error_code ignored;
    std::ifstream in;
    if (std::filesystem::is_regular_file(path, ignored)) in.open(path);
    if (!in.is_open()) fail(call.args[0]->loc, "cannot open '" + path.string() + "'");
    std::vector<double> values;
    for (double x; in >> x;) values.push_back(x);
    if (!in.eof())
      fail(call.args[0]->loc, "'" + path.string() + "' holds something other than numbers");
    return Value::list(std::move(values));
  }
  if (name == "Unique") {
    std::vector<double> values = evaluateNumbers(call.args);
    std::sort(values.begin(), values.end());
    values.erase(std::unique(values.begin(), values.end()), values.end());
    return Value::list(std::move(values));
  }
  return std::nullopt;
}

std::optional<Value> Interpreter::callQueryFunction(const ast::Expr& call) {
  const std::string& name = call.text;
  const auto& args = call.args;
  if (name == "Exists") {
    const bool named = args.size() == 1 && (args[0]->kind == ast::ExprKind::Variable ||
                                            args[0]->kind == ast::ExprKind::Member);
    if (!named) fail(call.loc, "Exists takes a variable name or a Struct member");
    const auto value = valueIfDefined(*args[0]);
    if (!value) return Value::number(0);
    // As in Gmsh, the name of a Struct (no variable) answers with the Struct's tag.
    const bool structName = args[0]->kind == ast::ExprKind::Variable &&
                            !variables_.contains(resolveName(args[0]->name));
    return structName ? *value : Value::number(1);
  }
  if (name == "FileExists") {
    if (args.size() != 1) fail(call.loc, "FileExists takes a file name");
    std::filesystem::path p = evaluateString(*args[0]);
    if (p.is_relative()) p = std::filesystem::path(directoryOf(call.loc.file)) / p;
    std::error_code ignored;
    return Value::number(std::filesystem::exists(p, ignored) ? 1 : 0);
  }
  // GetNumber and GetString read parameters (DefineConstant's Name, SetNumber, -setnumber),
  // never options: that is Gmsh's behaviour too.
  if (name == "GetNumber") {
    if (args.empty() || args.size() > 2) fail(call.loc, "GetNumber takes 1 or 2 arguments");
    const std::string key = evaluateString(*args[0]);
    if (auto it = parameterNumbers_.find(key); it != parameterNumbers_.end())
      return Value::number(it->second);
    return Value::number(args.size() > 1 ? evaluateNumber(*args[1]) : 0);
  }
  if (name == "GetString") {
    if (args.empty() || args.size() > 2) fail(call.loc, "GetString takes 1 or 2 arguments");
    const std::string key = evaluateString(*args[0]);
    if (auto it = parameterStrings_.find(key); it != parameterStrings_.end())
      return Value::string(it->second);
    return Value::string(args.size() > 1 ? evaluateString(*args[1]) : "");
  }
  if (name == "GetValue") {
    // A question for an interactive user: in a batch run, the prompt is shown and the
    // default is the answer.
    if (args.size() != 2) fail(call.loc, "GetValue takes a prompt and a default value");
    const std::string prompt = evaluateString(*args[0]);
    const double answer = evaluateNumber(*args[1]);
    if (session_.options().number("General.Verbosity") >= 3) {
      const std::vector<FormatArgument> shown{answer};
      session_.out() << prompt << " (default=" << formatPrintf("%g", shown) << "): ";
    }
    return Value::number(answer);
  }
  return std::nullopt;
}

std::optional<Value> Interpreter::builtinConstant(std::string_view name) {
  if (name == "Pi") return Value::number(M_PI);
  if (name == "GMSH_MAJOR_VERSION") return Value::number(4);
  if (name == "GMSH_MINOR_VERSION") return Value::number(15);
  if (name == "GMSH_PATCH_VERSION") return Value::number(2);
  if (name == "MPI_Size") return Value::number(1);
  if (name == "MPI_Rank") return Value::number(0);
  if (name == "Cpu") return Value::number(static_cast<double>(std::clock()) / CLOCKS_PER_SEC);
  if (name == "Memory") return Value::number(processMemoryMegabytes());
  if (name == "TotalMemory") return Value::number(totalMemoryMegabytes());
  GeoFactory& geo = session_.geo();
  int region = deletedPhysicalTag_;
  for (const auto& [id, group] : geo.physicalGroups()) region = std::max(region, id.tag);
  for (int kind : {1, 2, 3, int(GeoFactory::kCurveLoop), int(GeoFactory::kSurfaceLoop)})
    region = std::max(region, geo.maxTag(kind));
  const bool oldNewReg = session_.options().number("Geometry.OldNewReg") != 0;
  auto next = [&](int kind) { return Value::number((oldNewReg ? region : geo.maxTag(kind)) + 1); };
  if (name == "newp") return Value::number(geo.maxTag(0) + 1);
  if (name == "newl" || name == "newc") return next(1);
  if (name == "news") return next(2);
  if (name == "newv") return next(3);
  if (name == "newll" || name == "newcl") return next(GeoFactory::kCurveLoop);
  if (name == "newsl") return next(GeoFactory::kSurfaceLoop);
  if (name == "newreg") return Value::number(region + 1);
  return std::nullopt;
}

}  // namespace geomesh
