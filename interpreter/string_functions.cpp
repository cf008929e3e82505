// String functions: StrCat, Sprintf, StrSub, StrFind, UpperCase, DirName, GetEnv, ...
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>

#include "interpreter/script_interpreter.h"
#include "stdlib/format.h"

namespace geomesh {

namespace {

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
        for (double x : v.numbers())
          parts.push_back(formatPrintf("%g", std::vector<FormatArgument>{x}));
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
    std::error_code ignored;
    if (p.is_relative())
      p = std::filesystem::absolute(std::filesystem::path(directoryOf(call.loc.file)) / p, ignored);
    return Value::string(p.lexically_normal().string());
  }
  if (name == "StrSub") {
    arity(2, 3);
    std::string s = str(0);
    auto from = clampedInteger<std::size_t>(std::max(0.0, evaluateNumber(*args[1])));
    std::size_t count = std::string::npos;
    if (args.size() > 2)
      count = clampedInteger<std::size_t>(std::max(0.0, evaluateNumber(*args[2])));
    return Value::string(from < s.size() ? s.substr(from, count) : std::string());
  }
  if (name == "StrLen") { arity(1, 1); return Value::number(static_cast<double>(str(0).size())); }
  if (name == "StrFind") {
    arity(2, 2);
    return Value::number(str(0).find(str(1)) != std::string::npos ? 1 : 0);
  }
  if (name == "StrCmp") {
    // As C's strcmp: the difference of the first differing bytes (0 when equal).
    arity(2, 2);
    const std::string a = str(0), b = str(1);
    std::size_t i = 0;
    while (i < a.size() && i < b.size() && a[i] == b[i]) ++i;
    const int left = i < a.size() ? static_cast<unsigned char>(a[i]) : 0;
    const int right = i < b.size() ? static_cast<unsigned char>(b[i]) : 0;
    return Value::number(left - right);
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
    if (args[0]->kind != ast::ExprKind::Variable)
      fail(args[0]->loc, "NameToString takes a variable name");
    return Value::string(resolveName(args[0]->name));
  }
  return std::nullopt;
}

}  // namespace geomesh
