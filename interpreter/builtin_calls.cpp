// Built-in functions (math, strings, lists, queries) and constants (Pi, newp, ...).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <stdexcept>

#include "interpreter/script_interpreter.h"
#include "interpreter/session.h"
#include "stdlib/format.h"
#include "stdlib/ranges.h"

namespace geomesh {

namespace {

constexpr std::string_view kFunctionNames[] = {
    "AbsolutePath", "DirName", "Exists", "FileExists", "GetEnv", "GetNumber", "GetString",
    "GetValue", "LinSpace", "LogSpace", "LowerCase", "NameToString", "Sprintf", "Str", "StrCat",
    "StrChoice", "StrCmp", "StrFind", "StrLen", "StrPrefix", "StrRelative", "StrReplace",
    "StrSub", "Unique", "UpperCase", "Sin", "Cos", "Tan", "Asin", "Acos", "Atan", "Atan2",
    "Sinh", "Cosh", "Tanh", "Exp", "Log", "Log10", "Sqrt", "Fabs", "Abs", "Floor", "Ceil",
    "Round", "Fmod", "Modulo", "Hypot", "Rand", "Max", "Min", "Sign", "Step"};

std::string withoutExtension(const std::string& s) {
  auto dot = s.find_last_of('.');
  auto slash = s.find_last_of("/\\");
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return s;
  return s.substr(0, dot);
}

std::string withoutDirectory(const std::string& s) {
  auto slash = s.find_last_of("/\\");
  return slash == std::string::npos ? s : s.substr(slash + 1);
}

std::string directoryWithSlash(const std::string& s) {
  auto slash = s.find_last_of("/\\");
  return slash == std::string::npos ? std::string() : s.substr(0, slash + 1);
}

}  // namespace

Value Interpreter::callFunction(const ast::Expr& call) {
  const std::string& name = call.text;
  if (isMathFunction(name)) {
    std::vector<double> args;
    for (const auto& arg : call.args) args.push_back(evaluateNumber(*arg));
    try {
      return Value::number(*callMathFunction(name, args, random_));
    } catch (const std::invalid_argument& error) {
      fail(call.loc, error.what());
    }
  }
  if (auto value = callStringFunction(call)) return *value;
  if (auto value = callListFunction(call)) return *value;
  if (auto value = callQueryFunction(call)) return *value;
  // The old list syntax: a() is the whole list a[], a(i) its item a[i].
  if (auto it = variables_.find(name); it != variables_.end() && call.args.size() <= 1) {
    const Value& list = it->second;
    if (call.args.empty()) return list.isText() ? Value::stringList(list.strings()) : Value::list(list.numbers());
    const double index = evaluateNumber(*call.args[0]);
    if (index < 0 || static_cast<std::size_t>(index) >= list.size())
      fail(call.args[0]->loc, "index " + std::to_string(static_cast<long long>(index)) +
                                  " out of range for '" + name + "'");
    const auto at = static_cast<std::size_t>(index);
    return list.isText() ? Value::string(list.strings()[at]) : Value::number(list.numbers()[at]);
  }
  std::vector<std::string> known(std::begin(kFunctionNames), std::end(kFunctionNames));
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

std::optional<Value> Interpreter::callStringFunction(const ast::Expr& call) {
  const std::string& name = call.text;
  const auto& args = call.args;
  auto arity = [&](std::size_t low, std::size_t high) {
    if (args.size() < low || args.size() > high)
      fail(call.loc, "'" + name + "' takes " + std::to_string(low) +
                         (high != low ? " to " + std::to_string(high) : std::string()) +
                         " arguments, not " + std::to_string(args.size()));
  };
  auto str = [&](std::size_t i) { return evaluateString(*args[i]); };
  if (name == "StrCat" || name == "Str") {
    std::vector<std::string> parts;
    for (const auto& arg : args) {
      Value v = evaluate(*arg);
      if (v.isText())
        parts.insert(parts.end(), v.strings().begin(), v.strings().end());
      else
        for (double x : v.numbers()) parts.push_back(formatPrintf("%g", std::vector<FormatArgument>{x}));
    }
    if (name == "Str" && parts.size() != 1) return Value::stringList(std::move(parts));
    std::string joined;
    for (const auto& p : parts) joined += p;
    return Value::string(joined);
  }
  if (name == "Sprintf") { arity(1, 1000); return Value::string(format(args, call.loc)); }
  if (name == "StrPrefix") { arity(1, 1); return Value::string(withoutExtension(str(0))); }
  if (name == "StrRelative") { arity(1, 1); return Value::string(withoutDirectory(str(0))); }
  if (name == "DirName") { arity(1, 1); return Value::string(directoryWithSlash(str(0))); }
  if (name == "AbsolutePath") {
    arity(1, 1);
    std::filesystem::path p = str(0);
    if (p.is_relative()) p = std::filesystem::absolute(std::filesystem::path(directoryOf(call.loc.file)) / p);
    return Value::string(p.lexically_normal().string());
  }
  if (name == "StrSub") {
    arity(2, 3);
    std::string s = str(0);
    auto from = static_cast<std::size_t>(std::max(0.0, evaluateNumber(*args[1])));
    std::size_t count = args.size() > 2 ? static_cast<std::size_t>(std::max(0.0, evaluateNumber(*args[2])))
                                        : std::string::npos;
    return Value::string(from < s.size() ? s.substr(from, count) : std::string());
  }
  if (name == "StrLen") { arity(1, 1); return Value::number(static_cast<double>(str(0).size())); }
  if (name == "StrFind") {
    arity(2, 2);
    return Value::number(str(0).find(str(1)) != std::string::npos ? 1 : 0);
  }
  if (name == "StrCmp") {
    arity(2, 2);
    int c = str(0).compare(str(1));
    return Value::number(c < 0 ? -1 : (c > 0 ? 1 : 0));
  }
  if (name == "StrChoice") {
    arity(3, 3);
    return Value::string(evaluateNumber(*args[0]) != 0 ? str(1) : str(2));
  }
  if (name == "StrReplace") {
    arity(3, 3);
    std::string s = str(0), from = str(1), to = str(2);
    for (std::size_t at = from.empty() ? std::string::npos : s.find(from); at != std::string::npos;
         at = s.find(from, at + to.size()))
      s.replace(at, from.size(), to);
    return Value::string(s);
  }
  if (name == "UpperCase" || name == "LowerCase") {
    arity(1, 1);
    std::string s = str(0);
    for (char& c : s)
      c = static_cast<char>(name == "UpperCase" ? std::toupper(static_cast<unsigned char>(c))
                                                : std::tolower(static_cast<unsigned char>(c)));
    return Value::string(s);
  }
  if (name == "GetEnv") {
    arity(1, 1);
    const char* value = std::getenv(str(0).c_str());
    return Value::string(value ? value : "");
  }
  if (name == "NameToString") {
    arity(1, 1);
    if (args[0]->kind != ast::ExprKind::Variable) fail(args[0]->loc, "NameToString takes a variable name");
    return Value::string(resolveName(args[0]->name));
  }
  return std::nullopt;
}

std::optional<Value> Interpreter::callListFunction(const ast::Expr& call) {
  const std::string& name = call.text;
  if (name == "LinSpace" || name == "LogSpace") {
    if (call.args.size() != 3) fail(call.loc, "'" + name + "' takes 3 arguments");
    const double a = evaluateNumber(*call.args[0]), b = evaluateNumber(*call.args[1]);
    const int n = static_cast<int>(evaluateNumber(*call.args[2]));
    return Value::list(name == "LinSpace" ? linSpace(a, b, n) : logSpace(a, b, n));
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
    if (args.size() != 1 || args[0]->kind != ast::ExprKind::Variable)
      fail(call.loc, "Exists takes a variable name");
    return Value::number(variables_.contains(resolveName(args[0]->name)) ? 1 : 0);
  }
  if (name == "FileExists") {
    if (args.size() != 1) fail(call.loc, "FileExists takes a file name");
    std::filesystem::path p = evaluateString(*args[0]);
    if (p.is_relative()) p = std::filesystem::path(directoryOf(call.loc.file)) / p;
    return Value::number(std::filesystem::exists(p) ? 1 : 0);
  }
  if (name == "GetNumber" || name == "GetValue") {
    if (args.empty() || args.size() > 2) fail(call.loc, "'" + name + "' takes 1 or 2 arguments");
    const std::string key = evaluateString(*args[0]);
    if (auto it = parameterNumbers_.find(key); it != parameterNumbers_.end()) return Value::number(it->second);
    if (session_.options().hasNumber(key)) return Value::number(session_.options().number(key));
    return Value::number(args.size() > 1 ? evaluateNumber(*args[1]) : 0);
  }
  if (name == "GetString") {
    if (args.empty() || args.size() > 2) fail(call.loc, "GetString takes 1 or 2 arguments");
    const std::string key = evaluateString(*args[0]);
    if (auto it = parameterStrings_.find(key); it != parameterStrings_.end()) return Value::string(it->second);
    if (session_.options().hasString(key)) return Value::string(session_.options().string(key));
    return Value::string(args.size() > 1 ? evaluateString(*args[1]) : "");
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
  if (name == "Memory" || name == "TotalMemory") return Value::number(0);
  GeoFactory& geo = session_.geo();
  int region = maxPhysicalTag_;
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
