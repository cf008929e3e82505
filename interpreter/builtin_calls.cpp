// Built-in functions: the registry's lookup and the list and query families; constants (Pi,
// newp, ...).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "interpreter/script_interpreter.h"
#include "api/session.h"
#include "stdlib/format.h"
#include "stdlib/ranges.h"
#include "stdlib/system_info.h"

namespace geomesh {

FunctionRegistry Interpreter::builtinFunctions() {
  const std::span<const ScriptFunction> families[] = {stringFunctions(), listFunctions(),
                                                      queryFunctions(), structFunctions()};
  return FunctionRegistry(families);
}

Value Interpreter::callFunction(const ast::Expr& call) {
  const std::string& name = call.text;
  if (const BuiltinFunction* function = functions_.find(name)) {
    if (function->math) return callMath(*function->math, call);
    const ScriptFunction& script = *function->script;
    if (call.args.size() < script.minArgs || call.args.size() > script.maxArgs)
      fail(call.loc, wrongArgumentCount(script, call.args.size()));
    return script.body(*this, call);
  }
  // The old list syntax: a() is the whole list a[], a(i) its item a[i].
  if (auto it = variables_.find(name); it != variables_.end() && call.args.size() <= 1) {
    const Value& list = it->second;
    if (call.args.empty())
      return list.isText() ? Value::stringList(list.strings()) : Value::list(list.numbers());
    return itemsAt(name, call.loc, *call.args[0]);
  }
  fail(call.loc, "unknown function '" + name + "'" + didYouMean(name, functions_.names()));
}

// The arguments of a numeric function are numbers, counted once evaluated; a one-argument
// function applies item by item to a list: Abs(a[]).
Value Interpreter::callMath(const MathFunction& function, const ast::Expr& call) {
  try {
    if (call.args.size() == 1) {
      Value arg = evaluate(*call.args[0]);
      if (arg.kind() == Value::Kind::List) {
        for (double& x : arg.numbers()) x = applyMathFunction(function, std::span(&x, 1), random_);
        return arg;
      }
    }
    std::vector<double> args;
    for (const auto& arg : call.args) args.push_back(evaluateNumber(*arg));
    return Value::number(applyMathFunction(function, args, random_));
  } catch (const std::invalid_argument& error) {
    fail(call.loc, error.what());
  }
}

std::string Interpreter::format(const ast::ExprList& args, const SourceLocation& where,
                                bool listWithoutFormat) {
  const std::string pattern = evaluateString(*args[0]);
  std::vector<FormatArgument> values;
  for (std::size_t i = 1; i < args.size(); ++i) {
    Value value = evaluate(*args[i]);
    if (value.isText())
      for (auto& s : value.strings()) values.emplace_back(s);
    else
      for (double x : value.numbers()) values.emplace_back(x);
  }
  if (listWithoutFormat && pattern.find('%') == std::string::npos) {
    // Printf("x = ", x[]): a format with no conversion prints the values after it, numbered.
    std::string line = pattern;
    for (std::size_t i = 0; i < values.size(); ++i) {
      const std::vector<FormatArgument> item{values[i]};
      line += " [" + std::to_string(i) + "]" +
              formatPrintf(std::holds_alternative<double>(values[i]) ? "%g" : "%s", item);
    }
    return line;
  }
  try {
    return formatPrintf(pattern, values);
  } catch (const std::invalid_argument& error) {
    fail(where, error.what());
  }
}

namespace {

using Call = const ast::Expr&;
constexpr std::size_t kAnyCount = ScriptFunction::kAnyCount;

}  // namespace

// LinSpace(a, b, n), LogSpace(a, b, n), Find(list, items), ListFromFile("file"), Unique(list).
std::span<const ScriptFunction> Interpreter::listFunctions() {
  // n values from a to b, evenly spaced, or their powers of ten
  static constexpr auto spaced = [](Interpreter& in, Call call, bool logarithmic) {
    const std::string& name = call.text;
    const double a = in.evaluateNumber(*call.args[0]), b = in.evaluateNumber(*call.args[1]);
    const double count = in.evaluateNumber(*call.args[2]);
    if (count > 10'000'000) in.fail(call.args[2]->loc, "'" + name + "' asks for too many values");
    const int n = clampedInteger<int>(count);
    return Value::list(logarithmic ? logSpace(a, b, n) : linSpace(a, b, n));
  };
  static constexpr ScriptFunction kRows[] = {
      {"LinSpace", 3, 3, "'LinSpace' takes 3 arguments",
       [](Interpreter& in, Call call) { return spaced(in, call, false); }},
      {"LogSpace", 3, 3, "'LogSpace' takes 3 arguments",
       [](Interpreter& in, Call call) { return spaced(in, call, true); }},
      {"Find", 2, 2, "Find takes 2 lists",
       [](Interpreter& in, Call call) {
         // how many of the second list's items are in the first
         const std::vector<double> items = in.evaluateNumbers(*call.args[0]);
         double found = 0;
         for (double x : in.evaluateNumbers(*call.args[1]))
           if (std::find(items.begin(), items.end(), x) != items.end()) ++found;
         return Value::number(found);
       }},
      {"ListFromFile", 1, 1, "ListFromFile takes a file name",
       [](Interpreter& in, Call call) { return in.listFromFile(call); }},
      {"Unique", 0, kAnyCount, "",
       [](Interpreter& in, Call call) {
         std::vector<double> values = in.evaluateNumbers(call.args);
         std::sort(values.begin(), values.end());
         values.erase(std::unique(values.begin(), values.end()), values.end());
         return Value::list(std::move(values));
       }},
  };
  return kRows;
}

// The numbers of a text file, relative to the script's directory.
Value Interpreter::listFromFile(const ast::Expr& call) {
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

// Exists(name), FileExists("file"), GetNumber("name"[, default]), GetString("name"[, default]),
// GetValue("prompt", default). GetNumber and GetString read parameters (DefineConstant's Name,
// SetNumber, -setnumber), never options: that is Gmsh's behaviour too.
std::span<const ScriptFunction> Interpreter::queryFunctions() {
  static constexpr ScriptFunction kRows[] = {
      {"Exists", 1, 1, "Exists takes a variable name or a Struct member",
       [](Interpreter& in, Call call) { return in.exists(call); }},
      {"FileExists", 1, 1, "FileExists takes a file name",
       [](Interpreter& in, Call call) {
         std::filesystem::path p = in.evaluateString(*call.args[0]);
         if (p.is_relative()) p = std::filesystem::path(in.directoryOf(call.loc.file)) / p;
         std::error_code ignored;
         return Value::number(std::filesystem::exists(p, ignored) ? 1 : 0);
       }},
      {"GetNumber", 1, 2, "GetNumber takes 1 or 2 arguments",
       [](Interpreter& in, Call call) {
         const auto& args = call.args;
         const std::string key = in.evaluateString(*args[0]);
         if (auto it = in.parameterNumbers_.find(key); it != in.parameterNumbers_.end())
           return Value::number(it->second);
         return Value::number(args.size() > 1 ? in.evaluateNumber(*args[1]) : 0);
       }},
      {"GetString", 1, 2, "GetString takes 1 or 2 arguments",
       [](Interpreter& in, Call call) {
         const auto& args = call.args;
         const std::string key = in.evaluateString(*args[0]);
         if (auto it = in.parameterStrings_.find(key); it != in.parameterStrings_.end())
           return Value::string(it->second);
         return Value::string(args.size() > 1 ? in.evaluateString(*args[1]) : "");
       }},
      {"GetValue", 2, 2, "GetValue takes a prompt and a default value",
       [](Interpreter& in, Call call) { return in.getValue(call); }},
      {"GetStringValue", 2, 2, "GetStringValue takes a prompt and a default string",
       [](Interpreter& in, Call call) { return in.getValue(call); }},
  };
  return kRows;
}

// Exists(x) is 1 when x is a variable, list item or Struct member; as in Gmsh, the name of a
// Struct (no variable) answers with the Struct's tag.
Value Interpreter::exists(const ast::Expr& call) {
  const auto& args = call.args;
  const bool named =
      args[0]->kind == ast::ExprKind::Variable || args[0]->kind == ast::ExprKind::Member;
  if (!named) fail(call.loc, "Exists takes a variable name or a Struct member");
  const auto value = valueIfDefined(*args[0]);
  if (!value) return Value::number(0);
  const bool structName = args[0]->kind == ast::ExprKind::Variable &&
                          !variables_.contains(resolveName(args[0]->name));
  return structName ? *value : Value::number(1);
}

// A question for an interactive user (GetValue: a number, GetStringValue: a string): in a
// batch run, the prompt is shown and the default is the answer.
Value Interpreter::getValue(const ast::Expr& call) {
  const std::string prompt = evaluateString(*call.args[0]);
  const bool text = call.text == "GetStringValue";
  const Value answer = text ? Value::string(evaluateString(*call.args[1]))
                            : Value::number(evaluateNumber(*call.args[1]));
  if (session_.options().number("General.Verbosity") >= 3) {
    const std::vector<FormatArgument> shown{text ? 0.0 : answer.numbers()[0]};
    session_.out() << prompt << " (default="
                   << (text ? answer.strings()[0] : formatPrintf("%g", shown)) << "): ";
  }
  return answer;
}

// The string constants: Today (the date as "Tue Nov 24 05:27:03 2026"), the running program,
// the directory (with its final slash) and name of the script being read, OnelabAction
// (empty: no ONELAB server drives a batch run).
std::optional<Value> Interpreter::textConstant(std::string_view name, const SourceLocation& where) {
  if (name == "Today") {
    const std::time_t now = std::time(nullptr);
    char text[64] = "";
    std::strftime(text, sizeof text, "%a %b %e %H:%M:%S %Y", std::localtime(&now));
    return Value::string(text);
  }
  if (name == "GmshExecutableName") return Value::string("geomesh");
  if (name == "CurrentDirectory" || name == "CurrentDir") {
    std::error_code ignored;
    const auto directory = std::filesystem::absolute(directoryOf(where.file), ignored);
    std::string text = directory.lexically_normal().string();
    if (text.empty() || text.back() != '/') text += '/';
    return Value::string(text);
  }
  if (name == "CurrentFileName")
    return Value::string(std::filesystem::path(where.file).filename().string());
  if (name == "OnelabAction") return Value::string("");
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
  GeometryFactory& geo = session_.factory();
  int region = deletedPhysicalTag_;
  for (const auto& [id, group] : geo.physicalGroups()) region = std::max(region, id.tag);
  for (int kind : {1, 2, 3, int(GeometryFactory::kCurveLoop), int(GeometryFactory::kSurfaceLoop)})
    region = std::max(region, geo.maxTag(kind));
  const bool oldNewReg = session_.options().number("Geometry.OldNewReg") != 0;
  auto next = [&](int kind) { return Value::number((oldNewReg ? region : geo.maxTag(kind)) + 1); };
  if (name == "newp") return Value::number(geo.maxTag(0) + 1);
  if (name == "newl" || name == "newc") return next(1);
  if (name == "news") return next(2);
  if (name == "newv") return next(3);
  if (name == "newll" || name == "newcl") return next(GeometryFactory::kCurveLoop);
  if (name == "newsl") return next(GeometryFactory::kSurfaceLoop);
  if (name == "newreg") return Value::number(region + 1);
  return std::nullopt;
}

}  // namespace geomesh
